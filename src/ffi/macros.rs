//! Custom macro variables.

use super::{ffi_boundary, nonnull};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::{EW_DATA, EW_LENGTH, EW_NUMBER};
use crate::proto::macros::{DEC_FORBIDDEN, FIRST_WRITABLE, ReadMacros, WriteMacros};
use crate::proto::value::Value;
use crate::types::{IODBMR, IODBMR_data, ODBM};
use std::os::raw::{c_long, c_short, c_ushort};
use std::ptr::addr_of_mut;

/// Bytes of ODBM FANUC's library requires (datano .. dec_val, l32).
const ODBM_LEN: c_short = 10;
/// Bytes of IODBMR before the records, and per record (l32).
const IODBMR_HEAD: usize = 8;
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
    ffi_boundary!("cnc_rdmacro", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(macro_)?;
        if length < ODBM_LEN {
            return Err(Error::length());
        }
        let n = i32::from(number);
        let recs = h.call(&ReadMacros { s: n, e: n })?;
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

fn first(recs: &[Value]) -> Result<&Value> {
    recs.first().ok_or_else(|| {
        Error::protocol(
            crate::error::detail::SHORT_PAYLOAD,
            "macro reply carries no record",
        )
    })
}

/// Checks cnc_wrmacro / cnc_wrmacror make before any traffic (SPEC.md §5.2):
/// local variables (#1..#33, any number below 100) cannot be written
/// (EW_NUMBER), dec_val 32767 is refused (EW_DATA).
fn check_write(number: c_short, dec_val: c_short) -> Result<()> {
    if number < FIRST_WRITABLE {
        return Err(Error::local(EW_NUMBER, "local variables cannot be written"));
    }
    if dec_val == DEC_FORBIDDEN {
        return Err(Error::local(EW_DATA, "dec_val 32767 is not a value"));
    }
    Ok(())
}

/// Writes the custom macro variable `number` = `mcr_val · 10^-dec_val`.
/// `length` must be 10; `mcr_val` is taken as 32 bits (FANUC's x86-64
/// library truncates a 64-bit `long` the same way).
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
        let h = handles::get(FlibHndl)?;
        if length != ODBM_LEN {
            return Err(Error::local(EW_LENGTH, "length must be 10"));
        }
        check_write(number, dec_val)?;
        h.call(&WriteMacros {
            s: i32::from(number),
            values: vec![(mcr_val as i32, dec_val)],
        })
    })
}

/// Reads the custom macro variables `s_no`..`e_no` into `buf->data`
/// (8 bytes per variable, as FANUC's x86-64 library writes them).
/// `length` is the buffer's size: `8 + 8 · count`; no more variables than
/// fit are written. `datano_s`/`datano_e` are set from the request.
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
    ffi_boundary!("cnc_rdmacror", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(buf)?;
        let room = (length.max(0) as usize).checked_sub(IODBMR_HEAD);
        let Some(room) = room else {
            return Err(Error::length());
        };
        let recs = h.call(&ReadMacros {
            s: i32::from(s_no),
            e: i32::from(e_no),
        })?;
        let want = (i32::from(e_no) - i32::from(s_no) + 1).max(0) as usize;
        let n = recs.len().min(want).min(room / IODBMR_REC);
        unsafe {
            set(addr_of_mut!((*out).datano_s), s_no);
            set(addr_of_mut!((*out).datano_e), e_no);
            let data = addr_of_mut!((*out).data).cast::<IODBMR_data>();
            for (i, r) in recs[..n].iter().enumerate() {
                let (v, d) = r.to_decimal();
                let p = data.add(i);
                set(addr_of_mut!((*p).mcr_val), v);
                set(addr_of_mut!((*p).dec_val), d);
            }
        }
        Ok(())
    })
}
