//! Alarms, alarm messages, operator messages and the alarm history.

// --- alarm ---

use super::program::low16;
use super::{element, ffi_boundary, ffi_read, nonnull, put, put_member};
use crate::client::handles::{self, Handle};
use crate::error::{Error, Result};
use crate::ew::{EW_ATTRIB, EW_FUNC, EW_LENGTH, EW_NUMBER};
use crate::proto::alarm::{self as pa, AlmHisRecord, rdalmhistry};
use crate::proto::open::CncClass;
use crate::types::{
    ALMINFO, ALMINFO_alm1_rec, ALMINFO_alm2_rec, LONG, ODBAHIS, ODBAHIS_ALM, ODBAHIS2,
    ODBAHIS2_ALM, ODBALMMSG, ODBALMMSG2, OPMSG, OPMSG3,
};
use std::mem::offset_of;
use std::os::raw::{c_char, c_short, c_ushort};

/// The common part of cnc_rdalmmsg / cnc_rdalmmsg2: ODBALMMSG-shaped
/// records of `size` bytes with an N-byte text, at most `*num` of them.
unsafe fn read_almmsg<const N: usize>(
    FlibHndl: c_ushort,
    kind: c_short,
    num: *mut c_short,
    out: *mut u8,
) -> Result<()> {
    let h = handles::get(FlibHndl)?;
    let num = nonnull(num)?;
    let out = nonnull(out)?;
    let want = unsafe { num.read_unaligned() };
    if want <= 0 {
        return Err(Error::local(EW_LENGTH, "num must be at least 1"));
    }
    let recs = match h.call(&pa::rdalmmsg::<N>(kind, want)) {
        Ok(r) => r.0,
        // The CNC's EW_LENGTH reads as no alarm (FANUC's library).
        Err(Error::Cnc {
            code: EW_LENGTH, ..
        }) => Vec::new(),
        Err(e) => return Err(e),
    };
    let n = recs.len().min(want as usize);
    // ODBALMMSG and ODBALMMSG2 differ only in their text's length.
    const _: () = assert!(
        offset_of!(ODBALMMSG, msg_len) == offset_of!(ODBALMMSG2, msg_len)
            && offset_of!(ODBALMMSG, alm_msg) == offset_of!(ODBALMMSG2, alm_msg)
    );
    let text = offset_of!(ODBALMMSG, alm_msg);
    for (i, r) in recs.iter().take(n).enumerate() {
        let at = unsafe { out.add(i * (text + N)) };
        unsafe {
            put_member!(at, ODBALMMSG, alm_no, r.alm_no);
            put_member!(at, ODBALMMSG, r#type, low16(r.kind));
            put_member!(at, ODBALMMSG, axis, low16(r.axis));
            put_member!(at, ODBALMMSG, dummy, 0);
            put_member!(at, ODBALMMSG, msg_len, low16(r.msg_len));
            std::ptr::copy_nonoverlapping(r.msg.as_ptr(), at.add(text), N);
        }
    }
    unsafe { put(num, n as c_short) };
    Ok(())
}

/// Reads up to `*num` active alarms of `type` (−1: all) with 32-character
/// messages; `*num` becomes the number read. `*num` ≤ 0: EW_LENGTH without
/// traffic; at most 29 (cnc_rdalmmsg2: 17) are asked for, what fits in one
/// answer; a CNC answering EW_LENGTH gives `*num` 0 and EW_OK (as FANUC's
/// library).
///
/// # Safety
/// `num` must point to a readable and writable short; `almmsg` must have
/// `*num` writable ODBALMMSG.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmmsg(
    FlibHndl: c_ushort,
    r#type: c_short,
    num: *mut c_short,
    almmsg: *mut ODBALMMSG,
) -> c_short {
    ffi_read!("cnc_rdalmmsg", {
        unsafe { read_almmsg::<32>(FlibHndl, r#type, num, almmsg.cast()) }
    })
}

/// As cnc_rdalmmsg with 64-character messages.
///
/// # Safety
/// `num` must point to a readable and writable short; `almmsg` must have
/// `*num` writable ODBALMMSG2.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmmsg2(
    FlibHndl: c_ushort,
    r#type: c_short,
    num: *mut c_short,
    almmsg: *mut ODBALMMSG2,
) -> c_short {
    ffi_read!("cnc_rdalmmsg2", {
        unsafe { read_almmsg::<64>(FlibHndl, r#type, num, almmsg.cast()) }
    })
}

/// Reads active alarms of `alm_type` (−1 all): `type` 0 axis and number
/// (ALMINFO alm1, 8-byte records), 1 with messages (alm2, 40-byte records);
/// after the last record −1 is written into the next record's place (the
/// `data_end` slot when there are 5). `length` is the caller's buffer size:
/// at most 5 records and never more than `length` bytes are written (FANUC's
/// library writes every record the CNC sends). A `length` without room for
/// one record: EW_LENGTH without traffic. At most 29 records are asked for
/// (what fits in one answer). A CNC answering EW_LENGTH: −1 at the first
/// slot and EW_LENGTH, as FANUC's library.
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
    ffi_read!("cnc_rdalminfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(almmsg)?.cast::<u8>();
        // The records, then the end mark (a LONG -1) right after the last.
        let end = size_of::<LONG>();
        if i32::from(length) <= end as i32 {
            return Err(Error::local(EW_LENGTH, "length must be more than 4"));
        }
        // The records of type 0 have no text: the first members alike.
        const _: () = assert!(
            offset_of!(ALMINFO_alm1_rec, axis) == offset_of!(ALMINFO_alm2_rec, axis)
                && offset_of!(ALMINFO_alm1_rec, alm_no) == offset_of!(ALMINFO_alm2_rec, alm_no)
        );
        let rec = if r#type == 0 {
            size_of::<ALMINFO_alm1_rec>()
        } else {
            size_of::<ALMINFO_alm2_rec>()
        };
        let fit = (length as usize - end) / rec;
        if fit == 0 {
            return Err(Error::local(EW_LENGTH, "length holds no record"));
        }
        let recs = match h.call(&pa::rdalminfo(r#type, alm_type, fit as i32)) {
            Ok(r) => r.0,
            Err(e) => {
                // The CNC's EW_LENGTH: the end mark is written at the first
                // slot and the error returned (FANUC's library).
                if matches!(
                    e,
                    Error::Cnc {
                        code: EW_LENGTH,
                        ..
                    }
                ) {
                    unsafe { put(out.cast::<i32>(), -1) };
                }
                return Err(e);
            }
        };
        let n = recs.len().min(fit).min(5);
        for (i, r) in recs.iter().take(n).enumerate() {
            let at = unsafe { out.add(i * rec) };
            unsafe {
                put_member!(at, ALMINFO_alm2_rec, axis, i32::from(low16(r.axis)));
                put_member!(at, ALMINFO_alm2_rec, alm_no, low16(r.alm_no));
                if r#type != 0 {
                    put_member!(at, ALMINFO_alm2_rec, msg_len, low16(r.msg_len));
                    put_member!(at, ALMINFO_alm2_rec, alm_msg, r.msg.map(|b| b as c_char));
                }
            }
        }
        unsafe { put(out.add(n * rec).cast::<i32>(), -1) };
        Ok(())
    })
}

/// Reads the operator message of `type` 0 into OPMSG: number, type,
/// character count as the CNC sent them, then the text as sent (at most 256
/// bytes), zero-filled: always the 262 bytes of OPMSG, as FANUC's library.
/// Before any traffic: another `type`: EW_ATTRIB (4); `length` (unsigned)
/// below 262: EW_LENGTH (2). On a Series 15 an answer with less than 256
/// text bytes writes nothing, a whole one 136 bytes (FANUC's library). A
/// short answer reads as zeros.
///
/// # Safety
/// `opmsg` must have 262 writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdopmsg(
    FlibHndl: c_ushort,
    r#type: c_short,
    length: c_short,
    opmsg: *mut OPMSG,
) -> c_short {
    ffi_read!("cnc_rdopmsg", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(opmsg)?.cast::<u8>();
        if r#type != 0 {
            return Err(Error::local(EW_ATTRIB, "operator message type must be 0"));
        }
        const SIZE: usize = std::mem::size_of::<OPMSG>();
        if usize::from(length as u16) < SIZE {
            return Err(Error::local(EW_LENGTH, "length must be at least 262"));
        }
        let m = h.call(&pa::rdopmsg(r#type))?;
        // A Series 15 (FANUC's library: its 136-byte OPMSG, 130 text
        // bytes): only a whole answer (256 text bytes) is written.
        let written = if h.ctx().class == (CncClass::Series16 { kind: 2 }) {
            if m.text.len() < SIZE - 6 {
                return Ok(());
            }
            S15_OPMSG
        } else {
            SIZE
        };
        let mut b = [0u8; SIZE];
        b[0..2].copy_from_slice(&low16(m.datano).to_ne_bytes());
        b[2..4].copy_from_slice(&low16(m.kind).to_ne_bytes());
        b[4..6].copy_from_slice(&low16(m.char_num).to_ne_bytes());
        let n = m.text.len().min(SIZE - 6);
        b[6..6 + n].copy_from_slice(&m.text[..n]);
        unsafe { std::ptr::copy_nonoverlapping(b.as_ptr(), out, written) };
        Ok(())
    })
}

/// The bytes FANUC's library writes of a Series 15's operator message:
/// number, type, count and 130 text bytes (its OPMSG of 129 characters).
const S15_OPMSG: usize = 136;

/// Reads the operator messages of `type` (-1: all) on display into
/// `*num` OPMSG3 records; `*num` = the messages written. The 30i class is
/// asked five messages an exchange until `*num` are asked for (an error
/// after some were read ends the read), the 16i class once. More messages
/// in the first answer than `*num`: EW_LENGTH, nothing written.
///
/// # Safety
/// `num` must point to a writable short, `opmsg` to `*num` OPMSG3.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdopmsg3(
    FlibHndl: c_ushort,
    r#type: c_short,
    num: *mut c_short,
    opmsg: *mut OPMSG3,
) -> c_short {
    ffi_boundary!("cnc_rdopmsg3", {
        let h = handles::get(FlibHndl)?;
        let num = nonnull(num)?;
        let out = nonnull(opmsg)?.cast::<u8>();
        let want = i32::from(unsafe { num.read_unaligned() });
        if want <= 0 {
            return Err(Error::local(EW_LENGTH, "num must be at least 1"));
        }
        const SIZE: usize = std::mem::size_of::<OPMSG3>();
        let class30 = !h.ctx().class.is_16i();
        let (mut left, mut start, mut total, mut seen) = (want, 0i32, 0i16, 0i32);
        let mut at = 0usize;
        loop {
            let n = if class30 {
                left.min(pa::OPMSG3_CHUNK)
            } else {
                0
            };
            let recs = match h.call(&pa::rdopmsg3(class30, start, r#type, n)) {
                Ok(r) => r,
                Err(Error::Cnc { .. }) if class30 && total > 0 => break,
                Err(e) => return Err(e),
            };
            // FANUC's library counts the messages of each answer less the
            // start index asked for, and refuses more than `*num`.
            seen += recs.len() as i32 - start;
            if seen > want {
                return Err(Error::length());
            }
            total = total.wrapping_add(recs.len() as i16);
            for r in &recs {
                let mut b = [0u8; SIZE];
                for k in 0..3 {
                    let v = i16::from_be_bytes([r[4 * k + 2], r[4 * k + 3]]);
                    b[2 * k..2 * k + 2].copy_from_slice(&v.to_ne_bytes());
                }
                b[6..].copy_from_slice(&r[12..12 + 256]);
                unsafe { std::ptr::copy_nonoverlapping(b.as_ptr(), out.add(at), SIZE) };
                at += SIZE;
            }
            if !class30 {
                break;
            }
            left -= n;
            start += n;
            if left <= 0 {
                break;
            }
        }
        unsafe { put(num, total) };
        Ok(())
    })
}

// --- alarm history ---

/// The number of checked history entries, when all of them fit in `length`
/// (header `hdr` bytes, `rec` bytes per record); else EW_LENGTH, nothing
/// written (FANUC's library checks this after the exchange).
fn his_fit(length: c_ushort, hdr: usize, rec: usize, have: usize) -> Result<usize> {
    if usize::from(length) < hdr + rec * have {
        return Err(Error::length());
    }
    Ok(have)
}

fn his_call(h: &Handle, s_number: c_ushort, e_number: c_ushort) -> Result<Vec<AlmHisRecord>> {
    if s_number > e_number {
        return Err(Error::local(EW_NUMBER, "start number after end number"));
    }
    Ok(h.call(&rdalmhistry(s_number, e_number))?.valid())
}

/// Reads the alarm history entries `s_number..=e_number` (1 = newest) into
/// ODBAHIS: year as year mod 100, the other time fields as bytes, as
/// FANUC's library writes them. `e_no` = `s_no` + entries written - 1.
/// Entries with an impossible time stamp are skipped; an entry whose message
/// length runs past its text ends the list. At most 23 entries are asked
/// for (one answer); when they do not all fit in `length`: EW_LENGTH,
/// nothing written. Not on a Series 15 (EW_FUNC without traffic).
///
/// # Safety
/// `alm_hst` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmhistry(
    FlibHndl: c_ushort,
    s_number: c_ushort,
    e_number: c_ushort,
    length: c_ushort,
    alm_hst: *mut ODBAHIS,
) -> c_short {
    ffi_boundary!("cnc_rdalmhistry", {
        let h = handles::get(FlibHndl)?;
        if h.ctx().class == (CncClass::Series16 { kind: 2 }) {
            // FANUC's library: EW_FUNC without traffic on a Series 15.
            return Err(Error::local(EW_FUNC, "not available on a Series 15"));
        }
        let out = nonnull(alm_hst)?.cast::<u8>();
        let recs = his_call(&h, s_number, e_number)?;
        let n = his_fit(
            length,
            offset_of!(ODBAHIS, alm_his),
            size_of::<ODBAHIS_ALM>(),
            recs.len(),
        )?;
        unsafe {
            put_member!(out, ODBAHIS, s_no, s_number);
            put_member!(
                out,
                ODBAHIS,
                e_no,
                s_number.wrapping_add(n as u16).wrapping_sub(1)
            );
            for (i, r) in recs[..n].iter().enumerate() {
                let o = element!(out, ODBAHIS, alm_his[i]);
                put_member!(o, ODBAHIS_ALM, alm_grp, r.alm_grp);
                put_member!(o, ODBAHIS_ALM, alm_no, r.alm_no as i16);
                put_member!(o, ODBAHIS_ALM, axis_no, r.axis as c_char);
                put_member!(o, ODBAHIS_ALM, year, r.year_his() as c_char);
                put_member!(o, ODBAHIS_ALM, month, r.month as c_char);
                put_member!(o, ODBAHIS_ALM, day, r.day as c_char);
                put_member!(o, ODBAHIS_ALM, hour, r.hour as c_char);
                put_member!(o, ODBAHIS_ALM, minute, r.minute as c_char);
                put_member!(o, ODBAHIS_ALM, second, r.second as c_char);
                put_member!(o, ODBAHIS_ALM, len_msg, r.msg_len as i16);
                put_member!(o, ODBAHIS_ALM, alm_msg, r.msg.map(|b| b as c_char));
            }
        }
        Ok(())
    })
}

/// Reads the alarm history into ODBAHIS2 (all fields shorts). The year is
/// FANUC's: the low byte of the year, sign-extended (2024 → -24). Entry
/// checks and `length` as cnc_rdalmhistry (checked with the 52-byte
/// ODBAHIS2 record). Not on a 16i (EW_FUNC without traffic); a Series 15
/// answers.
///
/// # Safety
/// `alm_hst` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmhistry2(
    FlibHndl: c_ushort,
    s_number: c_ushort,
    e_number: c_ushort,
    length: c_ushort,
    alm_hst: *mut ODBAHIS2,
) -> c_short {
    ffi_boundary!("cnc_rdalmhistry2", {
        let h = handles::get(FlibHndl)?;
        if matches!(h.ctx().class, CncClass::Series16 { kind } if kind != 2) {
            // FANUC's library: EW_FUNC without traffic for any arguments on
            // a 16i (a Series 15 answers).
            return Err(Error::local(EW_FUNC, "not available on a 16i"));
        }
        let out = nonnull(alm_hst)?.cast::<u8>();
        let recs = his_call(&h, s_number, e_number)?;
        let n = his_fit(
            length,
            offset_of!(ODBAHIS2, alm_his),
            size_of::<ODBAHIS2_ALM>(),
            recs.len(),
        )?;
        unsafe {
            put_member!(out, ODBAHIS2, s_no, s_number);
            put_member!(
                out,
                ODBAHIS2,
                e_no,
                s_number.wrapping_add(n as u16).wrapping_sub(1)
            );
            for (i, r) in recs[..n].iter().enumerate() {
                let o = element!(out, ODBAHIS2, alm_his[i]);
                put_member!(o, ODBAHIS2_ALM, alm_grp, r.alm_grp);
                put_member!(o, ODBAHIS2_ALM, alm_no, r.alm_no as i16);
                put_member!(o, ODBAHIS2_ALM, axis_no, r.axis as i16);
                put_member!(o, ODBAHIS2_ALM, year, r.year_his2());
                put_member!(o, ODBAHIS2_ALM, month, r.month as i16);
                put_member!(o, ODBAHIS2_ALM, day, r.day as i16);
                put_member!(o, ODBAHIS2_ALM, hour, r.hour as i16);
                put_member!(o, ODBAHIS2_ALM, minute, r.minute as i16);
                put_member!(o, ODBAHIS2_ALM, second, r.second as i16);
                put_member!(o, ODBAHIS2_ALM, len_msg, r.msg_len as i16);
                put_member!(o, ODBAHIS2_ALM, alm_msg, r.msg.map(|b| b as c_char));
            }
        }
        Ok(())
    })
}
