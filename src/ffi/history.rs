//! Records read by number range (src/proto/history/): the operation
//! history, the operator message histories, alarm history 5 and the pitch
//! error table.

use super::{element, ffi_boundary, nonnull, put, put_member};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::{EW_LENGTH, EW_NUMBER, EW_VERSION};
use crate::proto::history::{self as ph, OpKind, be16, be32};
use crate::types::{
    IODBPI, IODBSIG3, ODBAHIS5, ODBAHIS5_ALM, ODBHIS, ODBHIS_ALM, ODBHIS_DATA, ODBHIS_DATE,
    ODBHIS_MDI, ODBHIS_SGN, ODBHIS_TIME, ODBOMHIS, ODBOMHIS2, ODBOMHIS2_OPM,
};
use std::mem::offset_of;
use std::os::raw::{c_char, c_short, c_ushort, c_void};

/// `s_number..=e_number` must be a range (FANUC's library: EW_NUMBER
/// before any traffic).
fn range(s: c_ushort, e: c_ushort) -> Result<()> {
    if s > e {
        return Err(Error::local(EW_NUMBER, "start number after end number"));
    }
    Ok(())
}

/// All `n` records must fit in `length` after a `hdr`-byte header (FANUC's
/// library checks after the exchange: EW_LENGTH, nothing written).
fn fit(length: c_ushort, hdr: usize, rec: usize, n: usize) -> Result<()> {
    if usize::from(length) < hdr + rec * n {
        return Err(Error::length());
    }
    Ok(())
}

/// e_no of `n` entries from `s`: s + n - 1 (wrapping, as FANUC's library).
fn last(s: c_ushort, n: usize) -> c_ushort {
    s.wrapping_add(n as u16).wrapping_sub(1)
}

/// Reads the operation history entries `s_number..=e_number` into ODBHIS,
/// each 8-byte record decoded by its type (MDI key, signal, alarm, date,
/// time; other types: the type alone). At most 89 entries are asked for;
/// when they do not all fit in `length`: EW_LENGTH, nothing written.
///
/// # Safety
/// `ophis` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdophistry(
    FlibHndl: c_ushort,
    s_number: c_ushort,
    e_number: c_ushort,
    length: c_ushort,
    ophis: *mut ODBHIS,
) -> c_short {
    ffi_boundary!("cnc_rdophistry", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(ophis)?.cast::<u8>();
        range(s_number, e_number)?;
        let recs = h.call(&ph::rdophistry(s_number, e_number))?;
        fit(
            length,
            offset_of!(ODBHIS, data),
            size_of::<ODBHIS_DATA>(),
            recs.len(),
        )?;
        unsafe {
            put_member!(out, ODBHIS, s_no, s_number);
            put_member!(out, ODBHIS, e_no, last(s_number, recs.len()));
            for (i, r) in recs.iter().enumerate() {
                // One member of the union ODBHIS_DATA, by the record's type.
                let o = element!(out, ODBHIS, data[i]);
                let t = be16(r, 2);
                put_member!(o, ODBHIS_ALM, rec_type, t);
                let lo = |at: usize| r[at + 1] as c_char;
                match OpKind::of(t) {
                    OpKind::Mdi => {
                        put_member!(o, ODBHIS_MDI, key_code, lo(4));
                        put_member!(o, ODBHIS_MDI, pw_flag, lo(6));
                    }
                    OpKind::Signal => {
                        put_member!(o, ODBHIS_SGN, sig_name, lo(8));
                        put_member!(o, ODBHIS_SGN, sig_old, r[10] as c_char);
                        put_member!(o, ODBHIS_SGN, sig_new, r[11] as c_char);
                        put_member!(o, ODBHIS_SGN, sig_no, be16(r, 6));
                    }
                    OpKind::Alarm => {
                        put_member!(o, ODBHIS_ALM, alm_grp, be16(r, 10));
                        put_member!(o, ODBHIS_ALM, alm_no, be16(r, 6));
                        put_member!(o, ODBHIS_ALM, axis_no, lo(14));
                    }
                    OpKind::Date => {
                        let year = (be16(r, 4) as u16 % 100) as u8;
                        put_member!(o, ODBHIS_DATE, year, year as c_char);
                        put_member!(o, ODBHIS_DATE, month, lo(6));
                        put_member!(o, ODBHIS_DATE, day, lo(8));
                        put_member!(o, ODBHIS_DATE, pw_flag, lo(10));
                    }
                    OpKind::Time => {
                        put_member!(o, ODBHIS_TIME, hour, lo(4));
                        put_member!(o, ODBHIS_TIME, minute, lo(6));
                        put_member!(o, ODBHIS_TIME, second, lo(8));
                        put_member!(o, ODBHIS_TIME, pw_flag, lo(10));
                    }
                    OpKind::Other => {}
                }
            }
        }
        Ok(())
    })
}

/// Reads the operation history records `s_number..=*e_number` (1 = the
/// oldest kept) into the caller's buffer as ODBOPHIS4 records packed one
/// after the other, each `rec_len` bytes long; `*length` (in: the buffer's
/// size) = the bytes written, `*e_number` = the last record written. The
/// CNC may answer a range in several exchanges; records that do not fit
/// end the exchange (the next one starts after the records the CNC sent),
/// the first not fitting is EW_LENGTH. An unknown record type is
/// EW_VERSION, the records before it written, as FANUC's library does.
///
/// # Safety
/// `e_number` and `length` must point to writable unsigned shorts, `ophis`
/// to `*length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdophistry4(
    FlibHndl: c_ushort,
    s_number: c_ushort,
    e_number: *mut c_ushort,
    length: *mut c_ushort,
    ophis: *mut c_void,
) -> c_short {
    ffi_boundary!("cnc_rdophistry4", {
        let h = handles::get(FlibHndl)?;
        let e_ptr = nonnull(e_number)?;
        let len_ptr = nonnull(length)?;
        let out = nonnull(ophis)?.cast::<u8>();
        let e = unsafe { e_ptr.read_unaligned() };
        if s_number == 0 {
            return Err(Error::local(EW_NUMBER, "history numbers start at 1"));
        }
        range(s_number, e)?;
        // FANUC's library: `*length` is 0 from here on, whatever follows.
        let mut room = i32::from(unsafe { len_ptr.read_unaligned() });
        unsafe { put(len_ptr, 0) };
        let (mut cur, mut written, mut last) = (i32::from(s_number), 0u16, e);
        loop {
            let ans = match h.call(&ph::OpHis4 {
                s: cur,
                e: i32::from(e),
            }) {
                Ok(a) => a,
                // The CNC's EW_NUMBER after some records: the range is done.
                Err(Error::Cnc {
                    code: EW_NUMBER, ..
                }) if written != 0 => return Ok(()),
                Err(err) => return Err(err),
            };
            let (recs, stop) = ph::op4_walk(&ans, room);
            for (kind, t, r) in &recs {
                let rec = unsafe {
                    std::slice::from_raw_parts_mut(out.add(usize::from(written)), kind.size)
                };
                ph::op4_put(kind, *t, r, rec);
                last = if written == 0 {
                    s_number
                } else {
                    last.wrapping_add(1)
                };
                written = written.wrapping_add(kind.size as u16);
                room -= kind.size as i32;
                unsafe {
                    put(e_ptr, last);
                    put(len_ptr, written);
                }
            }
            match stop {
                Some(ph::Op4Stop::Unknown) => {
                    return Err(Error::local(EW_VERSION, "unknown operation history record"));
                }
                Some(ph::Op4Stop::Full) if written == 0 => return Err(Error::length()),
                _ => {}
            }
            // More to read: from after the records the CNC sent. A "more"
            // answer without records would ask for the same for ever
            // (FANUC's library does): ours ends there.
            if ans.more == 0 || ans.count <= 0 {
                return Ok(());
            }
            cur += ans.count;
            if cur > i32::from(e) {
                return Ok(());
            }
        }
    })
}

/// Reads `*num` operator message history entries (at most five) from
/// `s_number` (0 = newest) into ODBOMHIS records; `*num` = the entries
/// written.
///
/// # Safety
/// `num` must point to a writable unsigned short, `omhis` to `*num` ODBOMHIS.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdomhistry(
    FlibHndl: c_ushort,
    s_number: c_ushort,
    num: *mut c_ushort,
    omhis: *mut ODBOMHIS,
) -> c_short {
    ffi_boundary!("cnc_rdomhistry", {
        let h = handles::get(FlibHndl)?;
        let num = nonnull(num)?;
        let out = nonnull(omhis)?.cast::<u8>();
        let want = usize::from(unsafe { num.read_unaligned() });
        if want == 0 {
            return Err(Error::local(EW_LENGTH, "num must be at least 1"));
        }
        let recs = h.call(&ph::rdomhistry(s_number, want as u16))?;
        let n = recs.len().min(want);
        unsafe {
            for (i, r) in recs[..n].iter().enumerate() {
                let o = out.add(size_of::<ODBOMHIS>() * i);
                put_member!(o, ODBOMHIS, om_no, be16(r, 2));
                put_member!(o, ODBOMHIS, year, (be16(r, 4) as u16 % 100) as i16);
                put_member!(o, ODBOMHIS, month, be16(r, 6));
                put_member!(o, ODBOMHIS, day, be16(r, 8));
                put_member!(o, ODBOMHIS, hour, be16(r, 10));
                put_member!(o, ODBOMHIS, minute, be16(r, 12));
                put_member!(o, ODBOMHIS, second, be16(r, 14));
                put_member!(o, ODBOMHIS, om_msg, text(&r[20..]));
            }
            put(num, n as u16);
        }
        Ok(())
    })
}

/// Reads the operator message history entries `s_number..=e_number` (at
/// most five) into ODBOMHIS2; when they do not all fit in `length`:
/// EW_LENGTH, nothing written.
///
/// # Safety
/// `omhis` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdomhistry2(
    FlibHndl: c_ushort,
    s_number: c_ushort,
    e_number: c_ushort,
    length: c_ushort,
    omhis: *mut ODBOMHIS2,
) -> c_short {
    ffi_boundary!("cnc_rdomhistry2", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(omhis)?.cast::<u8>();
        range(s_number, e_number)?;
        let recs = h.call(&ph::rdomhistry2(s_number, e_number))?;
        fit(
            length,
            offset_of!(ODBOMHIS2, opm_his),
            size_of::<ODBOMHIS2_OPM>(),
            recs.len(),
        )?;
        unsafe {
            put_member!(out, ODBOMHIS2, s_no, s_number);
            put_member!(out, ODBOMHIS2, e_no, last(s_number, recs.len()));
            for (i, r) in recs.iter().enumerate() {
                let o = element!(out, ODBOMHIS2, opm_his[i]);
                put_member!(o, ODBOMHIS2_OPM, dsp_flg, be16(r, 0));
                put_member!(o, ODBOMHIS2_OPM, om_no, be16(r, 2));
                put_member!(o, ODBOMHIS2_OPM, year, be16(r, 4));
                put_member!(o, ODBOMHIS2_OPM, month, be16(r, 6));
                put_member!(o, ODBOMHIS2_OPM, day, be16(r, 8));
                put_member!(o, ODBOMHIS2_OPM, hour, be16(r, 10));
                put_member!(o, ODBOMHIS2_OPM, minute, be16(r, 12));
                put_member!(o, ODBOMHIS2_OPM, second, be16(r, 14));
                put_member!(o, ODBOMHIS2_OPM, ope_msg, text(&r[16..]));
            }
        }
        Ok(())
    })
}

/// Reads alarm history entries `s_number..=e_number` (1 = newest) with their
/// modal and position snapshot into ODBAHIS5, two entries an exchange until
/// the range is read or the CNC has no more; when an exchange's entries do
/// not fit in `length`: EW_LENGTH, the entries before them written.
///
/// # Safety
/// `almhis` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmhistry5(
    FlibHndl: c_ushort,
    s_number: c_ushort,
    e_number: c_ushort,
    length: c_ushort,
    almhis: *mut ODBAHIS5,
) -> c_short {
    ffi_boundary!("cnc_rdalmhistry5", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(almhis)?.cast::<u8>();
        if s_number == 0 {
            return Err(Error::local(EW_NUMBER, "history numbers start at 1"));
        }
        range(s_number, e_number)?;
        // Two entries an exchange until the range is read or the CNC has
        // no more; each exchange's entries must fit in `length` (FANUC's
        // library: EW_LENGTH, the entries before them written).
        let (mut at, mut n) = (s_number, 0);
        loop {
            let asked = if at < e_number { 2 } else { 1 };
            let recs = h.call(&ph::rdalmhistry5(at, e_number))?;
            fit(
                length,
                offset_of!(ODBAHIS5, alm_his),
                size_of::<ODBAHIS5_ALM>(),
                n + recs.len(),
            )?;
            for r in &recs {
                unsafe { put_alm5(element!(out, ODBAHIS5, alm_his[n]), r) };
                n += 1;
            }
            if recs.len() < asked || usize::from(e_number - at) < asked {
                break;
            }
            at += asked as u16;
        }
        unsafe {
            put_member!(out, ODBAHIS5, s_no, s_number);
            put_member!(out, ODBAHIS5, e_no, last(s_number, n));
        }
        Ok(())
    })
}

/// One ODBAHIS5 entry from its 524-byte wire record.
unsafe fn put_alm5(o: *mut u8, r: &[u8]) {
    type A = ODBAHIS5_ALM;
    unsafe {
        put_member!(o, A, alm_grp, be16(r, 6));
        put_member!(o, A, alm_no, be16(r, 2));
        put_member!(o, A, axis_no, be16(r, 10));
        put_member!(o, A, year, be16(r, 12));
        put_member!(o, A, month, be16(r, 14));
        put_member!(o, A, day, be16(r, 16));
        put_member!(o, A, hour, be16(r, 18));
        put_member!(o, A, minute, be16(r, 20));
        put_member!(o, A, second, be16(r, 22));
        put_member!(o, A, len_msg, be16(r, 26));
        put_member!(o, A, pth_no, be16(r, 28));
        put_member!(o, A, sys_alm, be16(r, 30));
        put_member!(o, A, dsp_flg, be16(r, 32));
        put_member!(o, A, axis_num, be16(r, 34));
        put_member!(o, A, alm_msg, text(&r[36..]));
        // Modal blocks: 10 i32, then 10 flag bytes.
        for k in 0..10 {
            put_member!(o, A, g_modal[k], be32(r, 100 + 4 * k));
            put_member!(o, A, a_modal[k], be32(r, 152 + 4 * k));
        }
        put_member!(o, A, g_dp, text(&r[140..]));
        put_member!(o, A, a_dp, text(&r[192..]));
        // Positions: 32 i32, then 32 digit bytes.
        for k in 0..32 {
            put_member!(o, A, abs_pos[k], be32(r, 204 + 4 * k));
            put_member!(o, A, mcn_pos[k], be32(r, 364 + 4 * k));
        }
        put_member!(o, A, abs_dp, text(&r[332..]));
        put_member!(o, A, mcn_dp, text(&r[492..]));
    }
}

/// The first `N` bytes of `r` as C chars (zeros where `r` is shorter).
fn text<const N: usize>(r: &[u8]) -> [c_char; N] {
    let mut t = [0; N];
    for (d, s) in t.iter_mut().zip(r) {
        *d = *s as c_char;
    }
    t
}

/// Reads the pitch error compensation points `datano_s..=datano_e` into
/// IODBPI (one byte a point), 716 points an exchange; when an exchange's
/// points do not fit in `length`: EW_LENGTH, the points before them written.
///
/// # Safety
/// `pi` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdpitchr(
    FlibHndl: c_ushort,
    datano_s: c_short,
    datano_e: c_short,
    length: c_short,
    pi: *mut IODBPI,
) -> c_short {
    ffi_boundary!("cnc_rdpitchr", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(pi)?.cast::<u8>();
        if datano_s > datano_e {
            return Err(Error::local(EW_NUMBER, "start number after end number"));
        }
        // 716 points an exchange; a later exchange's error ends the read
        // with the points before it (FANUC's library).
        let (e, mut at, mut n) = (i32::from(datano_e), i32::from(datano_s), 0usize);
        while at <= e {
            let recs = match h.call(&ph::rdpitchr(at, e)) {
                Ok(r) => r,
                Err(err) if n == 0 => return Err(err),
                Err(_) => break,
            };
            fit(
                length as c_ushort,
                offset_of!(IODBPI, data),
                size_of::<c_char>(),
                n + recs.len(),
            )?;
            for r in &recs {
                unsafe { put_member!(out, IODBPI, data[n], r[1] as c_char) };
                n += 1;
            }
            if (recs.len() as i32) < (e - at + 1).min(ph::PITCH_CHUNK) {
                break;
            }
            at += ph::PITCH_CHUNK;
        }
        unsafe {
            put_member!(out, IODBPI, datano_s, datano_s);
            put_member!(
                out,
                IODBPI,
                datano_e,
                datano_s.wrapping_add(n as i16).wrapping_sub(1)
            );
        }
        Ok(())
    })
}

/// Writes the signals the operation history records: `type` entries of
/// IODBSIG3 (`datano` unused), their 16-byte wire form as cnc_rdhissgnl3
/// reads them. `type` outside 0..=60: EW_LENGTH before any traffic
/// (FANUC's library sends a broken frame for a negative one and reads past
/// the struct for more than 60).
///
/// # Safety
/// `sig` must point to a readable IODBSIG3.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrhissgnl3(FlibHndl: c_ushort, sig: *mut IODBSIG3) -> c_short {
    ffi_boundary!("cnc_wrhissgnl3", {
        let h = handles::get(FlibHndl)?;
        // SAFETY: the caller's IODBSIG3, only read.
        let s = unsafe { &*nonnull(sig)? };
        let n = usize::try_from(s.r#type)
            .ok()
            .filter(|&n| n <= s.data.len())
            .ok_or_else(|| Error::local(EW_LENGTH, "type (the entries) outside 0..=60"))?;
        let entries = s.data[..n]
            .iter()
            .map(|d| ph::Sig3 {
                ent_no: d.ent_no,
                pmc_no: d.pmc_no,
                sig_no: d.sig_no,
                sig_name: d.sig_name as u8,
                mask_pat: d.mask_pat as u8,
            })
            .collect();
        h.call(&ph::WriteSig3 { entries })
    })
}
