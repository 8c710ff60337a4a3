//! Load meters and axis data: cnc_rdsvmeter, cnc_rdspmeter and
//! cnc_rdaxisdata, over the meter / axis-data frame.

use super::position::{POS_TYPES, read_count};
use super::spindle::need_spindle_info;
use super::{ffi_read, nonnull, put, put_at};
use crate::client::handles;
use crate::error::Error;
use crate::ew::{EW_ATTRIB, EW_FUNC, EW_NUMBER};
use crate::proto::position::{AxisData, AxisDataCall, AxisValue, spdl};
use crate::types::{LOADELM, ODBAXDT, ODBSPLOAD, ODBSVLOAD};
use std::mem::offset_of;
use std::os::raw::{c_short, c_ushort};

/// The 11 bytes of a LOADELM FANUC writes (`reserve` untouched).
///
/// # Safety
/// `p` must point to a writable LOADELM.
unsafe fn put_load(p: *mut LOADELM, v: &AxisValue, unit: i16) {
    let b = p.cast::<u8>();
    unsafe {
        put_at(b, offset_of!(LOADELM, data), v.data);
        put_at(b, offset_of!(LOADELM, dec), v.dec);
        put_at(b, offset_of!(LOADELM, unit), unit);
        put_at(b, offset_of!(LOADELM, name), v.name[0]);
        put_at(b, offset_of!(LOADELM, suff1), v.name[1]);
        put_at(b, offset_of!(LOADELM, suff2), v.name[2]);
    }
}

/// Reads the servo load meters: `*data_num` in = room, out = axes written;
/// each load is written as its magnitude (a negative value from the CNC
/// reads positive), as FANUC's library writes it.
///
/// # Safety
/// `data_num` must point to a writable short, `loadmeter` to `*data_num`
/// writable ODBSVLOAD.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdsvmeter(
    FlibHndl: c_ushort,
    data_num: *mut c_short,
    loadmeter: *mut ODBSVLOAD,
) -> c_short {
    ffi_read!("cnc_rdsvmeter", {
        let h = handles::get(FlibHndl)?;
        let limit = read_count(data_num)?;
        let out = nonnull(loadmeter)?;
        if limit <= 0 {
            return Err(Error::length());
        }
        let r = h.call(&AxisDataCall {
            what: AxisData::Servo(vec![1]),
            limit,
        })?;
        for (i, v) in r.values[0].iter().enumerate() {
            // FANUC's library writes the load's magnitude: -1 gives 1,
            // i32::MIN stays itself.
            let v = AxisValue {
                data: v.data.wrapping_abs(),
                ..*v
            };
            unsafe { put_load(&raw mut (*out.add(i)).svload, &v, 0) };
        }
        unsafe { put(data_num, r.count as c_short) };
        r.error.map_or(Ok(()), Err)
    })
}

/// Reads the spindle load meters (`type` 0), motor speeds (1) or both (-1):
/// `*data_num` in = room, out = spindles written.
///
/// # Safety
/// `data_num` must point to a writable short, `loadmeter` to `*data_num`
/// writable ODBSPLOAD.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdspmeter(
    FlibHndl: c_ushort,
    r#type: c_short,
    data_num: *mut c_short,
    loadmeter: *mut ODBSPLOAD,
) -> c_short {
    ffi_read!("cnc_rdspmeter", {
        let h = handles::get(FlibHndl)?;
        let limit = read_count(data_num)?;
        let out = nonnull(loadmeter)?;
        if limit <= 0 {
            return Err(Error::length());
        }
        let (load, speed) = match r#type {
            0 => (true, false),
            1 => (false, true),
            -1 => (true, true),
            _ => return Err(Error::local(EW_ATTRIB, "type must be 0, 1 or -1")),
        };
        need_spindle_info(&h)?;
        // 16i class: FANUC always asks load and speed (recorded with our fake CNC).
        let both = h.ctx().class.is_16i();
        let mut codes = vec![];
        if load || both {
            codes.push(spdl::LOAD_METER);
        }
        if speed || both {
            codes.push(spdl::SPEED_METER);
        }
        let r = h.call(&AxisDataCall {
            what: AxisData::Spindle(codes),
            limit,
        })?;
        let mut rows = r.values.iter();
        if load || both {
            let row = rows.next();
            for (i, v) in row.into_iter().flatten().enumerate().filter(|_| load) {
                unsafe { put_load(&raw mut (*out.add(i)).spload, v, 0) };
            }
        }
        if speed {
            for (i, v) in rows.next().into_iter().flatten().enumerate() {
                unsafe { put_load(&raw mut (*out.add(i)).spspeed, v, 1) };
            }
        }
        unsafe { put(data_num, r.count as c_short) };
        r.error.map_or(Ok(()), Err)
    })
}

/// rdaxisdata class 1 types 4..17 → 0x26 codes (FANUC's library's table;
/// what the codes mean is not recorded).
const POS_TYPES_EXT: [i32; 14] = [11, 12, 13, 14, 15, 16, 17, 18, 8, 9, 10, 37, 38, 39];

/// rdaxisdata class 2 types 0..2 → (0x56 code, ODBAXDT unit), FANUC's
/// library's table: types 0 and 1 both ask 0x56[1] (servo load, unit 8 = %),
/// type 2 asks 0x56[3] (servo current, unit 9 = A).
const SERVO_TYPES: [(i32, i16); 3] = [(1, 8), (1, 8), (3, 9)];

/// rdaxisdata classes 3/4 types 0..4 → (0x40 code, ODBAXDT unit), FANUC's
/// library's table (unit 8 = %, 5 = min^-1).
const SPINDLE_TYPES: [(i32, i16); 5] = [(4, 8), (5, 5), (3, 5), (7, 5), (6, 8)];

/// Reads several values of all axes (`cls` 1 positions etc., types 0..17),
/// servo data (`cls` 2, types 0/1 load, 2 current), spindles (`cls` 3 all spindles / `cls` 4
/// spindle 1, types 0..4: load, speed, ...) or speeds (`cls` 5, types 0
/// feed, 1 spindle speed, 2 a third value; one item): `num` (1..4) types from
/// `type`; `*len` in = axes room per type, out = axes written. Record (type
/// k, axis i) is `axdata[k * len_in + i]`.
///
/// # Safety
/// `type` must point to `num` shorts, `len` to a writable short, `axdata`
/// to `num * *len` writable ODBAXDT.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdaxisdata(
    FlibHndl: c_ushort,
    cls: c_short,
    r#type: *mut c_short,
    num: c_short,
    len: *mut c_short,
    axdata: *mut ODBAXDT,
) -> c_short {
    ffi_read!("cnc_rdaxisdata", {
        let h = handles::get(FlibHndl)?;
        if h.ctx().class.is_16i() {
            // FANUC's library: EW_FUNC without traffic for any arguments.
            return Err(Error::local(EW_FUNC, "not available on a 16i-class CNC"));
        }
        let types_p = nonnull(r#type)?;
        let room = read_count(len)?;
        let out = nonnull(axdata)?;
        // FANUC's order: *len, then num, then the class, then the types.
        if room < 1 {
            return Err(Error::length());
        }
        if !(1..=4).contains(&num) {
            return Err(Error::local(EW_ATTRIB, "num must be 1..4"));
        }
        if !(1..=5).contains(&cls) {
            return Err(Error::local(EW_NUMBER, "class must be 1..5"));
        }
        let types: Vec<c_short> = (0..num as usize)
            .map(|i| unsafe { types_p.add(i).read_unaligned() })
            .collect();
        let bad = |ok: &dyn Fn(c_short) -> bool| types.iter().any(|t| !ok(*t));
        let (what, units): (AxisData, Vec<Option<i16>>) = match cls {
            1 => {
                if bad(&|t| (0..18).contains(&t)) {
                    return Err(Error::local(EW_ATTRIB, "class 1 types are 0..17"));
                }
                let codes = types
                    .iter()
                    .map(|&t| match t {
                        0..4 => POS_TYPES[t as usize],
                        _ => POS_TYPES_EXT[t as usize - 4],
                    })
                    .collect();
                (AxisData::Positions(codes), vec![None; types.len()])
            }
            2 => {
                if bad(&|t| (0..3).contains(&t)) {
                    return Err(Error::local(EW_ATTRIB, "class 2 types are 0..2"));
                }
                let codes = types.iter().map(|t| SERVO_TYPES[*t as usize].0).collect();
                let units = types
                    .iter()
                    .map(|t| Some(SERVO_TYPES[*t as usize].1))
                    .collect();
                (AxisData::Servo(codes), units)
            }
            3 | 4 => {
                if bad(&|t| (0..5).contains(&t)) {
                    return Err(Error::local(EW_ATTRIB, "class 3/4 types are 0..4"));
                }
                need_spindle_info(&h)?;
                let codes = types.iter().map(|t| SPINDLE_TYPES[*t as usize].0).collect();
                let units = types
                    .iter()
                    .map(|t| Some(SPINDLE_TYPES[*t as usize].1))
                    .collect();
                if cls == 3 {
                    (AxisData::Spindle(codes), units)
                } else {
                    (AxisData::FirstSpindle(codes), units)
                }
            }
            _ => {
                if bad(&|t| (0..3).contains(&t)) {
                    return Err(Error::local(EW_ATTRIB, "class 5 types are 0..2"));
                }
                let cmds = types
                    .iter()
                    .map(|t| {
                        [
                            crate::proto::position::ACTF,
                            crate::proto::position::ACTS,
                            crate::proto::position::SPEED_A5,
                        ][*t as usize]
                    })
                    .collect();
                (AxisData::Speed(cmds), vec![None; types.len()])
            }
        };
        let r = h.call(&AxisDataCall { what, limit: room })?;
        for (k, (row, unit)) in r.values.iter().zip(&units).enumerate() {
            for (i, v) in row.iter().enumerate() {
                let b = unsafe { out.add(k * room as usize + i) }.cast::<u8>();
                let (unit, flag) = match unit {
                    Some(u) => (*u, 0),
                    None => (v.unit, v.flag),
                };
                unsafe {
                    if v.short_name {
                        put_at(b, offset_of!(ODBAXDT, name), [v.name[0], v.name[1]]);
                    } else {
                        put_at(b, offset_of!(ODBAXDT, name), v.name);
                    }
                    put_at(b, offset_of!(ODBAXDT, data), v.data);
                    put_at(b, offset_of!(ODBAXDT, dec), v.dec);
                    put_at(b, offset_of!(ODBAXDT, unit), unit);
                    put_at(b, offset_of!(ODBAXDT, flag), flag);
                }
            }
        }
        unsafe { put(len, r.count as c_short) };
        r.error.map_or(Ok(()), Err)
    })
}
