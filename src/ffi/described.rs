//! The exported functions described as data (crate::spec). build.rs writes
//! each one's `extern "C"` function from its table entry (signature plainly,
//! body one [`exec`] call) into `$OUT_DIR/described.rs`, included here; the
//! header's declarations come from the same file (cbindgen reads it).

use super::{ffi_boundary, nonnull, put};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::EW_FUNC;
use crate::proto::described::{Described, form};
use crate::spec::{Func, Int};
#[allow(unused_imports)]
use crate::types::*;
#[allow(unused_imports)]
use std::mem::offset_of;
#[allow(unused_imports)]
use std::os::raw::{c_long, c_short, c_ushort};

/// Runs described function `f`: the handle, its checks and NULL outputs
/// before any traffic, the request for the CNC's class, then the reply's
/// integers into the caller's outputs (only when the whole reply decoded).
///
/// # Safety
/// Each `outs[i]` is NULL or points to writable memory of output i's C
/// type; `offsets[k]` is the byte offset of reply field k's member in its
/// output, and its `n` elements fit there (build.rs asserts it at compile
/// time).
pub(crate) unsafe fn exec(
    f: &'static Func,
    h: c_ushort,
    args: &[i32],
    outs: &[*mut u8],
    offsets: &[usize],
) -> Result<()> {
    let h = handles::get(h)?;
    for c in f.checks {
        let v = args[c.arg as usize];
        if v < c.lo || v > c.hi {
            return Err(Error::local(c.code, "argument out of range"));
        }
    }
    let outs = outs
        .iter()
        .map(|p| nonnull(*p))
        .collect::<Result<Vec<_>>>()?;
    if form(f, h.ctx().class).is_none() {
        return Err(Error::local(EW_FUNC, "not on this CNC class"));
    }
    let values = h.call(&Described { f, args })?;
    let mut v = values.into_iter();
    for (field, off) in f.reply.iter().zip(offsets) {
        for k in 0..field.n as usize {
            let x = v.next().unwrap_or(0);
            if field.to.is_none() {
                continue;
            }
            // SAFETY: the caller's contract (offset and element in the output).
            unsafe {
                let p = outs[field.out as usize].add(off + k * field.c.size());
                match field.c {
                    Int::I8 => put(p.cast::<i8>(), x as i8),
                    Int::U8 => put(p, x as u8),
                    Int::I16 => put(p.cast::<i16>(), x as i16),
                    Int::U16 => put(p.cast::<u16>(), x as u16),
                    Int::I32 => put(p.cast::<i32>(), x as i32),
                    Int::U32 => put(p.cast::<u32>(), x as u32),
                }
            }
        }
    }
    Ok(())
}

include!(concat!(env!("OUT_DIR"), "/described.rs"));
