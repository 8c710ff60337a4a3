//! System and status information.

use super::{ffi_boundary, nonnull, put};
use crate::client::handles;
use crate::error::Error;
use crate::ew::EW_PATH;
use crate::proto::status::{StatInfo, Status, Status2, rdcncid};
use crate::types::{ODBST, ODBST2, ODBSYS, chars};
use std::os::raw::{c_short, c_ulong, c_ushort};

/// Reads the CNC's system information (series, version, axes) of the
/// handle's current path, as the CNC reported it at connect time.
///
/// # Safety
/// `sysinfo` must point to a writable ODBSYS.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_sysinfo(FlibHndl: c_ushort, sysinfo: *mut ODBSYS) -> c_short {
    ffi_boundary!("cnc_sysinfo", {
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

/// Reads the CNC status (mode, run state, motion, alarm, emergency ...).
///
/// # Safety
/// `statinfo` must point to a writable ODBST.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_statinfo(FlibHndl: c_ushort, statinfo: *mut ODBST) -> c_short {
    ffi_boundary!("cnc_statinfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(statinfo)?;
        let (hdck, tmmode, s) = h.call(&StatInfo::<Status>::new())?;
        let v = ODBST {
            hdck,
            tmmode,
            aut: s.aut,
            run: s.run,
            motion: s.motion,
            mstb: s.mstb,
            emergency: s.emergency,
            alarm: s.alarm,
            edit: s.edit,
        };
        unsafe { put(out, v) };
        Ok(())
    })
}

/// Reads the CNC status, extended form (adds warning, o3dchk, ext_opt, restart).
///
/// # Safety
/// `statinfo` must point to a writable ODBST2.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_statinfo2(FlibHndl: c_ushort, statinfo: *mut ODBST2) -> c_short {
    ffi_boundary!("cnc_statinfo2", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(statinfo)?;
        let (hdck, tmmode, s) = h.call(&StatInfo::<Status2>::new())?;
        let v = ODBST2 {
            hdck,
            tmmode,
            aut: s.aut,
            run: s.run,
            motion: s.motion,
            mstb: s.mstb,
            emergency: s.emergency,
            alarm: s.alarm,
            edit: s.edit,
            warning: s.warning,
            o3dchk: s.o3dchk,
            ext_opt: s.ext_opt,
            restart: s.restart,
        };
        unsafe { put(out, v) };
        Ok(())
    })
}

/// Reads the CNC's identification number: four 32-bit words.
///
/// The pointer keeps FANUC's `unsigned long *` spelling, but, exactly as
/// FANUC's x86-64 library does, four 4-byte words are written (16 bytes):
/// pass a `uint32_t[4]` (or an `unsigned long[4]` read as 32-bit words).
/// Only the words the CNC sent are written.
///
/// # Safety
/// `cncid` must point to 16 writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdcncid(FlibHndl: c_ushort, cncid: *mut c_ulong) -> c_short {
    ffi_boundary!("cnc_rdcncid", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(cncid)?.cast::<u32>();
        let id = h.call(&rdcncid())?;
        for (i, w) in id.0.iter().enumerate() {
            unsafe { put(out.add(i), *w) };
        }
        Ok(())
    })
}
