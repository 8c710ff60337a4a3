//! Program upload over connection 1 (cnc_upstart ... cnc_upend).
//!
//! Recorded from FANUC's library: cnc_upstart, cnc_upstart3, cnc_upload3,
//! cnc_upend3 (vectors); cnc_upstart4, cnc_upload4, cnc_upload, cnc_upend4,
//! cnc_upend and the buffer rule (room in whole 256s, frames split to fit)
//! by the oracle helper (/tmp/orc/findings/cnc_upload_family.md, \[lib\],
//! no vectors). Read from its code (\[dis\]): cnc_upload4
//! and cnc_upend4 are cnc_upload3 and cnc_upend3 under another name;
//! cnc_upstart4 sends the start name "N:`<prgname>`" ("N:" for NULL);
//! cnc_cupload is cnc_upload3 into ODBUP.data with an `unsigned short`
//! length (255 or less: EW_LENGTH), cnc_upload repeats it every millisecond
//! while it returns EW_BUFFER; cnc_cupload, cnc_upload and cnc_upend turn
//! EW_REJECT (13) and EW_ALARM (15) into EW_UNEXP (-6), cnc_upstart turns
//! 2, 4, 6 into -6 and 12, 13, 15 into EW_BUSY (-1). The start frame's
//! second word is the handle's path (FANUC's library puts its path word
//! there; only path 1 was recorded). FANUC's functions also test a handle
//! flag ("checkOption": bit 1 of a word of its handle object, EW_NOOPT when
//! clear) whose source we do not know; we do not test it.

use super::{cstr, ffi_boundary, nonnull, put};
use crate::client::handles::{self, Handle};
use crate::error::{Error, Result};
use crate::ew::{EW_BUFFER, EW_BUSY, EW_DATA, EW_LENGTH, EW_UNEXP};
use crate::proto::upload::{NAME_LEN, StartReq, name4, range_name};
use crate::types::ODBUP;
use std::os::raw::{c_char, c_long, c_short, c_ushort};
use std::sync::Arc;

/// Records a failure for cnc_getdtailerr.
fn noted<T>(h: &Handle, r: Result<T>) -> Result<T> {
    if let Err(e) = &r {
        h.note(e);
    }
    r
}

fn start(h: &Arc<Handle>, handle: u16, dtype: c_short, name: Vec<u8>) -> Result<()> {
    if name.len() >= NAME_LEN {
        return Err(Error::local(EW_DATA, "program name too long"));
    }
    let (path, timeout) = {
        let s = h.state.lock();
        (s.path, s.timeout)
    };
    let req = StartReq {
        dtype,
        path,
        start: name,
        end: Vec::new(),
    };
    noted(h, h.upload_start(handle, &req, timeout))
}

fn read(h: &Handle, handle: u16, out: &mut [u8]) -> Result<usize> {
    let timeout = h.state.lock().timeout;
    noted(h, h.upload_read(handle, out, timeout))
}

fn end(h: &Handle, handle: u16) -> Result<()> {
    let timeout = h.state.lock().timeout;
    noted(h, h.upload_end(handle, timeout))
}

/// FANUC's cnc_cupload / cnc_upload / cnc_upend: EW_REJECT and EW_ALARM become EW_UNEXP.
fn old_style<T>(r: Result<T>) -> Result<T> {
    r.map_err(|e| match e.ew() {
        13 | 15 => Error::local(EW_UNEXP, "upload rejected by the CNC"),
        _ => e,
    })
}

/// Starts uploading NC program `prgno` (text `O<n>-O<n>`, data type 0).
/// Then cnc_upload / cnc_upload3 read the text and cnc_upend ends it.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_upstart(FlibHndl: c_ushort, prgno: c_short) -> c_short {
    ffi_boundary!("cnc_upstart", {
        let h = handles::get(FlibHndl)?;
        let n = i32::from(prgno);
        start(&h, FlibHndl, 0, range_name(n, n)).map_err(|e| match e.ew() {
            2 | 4 | 6 => Error::local(EW_UNEXP, "upload start refused"),
            12 | 13 | 15 => Error::local(EW_BUSY, "upload start refused: CNC busy"),
            _ => e,
        })
    })
}

/// Starts uploading data of `type` (0 = NC programs) for the O-number range
/// `start`..`end`.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_upstart3(
    FlibHndl: c_ushort,
    r#type: c_short,
    startno: c_long,
    endno: c_long,
) -> c_short {
    ffi_boundary!("cnc_upstart3", {
        let h = handles::get(FlibHndl)?;
        // FANUC formats the low 32 bits with "%d".
        start(
            &h,
            FlibHndl,
            r#type,
            range_name(startno as i32, endno as i32),
        )
    })
}

/// Starts uploading data of `type` for the program named `prgname`
/// (e.g. "O1234" or "//CNC_MEM/USER/PATH1/O1234"); NULL sends no name.
///
/// # Safety
/// `prgname` must be NULL or a NUL-terminated string.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_upstart4(
    FlibHndl: c_ushort,
    r#type: c_short,
    prgname: *mut c_char,
) -> c_short {
    ffi_boundary!("cnc_upstart4", {
        let h = handles::get(FlibHndl)?;
        let name = if prgname.is_null() {
            None
        } else {
            Some(unsafe { cstr(prgname) }?)
        };
        start(&h, FlibHndl, r#type, name4(name))
    })
}

/// Reads the next piece of uploaded text into `data` (at most `*length`
/// rounded down to whole 256 bytes; 256 or more required; not
/// NUL-terminated) and sets `*length` to its size. Returns EW_BUFFER while nothing has arrived
/// (call again), EW_RESET (-2) once the whole text was read.
///
/// # Safety
/// `length` must point to a `long` (4 bytes are read and written);
/// `data` to `*length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_upload3(
    FlibHndl: c_ushort,
    length: *mut c_long,
    data: *mut c_char,
) -> c_short {
    ffi_boundary!("cnc_upload3", {
        unsafe { upload3(FlibHndl, length, data) }
    })
}

/// As cnc_upload3 (FANUC's cnc_upload4 is the same function).
///
/// # Safety
/// As cnc_upload3.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_upload4(
    FlibHndl: c_ushort,
    length: *mut c_long,
    data: *mut c_char,
) -> c_short {
    ffi_boundary!("cnc_upload4", {
        unsafe { upload3(FlibHndl, length, data) }
    })
}

unsafe fn upload3(handle: c_ushort, length: *mut c_long, data: *mut c_char) -> Result<()> {
    let h = handles::get(handle)?;
    let len_p = nonnull(length)?.cast::<i32>();
    let data = nonnull(data)?.cast::<u8>();
    let want = unsafe { len_p.read_unaligned() }.max(0) as usize;
    let out = unsafe { std::slice::from_raw_parts_mut(data, want) };
    let n = read(&h, handle, out)?;
    unsafe { put(len_p, n as i32) };
    Ok(())
}

/// Reads the next piece of uploaded text (at most 256 bytes) into
/// `upload->data`, waiting until some has arrived (FANUC polls every
/// millisecond; the handle's timeout still ends a stalled upload with
/// EW_SOCKET). `*length`: at least 256 in, size read out. EW_RESET (-2)
/// at the end.
///
/// # Safety
/// `upload` must point to a writable ODBUP, `length` to an `unsigned short`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_upload(
    FlibHndl: c_ushort,
    upload: *mut ODBUP,
    length: *mut c_ushort,
) -> c_short {
    ffi_boundary!("cnc_upload", {
        loop {
            match unsafe { cupload(FlibHndl, upload, length) } {
                Err(e) if e.ew() == EW_BUFFER => {
                    std::thread::sleep(std::time::Duration::from_millis(1))
                }
                r => return r,
            }
        }
    })
}

/// As cnc_upload, but returns EW_BUFFER instead of waiting when nothing
/// has arrived yet (conditional upload).
///
/// # Safety
/// As cnc_upload.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_cupload(
    FlibHndl: c_ushort,
    upload: *mut ODBUP,
    length: *mut c_ushort,
) -> c_short {
    ffi_boundary!("cnc_cupload", {
        unsafe { cupload(FlibHndl, upload, length) }
    })
}

unsafe fn cupload(handle: c_ushort, upload: *mut ODBUP, length: *mut c_ushort) -> Result<()> {
    let h = handles::get(handle)?;
    let len_p = nonnull(length)?;
    let up = nonnull(upload)?;
    let want = unsafe { len_p.read_unaligned() } as usize;
    if want <= 255 {
        return Err(Error::local(EW_LENGTH, "length must be more than 255"));
    }
    // FANUC writes up to `*length` (in whole 256s) past ODBUP.data's 256
    // bytes; we never write beyond the struct.
    let want = want.min(256);
    let data = unsafe { up.cast::<u8>().add(4) };
    let out = unsafe { std::slice::from_raw_parts_mut(data, want) };
    let n = old_style(read(&h, handle, out))?;
    unsafe { put(len_p, n as c_ushort) };
    Ok(())
}

/// Ends the upload: after the whole text nothing is sent; before, the
/// upload is aborted (frame 0x1804).
#[unsafe(no_mangle)]
pub extern "C" fn cnc_upend3(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_upend3", {
        let h = handles::get(FlibHndl)?;
        end(&h, FlibHndl)
    })
}

/// As cnc_upend3 (FANUC's cnc_upend4 is the same function).
#[unsafe(no_mangle)]
pub extern "C" fn cnc_upend4(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_upend4", {
        let h = handles::get(FlibHndl)?;
        end(&h, FlibHndl)
    })
}

/// Ends the upload started by cnc_upstart (as cnc_upend3).
#[unsafe(no_mangle)]
pub extern "C" fn cnc_upend(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_upend", {
        let h = handles::get(FlibHndl)?;
        old_style(end(&h, FlibHndl))
    })
}
