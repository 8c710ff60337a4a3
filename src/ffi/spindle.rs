//! Spindles, feed and speed: cnc_acts2, cnc_rdspeed, and the serial-spindle
//! figures (cnc_rdspload, cnc_rdspmaxrpm, cnc_rdspgear).

use super::{ffi_boundary, ffi_read, nonnull, put, put_at};
use crate::client::handles::{self, Handle};
use crate::error::{Error, Result};
use crate::ew::{EW_ATTRIB, EW_NOOPT, EW_NUMBER};
use crate::proto::position::{Speed, SpeedValue, SpindleData, low16, spdl};
use crate::types::{MAX_SPINDLE, ODBACT2, ODBSPEED, ODBSPN, SPEEDELM};
use std::mem::offset_of;
use std::os::raw::{c_char, c_short, c_ushort};

/// The spindle functions of a 30i-class CNC need the open response's
/// spindle word (SPEC.md §5.3): without it EW_NOOPT, without traffic.
pub(super) fn need_spindle_info(h: &Handle) -> Result<()> {
    if h.pair.info.open.has_spindle_info() {
        Ok(())
    } else {
        Err(Error::local(
            EW_NOOPT,
            "the CNC reports no spindle information",
        ))
    }
}

/// Reads the actual speed of spindle `sp_no` (1..) or of all spindles (-1):
/// `datano` = sp_no, `data[i]` per spindle.
///
/// # Safety
/// `actualspindle` must point to a writable ODBACT2.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_acts2(
    FlibHndl: c_ushort,
    sp_no: c_short,
    actualspindle: *mut ODBACT2,
) -> c_short {
    ffi_read!("cnc_acts2", {
        let h = handles::get(FlibHndl)?;
        let base = nonnull(actualspindle)?.cast::<u8>();
        if sp_no > MAX_SPINDLE as c_short {
            return Err(Error::local(EW_NUMBER, "spindle number above 8"));
        }
        let (n, recs) = h.call(&SpindleData {
            code: spdl::SPEED_ACT,
            sp_no,
        })?;
        // 16i class: FANUC writes only the open body's maximum spindles.
        let room = if h.ctx().class.is_16i() {
            usize::from(n).min(MAX_SPINDLE)
        } else {
            MAX_SPINDLE
        };
        unsafe {
            put_at(base, offset_of!(ODBACT2, datano), sp_no);
            for (i, r) in recs.iter().take(room).enumerate() {
                // Every class: the low 16 bits, sign-extended (16i: a record
                // of 0x5a bytes gave 0x5a5a; 30i fuzz: 0x9b2a99c9 gave
                // 0xffff99c9).
                put_at(base, offset_of!(ODBACT2, data) + 4 * i, low16(r.value));
            }
        }
        Ok(())
    })
}

/// Reads the actual feed rate (`type` 0), spindle speed (1) or both (-1)
/// with decimals, units and names (ODBSPEED). Other types: EW_ATTRIB.
/// Units: feed 0 mm/min, 1 inch/min, 3 mm/rev, 4 inch/rev (on the 30i
/// class the CNC's feed unit word minus 3); spindle 2.
///
/// # Safety
/// `speed` must point to a writable ODBSPEED.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdspeed(
    FlibHndl: c_ushort,
    r#type: c_short,
    speed: *mut ODBSPEED,
) -> c_short {
    ffi_read!("cnc_rdspeed", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(speed)?;
        let (feed, spindle) = match r#type {
            0 => (true, false),
            1 => (false, true),
            -1 => (true, true),
            _ => return Err(Error::local(EW_ATTRIB, "type must be 0, 1 or -1")),
        };
        let r = h.call(&Speed { feed, spindle })?;
        let elem = |v: SpeedValue| SPEEDELM {
            data: v.data,
            dec: v.dec,
            unit: v.unit,
            disp: v.disp,
            name: v.name as c_char,
            suff: v.suff as c_char,
        };
        if let Some(f) = r.actf {
            unsafe { put(&raw mut (*out).actf, elem(f)) };
        }
        if let Some(s) = r.acts {
            unsafe { put(&raw mut (*out).acts, elem(s)) };
        }
        Ok(())
    })
}

/// A serial-spindle figure (0x40 `code`) of spindle `sp_no` (1..8, or -1
/// all) into ODBSPN: `datano` = sp_no, `data[i]` = low 16 bits of each
/// value (`type` not written).
fn serial_spindle(code: i32, h: c_ushort, sp_no: c_short, out: *mut ODBSPN) -> Result<()> {
    let h = handles::get(h)?;
    let base = nonnull(out)?.cast::<u8>();
    if sp_no > MAX_SPINDLE as c_short {
        return Err(Error::local(EW_NUMBER, "spindle number above 8"));
    }
    let (n, recs) = h.call(&SpindleData { code, sp_no })?;
    if sp_no > n as c_short {
        return Err(Error::local(EW_NUMBER, "the CNC has fewer spindles"));
    }
    let room = if h.ctx().class.is_16i() {
        usize::from(n).min(MAX_SPINDLE)
    } else {
        MAX_SPINDLE
    };
    unsafe {
        put_at(base, offset_of!(ODBSPN, datano), sp_no);
        for (i, r) in recs.iter().take(room).enumerate() {
            put_at(base, offset_of!(ODBSPN, data) + 2 * i, r.value as i16);
        }
    }
    Ok(())
}

/// Reads the load of serial spindle `sp_no` (1..8, or -1 all): `datano` =
/// sp_no, `data[i]` = low 16 bits of each value (`type` not written).
///
/// # Safety
/// `serialspindle` must point to a writable ODBSPN.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdspload(
    FlibHndl: c_ushort,
    sp_no: c_short,
    serialspindle: *mut ODBSPN,
) -> c_short {
    ffi_read!("cnc_rdspload", {
        serial_spindle(spdl::LOAD_SERIAL, FlibHndl, sp_no, serialspindle)
    })
}

/// Reads the maximum r.p.m. ratio of serial spindle `sp_no` (1..8, or -1
/// all), as cnc_rdspload reads the load.
///
/// # Safety
/// `serialspindle` must point to a writable ODBSPN.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdspmaxrpm(
    FlibHndl: c_ushort,
    sp_no: c_short,
    serialspindle: *mut ODBSPN,
) -> c_short {
    ffi_boundary!("cnc_rdspmaxrpm", {
        serial_spindle(spdl::MAX_RPM_RATIO, FlibHndl, sp_no, serialspindle)
    })
}

/// Reads the gear ratio of serial spindle `sp_no` (1..8, or -1 all), as
/// cnc_rdspload reads the load.
///
/// # Safety
/// `serialspindle` must point to a writable ODBSPN.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdspgear(
    FlibHndl: c_ushort,
    sp_no: c_short,
    serialspindle: *mut ODBSPN,
) -> c_short {
    ffi_boundary!("cnc_rdspgear", {
        serial_spindle(spdl::GEAR_RATIO, FlibHndl, sp_no, serialspindle)
    })
}
