//! Process, handle and connection functions.

use super::{cstr, ffi_boundary, ffi_read, nonnull, put};
use crate::client::{handles, log, pair};
use crate::error::Error;
use crate::ew::*;
use crate::types::ODBERR;
use std::os::raw::{c_char, c_long, c_short, c_ulong, c_ushort};
use std::os::unix::ffi::OsStrExt;

/// Starts the library's log. `level` 0 = off, 1 = errors, 2 = every call,
/// 3 = every byte sent and received; `logfile` is created (truncated).
/// Levels outside 0..=3 return EW_NUMBER (3) as FANUC's library does.
/// Unlike FANUC's library, calling this is optional and a missing log file
/// never aborts the process.
///
/// # Safety
/// `logfile` must be NULL or a NUL-terminated path.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_startupprocess(level: c_long, logfile: *const c_char) -> c_short {
    ffi_boundary!("cnc_startupprocess", {
        if !(0..=3).contains(&level) {
            return Err(Error::local(EW_NUMBER, "log level must be 0 to 3"));
        }
        if level == 0 {
            log::stop();
            return Ok(());
        }
        let path = if logfile.is_null() {
            None
        } else {
            Some(unsafe { cstr(logfile)? })
        };
        // A log file that cannot be created leaves logging off; it is not an error
        // worth failing a machine connection for.
        let path = path.map(|b| std::path::Path::new(std::ffi::OsStr::from_bytes(b)));
        if log::start(level as u8, path).is_err() {
            log::stop();
        }
        Ok(())
    })
}

/// Frees every handle, closes every connection and the log.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_exitprocess() -> c_short {
    ffi_boundary!("cnc_exitprocess", {
        for h in handles::drain() {
            let timeout = h.state.lock().timeout;
            let _ = h.pair.release(timeout);
        }
        pair::forget_all();
        log::stop();
        Ok(())
    })
}

fn allocate(
    ip: *const c_char,
    port: c_ushort,
    timeout: c_long,
    id: u32,
    h: *mut c_ushort,
) -> crate::error::Result<()> {
    let out = nonnull(h)?;
    // A host name that is not UTF-8 resolves to nothing, as FANUC's.
    let host = String::from_utf8_lossy(unsafe { cstr(ip)? });
    let timeout = timeout.clamp(i32::MIN as c_long, i32::MAX as c_long) as i32;
    let pair = pair::acquire(host.trim(), port, timeout, id)?;
    let handle = match handles::insert(pair.clone(), timeout) {
        Ok(x) => x,
        Err(e) => {
            let _ = pair.release(timeout);
            return Err(e);
        }
    };
    unsafe { put(out, handle) };
    Ok(())
}

/// Connects to the CNC at `ip:port` (or shares the existing connection to
/// it) and returns a handle in `*FlibHndl`. `timeout` is in seconds; 0 or
/// less waits forever.
///
/// # Safety
/// `ip` must be a NUL-terminated string, `FlibHndl` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_allclibhndl3(
    ip: *const c_char,
    port: c_ushort,
    timeout: c_long,
    FlibHndl: *mut c_ushort,
) -> c_short {
    ffi_boundary!("cnc_allclibhndl3", {
        allocate(ip, port, timeout, 0, FlibHndl)
    })
}

/// The same as cnc_allclibhndl3 (an alias some programs use).
///
/// # Safety
/// `ip` must be a NUL-terminated string, `FlibHndl` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_allclibhdl3(
    ip: *const c_char,
    port: c_ushort,
    timeout: c_long,
    FlibHndl: *mut c_ushort,
) -> c_short {
    unsafe { cnc_allclibhndl3(ip, port, timeout, FlibHndl) }
}

/// As cnc_allclibhndl3; a non-zero `id` is presented to the CNC (frame 0xf501)
/// before the open on each connection.
///
/// # Safety
/// `ip` must be a NUL-terminated string, `FlibHndl` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_allclibhndl4(
    ip: *const c_char,
    port: c_ushort,
    timeout: c_long,
    id: c_ulong,
    FlibHndl: *mut c_ushort,
) -> c_short {
    ffi_boundary!("cnc_allclibhndl4", {
        allocate(ip, port, timeout, id as u32, FlibHndl)
    })
}

/// Frees a handle. The last handle to a CNC closes its connections.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_freelibhndl(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_freelibhndl", {
        let h = handles::remove(FlibHndl)?;
        let timeout = h.state.lock().timeout;
        h.pair.release(timeout)
    })
}

/// Drops the connections of the handle's CNC, as FANUC's library does on
/// Ethernet: no close frames, EW_OK, and every later call of every handle
/// to that CNC answers EW_SOCKET (-16) until they are freed; a handle with
/// fwlib_set_reconnect on reconnects at its next call.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_resetconnect(FlibHndl: c_ushort) -> c_short {
    ffi_boundary!("cnc_resetconnect", {
        handles::get(FlibHndl)?.pair.kill();
        Ok(())
    })
}

/// Sets the handle's timeout in seconds (0 or less: wait forever).
#[unsafe(no_mangle)]
pub extern "C" fn cnc_settimeout(FlibHndl: c_ushort, timeout: c_long) -> c_short {
    ffi_boundary!("cnc_settimeout", {
        let h = handles::get(FlibHndl)?;
        h.state.lock().timeout = timeout.clamp(i32::MIN as c_long, i32::MAX as c_long) as i32;
        Ok(())
    })
}

/// Reads the current path of this handle and the CNC's number of paths.
///
/// # Safety
/// `path_no` and `maxpath_no` must point to writable shorts.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_getpath(
    FlibHndl: c_ushort,
    path_no: *mut c_short,
    maxpath_no: *mut c_short,
) -> c_short {
    ffi_read!("cnc_getpath", {
        let h = handles::get(FlibHndl)?;
        let (p, m) = (nonnull(path_no)?, nonnull(maxpath_no)?);
        let path = h.state.lock().path;
        unsafe {
            put(p, path as c_short);
            put(m, h.pair.info.open.maxpath_no() as c_short);
        }
        Ok(())
    })
}

/// Selects the path later calls on this handle address (0 or -1: path 1).
/// Other handles, even to the same CNC, are not affected.
#[unsafe(no_mangle)]
pub extern "C" fn cnc_setpath(FlibHndl: c_ushort, path_no: c_short) -> c_short {
    ffi_boundary!("cnc_setpath", {
        let h = handles::get(FlibHndl)?;
        let count = h.pair.info.open.path_count() as c_short;
        let path = match path_no {
            0 | -1 => 1,
            p if p >= 1 && p <= count => p,
            _ => return Err(Error::local(EW_PATH, "no such path")),
        };
        h.state.lock().path = path as u16;
        Ok(())
    })
}

/// Reads the detail words of the last error on this handle.
///
/// # Safety
/// `err` must point to a writable ODBERR.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_getdtailerr(FlibHndl: c_ushort, err: *mut ODBERR) -> c_short {
    ffi_read!("cnc_getdtailerr", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(err)?;
        let (err_no, err_dtno) = h.state.lock().detail;
        unsafe { put(out, ODBERR { err_no, err_dtno }) };
        Ok(())
    })
}
