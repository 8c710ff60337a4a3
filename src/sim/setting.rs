//! The setting data (cnc_rdset, cnc_rdsetr, cnc_wrset): the profile's parameters
//! numbered up to `[param] setting_max` (cnc_rdsetnum counts them), read
//! and written with the setting commands in the parameter block form of
//! src/sim/param.rs. A number above `setting_max` (or none) is EW_NUMBER;
//! a setting written is the parameter cnc_rdparam then reads, with the
//! write checks of cnc_wrparam (a refused write changes nothing).

use super::machine::Machine;
use super::profile::Class;
use super::route::{Asked, Route};
use super::service::{CncError, Reply};
use crate::proto::cmd::{RDSET, RDSET16, WRSET, WRSET16};
use crate::proto::described::block;
use crate::proto::open::CncClass;
use crate::proto::param::Table;
use crate::proto::wire::Wire;

pub(super) const ROUTES: &[Route] = &[
    Route::table(RDSET, read),
    Route::table(RDSET16, read),
    Route::table(WRSET, write),
    Route::table(WRSET16, write),
];

impl Machine {
    /// The CNC's class, as the block form goes.
    pub(super) fn set_class(&self) -> CncClass {
        let c = &self.profile.cnc;
        match c.class {
            Class::Series30 => CncClass::Series30,
            Class::Series16 => CncClass::Series16 { kind: c.kind },
        }
    }

    /// EW_NUMBER unless `number` is a setting data number.
    fn setting(&self, number: i32) -> Reply<()> {
        let p = &self.profile.param;
        if number > p.setting_max || !p.parameters.iter().any(|e| e.number == number) {
            return Err(CncError::NUMBER);
        }
        Ok(())
    }
}

/// cnc_rdset [n, n, axis]: the setting's parameter block, as cnc_rdparam's
/// answer (30i: value records; 16i class and Series 15: words);
/// cnc_rdsetr [s, e, axis], s < e: the blocks of the settings from s on,
/// as cnc_rdparar's (the range ends at `setting_max`).
fn read(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let [s, e, axis, ..] = q.words;
    let axis = axis as i16;
    let class = m.set_class();
    let bytes = if s == e {
        m.setting(s)?;
        match class {
            CncClass::Series30 => m.table_read30(q.path, Table::Param, s, s, axis)?,
            CncClass::Series16 { .. } => m.table_read16(q.path, Table::Param, s, axis)?.to_bytes(),
        }
    } else {
        let max = m.profile.param.setting_max;
        if s > max {
            return Err(CncError::NUMBER);
        }
        let e = e.min(max).max(s);
        // A Series 15's range in the 30i form, as FANUC's cnc_rdparar
        // reads a range from it.
        match class {
            CncClass::Series30 | CncClass::Series16 { kind: 2 } => {
                m.table_read30(q.path, Table::Param, s, e, axis)?
            }
            CncClass::Series16 { .. } => m.table_read16_range(q.path, Table::Param, s, e, axis)?,
        }
    };
    block::wire_values(class, false, &bytes).map_err(|_| CncError::FUNC)
}

/// cnc_wrset: one block, written as cnc_wrparam's is (its checks, in
/// its order), when its number is a setting's.
fn write(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let class = m.set_class();
    let bytes =
        block::encode(class, true, q.payload).map_err(|_| CncError::new(crate::ew::EW_LENGTH))?;
    m.setting(q.payload.first().copied().unwrap_or(-1) as i32)?;
    // A Series 15 takes the 30i block.
    m.table_write(q.path, !block::records(class, true), &bytes)?;
    Ok(Vec::new())
}
