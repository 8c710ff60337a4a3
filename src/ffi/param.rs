//! Parameters: the packed write cnc_wrparas. The one-item reads and the
//! write (cnc_rdparam, cnc_rdparam3, cnc_diagnoss, cnc_rddiag,
//! cnc_wrparam), the range read cnc_rdparar and the number ranges are
//! described as data (src/spec/table/param.rs); the attributes are in
//! paraminfo.rs.

use super::{ffi_boundary, nonnull};
use crate::client::handles;
use crate::proto::param::{Packed, WriteSeveral, block_len, wrparas_per_frame};
use std::os::raw::{c_short, c_ushort, c_void};

/// Writes several parameters given as packed records (the format
/// cnc_rdparar reads) in `length` bytes, without reading their attributes
/// first: one write block of the CNC's max axes per record, as many per
/// exchange as fit FANUC's budget (5 on a 30i with 32 axes, 10 on a 16i).
/// `length` ≤ 0 writes nothing. A record that does not fit in `length` is
/// EW_LENGTH before any traffic. A record of a type other than 0..4 is its
/// 4-byte header alone, sent without values (zeros; FANUC's library sends
/// the values of its previous block there). The CNC checks each write as
/// for cnc_wrparam; the first refused exchange ends the call with its
/// error (earlier exchanges stay written).
///
/// # Safety
/// `param` must point to `length` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrparas(
    FlibHndl: c_ushort,
    length: c_short,
    param: *mut c_void,
) -> c_short {
    ffi_boundary!("cnc_wrparas", {
        let h = handles::get(FlibHndl)?;
        let inp = nonnull(param)?.cast::<u8>();
        if length <= 0 {
            return Ok(());
        }
        let cx = h.ctx();
        let axes = cx.axes();
        let buf = unsafe { std::slice::from_raw_parts(inp, length as usize) };
        let mut records = Vec::new();
        let mut at = 0;
        while at < buf.len() {
            let (r, n) = Packed::from_c(&buf[at..], axes)?;
            records.push(r);
            at += n;
        }
        let per = wrparas_per_frame(block_len(cx.class, cx.max_axes as usize));
        for chunk in records.chunks(per) {
            h.call(&WriteSeveral {
                records: chunk.to_vec(),
            })?;
        }
        Ok(())
    })
}
