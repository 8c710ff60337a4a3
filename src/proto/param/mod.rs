//! Parameters and diagnostics (SPEC.md §5.2, §5.3).
//!
//! One payload shape serves reads and writes of both classes: number, axis,
//! type, then values (30i: 8-byte [`Value`](super::value::Value) records;
//! 16i: 4-byte i32). [`Elem`] is the one codec between a value and the
//! bytes of the caller's C buffer (IODBPSD / ODBDGN / the write input):
//! `get` is `put` reversed.
//!
//! By subject: `data` (the payload shape and the value codec), `read`
//! (cnc_rdparam / cnc_diagnoss and the number ranges), `info` (attributes
//! and info lists), `write` (cnc_wrparam), `ext` (cnc_rdparam_ext /
//! cnc_rddiag_ext), `packed` (cnc_rdparar / cnc_wrparas).

pub use super::cmd::{
    DIAGNOSS, DIAGNOSS16, DIAGTYPE, PARAMTYPE, RDDIAGINFO, RDDIAGINFO15, RDDIAGNUM, RDPARAINFO,
    RDPARAINFO15, RDPARAM, RDPARAM16, RDPARANUM, WRPARAM, WRPARAM16,
};

mod data;
mod ext;
mod info;
mod packed;
mod read;
mod write;

pub use data::*;
pub use ext::*;
pub use info::*;
pub use packed::*;
pub use read::*;
pub use write::*;
