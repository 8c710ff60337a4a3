//! Parameters and diagnostics: their values (cnc_rdparam, cnc_diagnoss,
//! cnc_wrparam, the number ranges, cnc_rdparar / cnc_wrparas). Their
//! attributes are in paraminfo.rs.

use super::{ffi_boundary, ffi_read, nonnull, put};
use crate::client::handles::{self, Handle};
use crate::error::{Error, Result};
use crate::ew::{EW_LENGTH, EW_NUMBER};
use crate::proto::open::CncClass;
use crate::proto::param::{
    Item, Packed, ParamInfo, ReadOne, ReadRange, Table, WriteParam, WriteSeveral, block_len,
    check_length, rdnum, wrparas_per_frame,
};
use crate::types::{IODBPSD, ODBDGN, ODBDIAGNUM, ODBPARANUM};
use std::os::raw::{c_short, c_ushort, c_void};

/// Reads one item and writes datano, type (the axis word of the answer)
/// and the values from offset 4 of `out`. Like FANUC's library, the header
/// is written before the length check, which happens after the exchange.
///
/// # Safety
/// `out` must point to 4 writable bytes plus the values (at most 256).
unsafe fn read_one(
    h: &Handle,
    table: Table,
    (number, axis, flag): (c_short, c_short, i32),
    length: c_short,
    out: *mut u8,
) -> Result<()> {
    let item: Item = h.call(&ReadOne {
        table,
        number: number as i32,
        axis,
        flag,
    })?;
    // A `length` below the header's 4 bytes: nothing is written.
    if length < 4 {
        return Err(Error::local(EW_LENGTH, "length is below the 4-byte header"));
    }
    let mut head = [0u8; 4];
    head[..2].copy_from_slice(&(item.number as i16).to_le_bytes());
    // The `type` field: the answer's axis word; from a Series 15, FANUC's
    // library writes (type << 8) | (axis & 0xff) there, as cnc_rdparar does.
    let type_field = match h.ctx().class {
        CncClass::Series16 { kind: 2 } => ((item.ptype & 0xff) << 8) as i16 | (item.axis & 0xff),
        _ => item.axis,
    };
    head[2..].copy_from_slice(&type_field.to_le_bytes());
    unsafe { put(out.cast::<[u8; 4]>(), head) };
    check_length(length, &item)?;
    let data = item.data_bytes();
    debug_assert!(data.len() <= 256);
    unsafe { std::ptr::copy_nonoverlapping(data.as_ptr(), out.add(4), data.len()) };
    Ok(())
}

/// Reads a CNC parameter: one axis (`axis` ≥ 1), no axis (0) or all axes
/// (-1). The answer's axis word decides how many values come back: a
/// negative one max-axes values, any other one value (a non-axis parameter
/// read with -1). `length` must be at least 4 + their size (1 for bit and
/// byte, 2 word, 4 2-word, 8 real each), checked after the exchange as
/// FANUC does (EW_LENGTH with `datano` and `type` written; below 4 nothing
/// is written). A Series 15 is asked with the 30i command (0x8d).
///
/// # Safety
/// `param` must point to a writable IODBPSD.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdparam(
    FlibHndl: c_ushort,
    number: c_short,
    axis: c_short,
    length: c_short,
    param: *mut IODBPSD,
) -> c_short {
    ffi_read!("cnc_rdparam", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(param)?;
        unsafe { read_one(&h, Table::Param, (number, axis, 0), length, out.cast()) }
    })
}

/// Reads a CNC parameter as cnc_rdparam does; a `type` other than 0 sets
/// the request's fifth word (what the CNC makes of it is not known).
///
/// # Safety
/// `param` must point to a writable IODBPSD.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdparam3(
    FlibHndl: c_ushort,
    number: c_short,
    axis: c_short,
    length: c_short,
    r#type: c_short,
    param: *mut IODBPSD,
) -> c_short {
    ffi_boundary!("cnc_rdparam3", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(param)?;
        let flag = i32::from(r#type != 0) << 16;
        unsafe { read_one(&h, Table::Param, (number, axis, flag), length, out.cast()) }
    })
}

/// Reads CNC diagnosis data, as cnc_rdparam reads parameters (sizes: byte
/// and bit 1, word 2, 2-word 4, real 8).
///
/// # Safety
/// `diag` must point to a writable ODBDGN.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_diagnoss(
    FlibHndl: c_ushort,
    number: c_short,
    axis: c_short,
    length: c_short,
    diag: *mut ODBDGN,
) -> c_short {
    ffi_read!("cnc_diagnoss", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(diag)?;
        unsafe { read_one(&h, Table::Diag, (number, axis, 0), length, out.cast()) }
    })
}

/// The same as cnc_diagnoss (an alias some programs use).
///
/// # Safety
/// `diag` must point to a writable ODBDGN.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rddiag(
    FlibHndl: c_ushort,
    number: c_short,
    axis: c_short,
    length: c_short,
    diag: *mut ODBDGN,
) -> c_short {
    unsafe { cnc_diagnoss(FlibHndl, number, axis, length, diag) }
}

/// Writes a CNC parameter. The parameter's attributes are read first
/// (one exchange); `length` must then equal 4 + the size of the values
/// (one value, or one per axis of the path for `type` -1), else EW_LENGTH
/// and nothing is written. A 30i type word other than 0..4 (none a CNC
/// uses) is written back as it came with every value zero, whatever
/// `length`, as FANUC's library does. The input is read with the l32 layout (values
/// from offset 4). The write is sent once; the CNC decides whether it is
/// allowed (parameter write enable, MDI mode ...). A 16i-class write
/// carries one value slot per axis of the CNC's maximum (as FANUC's library);
/// a Series 15 gets EW_LENGTH without traffic for every length, as from
/// FANUC's library.
///
/// # Safety
/// `param` must point to a readable IODBPSD.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrparam(
    FlibHndl: c_ushort,
    length: c_short,
    param: *mut IODBPSD,
) -> c_short {
    ffi_boundary!("cnc_wrparam", {
        let h = handles::get(FlibHndl)?;
        let inp = nonnull(param)?.cast::<u8>();
        // FANUC's library refuses every length for a Series 15 before any
        // traffic (the lengths it would take are not known).
        if h.ctx().class == (CncClass::Series16 { kind: 2 }) {
            return Err(Error::local(EW_LENGTH, "Series 15: length refused"));
        }
        let raw: [u8; 260] = unsafe { inp.cast::<[u8; 260]>().read_unaligned() };
        let number = i16::from_le_bytes([raw[0], raw[1]]) as i32;
        let axis = i16::from_le_bytes([raw[2], raw[3]]);
        let info = h.call(&ParamInfo { number })?;
        // A type word FANUC's library does not know (30i: not 0..4): no
        // length check, every value slot sent as zero, the CNC decides.
        let values = match info.elem {
            Some(elem) => {
                let count = if axis == -1 { h.ctx().axes() } else { 1 };
                let size = elem.size();
                if length as i32 != (4 + size * count) as i32 {
                    return Err(Error::local(
                        EW_LENGTH,
                        "length is not 4 + the size of the parameter's values",
                    ));
                }
                (0..count).map(|i| elem.get(&raw[4 + i * size..])).collect()
            }
            None => Vec::new(),
        };
        h.call(&WriteParam {
            number,
            axis,
            ptype: info.ptype,
            values,
        })
    })
}

/// Reads the smallest and largest parameter numbers and how many there are.
///
/// # Safety
/// `paranum` must point to a writable ODBPARANUM.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdparanum(FlibHndl: c_ushort, paranum: *mut ODBPARANUM) -> c_short {
    ffi_boundary!("cnc_rdparanum", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(paranum)?;
        let r = h.call(&rdnum(Table::Param))?;
        let v = ODBPARANUM {
            para_min: r.min as c_ushort,
            para_max: r.max as c_ushort,
            total_no: r.total as c_ushort,
        };
        unsafe { put(out, v) };
        Ok(())
    })
}

/// Reads the smallest and largest diagnosis numbers and how many there are.
///
/// # Safety
/// `diagnum` must point to a writable ODBDIAGNUM.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rddiagnum(FlibHndl: c_ushort, diagnum: *mut ODBDIAGNUM) -> c_short {
    ffi_boundary!("cnc_rddiagnum", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(diagnum)?;
        let r = h.call(&rdnum(Table::Diag))?;
        let v = ODBDIAGNUM {
            diag_min: r.min as c_ushort,
            diag_max: r.max as c_ushort,
            total_no: r.total as c_ushort,
        };
        unsafe { put(out, v) };
        Ok(())
    })
}

/// Reads the parameters `*s_number..=*e_number` (those the CNC has) into
/// `param` as packed records: i16 number, i16 type word `(type << 8) |
/// (axis & 0xff)`, then one value (axis -1: one per axis of the CNC) of
/// the type's size (bit and byte 1, word 2, 2-word 4, real 8 = value and
/// decimals), each record padded to a multiple of 4 (the padding bytes are
/// not written). Asks the CNC again from the last number received + 1
/// (the block's whole 32-bit number, wrapping) while that is not above
/// `*e_number`; an answer without a whole block asks again from there too
/// (from 1 before any block), and ends in EW_PROTOCOL when that would
/// repeat the request just answered (FANUC's library repeats it for ever).
/// On success `*s_number` is the first
/// number read, `*e_number` the last, and `*length` (in: the buffer's
/// size) the bytes used. `*s_number > *e_number` is EW_NUMBER without
/// traffic. A record that does not fit with its padding is EW_LENGTH: the
/// records before it stay written, as does its 4-byte header if that fits,
/// and the three pointers keep their values (all as FANUC's library, checked
/// against it with our simulator).
///
/// # Safety
/// `s_number`, `e_number` and `length` must point to readable and writable
/// shorts, `param` to `*length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdparar(
    FlibHndl: c_ushort,
    s_number: *mut c_short,
    axis: c_short,
    e_number: *mut c_short,
    length: *mut c_short,
    param: *mut c_void,
) -> c_short {
    ffi_boundary!("cnc_rdparar", {
        let h = handles::get(FlibHndl)?;
        let s_number = nonnull(s_number)?;
        let e_number = nonnull(e_number)?;
        let length = nonnull(length)?;
        let out = nonnull(param)?.cast::<u8>();
        let s = unsafe { s_number.read_unaligned() } as i32;
        let e = unsafe { e_number.read_unaligned() } as i32;
        let room = unsafe { length.read_unaligned() }.max(0) as usize;
        if s > e {
            return Err(Error::local(EW_NUMBER, "start number above end number"));
        }
        let mut used = 0usize;
        let mut first: Option<i16> = None;
        // FANUC's library's loop [fuzz, seed 0x21b01128]: `last` is the i32
        // number of the last block received (0 before any); after each
        // answer it asks on from last + 1 (wrapping) while that is ≤ e, so
        // an answer without a block restarts from 1, or repeats the request.
        let mut last: i32 = 0;
        let mut next = s;
        loop {
            let recs = match h.call(&ReadRange {
                start: next,
                end: e,
                axis,
            }) {
                // No more numbers after some were read: done.
                Err(Error::Cnc {
                    code: EW_NUMBER, ..
                }) if first.is_some() => break,
                r => r?,
            };
            for (number, r) in &recs {
                let bytes = r.to_c();
                if used + r.padded_len() > room {
                    // Its header, as FANUC's library writes it, if it fits.
                    if used + 4 <= room {
                        unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), out.add(used), 4) };
                    }
                    return Err(Error::local(EW_LENGTH, "a record does not fit in length"));
                }
                unsafe {
                    std::ptr::copy_nonoverlapping(bytes.as_ptr(), out.add(used), bytes.len())
                };
                used += r.padded_len();
                first.get_or_insert(r.number);
                last = *number;
            }
            let asked = next;
            next = last.wrapping_add(1);
            // A request answered without a block that FANUC's library would
            // send again: it asks for ever of a CNC that answers the same;
            // ours ends there (every record takes room in the buffer, so a
            // CNC that goes back without end ends in EW_LENGTH).
            if recs.is_empty() && next == asked {
                return Err(Error::short(
                    "parameter range answer without a block, to the request it would repeat",
                ));
            }
            if next > e {
                break;
            }
        }
        unsafe {
            put(s_number, first.unwrap_or(s as i16));
            put(length, used as c_short);
            // The last block's number (low 16 bits), 0 before any.
            put(e_number, last as c_short);
        }
        Ok(())
    })
}

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
