//! Programs in the CNC's memory: the functions the table cannot describe
//! (src/spec/table/ has the others: cnc_search, cnc_delete ...).

use super::program::progdir_records;
use super::{ffi_boundary, nonnull, put};
use crate::client::handles;
use crate::error::Error;
use crate::ew::{EW_ATTRIB, EW_LENGTH};
use crate::proto::call::Single;
use crate::proto::open::CncClass;
use crate::proto::packet::ReqSub;
use crate::proto::program::{PathName, ProgInfo, RDMDIPROG, RDPROGINFO, WRMDIPROG};
use crate::types::{ODBNC, ODBNC_bin, PRGDIR2, PRGDIR2O8};
use std::os::raw::{c_char, c_long, c_short, c_ushort};

/// Size of one PRGDIR2 / PRGDIR2O8 record (60 bytes).
const PRGDIR2_SIZE: usize = std::mem::size_of::<PRGDIR2>();
const _: () = assert!(PRGDIR2_SIZE == std::mem::size_of::<PRGDIR2O8>());

/// Reads up to `*num_prog` programs numbered `*top_prog` or more: `type` 0
/// the numbers, 1 also the comments, 2 also the sizes (as FANUC's library:
/// the number as 4 bytes over `number` and its padding, `dummy` never
/// written). Out: `*num_prog` records read, `*top_prog` the first one's
/// number as a short read back from `buf` (with no program, what `buf`
/// held: FANUC's library does so). Type not 0..2: EW_ATTRIB, `*num_prog` ≤ 0:
/// EW_LENGTH, without traffic. 19 programs per exchange at most.
/// (FANUC's library calls cnc_rdprogdir2o8 with `*top_prog` sign-extended
/// and keeps the low 16 bits of the number it gives back.)
///
/// # Safety
/// `top_prog` and `num_prog` must point to readable and writable shorts;
/// `buf` must have `*num_prog` writable PRGDIR2.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdprogdir2(
    FlibHndl: c_ushort,
    r#type: c_short,
    top_prog: *mut c_short,
    num_prog: *mut c_short,
    buf: *mut PRGDIR2,
) -> c_short {
    ffi_boundary!("cnc_rdprogdir2", {
        let top = nonnull(top_prog)?;
        let mut wide = i32::from(unsafe { top.read_unaligned() });
        progdir2(FlibHndl, r#type, &mut wide, num_prog, buf.cast())?;
        unsafe { put(top, wide as c_short) };
        Ok(())
    })
}

/// cnc_rdprogdir2 with 8-digit program numbers: `*top_prog` a 4-byte
/// `long` (sent as it is), PRGDIR2O8 records; out, `*top_prog` = the first
/// record's number read back from `buf` (with no program, the 4 bytes
/// `buf` held, as FANUC's library), `*num_prog` the records read. The same
/// checks and exchanges.
///
/// # Safety
/// `top_prog` must point to 4 readable and writable bytes, `num_prog` to a
/// readable and writable short; `buf` must have `*num_prog` writable
/// PRGDIR2O8.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdprogdir2o8(
    FlibHndl: c_ushort,
    r#type: c_short,
    top_prog: *mut c_long,
    num_prog: *mut c_short,
    buf: *mut PRGDIR2O8,
) -> c_short {
    ffi_boundary!("cnc_rdprogdir2o8", {
        // FANUC's x86-64 library reads and writes 4 bytes through a `long *`.
        let top = nonnull(top_prog)?.cast::<i32>();
        let mut wide = unsafe { top.read_unaligned() };
        progdir2(FlibHndl, r#type, &mut wide, num_prog, buf.cast())?;
        unsafe { put(top, wide) };
        Ok(())
    })
}

/// cnc_rdprogdir2 / cnc_rdprogdir2o8: `top` in, the first record's number
/// (4 bytes read back from `buf`) out when the call succeeds.
fn progdir2(
    hndl: c_ushort,
    r#type: c_short,
    top: &mut i32,
    num_prog: *mut c_short,
    buf: *mut u8,
) -> crate::error::Result<()> {
    let h = handles::get(hndl)?;
    let num = nonnull(num_prog)?;
    let out = nonnull(buf)?;
    if !(0..=2).contains(&r#type) {
        return Err(Error::local(EW_ATTRIB, "type must be 0, 1 or 2"));
    }
    let want = unsafe { num.read_unaligned() };
    if want <= 0 {
        return Err(Error::local(EW_LENGTH, "*num_prog must be at least 1"));
    }
    let got = progdir_records(&h, i32::from(r#type), *top, want as usize)?;
    for (i, e) in got.iter().enumerate() {
        let at = unsafe { out.add(i * PRGDIR2_SIZE) };
        unsafe {
            put(at.cast::<i32>(), e.number);
            if r#type >= 1 {
                put(
                    at.add(8).cast::<[u8; 51]>(),
                    e.comment[..51].try_into().expect("51"),
                );
            }
            if r#type == 2 {
                put(at.add(4).cast::<i32>(), e.length);
            }
        }
    }
    unsafe {
        put(num, got.len() as c_short);
        // FANUC's library reads it back from the first record, written or not.
        *top = out.cast::<i32>().read_unaligned();
    }
    Ok(())
}

/// Reads the MDI program's text into `data` (no NUL), `*length` set to its
/// length. A text longer than `*length`: EW_LENGTH after the exchange,
/// nothing written, as FANUC's library.
///
/// # Safety
/// `length` must point to a readable and writable short; `data` must have
/// `*length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdmdiprog(
    FlibHndl: c_ushort,
    length: *mut c_short,
    data: *mut c_char,
) -> c_short {
    ffi_boundary!("cnc_rdmdiprog", {
        let h = handles::get(FlibHndl)?;
        let (len, out) = (nonnull(length)?, nonnull(data)?.cast::<u8>());
        let text = h
            .call(&Single::<PathName>::new(ReqSub::cnc(RDMDIPROG, &[])))?
            .0;
        if i64::from(unsafe { len.read_unaligned() }) < text.len() as i64 {
            return Err(Error::local(
                EW_LENGTH,
                "the MDI program is longer than *length",
            ));
        }
        unsafe {
            std::ptr::copy_nonoverlapping(text.as_ptr(), out, text.len());
            put(len, text.len() as c_short);
        }
        Ok(())
    })
}

/// Writes the MDI program: `length` bytes of `data` go to the CNC as they
/// are. A negative `length`: EW_LENGTH without traffic (FANUC's library
/// aborts the process).
///
/// # Safety
/// `data` must have `length` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrmdiprog(
    FlibHndl: c_ushort,
    length: c_short,
    data: *mut c_char,
) -> c_short {
    ffi_boundary!("cnc_wrmdiprog", {
        let h = handles::get(FlibHndl)?;
        let p = nonnull(data)?.cast::<u8>();
        if length < 0 {
            return Err(Error::local(EW_LENGTH, "length must not be negative"));
        }
        let text = unsafe { std::slice::from_raw_parts(p, length as usize) }.to_vec();
        let sub = ReqSub::cnc(WRMDIPROG, &[]).with_payload(text);
        h.call(&Single::<PathName>::new(sub)).map(drop)
    })
}

/// Reads program memory information: `type` 0 into `prog->u.bin`, 1 as the
/// text `"%\n<reg>\n<unreg>\n<used>\n<unused>\n%"` and a NUL into
/// `prog->u.asc` (as FANUC's library writes it; never more than `length`
/// bytes). Type not 0/1: EW_ATTRIB; `length` under 12 (type 0) or 31
/// (type 1), on a Series 15 16 or 35: EW_LENGTH; both without traffic.
///
/// # Safety
/// `prog` must point to `length` writable bytes (at least an ODBNC).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdproginfo(
    FlibHndl: c_ushort,
    r#type: c_short,
    length: c_short,
    prog: *mut ODBNC,
) -> c_short {
    ffi_boundary!("cnc_rdproginfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(prog)?;
        let s15 = h.ctx().class == (CncClass::Series16 { kind: 2 });
        let min = match (r#type, s15) {
            (0, false) => 12,
            (0, true) => 16,
            (1, false) => 31,
            (1, true) => 35,
            _ => return Err(Error::local(EW_ATTRIB, "type must be 0 or 1")),
        };
        if length < min {
            return Err(Error::local(EW_LENGTH, "length too small for the type"));
        }
        let i = h.call(&Single::<ProgInfo>::padded(ReqSub::cnc(RDPROGINFO, &[])))?;
        if r#type == 0 {
            let bin = ODBNC_bin {
                reg_prg: i.reg_prg as c_short,
                unreg_prg: i.unreg_prg as c_short,
                used_mem: i.used_mem,
                unused_mem: i.unused_mem,
            };
            unsafe { put(out.cast::<ODBNC_bin>(), bin) };
            return Ok(());
        }
        let text = format!(
            "%\n{}\n{}\n{}\n{}\n%\0",
            i.reg_prg, i.unreg_prg, i.used_mem, i.unused_mem
        );
        let n = text.len().min(length as usize);
        unsafe { std::ptr::copy_nonoverlapping(text.as_ptr(), out.cast::<u8>(), n) };
        Ok(())
    })
}
