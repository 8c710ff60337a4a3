//! Tool and work offsets.
//!
//! Requests, local checks and output bytes as FANUC's library (vectors
//! cnc_rdtofs / cnc_rdzofs; the other functions recorded from FANUC's
//! library against a fake CNC). Outputs are written field by field at their
//! l32 offsets, and only on success (cnc_rdzofsr: see there).

use super::{ffi_boundary, ffi_read, len_of, nonnull, put_at, put_member};
use crate::client::handles::{self, Handle};
use crate::error::{Error, Result};
use crate::ew::{EW_ATTRIB, EW_NUMBER};
use crate::proto::offset as p;
use crate::proto::value::Value;
use crate::types::{IODBTO, IODBWCSF, IODBZOFS, IODBZOR, LONG, ODBTOFS};
use std::mem::offset_of;
use std::os::raw::{c_long, c_short, c_ushort};

/// Bytes IODBZOFS needs for `axis`, FANUC's local check: every negative
/// axis means all axes (4 + 4 · max_axes bytes; FANUC's library treats -2,
/// -3 … as -1 and sends them as they are), axis > max → EW_ATTRIB.
fn zofs_needed(h: &Handle, axis: c_short) -> Result<usize> {
    let max = h.ctx().axes();
    match axis {
        a if a < 0 => Ok(4 + 4 * max),
        a if a as usize > max => Err(Error::local(EW_ATTRIB, "axis beyond the CNC's axes")),
        _ => Ok(8),
    }
}

/// Bytes per value and per offset number in cnc_rdtofsr's output for
/// `type`, FANUC's table: (value size, bytes per number for the length
/// check). Types 9 and 20 are 2-byte values; the "all" types -2..-6 take
/// several values per number.
fn tofsr_sizes(r#type: c_short) -> (usize, usize) {
    match r#type {
        9 | 20 => (2, 2),
        -2 | -4 => (4, 8),
        -3 => (4, 16),
        -5 => (4, 12),
        -6 => (4, 20),
        _ => (4, 4),
    }
}

fn first(v: &[Value]) -> Result<i32> {
    v.first().map(|r| r.value).ok_or_else(short)
}

fn short() -> Error {
    Error::short("payload shorter than the answer needs")
}

/// Reads one tool offset value (`type`: offset kind, e.g. on a mill with
/// memory C 0/1 radius wear/geometry, 2/3 length wear/geometry).
///
/// # Safety
/// `tofs` must point to a writable ODBTOFS.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdtofs(
    FlibHndl: c_ushort,
    number: c_short,
    r#type: c_short,
    length: c_short,
    tofs: *mut ODBTOFS,
) -> c_short {
    ffi_read!("cnc_rdtofs", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(tofs)?.cast::<u8>();
        // Compared unsigned, as FANUC's library does (-1 is 65535).
        if usize::from(length as u16) < size_of::<ODBTOFS>() {
            return Err(Error::length());
        }
        let v = first(&h.call(&p::rdtofs(number, r#type))?.0)?;
        unsafe {
            put_member!(out, ODBTOFS, datano, number);
            put_member!(out, ODBTOFS, r#type, r#type);
            put_member!(out, ODBTOFS, data, v);
        }
        Ok(())
    })
}

/// Writes one tool offset value. `data` is sent as its low 32 bits, as
/// FANUC's x86-64 library does.
///
/// # Safety
/// No pointer arguments.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrtofs(
    FlibHndl: c_ushort,
    number: c_short,
    r#type: c_short,
    length: c_short,
    data: c_long,
) -> c_short {
    ffi_boundary!("cnc_wrtofs", {
        let h = handles::get(FlibHndl)?;
        if len_of(length) < 8 {
            return Err(Error::length());
        }
        h.call(&p::wrtofs(number, r#type, data as i32))?;
        Ok(())
    })
}

/// Reads the tool offsets `s_number..=e_number` of one type (-1: all types
/// of each offset), one value each from offset 8: 4 bytes, or the low 16
/// bits for types 9 and 20 (as FANUC's library). The length check before
/// traffic uses FANUC's bytes-per-number table; values that do not fit in
/// `length` are not written (FANUC's library writes every value the CNC
/// sent).
///
/// # Safety
/// `tofs` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdtofsr(
    FlibHndl: c_ushort,
    s_number: c_short,
    r#type: c_short,
    e_number: c_short,
    length: c_short,
    tofs: *mut IODBTO,
) -> c_short {
    ffi_boundary!("cnc_rdtofsr", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(tofs)?.cast::<u8>();
        if s_number > e_number {
            return Err(Error::local(EW_NUMBER, "start number after end number"));
        }
        // Compared unsigned, as FANUC's library does (-1 is 65535).
        let room = length as u16 as usize;
        let count = (i32::from(e_number) - i32::from(s_number) + 1) as usize;
        let (size, per_number) = tofsr_sizes(r#type);
        // The values: an array of the union `u`, shorts or longs by type.
        let u = offset_of!(IODBTO, u);
        if room < u + per_number * count {
            return Err(Error::length());
        }
        let v = h.call(&p::rdtofsr(s_number, r#type, e_number))?.0;
        let n = v.len().min((room - u) / size);
        unsafe {
            put_member!(out, IODBTO, datano_s, s_number);
            put_member!(out, IODBTO, r#type, r#type);
            put_member!(out, IODBTO, datano_e, e_number);
            for (i, r) in v[..n].iter().enumerate() {
                if size == 2 {
                    put_at(out, u + 2 * i, r.value as i16);
                } else {
                    put_at(out, u + 4 * i, r.value);
                }
            }
        }
        Ok(())
    })
}

/// Reads a work zero offset (`number` 0 external, 1..6 G54..G59, 7.. G54.1
/// P1..) for one axis or all axes (-1). An all-axes answer must carry a
/// value per axis (FANUC's library writes uninitialised memory otherwise;
/// we return the code EW_PROTOCOL); a one-axis answer without a whole
/// value record gives the value 0, as from FANUC's library.
///
/// # Safety
/// `zofs` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdzofs(
    FlibHndl: c_ushort,
    number: c_short,
    axis: c_short,
    length: c_short,
    zofs: *mut IODBZOFS,
) -> c_short {
    ffi_read!("cnc_rdzofs", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(zofs)?.cast::<u8>();
        // Compared unsigned, as FANUC's library does (-1 is 65535).
        if (length as u16 as usize) < zofs_needed(&h, axis)? {
            return Err(Error::length());
        }
        // When the CNC answers an error, FANUC's library has already
        // written the header and a zero first value: so do we.
        let v = h
            .call(&p::rdzofs(number, axis))
            .inspect_err(|e| {
                if matches!(e, Error::Cnc { .. }) {
                    unsafe {
                        put_member!(out, IODBZOFS, datano, number);
                        put_member!(out, IODBZOFS, r#type, axis);
                        put_member!(out, IODBZOFS, data[0], 0);
                    }
                }
            })?
            .0;
        let n = if axis < 0 { h.ctx().axes() } else { 1 };
        // An answer of more records than FANUC's library takes: EW_LENGTH,
        // with the header and zero values it wrote before the exchange.
        // One axis: more than the CNC's axes; all axes: twice them or more
        // [oracle, verified over 4, 8 and 32 axes; fuzz rdzofs `s0Tmore`].
        let most = h.ctx().axes() * if axis < 0 { 2 } else { 1 };
        if v.len() + usize::from(axis < 0) > most {
            unsafe {
                put_member!(out, IODBZOFS, datano, number);
                put_member!(out, IODBZOFS, r#type, axis);
                for i in 0..n.max(1) {
                    put_member!(out, IODBZOFS, data[i], 0);
                }
            }
            return Err(Error::length());
        }
        // One axis: the header and the zero first value come first, so an
        // answer without a whole record (empty or cut) leaves data[0] = 0,
        // EW_OK [fuzz, rdzofs `s0Twcut`, `short1`, `empty`: FANUC's library
        // wrote 0 for each, not the bytes it lacked]. All axes: FANUC's
        // library writes uninitialised memory past the records, ours
        // EW_PROTOCOL.
        if axis < 0 && v.len() < n {
            return Err(short());
        }
        unsafe {
            put_member!(out, IODBZOFS, datano, number);
            put_member!(out, IODBZOFS, r#type, axis);
            put_member!(out, IODBZOFS, data[0], 0);
            for (i, r) in v.iter().take(n).enumerate() {
                put_member!(out, IODBZOFS, data[i], r.value);
            }
        }
        Ok(())
    })
}

/// Writes a work zero offset for one axis (`type` = axis) or all axes
/// (any negative `type`, sent as it is: one value per axis of the CNC, as
/// FANUC's library).
///
/// # Safety
/// `zofs` must point to `length` readable bytes (an IODBZOFS), and at least 4
/// (its first two shorts are read before `length` is checked, as FANUC's
/// library reads them).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrzofs(
    FlibHndl: c_ushort,
    length: c_short,
    zofs: *mut IODBZOFS,
) -> c_short {
    ffi_boundary!("cnc_wrzofs", {
        let h = handles::get(FlibHndl)?;
        let inp = nonnull(zofs)?.cast::<u8>().cast_const();
        let rd = |off: usize| unsafe { inp.add(off).cast::<i32>().read_unaligned() };
        let number = unsafe { inp.cast::<i16>().read_unaligned() };
        let axis = unsafe { inp.add(2).cast::<i16>().read_unaligned() };
        if len_of(length) < zofs_needed(&h, axis)? {
            return Err(Error::length());
        }
        let n = if axis < 0 { h.ctx().axes() } else { 1 };
        let values: Vec<i32> = (0..n).map(|i| rd(4 + 4 * i)).collect();
        h.call(&p::wrzofs(number, axis, &values))?;
        Ok(())
    })
}

/// Writes the work coordinate shift of one axis (`type`) or of all axes
/// (`type` -1: max_axes values from `data`); `length` as cnc_wrzofs's.
///
/// # Safety
/// `shift` must point to `length` readable bytes (an IODBWCSF), and at least 4
/// (its first two shorts are read before `length` is checked, as FANUC's
/// library reads them).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrwkcdshft(
    FlibHndl: c_ushort,
    length: c_short,
    shift: *mut IODBWCSF,
) -> c_short {
    ffi_boundary!("cnc_wrwkcdshft", {
        let h = handles::get(FlibHndl)?;
        let inp = nonnull(shift)?.cast::<u8>().cast_const();
        let axis = unsafe { inp.add(2).cast::<i16>().read_unaligned() };
        if len_of(length) < zofs_needed(&h, axis)? {
            return Err(Error::length());
        }
        let n = if axis < 0 { h.ctx().axes() } else { 1 };
        let rd = |i: usize| unsafe { inp.add(4 + 4 * i).cast::<i32>().read_unaligned() };
        let values: Vec<i32> = (0..n).map(rd).collect();
        h.call(&p::wrwkcdshft(axis, &values))?;
        Ok(())
    })
}

/// Reads the work zero offsets `s_number..=e_number` for one axis or all
/// axes (any negative axis, sent as it is), as FANUC's library: requests of
/// at most 179 value records each (5 numbers of 32 axes, 179 of one axis),
/// a number's values packed from offset 8 (max_axes of them for all axes).
/// Each answer's whole numbers are checked against `length` (unsigned:
/// 8 + 4 · values so far, else EW_LENGTH) and written; a shorter answer
/// ends the read, and so does the CNC's EW_NUMBER after the first request
/// (a range past the table). Then `datano_s`, `type` and `datano_e` (the
/// last number read) are written. On an error after the first answer, the
/// values already written stay (as FANUC's library; all within `length`).
///
/// # Safety
/// `zofsr` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdzofsr(
    FlibHndl: c_ushort,
    s_number: c_short,
    axis: c_short,
    e_number: c_short,
    length: c_short,
    zofsr: *mut IODBZOR,
) -> c_short {
    ffi_boundary!("cnc_rdzofsr", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(zofsr)?.cast::<u8>();
        if s_number > e_number {
            return Err(Error::local(EW_NUMBER, "start number after end number"));
        }
        // Compared unsigned, as FANUC's library does (-1 is 65535).
        let room = length as u16 as usize;
        let per = if axis < 0 { h.ctx().axes().max(1) } else { 1 };
        let chunk = (p::RDZOFSR_RECORDS / per).max(1) as i32;
        let (first, e) = (i32::from(s_number), i32::from(e_number));
        let mut s = first;
        let mut numbers = 0usize;
        while s <= e {
            let last = e.min(s + chunk - 1);
            let v = match h.call(&p::ReadZofsRange { s, e: last, axis }) {
                Ok(v) => v,
                Err(Error::Cnc {
                    code: EW_NUMBER, ..
                }) if s > first => break,
                Err(err) => return Err(err),
            };
            let n = v.len() / per;
            if offset_of!(IODBZOR, data) + size_of::<LONG>() * per * (numbers + n) > room {
                return Err(Error::length());
            }
            unsafe {
                for (i, r) in v[..n * per].iter().enumerate() {
                    put_member!(out, IODBZOR, data[per * numbers + i], r.value);
                }
            }
            numbers += n;
            if n < (last - s + 1) as usize {
                break;
            }
            s = last + 1;
        }
        unsafe {
            put_member!(out, IODBZOR, datano_s, s_number);
            put_member!(out, IODBZOR, r#type, axis);
            put_member!(out, IODBZOR, datano_e, (first + numbers as i32 - 1) as i16);
        }
        Ok(())
    })
}
