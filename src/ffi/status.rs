//! System and status information.

use super::{ffi_boundary, ffi_read, nonnull, put, put_at, put_member};
use crate::client::handles::{self, Handle};
use crate::error::{Error, Result};
use crate::ew::EW_PATH;
use crate::proto::status::{StatInfo, StatWords, Status, Status2, StatusWords};
use crate::types::{MAX_CNCPATH, ODBST, ODBST2, ODBSYS, ODBSYSEX, ODBSYSEX_PATH, chars};
use std::mem::{offset_of, size_of};
use std::os::raw::{c_short, c_ushort};

/// Reads the CNC's system information (series, version, axes) of the
/// handle's current path, as the CNC reported it at connect time.
///
/// # Safety
/// `sysinfo` must point to a writable ODBSYS.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_sysinfo(FlibHndl: c_ushort, sysinfo: *mut ODBSYS) -> c_short {
    ffi_read!("cnc_sysinfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(sysinfo)?;
        let s = h
            .sysinfo()
            .ok_or(Error::local(EW_PATH, "path has no system information"))?;
        let v = ODBSYS {
            addinfo: s.addinfo as c_short,
            max_axis: s.max_axis as c_short,
            cnc_type: chars(s.cnc_type),
            mt_type: chars(s.mt_type),
            series: chars(s.series),
            version: chars(s.version),
            axes: chars(s.axes),
        };
        unsafe { put(out, v) };
        Ok(())
    })
}

/// Path entries cnc_sysinfo_ex writes, as FANUC's library [oracle].
const PATHS_WRITTEN: usize = 10;
const _: () = assert!(PATHS_WRITTEN <= MAX_CNCPATH);

/// Reads the CNC's maximum and controlled axes, spindles, paths and machine
/// groups, and each path's, as the CNC reported them when the connection
/// opened (no traffic, as FANUC's library). The first 10 path entries are
/// written, zeros past the CNC's paths, as FANUC's library writes them (its
/// Ethernet build has 10 paths; the struct holds MAX_CNCPATH = 15); the
/// `reserved` words are not.
///
/// # Safety
/// `sysinfoex` must point to a writable ODBSYSEX.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_sysinfo_ex(FlibHndl: c_ushort, sysinfoex: *mut ODBSYSEX) -> c_short {
    ffi_boundary!("cnc_sysinfo_ex", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(sysinfoex)?.cast::<u8>();
        let info = &h.pair.info;
        let (head, paths) = info.open.system_ex(info.axes15);
        let path_at = |k: usize| offset_of!(ODBSYSEX, path) + k * size_of::<ODBSYSEX_PATH>();
        // The head's words are consecutive shorts from max_axis on, as are
        // each path's from its first member on.
        const _: () =
            assert!(offset_of!(ODBSYSEX, addinfo) == offset_of!(ODBSYSEX, max_axis) + 9 * 2);
        unsafe {
            for (i, w) in head.iter().enumerate() {
                put_at(out, offset_of!(ODBSYSEX, max_axis) + 2 * i, *w);
            }
            for k in 0..PATHS_WRITTEN {
                let p = paths.get(k).copied().unwrap_or_default();
                for (i, w) in p.iter().enumerate() {
                    put_at(out, path_at(k) + 2 * i, *w);
                }
            }
        }
        Ok(())
    })
}

/// The common part of cnc_statinfo / cnc_statinfo2: hdck and tmmode, then
/// the status words the CNC sent, at most `N` (FANUC's library writes every
/// word sent, past the struct).
unsafe fn read_status<T: StatusWords, const N: usize>(h: &Handle, out: *mut u8) -> Result<()> {
    const { assert!(N <= StatWords::MAX) };
    let r = h.call(&StatInfo::<T>::new())?;
    // ODBST and ODBST2 begin alike: hdck, tmmode, then the status words.
    const _: () = assert!(
        offset_of!(ODBST, hdck) == offset_of!(ODBST2, hdck)
            && offset_of!(ODBST, tmmode) == offset_of!(ODBST2, tmmode)
            && offset_of!(ODBST, aut) == offset_of!(ODBST2, aut)
    );
    unsafe {
        put_member!(out, ODBST, hdck, r.hdck);
        put_member!(out, ODBST, tmmode, r.tmmode);
    }
    let words = r.words.inspect_err(|e| h.note(e))?;
    for (i, w) in words.iter().take(N).enumerate() {
        unsafe { put_at(out, offset_of!(ODBST, aut) + 2 * i, *w) };
    }
    Ok(())
}

/// Reads the CNC status (mode, run state, motion, alarm, emergency ...).
/// hdck and tmmode are written even when the status answers an error; a
/// short answer writes the words there are (as FANUC's library).
///
/// # Safety
/// `statinfo` must point to a writable ODBST.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_statinfo(FlibHndl: c_ushort, statinfo: *mut ODBST) -> c_short {
    ffi_read!("cnc_statinfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(statinfo)?.cast::<u8>();
        unsafe { read_status::<Status, 7>(&h, out) }
    })
}

/// Reads the CNC status, extended form (adds warning, o3dchk, ext_opt,
/// restart); as cnc_statinfo.
///
/// # Safety
/// `statinfo` must point to a writable ODBST2.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_statinfo2(FlibHndl: c_ushort, statinfo: *mut ODBST2) -> c_short {
    ffi_read!("cnc_statinfo2", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(statinfo)?.cast::<u8>();
        unsafe { read_status::<Status2, 11>(&h, out) }
    })
}
