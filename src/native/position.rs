//! Axis positions with names, decimals and units (the cnc_rdposition frame).

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::decimal::Decimal;
use super::error::{Error, Result};
use super::part::{Part, via};
use crate::proto::described::Described;
use crate::proto::position::{AxisData, AxisDataCall, AxisValue, pos};
use std::fmt;

/// The unit of an axis's positions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Unit {
    Mm,
    Inch,
    Degree,
    /// A unit code without a name here.
    Other(i16),
}

impl Unit {
    pub fn from_code(code: i16) -> Unit {
        match code {
            0 => Unit::Mm,
            1 => Unit::Inch,
            2 => Unit::Degree,
            c => Unit::Other(c),
        }
    }
}

impl fmt::Display for Unit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Unit::Mm => f.pad("mm"),
            Unit::Inch => f.pad("inch"),
            Unit::Degree => f.pad("deg"),
            Unit::Other(c) => f.pad(&format!("unit {c}")),
        }
    }
}

/// The positions of one axis, each with the decimal places the CNC keeps.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct AxisPosition {
    /// The axis name with its suffix ("X", "Y2" ...).
    pub name: String,
    /// Absolute position (workpiece coordinates).
    pub absolute: Decimal,
    /// Machine position.
    pub machine: Decimal,
    /// Relative position.
    pub relative: Decimal,
    /// Distance to go.
    pub distance: Decimal,
    /// The unit of the absolute position (the others share it, except the
    /// machine position on some machines).
    pub unit: Unit,
}

/// A name entry's text (up to its first NUL).
pub(crate) fn name(b: &[u8]) -> String {
    let end = b.iter().position(|c| *c == 0).unwrap_or(b.len());
    String::from_utf8_lossy(&b[..end]).trim().to_string()
}

fn dec(v: &AxisValue) -> Decimal {
    Decimal::new(v.data, v.dec)
}

fn positions_part(cnc: &Cnc) -> impl Part<Out = Vec<AxisPosition>> + Send + 'static {
    const CALL: &str = "cnc_rdposition";
    let n = cnc.ctx().axes();
    let call = AxisDataCall {
        what: AxisData::Positions(vec![
            pos::ABSOLUTE2,
            pos::MACHINE,
            pos::RELATIVE2,
            pos::DISTANCE2,
        ]),
        limit: crate::types::MAX_AXIS as i16,
    };
    // Two counts, names (4 + 16 per axis), two unit and one flag word per
    // axis, four value records per axis.
    via(CALL, call, 8 + 60 * n, |r| {
        if let Some(e) = r.error {
            return Err(Error::of(CALL, e));
        }
        let [abs, mach, rel, dist] = &r.values[..] else {
            return Err(Error::of(CALL, crate::error::Error::short("four rows")));
        };
        Ok((0..r.count)
            .map(|i| AxisPosition {
                name: name(&abs[i].name),
                absolute: dec(&abs[i]),
                machine: dec(&mach[i]),
                relative: dec(&rel[i]),
                distance: dec(&dist[i]),
                unit: Unit::from_code(abs[i].unit),
            })
            .collect())
    })
}

impl Cnc {
    /// The absolute, machine, relative positions and distances to go of
    /// every axis of the current path, in one exchange.
    ///
    /// ```
    /// use fwlib32::native::{Cnc, Decimal, Unit};
    /// use fwlib32::sim::{Profile, Simulator};
    /// use std::time::Duration;
    ///
    /// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// sim.set_elapsed(Duration::ZERO); // the program has not moved the axes yet
    /// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
    /// let axes = cnc.positions()?;
    /// let names: Vec<&str> = axes.iter().map(|a| a.name.as_str()).collect();
    /// assert_eq!(names, ["X", "Y", "Z"]);
    /// assert_eq!(axes[1].absolute, Decimal::new(-42500, 3));
    /// assert_eq!(axes[1].absolute.to_string(), "-42.500");
    /// assert_eq!(axes[0].unit, Unit::Mm);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn positions(&self) -> Result<Vec<AxisPosition>> {
        self.run(positions_part(self))
    }

    /// The names of the current path's axes ("X", "Y", "Z" ...; cnc_rdaxisname).
    pub fn axis_names(&self) -> Result<Vec<String>> {
        self.run(names_part())
    }
}

fn names_part() -> impl Part<Out = Vec<String>> + Send + 'static {
    const CALL: &str = "cnc_rdaxisname";
    const MAX_AXIS: i32 = crate::types::MAX_AXIS as i32;
    let f = crate::spec::find(CALL).expect("a described function");
    // The reply's integers: 4 bytes a name (name, suffix, two more).
    via(
        CALL,
        Described::new(f, &[MAX_AXIS]),
        4 * MAX_AXIS as usize,
        |v| {
            Ok(v.chunks_exact(4)
                .map(|e| name(&e.iter().map(|b| *b as u8).collect::<Vec<_>>()))
                .collect())
        },
    )
}

impl Batch<'_> {
    /// [`Cnc::axis_names`] in the batch.
    pub fn axis_names(&mut self) -> Ticket<Vec<String>> {
        self.push(names_part())
    }

    /// [`Cnc::positions`] in the batch.
    pub fn positions(&mut self) -> Ticket<Vec<AxisPosition>> {
        let p = positions_part(self.cnc());
        self.push(p)
    }
}
