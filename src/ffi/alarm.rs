//! Alarms, alarm messages, operator messages and the alarm history.

// --- alarm ---

use super::program::low16;
use super::{ffi_boundary, nonnull, put};
use crate::client::handles;
use crate::error::Error;
use crate::ew::EW_LENGTH;
use crate::proto::alarm as pa;
use crate::types::{ALMINFO, ODBALM, ODBALMMSG, ODBALMMSG2, OPMSG};
use std::os::raw::{c_long, c_short, c_ushort};

/// Reads the alarm status bits; `data` = their low 16 bits.
///
/// # Safety
/// `alarm` must point to a writable ODBALM.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_alarm(FlibHndl: c_ushort, alarm: *mut ODBALM) -> c_short {
    ffi_boundary!("cnc_alarm", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(alarm)?;
        let a = h.call(&pa::alarm())?;
        unsafe { put(&raw mut (*out).data, a.bits as u16 as c_short) };
        Ok(())
    })
}

/// Reads the alarm status bits (32 bits, 4 bytes written into the `long`).
///
/// # Safety
/// `alarm` must point to 4 writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_alarm2(FlibHndl: c_ushort, alarm: *mut c_long) -> c_short {
    ffi_boundary!("cnc_alarm2", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(alarm)?.cast::<u32>();
        let a = h.call(&pa::alarm())?;
        unsafe { put(out, a.bits) };
        Ok(())
    })
}

/// The common part of cnc_rdalmmsg / cnc_rdalmmsg2: ODBALMMSG-shaped
/// records of `size` bytes with an N-byte text, at most `*num` of them.
unsafe fn read_almmsg<const N: usize>(
    FlibHndl: c_ushort,
    kind: c_short,
    num: *mut c_short,
    out: *mut u8,
) -> crate::error::Result<()> {
    let h = handles::get(FlibHndl)?;
    let num = nonnull(num)?;
    let out = nonnull(out)?;
    let want = unsafe { num.read_unaligned() };
    let recs = h.call(&pa::rdalmmsg::<N>(kind, want))?;
    let n = recs.len().min(want.max(0) as usize);
    let size = 12 + N;
    for (i, r) in recs.iter().take(n).enumerate() {
        let at = unsafe { out.add(i * size) };
        unsafe {
            put(at.cast::<i32>(), r.alm_no);
            put(at.add(4).cast::<c_short>(), low16(r.kind));
            put(at.add(6).cast::<c_short>(), low16(r.axis));
            put(at.add(8).cast::<c_short>(), 0);
            put(at.add(10).cast::<c_short>(), low16(r.msg_len));
            std::ptr::copy_nonoverlapping(r.msg.as_ptr(), at.add(12), N);
        }
    }
    unsafe { put(num, n as c_short) };
    Ok(())
}

/// Reads up to `*num` active alarms of `type` (−1: all) with 32-character
/// messages; `*num` becomes the number read.
///
/// # Safety
/// `num` readable and writable; `almmsg` must have room for `*num` records.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmmsg(
    FlibHndl: c_ushort,
    r#type: c_short,
    num: *mut c_short,
    almmsg: *mut ODBALMMSG,
) -> c_short {
    ffi_boundary!("cnc_rdalmmsg", {
        unsafe { read_almmsg::<32>(FlibHndl, r#type, num, almmsg.cast()) }
    })
}

/// As cnc_rdalmmsg with 64-character messages.
///
/// # Safety
/// `num` readable and writable; `almmsg` must have room for `*num` records.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmmsg2(
    FlibHndl: c_ushort,
    r#type: c_short,
    num: *mut c_short,
    almmsg: *mut ODBALMMSG2,
) -> c_short {
    ffi_boundary!("cnc_rdalmmsg2", {
        unsafe { read_almmsg::<64>(FlibHndl, r#type, num, almmsg.cast()) }
    })
}

/// Reads active alarms of `alm_type` (−1 all): `type` 0 axis and number
/// (ALMINFO alm1, 8-byte records), 1 with messages (alm2, 40-byte records);
/// after the last record −1 is written into the next record's place (the
/// `data_end` slot when there are 5). `length` is the caller's buffer size:
/// at most 5 records and never more than `length` bytes are written (FANUC's
/// library writes every record the CNC sends). `length` ≤ 4: EW_LENGTH
/// without traffic.
///
/// # Safety
/// `almmsg` must have `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalminfo(
    FlibHndl: c_ushort,
    r#type: c_short,
    alm_type: c_short,
    length: c_short,
    almmsg: *mut ALMINFO,
) -> c_short {
    ffi_boundary!("cnc_rdalminfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(almmsg)?.cast::<u8>();
        if length <= 4 {
            return Err(Error::local(EW_LENGTH, "length must be more than 4"));
        }
        let rec = if r#type == 0 { 8 } else { 40 };
        let fit = (length as usize - 4) / rec;
        let recs = h.call(&pa::rdalminfo(r#type, alm_type, fit.max(1) as i32))?;
        let n = recs.len().min(fit).min(5);
        for (i, r) in recs.iter().take(n).enumerate() {
            let at = unsafe { out.add(i * rec) };
            unsafe {
                put(at.cast::<i32>(), i32::from(low16(r.axis)));
                put(at.add(4).cast::<c_short>(), low16(r.alm_no));
                if r#type != 0 {
                    put(at.add(6).cast::<c_short>(), low16(r.msg_len));
                    std::ptr::copy_nonoverlapping(r.msg.as_ptr(), at.add(8), 32);
                }
            }
        }
        unsafe { put(out.add(n * rec).cast::<i32>(), -1) };
        Ok(())
    })
}

/// Reads the operator message of `type` (0..4): number, type, length and
/// text, zero-filled to `length` bytes (at most the 262 of OPMSG).
/// `length` < 6: EW_LENGTH without traffic.
///
/// # Safety
/// `opmsg` must have `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdopmsg(
    FlibHndl: c_ushort,
    r#type: c_short,
    length: c_short,
    opmsg: *mut OPMSG,
) -> c_short {
    ffi_boundary!("cnc_rdopmsg", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(opmsg)?.cast::<u8>();
        if length < 6 {
            return Err(Error::local(EW_LENGTH, "length must be at least 6"));
        }
        let m = h.call(&pa::rdopmsg(r#type))?;
        let room = (length as usize).min(std::mem::size_of::<OPMSG>()) - 6;
        let mut text = vec![0u8; room];
        let n = m.text.len().min(room).min(m.char_num.max(0) as usize);
        text[..n].copy_from_slice(&m.text[..n]);
        unsafe {
            put(out.cast::<c_short>(), low16(m.datano));
            put(out.add(2).cast::<c_short>(), low16(m.kind));
            put(out.add(4).cast::<c_short>(), low16(m.char_num));
            std::ptr::copy_nonoverlapping(text.as_ptr(), out.add(6), room);
        }
        Ok(())
    })
}
