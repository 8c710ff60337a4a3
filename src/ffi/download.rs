//! Program download and DNC operation over connection 1 (cnc_dwnstart ...
//! cnc_dncend2). Frames: src/proto/download.rs; the transfer state:
//! src/client/download.rs.
//!
//! Local checks learnt from FANUC's library \[oracle\]: the first forms
//! (cnc_dwnstart, cnc_download, cnc_dwnend, cnc_dncstart, cnc_dnc,
//! cnc_dncend) need the CNC's FOCAS option bit (EW_NOOPT, before anything
//! else); cnc_dncstart sends its start frame with the first cnc_dnc (a
//! cnc_dncend before it is EW_FUNC); a cnc_dwnstart3 with a negative data
//! type is EW_ATTRIB (cnc_dwnstart4 sends it); cnc_download takes 1..=256
//! bytes, cnc_dnc 0..=40959, cnc_download3/4 and
//! cnc_dnc2 a `*length` of 1 or more (else EW_LENGTH, nothing sent);
//! cnc_dncend2 ends with `rslt` -1, aborts with -32768 (the client's error
//! frame carries it) and refuses any other value with EW_DATA. A second
//! start while a transfer runs is EW_BUSY; a data or end call without a
//! start is EW_FUNC. Where FANUC's library crashes (a NULL `data` or
//! `length`, a cnc_dwnstart4 name of 254 characters or more) ours returns
//! EW_DATA.

use super::{cstr, ffi_boundary, nonnull};
use crate::client::handles::{self, Handle};
use crate::error::{Error, Result};
use crate::ew::{EW_ATTRIB, EW_DATA, EW_LENGTH, EW_NOOPT};
use crate::proto::download::{DNC, DOWNLOAD, Outgoing};
use crate::proto::upload::{NAME_LEN, StartReq, name4};
use std::os::raw::{c_char, c_long, c_short, c_ushort};

/// Runs `f` on the handle with its number and timeout; records a failure
/// for cnc_getdtailerr. `option`: the call needs the FOCAS option bit.
fn on(
    handle: c_ushort,
    option: bool,
    f: impl FnOnce(&Handle, u16, i32) -> Result<()>,
) -> Result<()> {
    let h = handles::get(handle)?;
    if option && h.pair.info.option & 1 == 0 {
        return Err(Error::local(EW_NOOPT, "the CNC has no FOCAS option"));
    }
    let timeout = h.state.lock().timeout;
    let r = f(&h, handle, timeout);
    if let Err(e) = &r {
        h.note(e);
    }
    r
}

/// A start: `checked` refuses a negative data type (cnc_dwnstart3; not
/// cnc_dwnstart4); `defer` leaves the start frame to the first data call.
fn start(
    handle: c_ushort,
    option: bool,
    how: Outgoing,
    dtype: c_short,
    name: Vec<u8>,
    checked: bool,
    defer: bool,
) -> Result<()> {
    on(handle, option, |h, n, t| {
        if checked && dtype < 0 {
            return Err(Error::local(EW_ATTRIB, "negative data type"));
        }
        if name.len() >= NAME_LEN {
            return Err(Error::local(EW_DATA, "program name too long"));
        }
        let path = h.state.lock().path;
        let req = StartReq {
            dtype,
            path,
            start: name,
            end: Vec::new(),
        };
        h.send_start(n, how, &req, defer, t)
    })
}

/// `len` bytes at `data`: checked against `max`, then sent.
///
/// # Safety
/// `data` must be NULL or point to `len` readable bytes.
unsafe fn data(
    handle: c_ushort,
    option: bool,
    how: Outgoing,
    data: *mut c_char,
    len: i64,
    range: std::ops::RangeInclusive<i64>,
) -> Result<()> {
    on(handle, option, |h, n, t| {
        if !range.contains(&len) {
            return Err(Error::local(EW_LENGTH, "data length out of range"));
        }
        let bytes = match len {
            0 => &[][..],
            _ => {
                let data = nonnull(data).map_err(|_| Error::local(EW_DATA, "data is NULL"))?;
                unsafe { std::slice::from_raw_parts(data.cast::<u8>(), len as usize) }
            }
        };
        h.send_data(n, how, bytes, t)
    })
}

/// `*length` bytes at `data` (cnc_download3/4, cnc_dnc2); `*length` is left as it is.
///
/// # Safety
/// `length` must be NULL or point to a `long` (4 bytes read); `data` to that many bytes.
unsafe fn data3(
    handle: c_ushort,
    how: Outgoing,
    length: *mut c_long,
    d: *mut c_char,
) -> Result<()> {
    let len_p = nonnull(length).map_err(|_| Error::local(EW_DATA, "length is NULL"))?;
    let len = unsafe { len_p.cast::<i32>().read_unaligned() };
    unsafe {
        data(
            handle,
            false,
            how,
            d,
            i64::from(len),
            1..=i64::from(i32::MAX),
        )
    }
}

fn end(handle: c_ushort, option: bool, how: Outgoing) -> Result<()> {
    on(handle, option, |h, n, t| h.send_end(n, how, t))
}

/// Starts downloading an NC program (data type 0). Needs the FOCAS option.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_dwnstart(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_dwnstart", {
        start(FlibHndl, true, DOWNLOAD, 0, Vec::new(), true, false)
    })
}

/// Sends `number` (1..256) bytes of NC program text.
///
/// # Safety
/// `data` must point to `number` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_download(
    FlibHndl: c_ushort,
    data: *mut c_char,
    number: c_short,
) -> c_short {
    ffi_boundary!("cnc_download", {
        unsafe { self::data(FlibHndl, true, DOWNLOAD, data, i64::from(number), 1..=256) }
    })
}

/// Ends the download started by cnc_dwnstart: the CNC stores the program
/// and answers, or returns its refusal (EW_DATA, EW_OVRFLOW, EW_PROT ...).
#[unsafe(no_mangle)]
pub extern "C" fn cnc_dwnend(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_dwnend", { end(FlibHndl, true, DOWNLOAD) })
}

/// Starts downloading data of `type` (0 = NC programs).
#[unsafe(no_mangle)]
pub extern "C" fn cnc_dwnstart3(FlibHndl: c_ushort, r#type: c_short) -> c_short {
    ffi_boundary!("cnc_dwnstart3", {
        start(FlibHndl, false, DOWNLOAD, r#type, Vec::new(), true, false)
    })
}

/// Sends `*length` bytes of NC program text (any size: FANUC's frames of
/// 1280 bytes). A CNC refusal that has arrived is returned instead.
///
/// # Safety
/// `length` must point to a `long` (4 bytes are read), `data` to `*length` bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_download3(
    FlibHndl: c_ushort,
    length: *mut c_long,
    data: *mut c_char,
) -> c_short {
    ffi_boundary!("cnc_download3", {
        unsafe { data3(FlibHndl, DOWNLOAD, length, data) }
    })
}

/// Ends the download (see cnc_dwnend).
#[unsafe(no_mangle)]
pub extern "C" fn cnc_dwnend3(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_dwnend3", { end(FlibHndl, false, DOWNLOAD) })
}

/// Starts downloading data of `type` into the folder or program `prgname`
/// (e.g. "//CNC_MEM/USER/PATH1/"; NULL sends no name).
///
/// # Safety
/// `prgname` must be NULL or a NUL-terminated string.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_dwnstart4(
    FlibHndl: c_ushort,
    r#type: c_short,
    prgname: *mut c_char,
) -> c_short {
    ffi_boundary!("cnc_dwnstart4", {
        let name = if prgname.is_null() {
            None
        } else {
            Some(unsafe { cstr(prgname) }?)
        };
        start(FlibHndl, false, DOWNLOAD, r#type, name4(name), false, false)
    })
}

/// As cnc_download3 (FANUC's cnc_download4 is the same function).
///
/// # Safety
/// As cnc_download3.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_download4(
    FlibHndl: c_ushort,
    length: *mut c_long,
    data: *mut c_char,
) -> c_short {
    ffi_boundary!("cnc_download4", {
        unsafe { data3(FlibHndl, DOWNLOAD, length, data) }
    })
}

/// As cnc_dwnend3.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_dwnend4(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_dwnend4", { end(FlibHndl, false, DOWNLOAD) })
}

/// Starts a DNC operation: the CNC runs the program while it arrives.
/// Needs the FOCAS option.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_dncstart(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_dncstart", {
        start(FlibHndl, true, DNC, 0, Vec::new(), true, true)
    })
}

/// Sends `number` (0..40959) bytes of the DNC program (the first call
/// also sends the start cnc_dncstart left to it).
///
/// # Safety
/// `data` must point to `number` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_dnc(
    FlibHndl: c_ushort,
    data: *mut c_char,
    number: c_ushort,
) -> c_short {
    ffi_boundary!("cnc_dnc", {
        unsafe { self::data(FlibHndl, true, DNC, data, i64::from(number), 0..=40959) }
    })
}

/// Ends the DNC operation.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_dncend(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_dncend", { end(FlibHndl, true, DNC) })
}

/// Starts a DNC operation (FANUC's library sends no name: `fname` is not used).
///
/// # Safety
/// `fname` must be NULL or a NUL-terminated string (it is not read).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_dncstart2(FlibHndl: c_ushort, fname: *mut c_char) -> c_short {
    ffi_boundary!("cnc_dncstart2", {
        let _ = fname;
        start(FlibHndl, false, DNC, 0, Vec::new(), true, false)
    })
}

/// Sends `*length` bytes of the DNC program.
///
/// # Safety
/// `length` must point to a `long` (4 bytes are read), `data` to `*length` bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_dnc2(
    FlibHndl: c_ushort,
    length: *mut c_long,
    data: *mut c_char,
) -> c_short {
    ffi_boundary!("cnc_dnc2", {
        unsafe { data3(FlibHndl, DNC, length, data) }
    })
}

/// Ends the DNC operation: `rslt` -1 ends it normally, -32768 aborts it
/// (the CNC is sent that code); other values are EW_DATA.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_dncend2(FlibHndl: c_ushort, rslt: c_short) -> c_short {
    ffi_boundary!("cnc_dncend2", {
        match rslt {
            -1 => end(FlibHndl, false, DNC),
            i16::MIN => on(FlibHndl, false, |h, n, t| h.send_abort(n, DNC, rslt, t)),
            _ => Err(Error::local(EW_DATA, "rslt must be -1 or -32768")),
        }
    })
}
