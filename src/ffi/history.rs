//! Records read by number range (src/proto/history.rs): the operation
//! history, the operator message histories, alarm history 5 and the pitch
//! error table.

use super::{ffi_boundary, nonnull, put, put_at};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::{EW_LENGTH, EW_NUMBER, EW_VERSION};
use crate::proto::history::{self as ph, OpKind, be16, be32};
use crate::types::{IODBPI, IODBSIG3, ODBAHIS5, ODBHIS, ODBOMHIS, ODBOMHIS2};
use std::os::raw::{c_short, c_ushort, c_void};

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

/// Writes s_no and e_no (s_no + n - 1) at `at_e`.
unsafe fn numbers(out: *mut u8, at_e: usize, s: c_ushort, n: usize) {
    unsafe {
        put_at(out, 0, s);
        put_at(out, at_e, s.wrapping_add(n as u16).wrapping_sub(1));
    }
}

/// Copies the `n` big-endian i16 at `from` of record `r` to `to` on, as
/// native shorts.
unsafe fn shorts(out: *mut u8, to: usize, r: &[u8], from: usize, n: usize) {
    for k in 0..n {
        unsafe { put_at(out, to + 2 * k, be16(r, from + 2 * k)) };
    }
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
        fit(length, 6, 8, recs.len())?;
        unsafe {
            numbers(out, 4, s_number, recs.len());
            for (i, r) in recs.iter().enumerate() {
                let o = 6 + 8 * i;
                let t = be16(r, 2);
                put_at(out, o, t);
                let lo = |at: usize| r[at + 1];
                match OpKind::of(t) {
                    OpKind::Mdi => {
                        put_at(out, o + 2, lo(4));
                        put_at(out, o + 3, lo(6));
                    }
                    OpKind::Signal => {
                        put_at(out, o + 2, lo(8));
                        put_at(out, o + 3, r[10]);
                        put_at(out, o + 4, r[11]);
                        put_at(out, o + 6, be16(r, 6));
                    }
                    OpKind::Alarm => {
                        put_at(out, o + 2, be16(r, 10));
                        put_at(out, o + 4, be16(r, 6));
                        put_at(out, o + 6, lo(14));
                    }
                    OpKind::Date => {
                        put_at(out, o + 2, (be16(r, 4) as u16 % 100) as u8);
                        for k in 1..4 {
                            put_at(out, o + 2 + k, lo(4 + 2 * k));
                        }
                    }
                    OpKind::Time => {
                        for k in 0..4 {
                            put_at(out, o + 2 + k, lo(4 + 2 * k));
                        }
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
        let size = std::mem::size_of::<ODBOMHIS>();
        unsafe {
            for (i, r) in recs[..n].iter().enumerate() {
                let o = size * i;
                put_at(out, o, be16(r, 2));
                put_at(out, o + 2, (be16(r, 4) as u16 % 100) as i16);
                shorts(out, o + 4, r, 6, 5);
                put_at(
                    out,
                    o + 14,
                    <[u8; ph::OM_TEXT]>::try_from(&r[20..]).unwrap_or([0; ph::OM_TEXT]),
                );
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
        fit(length, 4, ph::OM2_REC, recs.len())?;
        unsafe {
            numbers(out, 2, s_number, recs.len());
            for (i, r) in recs.iter().enumerate() {
                shorts(out, 4 + ph::OM2_REC * i, r, 0, 8);
                let t = <[u8; ph::OM_TEXT]>::try_from(&r[16..]).unwrap_or([0; ph::OM_TEXT]);
                put_at(out, 4 + ph::OM2_REC * i + 16, t);
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
        const SIZE: usize = std::mem::size_of::<crate::types::ODBAHIS5_ALM>();
        let (mut at, mut n) = (s_number, 0);
        loop {
            let asked = if at < e_number { 2 } else { 1 };
            let recs = h.call(&ph::rdalmhistry5(at, e_number))?;
            fit(length, 4, SIZE, n + recs.len())?;
            for r in &recs {
                unsafe { put_alm5(out.add(4 + SIZE * n), r) };
                n += 1;
            }
            if recs.len() < asked || usize::from(e_number - at) < asked {
                break;
            }
            at += asked as u16;
        }
        unsafe { numbers(out, 2, s_number, n) };
        Ok(())
    })
}

/// One ODBAHIS5 entry from its 524-byte wire record.
unsafe fn put_alm5(o: *mut u8, r: &[u8]) {
    unsafe {
        put_at(o, 0, be16(r, 6));
        put_at(o, 2, be16(r, 2));
        put_at(o, 4, be16(r, 10));
        shorts(o, 6, r, 12, 6);
        put_at(o, 18, be16(r, 26));
        shorts(o, 20, r, 28, 4);
        std::ptr::copy_nonoverlapping(r.as_ptr().add(36), o.add(28), ph::ALM5_TEXT);
        // Modal blocks: 10 i32 and 10 flag bytes each, 2 bytes apart.
        for (wire, at) in [(100, 92), (152, 144)] {
            for k in 0..10 {
                put_at(o, at + 4 * k, be32(r, wire + 4 * k));
            }
            std::ptr::copy_nonoverlapping(r.as_ptr().add(wire + 40), o.add(at + 40), 10);
        }
        // Positions: 32 i32 and 32 digit bytes each.
        for (wire, at) in [(204, 196), (364, 356)] {
            for k in 0..32 {
                put_at(o, at + 4 * k, be32(r, wire + 4 * k));
            }
            std::ptr::copy_nonoverlapping(r.as_ptr().add(wire + 128), o.add(at + 128), 32);
        }
    }
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
            fit(length as c_ushort, 6, 1, n + recs.len())?;
            for r in &recs {
                unsafe { put_at(out, 6 + n, r[1]) };
                n += 1;
            }
            if (recs.len() as i32) < (e - at + 1).min(ph::PITCH_CHUNK) {
                break;
            }
            at += ph::PITCH_CHUNK;
        }
        unsafe {
            put_at(out, 0, datano_s);
            put_at(out, 4, datano_s.wrapping_add(n as i16).wrapping_sub(1));
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
