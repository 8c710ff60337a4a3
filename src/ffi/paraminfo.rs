//! Parameter and diagnosis attributes: the info lists (cnc_rdparainfo,
//! cnc_rddiaginfo, cnc_rdparainfo3) and the IODBPRM records of
//! cnc_rdparam_ext / cnc_rddiag_ext (attributes with all-axes values).

use super::{ffi_boundary, ffi_read, nonnull, put, put_at};
use crate::client::handles::{self, Handle};
use crate::error::{Error, Result};
use crate::ew::EW_LENGTH;
use crate::proto::packet::MAX_ANSWER;
use crate::proto::param::{ExtRecord, InfoList, ReadExt, ReadInfo, Table, ext_per_frame};
use crate::types::{IODBPRM, IODBPRM_data, ODBDIAGIF, ODBPARAIF};
use std::os::raw::{c_long, c_short, c_ushort};

/// Writes an info list into an ODBPARAIF / ODBDIAGIF (same layout).
/// info_no is capped at `read_no`: FANUC's library takes every entry the
/// CNC sent and may overrun the caller's buffer; we never write more than
/// the caller asked for.
///
/// # Safety
/// `out` must point to 6 + 4 · read_no writable bytes.
unsafe fn put_info(l: &InfoList, read_no: c_ushort, out: *mut u8) {
    let n = l.entries.len().min(read_no as usize);
    let mut b = Vec::with_capacity(6 + 4 * n);
    b.extend_from_slice(&(n as u16).to_le_bytes());
    b.extend_from_slice(&(l.prev as i16).to_le_bytes());
    b.extend_from_slice(&(l.next as i16).to_le_bytes());
    for e in &l.entries[..n] {
        b.extend_from_slice(&(e.number as i16).to_le_bytes());
        b.extend_from_slice(&(e.ptype as i16).to_le_bytes());
    }
    unsafe { std::ptr::copy_nonoverlapping(b.as_ptr(), out, b.len()) };
}

/// Reads an info list into `out` (ODBPARAIF / ODBDIAGIF). `read_no` 0 is
/// EW_LENGTH without traffic; at most 178 entries are asked for. When the
/// CNC answers an error, `info_no` 0 and `prev_no` = `next_no` = `s_number`
/// are written before it is returned (as FANUC's library does). An answer
/// short of `prev` and `next` reads their missing bytes as zeros, and an
/// empty one gives `info_no` -1, both `EW_OK`, as from FANUC's library.
///
/// # Safety
/// `out` must point to 6 + 4 · read_no writable bytes.
unsafe fn read_info(
    h: &Handle,
    table: Table,
    s_number: c_short,
    read_no: c_ushort,
    out: *mut u8,
) -> Result<()> {
    if read_no == 0 {
        return Err(Error::local(EW_LENGTH, "read_no is 0"));
    }
    let (l, empty) = h
        .call(&ReadInfo {
            table,
            start: s_number as i32,
            count: read_no as i32,
        })
        .inspect_err(|e| {
            if matches!(e, Error::Cnc { .. }) {
                let s = s_number as i32;
                let empty = InfoList {
                    prev: s,
                    next: s,
                    entries: Vec::new(),
                };
                unsafe { put_info(&empty, read_no, out) };
            }
        })?;
    unsafe { put_info(&l, read_no, out) };
    if empty {
        // An empty answer: info_no -1 ((0 - 8) / 8 entries), as FANUC's.
        unsafe { put_at(out, 0, -1i16) };
    }
    Ok(())
}

/// Reads the numbers and attributes of up to `read_no` parameters from
/// `s_number` on, with the previous and next existing numbers. The
/// attribute word: bits 0-1 data type (bit, byte, word, 2-word), bit 8
/// axis parameter.
///
/// # Safety
/// `paraif` must point to a writable ODBPARAIF with room for `read_no`
/// entries (the declared 10, or a larger allocation).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdparainfo(
    FlibHndl: c_ushort,
    s_number: c_short,
    read_no: c_ushort,
    paraif: *mut ODBPARAIF,
) -> c_short {
    ffi_read!("cnc_rdparainfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(paraif)?;
        unsafe { read_info(&h, Table::Param, s_number, read_no, out.cast()) }
    })
}

/// Reads the numbers and attributes of up to `read_no` diagnosis data
/// items from `s_number` on, as cnc_rdparainfo.
///
/// # Safety
/// `diagif` must point to a writable ODBDIAGIF with room for `read_no` entries.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rddiaginfo(
    FlibHndl: c_ushort,
    s_number: c_short,
    read_no: c_ushort,
    diagif: *mut ODBDIAGIF,
) -> c_short {
    ffi_read!("cnc_rddiaginfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(diagif)?;
        unsafe { read_info(&h, Table::Diag, s_number, read_no, out.cast()) }
    })
}

/// Reads `num` parameters (`table` Param) or diagnosis items into IODBPRM
/// records: per number its attributes and all-axes values, as many numbers per
/// exchange as FANUC's library asks ([`ext_per_frame`]: 8 on a 30i with 32 axes).
///
/// # Safety
/// `nos` must point to `num` 4-byte numbers, `out` to `num` IODBPRM records.
unsafe fn read_ext(
    h: &Handle,
    table: Table,
    nos: *const i32,
    num: c_short,
    out: *mut IODBPRM,
) -> Result<()> {
    let num = num.max(0) as usize;
    let numbers: Vec<i32> = (0..num)
        .map(|i| unsafe { nos.add(i).read_unaligned() })
        .collect();
    let per = ext_per_frame(&h.ctx());
    for (c, chunk) in numbers.chunks(per).enumerate() {
        let (recs, err) = h.call(&ReadExt {
            table,
            numbers: chunk.to_vec(),
        })?;
        for (i, r) in recs.iter().enumerate() {
            let k = c * per + i;
            let rec = unsafe { out.add(k) };
            let datano = numbers[k];
            unsafe { std::ptr::addr_of_mut!((*rec).datano).write_unaligned(datano) };
            match r {
                ExtRecord::Missing => unsafe {
                    std::ptr::addr_of_mut!((*rec).r#type).write_unaligned(-1)
                },
                ExtRecord::Found {
                    ptype,
                    axis,
                    info,
                    unit,
                    data,
                } => {
                    let mut v = IODBPRM {
                        datano,
                        r#type: *ptype,
                        axis: *axis,
                        info: *info,
                        unit: *unit,
                        ..IODBPRM::default()
                    };
                    // Records beyond the CNC's axes keep the caller's bytes.
                    let keep = unsafe { rec.read_unaligned() };
                    v.data = keep.data;
                    for (d, (val, dec)) in v.data.iter_mut().zip(data) {
                        *d = IODBPRM_data {
                            prm_val: *val,
                            dec_val: *dec,
                        };
                    }
                    unsafe { put(rec, v) };
                }
            }
        }
        if let Some(e) = err {
            h.note(&e);
            return Err(e);
        }
    }
    Ok(())
}

/// Reads several parameters, all axes each, with their attributes. The
/// numbers are 32-bit (`prm_no` is read 4 bytes per element, as FANUC's
/// x86-64 library does). A number the CNC does not know gets `type` -1 and
/// nothing else. As many parameters per exchange as FANUC's library asks
/// (8 on a 30i with 32 axes, 7 on a 16i, 4 on a Series 15).
///
/// # Safety
/// `prm_no` must point to `num` 32-bit numbers, `prm` to `num` writable IODBPRM.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdparam_ext(
    FlibHndl: c_ushort,
    prm_no: *mut c_long,
    num: c_short,
    prm: *mut IODBPRM,
) -> c_short {
    ffi_boundary!("cnc_rdparam_ext", {
        let h = handles::get(FlibHndl)?;
        let nos = nonnull(prm_no)?.cast::<i32>();
        let out = nonnull(prm)?;
        unsafe { read_ext(&h, Table::Param, nos, num, out) }
    })
}

/// Reads several diagnosis data items, all axes each, as cnc_rdparam_ext.
///
/// # Safety
/// `diag_no` must point to `num` 32-bit numbers, `diag` to `num` writable IODBPRM.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rddiag_ext(
    FlibHndl: c_ushort,
    diag_no: *mut c_long,
    num: c_short,
    diag: *mut IODBPRM,
) -> c_short {
    ffi_boundary!("cnc_rddiag_ext", {
        let h = handles::get(FlibHndl)?;
        let nos = nonnull(diag_no)?.cast::<i32>();
        let out = nonnull(diag)?;
        unsafe { read_ext(&h, Table::Diag, nos, num, out) }
    })
}

/// Reads the attributes of up to `*num` parameters from `s_number` on into
/// ODBPARAIF2 records: number, size, array, unit, dimension, input, display
/// and other words; `*prev` and `*next` the existing numbers around them,
/// `*num` the records written (0 when the CNC answers an error). A `*num`
/// of 0 or less is EW_LENGTH before any traffic. At most 71 records are
/// asked for.
///
/// # Safety
/// `num`, `prev`, `next` must point to writable shorts, `paraif` to `*num`
/// ODBPARAIF2.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdparainfo3(
    FlibHndl: c_ushort,
    s_number: c_short,
    num: *mut c_short,
    prev: *mut c_short,
    next: *mut c_short,
    paraif: *mut crate::types::ODBPARAIF2,
) -> c_short {
    ffi_boundary!("cnc_rdparainfo3", {
        let h = handles::get(FlibHndl)?;
        let (num, prev, next) = (nonnull(num)?, nonnull(prev)?, nonnull(next)?);
        let out = nonnull(paraif)?.cast::<u8>();
        let want = unsafe { num.read_unaligned() };
        if want <= 0 {
            return Err(Error::local(EW_LENGTH, "num must be at least 1"));
        }
        // At most one answer's records; a CNC error sets *num 0.
        let ask = want.min(((MAX_ANSWER - 8) / crate::proto::param::INFO3_REC) as i16);
        let b: Vec<u8> = match h.call(&crate::proto::param::rdparainfo3(s_number, ask)) {
            Ok(b) => b.concat(),
            Err(e) => {
                unsafe { put(num, 0) };
                return Err(e);
            }
        };
        let word = |at: usize| {
            b.get(at..at + 2)
                .map_or(0, |w| i16::from_be_bytes([w[0], w[1]]))
        };
        let rec = crate::proto::param::INFO3_REC;
        let n = (b.len().saturating_sub(8) / rec).min(want as usize);
        unsafe {
            for i in 0..n {
                let r = 8 + rec * i;
                for k in 0..8 {
                    put(out.add(16 * i + 2 * k).cast::<i16>(), word(r + 2 + 2 * k));
                }
            }
            put(prev, word(2));
            put(next, word(6));
            put(num, n as i16);
        }
        Ok(())
    })
}
