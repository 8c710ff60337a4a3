//! Machine data (issue 11): the program restart information (the spindle
//! control signals are table entries, src/spec/table/signals.rs).

use super::{ffi_boundary, nonnull, put_at, put_member};
use crate::client::handles;
use crate::proto::machine::PrstrInfo;
use crate::types::ODBPRS;
use std::mem::offset_of;
use std::os::raw::{c_short, c_ushort};

/// Where each 0x0043 answer's words go in ODBPRS: rstr_bc, rstr_m,
/// rstr_t, rstr_s, rstr_b.
const PRS_WORDS: [usize; 5] = [
    offset_of!(ODBPRS, rstr_bc),
    offset_of!(ODBPRS, rstr_m),
    offset_of!(ODBPRS, rstr_t),
    offset_of!(ODBPRS, rstr_s),
    offset_of!(ODBPRS, rstr_b),
];
/// Where the restart positions go: `dest`, the distances right after the
/// positions received (FANUC's library packs them).
const PRS_DEST: usize = offset_of!(ODBPRS, dest);

/// Reads the program restart information in one exchange: for the block
/// counter, M, T, S and B codes the number of values the CNC sent
/// (`data_info`) and the values, then the restart position and distance
/// of every axis. The answers are written in order, each at its member
/// (more values than a member holds run into the next ones, as FANUC's
/// library writes them, but never past ODBPRS); a CNC error in a later
/// subpacket is returned with the earlier ones written.
///
/// # Safety
/// `prs` must point to a writable ODBPRS.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdprstrinfo(FlibHndl: c_ushort, prs: *mut ODBPRS) -> c_short {
    ffi_boundary!("cnc_rdprstrinfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(prs)?.cast::<u8>();
        let a = h.call(&PrstrInfo)?;
        const SIZE: usize = std::mem::size_of::<ODBPRS>();
        let word = |at: usize, v: i32| {
            if at + 4 <= SIZE {
                // SAFETY: inside the caller's ODBPRS.
                unsafe { put_at(out, at, v) };
            }
        };
        for (k, words) in a.words.iter().enumerate() {
            unsafe { put_member!(out, ODBPRS, data_info[k], words.len() as u16 as i16) };
            for (i, v) in words.iter().enumerate() {
                word(PRS_WORDS[k] + 4 * i, *v);
            }
        }
        let mut at = PRS_DEST;
        for v in a.positions.iter().flatten() {
            word(at, *v);
            at += 4;
        }
        match a.error {
            Some(e) => {
                h.note(&e);
                Err(e)
            }
            None => Ok(()),
        }
    })
}
