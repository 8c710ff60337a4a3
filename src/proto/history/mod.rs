//! Records read by number range: the operation history (cnc_rdophistry),
//! the operator message histories (cnc_rdomhistry, cnc_rdomhistry2), alarm
//! history 5 (cnc_rdalmhistry5) and the pitch error table (cnc_rdpitchr).
//! Learnt with the oracle (docs/protocol/history.md).
//!
//! Each answer is fixed-size records (cnc_rdomhistry2: after a 4-byte
//! count).
//!
//! By subject: `records` (the range reads), `record` (the record kinds, and
//! the records as the CNC sends them), `op4` (cnc_rdophistry4), `sig3`
//! (the operation history's signal table, cnc_wrhissgnl3).

pub use super::cmd::{
    RDALMHISTRY5, RDOMHISTRY, RDOMHISTRY2, RDOPHISTRY, RDOPHISTRY4, RDPITCHR, WRHISSGNL3,
};

mod op4;
mod record;
mod records;
mod sig3;

pub use op4::*;
pub use record::*;
pub use records::*;
pub use sig3::*;
