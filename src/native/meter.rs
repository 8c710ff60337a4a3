//! Load meters: each servo axis's load (cnc_rdsvmeter) and each spindle's
//! load and speed (cnc_rdspmeter), named as the CNC names them.

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::decimal::Decimal;
use super::error::{Error, Ew, Result};
use super::part::{Part, Ready, via};
use super::position::name;
use crate::proto::position::{AxisData, AxisDataCall, spdl};

/// One axis's or spindle's meter reading.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Meter {
    /// The axis's ("X") or spindle's ("S1") name.
    pub name: String,
    /// Load, %.
    pub load: Decimal,
    /// Motor speed, min⁻¹ (spindles; zero for axes).
    pub speed: Decimal,
}

fn servo_part(cnc: &Cnc) -> impl Part<Out = Vec<Meter>> + Send + 'static {
    const CALL: &str = "cnc_rdsvmeter";
    // Two counts; a name (4 bytes) and a value record (8) per axis.
    let n = cnc.ctx().axes();
    let call = AxisDataCall {
        what: AxisData::Servo(vec![1]),
        limit: crate::types::MAX_AXIS as i16,
    };
    via(CALL, call, 8 + 12 * n, |r| {
        if let Some(e) = r.error {
            return Err(Error::of(CALL, e));
        }
        Ok(r.values
            .first()
            .map(|row| {
                row.iter()
                    .take(r.count)
                    .map(|v| Meter {
                        name: name(&v.name),
                        load: Decimal::new(v.data, v.dec),
                        speed: Decimal::new(0, 0),
                    })
                    .collect()
            })
            .unwrap_or_default())
    })
}

const SPINDLE_CALL: &str = "cnc_rdspmeter";

/// The refusal when the CNC reports no spindle information (as the C
/// function's, without traffic).
fn no_spindles(cnc: &Cnc) -> Option<Ready<Vec<Meter>>> {
    (!cnc.handle().pair.info.open.has_spindle_info()).then(|| {
        Ready(Err(Error::invalid(
            SPINDLE_CALL,
            Ew::NOOPT,
            "the CNC reports no spindle information",
        )))
    })
}

fn spindle_part() -> impl Part<Out = Vec<Meter>> + Send + 'static {
    const CALL: &str = SPINDLE_CALL;
    let call = AxisDataCall {
        what: AxisData::Spindle(vec![spdl::LOAD_METER, spdl::SPEED_METER]),
        limit: crate::types::MAX_SPINDLE as i16,
    };
    // Two counts; a name and two value records per spindle.
    via(CALL, call, 8 + 20 * crate::types::MAX_SPINDLE, |r| {
        if let Some(e) = r.error {
            return Err(Error::of(CALL, e));
        }
        let (Some(load), Some(speed)) = (r.values.first(), r.values.get(1)) else {
            return Err(Error::of(CALL, crate::error::Error::short("two rows")));
        };
        Ok(load
            .iter()
            .zip(speed)
            .take(r.count)
            .map(|(l, s)| Meter {
                name: name(&l.name),
                load: Decimal::new(l.data, l.dec),
                speed: Decimal::new(s.data, s.dec),
            })
            .collect())
    })
}

impl Cnc {
    /// Every servo axis's load meter, % (cnc_rdsvmeter).
    pub fn servo_loads(&self) -> Result<Vec<Meter>> {
        self.run(servo_part(self))
    }

    /// Every spindle's load, % and motor speed (cnc_rdspmeter, both).
    pub fn spindle_meters(&self) -> Result<Vec<Meter>> {
        match no_spindles(self) {
            Some(r) => self.run(r),
            None => self.run(spindle_part()),
        }
    }
}

impl Batch<'_> {
    /// [`Cnc::servo_loads`] in the batch.
    pub fn servo_loads(&mut self) -> Ticket<Vec<Meter>> {
        let p = servo_part(self.cnc());
        self.push(p)
    }

    /// [`Cnc::spindle_meters`] in the batch.
    pub fn spindle_meters(&mut self) -> Ticket<Vec<Meter>> {
        match no_spindles(self.cnc()) {
            Some(r) => self.push(r),
            None => self.push(spindle_part()),
        }
    }
}
