//! Axes and spindles: names, positions, speeds, loads, dynamic data, figures
//! (SPEC.md §5.3). Payload structures and the calls that use them.
//!
//! The 0x1a / 0x1c / 0x1d payloads ([`AlarmBits`], [`ProgNums`], [`SeqNum`])
//! are part of cnc_rddynamic2's frame and are also what cnc_alarm,
//! cnc_rdprgnum and cnc_rdseqnum read: they are shared with the program and
//! alarm areas.
//!
//! By subject: `codes` (the 0x26 / 0x40 codes), `payload` (the payload
//! structures), `read` (reading a frame as FANUC's library does), then one
//! file per call family: `simple`, `dynamic`, `spindle`, `axis_data`,
//! `speed`, `position16`.

pub use super::cmd::{
    ACTF, ACTS, ALARM, AXIS_FLAGS, COUNT, GETFIGURE, POSITION, PRGNUM, RDAXISNAME, RDSPDLNAME,
    SEQNUM, SERVO_LOAD, SPEED_A5, SPINDLE, SPINDLE_SHOWN15, UNITS,
};

mod axis_data;
mod codes;
mod dynamic;
mod payload;
mod position16;
mod read;
mod simple;
mod speed;
mod spindle;

pub use axis_data::*;
pub use codes::*;
pub use dynamic::*;
pub use payload::*;
pub use position16::*;
pub use read::*;
pub use simple::*;
pub use speed::*;
pub use spindle::*;
