//! Custom macro variables.

use super::{ffi_boundary, ffi_read, len_of, nonnull};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::{EW_DATA, EW_LENGTH, EW_NUMBER};
use crate::proto::macros::{DEC_FORBIDDEN, FIRST_WRITABLE, ReadMacros, WriteMacros};
use crate::proto::open::CncClass;
use crate::proto::value::Value;
use crate::types::{IODBMR, IODBMR_data, ODBM};
use std::os::raw::{c_long, c_short, c_ushort};
use std::ptr::addr_of_mut;

/// Bytes of ODBM FANUC's library requires (datano .. dec_val, l32).
const ODBM_LEN: c_short = 10;
/// Bytes of IODBMR before the records, and per record (l32).
const IODBMR_HEAD: usize = 8;
/// Variables one cnc_rdmacror request asks for at most.
const RDMACROR_MAX: i32 = 179;
const IODBMR_REC: usize = std::mem::size_of::<IODBMR_data>();

/// Writes one field of a caller's structure.
///
/// # Safety
/// `p` must be valid for writes.
unsafe fn set<T>(p: *mut T, v: T) {
    unsafe { p.write_unaligned(v) }
}

/// Reads the custom macro variable `number` (common #100.., #500.., system
/// variables): `mcr_val · 10^-dec_val`; a vacant variable reads as
/// mcr_val 0, dec_val -1. `length` must be at least 10 (the l32 ODBM).
///
/// # Safety
/// `macro_` must point to a writable ODBM.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdmacro(
    FlibHndl: c_ushort,
    number: c_short,
    length: c_short,
    macro_: *mut ODBM,
) -> c_short {
    ffi_read!("cnc_rdmacro", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(macro_)?;
        if length < ODBM_LEN {
            return Err(Error::length());
        }
        let n = i32::from(number);
        let recs = h.call(&ReadMacros { s: n, e: n })?;
        // FANUC's library reads with room for 5 records: an answer of more
        // whole records is EW_LENGTH [fuzz seed 0x202e1129; crafted: 5
        // records and 7 bytes pass, 6 do not] (it writes datano and an
        // uninitialised mcr_val then; ours nothing, README).
        if recs.len() > RDMACRO_ROOM {
            return Err(Error::local(
                EW_LENGTH,
                "more records than cnc_rdmacro has room for",
            ));
        }
        let (mcr_val, dec_val) = first(&recs)?.to_decimal();
        // FANUC writes datano, mcr_val, dec_val; `dummy` stays as it was.
        unsafe {
            set(addr_of_mut!((*out).datano), number);
            set(addr_of_mut!((*out).mcr_val), mcr_val);
            set(addr_of_mut!((*out).dec_val), dec_val);
        }
        Ok(())
    })
}

/// The end number cnc_rdmacror asks for (as FANUC's library): `e_no`, but
/// not past the end of the start's range (#0..#99, #100..#499, #500..#999)
/// and at most 179 variables.
fn rdmacror_end(s_no: c_short, e_no: c_short) -> i32 {
    let (s, e) = (i32::from(s_no), i32::from(e_no));
    e.min(range_end(i64::from(s)) as i32)
        .min(s + RDMACROR_MAX - 1)
}

/// The last variable of the range `s` is in, as FANUC's library splits
/// cnc_rdmacror requests: #0..#99, #100..#499, #500..#999;
/// other numbers have no end.
fn range_end(s: i64) -> i64 {
    match s {
        0..=99 => 99,
        100..=499 => 499,
        500..=999 => 999,
        _ => i64::from(i32::MAX),
    }
}

/// The records cnc_rdmacro takes from an answer (FANUC's library's room).
const RDMACRO_ROOM: usize = 5;

fn first(recs: &[Value]) -> Result<&Value> {
    recs.first()
        .ok_or_else(|| Error::short("macro reply carries no record"))
}

/// FANUC's library refuses dec_val 32767 and -32768 / -13108 (cnc_wrmacror) with EW_DATA, accepts -1 (vacant), 3, 16;
/// the exact range is not known: we refuse 32767 and anything below -1.
fn check_dec(dec_val: c_short) -> Result<()> {
    if dec_val == DEC_FORBIDDEN || dec_val < -1 {
        return Err(Error::local(
            EW_DATA,
            "dec_val is not a number of decimal places",
        ));
    }
    Ok(())
}

/// Writes the custom macro variable `number` = `mcr_val · 10^-dec_val`.
/// `length` must be at least 10 (checked first, as FANUC's library does,
/// before the handle); `mcr_val` is taken as 32 bits (FANUC's x86-64
/// library truncates a 64-bit `long` the same way); `dec_val` outside
/// -128..=127 is EW_DATA.
///
/// # Safety
/// No pointers.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrmacro(
    FlibHndl: c_ushort,
    number: c_short,
    length: c_short,
    mcr_val: c_long,
    dec_val: c_short,
) -> c_short {
    ffi_boundary!("cnc_wrmacro", {
        if length < ODBM_LEN {
            return Err(Error::local(EW_LENGTH, "length must be at least 10"));
        }
        let h = handles::get(FlibHndl)?;
        if number < FIRST_WRITABLE {
            return Err(Error::local(EW_NUMBER, "local variables cannot be written"));
        }
        // FANUC's library refuses decimals outside a byte's range.
        if i8::try_from(dec_val).is_err() {
            return Err(Error::local(EW_DATA, "dec_val outside -128..127"));
        }
        h.call(&WriteMacros {
            s: i32::from(number),
            values: vec![(mcr_val as i32, dec_val)],
        })
    })
}

/// Reads the custom macro variables `s_no`..`e_no` into `buf->data`
/// (8 bytes per variable, as FANUC's x86-64 library writes them).
/// `e_no < s_no` is EW_NUMBER without traffic; the request stops at the end
/// of `s_no`'s range (#99, #499, #999) and after 179 variables. Every
/// variable the CNC sends must fit in `length` (`8 + 8 · count`, compared
/// unsigned, after the exchange), else EW_LENGTH and nothing is written.
/// `datano_s` = `s_no`, `datano_e` = `s_no` + variables received - 1.
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdmacror(
    FlibHndl: c_ushort,
    s_no: c_short,
    e_no: c_short,
    length: c_short,
    buf: *mut IODBMR,
) -> c_short {
    ffi_read!("cnc_rdmacror", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(buf)?;
        if e_no < s_no {
            return Err(Error::local(EW_NUMBER, "end number below start number"));
        }
        if s_no < 0 && h.ctx().class.is_16i() {
            return Err(Error::local(EW_NUMBER, "negative start number (16i class)"));
        }
        let recs = h.call(&ReadMacros {
            s: i32::from(s_no),
            e: rdmacror_end(s_no, e_no),
        })?;
        // `length` is compared unsigned after the exchange, as FANUC's
        // library does (-1 is 65535 bytes).
        let n = recs.len();
        if IODBMR_HEAD + n * IODBMR_REC > length as u16 as usize {
            return Err(Error::local(EW_LENGTH, "the records do not fit in length"));
        }
        let e_no = (i32::from(s_no) + n as i32 - 1) as c_short;
        unsafe {
            set(addr_of_mut!((*out).datano_s), s_no);
            set(addr_of_mut!((*out).datano_e), e_no);
            let data = addr_of_mut!((*out).data).cast::<IODBMR_data>();
            for (i, r) in recs.iter().enumerate() {
                let (v, d) = r.to_decimal();
                let p = data.add(i);
                set(addr_of_mut!((*p).mcr_val), v);
                set(addr_of_mut!((*p).dec_val), d);
            }
        }
        Ok(())
    })
}

/// Writes the custom macro variables `buf->datano_s`..`buf->datano_e` from
/// `buf->data` (8 bytes per variable, l32) in one request, no further than
/// the end of `datano_s`'s range (#499, #999; the rest is left out, as
/// FANUC's library does). `length` must cover the records written (at least
/// `8 · count + 6`, and 8 before anything else is checked); numbers below 100 or a
/// reversed range give EW_NUMBER, a dec_val of 32767 or below -1 EW_DATA,
/// all before any traffic.
///
/// # Safety
/// `buf` must point to `length` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrmacror(
    FlibHndl: c_ushort,
    length: c_short,
    buf: *mut IODBMR,
) -> c_short {
    ffi_boundary!("cnc_wrmacror", {
        let h = handles::get(FlibHndl)?;
        let inp = nonnull(buf)?;
        // FANUC's library refuses a length below 8 before looking at the
        // numbers (which are not read then: `buf` holds `length` bytes).
        if len_of(length) < 8 {
            return Err(Error::length());
        }
        let (s, e) = unsafe {
            (
                addr_of_mut!((*inp).datano_s).read_unaligned(),
                addr_of_mut!((*inp).datano_e).read_unaligned(),
            )
        };
        if s < FIRST_WRITABLE || e < s {
            return Err(Error::local(
                EW_NUMBER,
                "variables below #100 or a reversed range",
            ));
        }
        // FANUC's library writes no further than the end of the start's
        // range (#499, #999; a Series 15's #100..#999 are one): the
        // variables past it are left out, and the call succeeds. The last
        // dec_val written must lie within `length`.
        let s15 = h.ctx().class == (CncClass::Series16 { kind: 2 });
        let end = match i64::from(s) {
            100..=999 if s15 => 999,
            s => range_end(s),
        };
        let n = ((e - s) as usize + 1).min((end - i64::from(s) + 1) as usize);
        if len_of(length) < IODBMR_REC * n + 6 {
            return Err(Error::length());
        }
        let data = unsafe { addr_of_mut!((*inp).data).cast::<IODBMR_data>() };
        let mut values = Vec::with_capacity(n);
        for i in 0..n {
            let (v, d) = unsafe {
                let p = data.add(i);
                (
                    addr_of_mut!((*p).mcr_val).read_unaligned(),
                    addr_of_mut!((*p).dec_val).read_unaligned(),
                )
            };
            check_dec(d)?;
            values.push((v, d));
        }
        h.call(&WriteMacros {
            s: i32::from(s),
            values,
        })
    })
}
