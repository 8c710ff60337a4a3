//! Axes and spindles: names, positions, speeds, loads, dynamic data, figures.
//!
//! Outputs are written field by field at their l32 offsets, only the bytes
//! FANUC's library writes (so a caller's buffer of `length` bytes is never
//! overrun), and only on success.

use super::{ffi_boundary, ffi_read, nonnull, put, put_at};
use crate::client::handles::{self, Handle};
use crate::error::{Error, Result};
use crate::ew::{EW_ATTRIB, EW_FUNC, EW_LENGTH, EW_NOOPT, EW_NUMBER};
use crate::proto::open::CncClass;
use crate::proto::position::{
    AxisData, AxisDataCall, AxisValue, Dynamic, DynamicData, Position16, Speed, SpeedValue,
    SpindleData, getfigure, low16, pos, position, spdl,
};
use crate::types::{
    LOADELM, MAX_AXIS, MAX_SPINDLE, ODBACT2, ODBAXDT, ODBAXIS, ODBDY, ODBDY_FAXIS, ODBDY_OAXIS,
    ODBDY2, ODBPOS, ODBSPEED, ODBSPLOAD, ODBSPN, ODBSVLOAD, POSELM, SPEEDELM,
};
use std::mem::{offset_of, size_of};
use std::os::raw::{c_char, c_short, c_ushort};

/// The spindle functions of a 30i-class CNC need the open response's
/// spindle word (SPEC.md §5.3): without it EW_NOOPT, without traffic.
fn need_spindle_info(h: &Handle) -> Result<()> {
    if h.pair.info.open.has_spindle_info() {
        Ok(())
    } else {
        Err(Error::local(
            EW_NOOPT,
            "the CNC reports no spindle information",
        ))
    }
}

/// A `short *` in/out count, read before any traffic.
fn read_count(p: *mut c_short) -> Result<c_short> {
    Ok(unsafe { nonnull(p)?.read_unaligned() })
}

// ---------------------------------------------------------------------------
// Dynamic data
// ---------------------------------------------------------------------------

/// Byte offsets of the fields the dynamic functions write.
struct DynLayout {
    axis: usize,
    /// alarm, prgnum, prgmnum: 4 bytes (ODBDY2) or 2 bytes (ODBDY).
    numbers: [usize; 3],
    wide: bool,
    seqnum: usize,
    actf: usize,
    acts: usize,
    pos: usize,
    /// Size with one axis and with all axes.
    one: usize,
    all: usize,
}

const DY2: DynLayout = DynLayout {
    axis: offset_of!(ODBDY2, axis),
    numbers: [
        offset_of!(ODBDY2, alarm),
        offset_of!(ODBDY2, prgnum),
        offset_of!(ODBDY2, prgmnum),
    ],
    wide: true,
    seqnum: offset_of!(ODBDY2, seqnum),
    actf: offset_of!(ODBDY2, actf),
    acts: offset_of!(ODBDY2, acts),
    pos: offset_of!(ODBDY2, pos),
    one: offset_of!(ODBDY2, pos) + size_of::<ODBDY_OAXIS>(),
    all: size_of::<ODBDY2>(),
};

const DY: DynLayout = DynLayout {
    axis: offset_of!(ODBDY, axis),
    numbers: [
        offset_of!(ODBDY, alarm),
        offset_of!(ODBDY, prgnum),
        offset_of!(ODBDY, prgmnum),
    ],
    wide: false,
    seqnum: offset_of!(ODBDY, seqnum),
    actf: offset_of!(ODBDY, actf),
    acts: offset_of!(ODBDY, acts),
    pos: offset_of!(ODBDY, pos),
    one: offset_of!(ODBDY, pos) + size_of::<ODBDY_OAXIS>(),
    all: size_of::<ODBDY>(),
};

/// Offsets of absolute, machine, relative, distance within `faxis`.
const FAXIS: [usize; 4] = [
    offset_of!(ODBDY_FAXIS, absolute),
    offset_of!(ODBDY_FAXIS, machine),
    offset_of!(ODBDY_FAXIS, relative),
    offset_of!(ODBDY_FAXIS, distance),
];

/// FANUC's order: axis 0 or below -1 is EW_ATTRIB and a `length` (read as
/// an unsigned short) below the one-axis or all-axes size EW_LENGTH, both
/// before any traffic; an axis beyond the CNC's goes to it. The fields are
/// written group by group as their subpackets are read: a CNC error in a
/// later subpacket is returned with the earlier groups written.
fn dynamic(l: &DynLayout, h: c_ushort, axis: c_short, length: c_short, out: *mut u8) -> Result<()> {
    {
        let h = handles::get(h)?;
        let base = nonnull(out)?;
        if axis == 0 || axis < -1 {
            return Err(Error::local(EW_ATTRIB, "axis must be -1 or 1.."));
        }
        let need = if axis == -1 { l.all } else { l.one };
        if (length as c_ushort as usize) < need {
            return Err(Error::length());
        }
        let d: DynamicData = h.call(&Dynamic { axis })?;
        unsafe {
            if let Some(alarm) = d.alarm {
                put_number(l, base, 0, alarm as i32);
            }
            if let Some((prgnum, prgmnum)) = d.prgnum {
                put_number(l, base, 1, prgnum);
                put_number(l, base, 2, prgmnum);
            }
            if let Some(v) = d.seqnum {
                put_at(base, l.seqnum, v);
            }
            if let Some(v) = d.actf {
                put_at(base, l.actf, v);
            }
            if let Some(v) = d.acts {
                put_at(base, l.acts, v);
            }
            if d.axis {
                put_at(base, l.axis, axis);
            }
            if let Some(pos) = &d.pos {
                if axis == -1 {
                    // Every record at its struct offset (FANUC packs them by
                    // the number received: the same bytes for MAX_AXIS records).
                    for (k, vals) in pos.iter().enumerate() {
                        for (i, v) in vals.iter().take(MAX_AXIS).enumerate() {
                            put_at(base, l.pos + FAXIS[k] + 4 * i, *v);
                        }
                    }
                } else {
                    for (k, vals) in pos.iter().enumerate() {
                        put_at(base, l.pos + 4 * k, vals[0]);
                    }
                }
            }
        }
        match d.error {
            Some(e) => {
                h.note(&e);
                Err(e)
            }
            None => Ok(()),
        }
    }
}

/// Alarm, program or main program number `k`: FANUC takes the low 16 bits,
/// sign-extended (4 bytes in ODBDY2, 2 in ODBDY).
///
/// # Safety
/// `base` must point to a writable struct of layout `l`.
unsafe fn put_number(l: &DynLayout, base: *mut u8, k: usize, v: i32) {
    unsafe {
        if l.wide {
            put_at(base, l.numbers[k], low16(v));
        } else {
            put_at(base, l.numbers[k], v as i16);
        }
    }
}

/// Reads the dynamic data in one exchange: alarm status, program numbers,
/// sequence number, actual feed and spindle speed, and the absolute,
/// machine, relative and distance-to-go positions of one axis (`oaxis`,
/// `length` ≥ 44) or of all axes (`axis` = -1, `faxis`, `length` ≥ 540).
/// For all axes every record is placed at its array index; slots the CNC
/// sent no record for are left as they were.
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rddynamic2(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBDY2,
) -> c_short {
    ffi_read!("cnc_rddynamic2", {
        dynamic(&DY2, FlibHndl, axis, length, buf.cast())
    })
}

/// cnc_rddynamic2 with alarm and program numbers as shorts (ODBDY;
/// `length` ≥ 40 for one axis, 536 for all).
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rddynamic(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBDY,
) -> c_short {
    ffi_read!("cnc_rddynamic", {
        dynamic(&DY, FlibHndl, axis, length, buf.cast())
    })
}

// ---------------------------------------------------------------------------
// Feed and speed
// ---------------------------------------------------------------------------

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

// ---------------------------------------------------------------------------
// Load meters and axis data
// ---------------------------------------------------------------------------

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

/// Position types of rdaxisdata class 1 / rdposition: 0 absolute,
/// 1 machine, 2 relative, 3 distance to go (0x26 codes 0..3).
const POS_TYPES: [i32; 4] = [pos::ABSOLUTE2, pos::MACHINE, pos::RELATIVE2, pos::DISTANCE2];

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

/// Reads positions with decimals, units and names: `type` 0 absolute,
/// 1 machine, 2 relative, 3 distance to go, -1 all four; `*data_num` in =
/// room (at least 1), out = axes written. As FANUC's library, a 16i-class
/// CNC gives its maximum axes per path (at most `*data_num`), a Series 15
/// the count of its sysinfo companion; on the 16i class the distance to go
/// outside MDI, MEM and remote mode reads 0 with `dec` -1.
///
/// # Safety
/// `data_num` must point to a writable short, `position` to `*data_num`
/// writable ODBPOS.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdposition(
    FlibHndl: c_ushort,
    r#type: c_short,
    data_num: *mut c_short,
    position: *mut ODBPOS,
) -> c_short {
    ffi_read!("cnc_rdposition", {
        let h = handles::get(FlibHndl)?;
        let limit = read_count(data_num)?;
        let out = nonnull(position)?;
        let class = h.ctx().class;
        // FANUC's order: the 30i class checks the type first, the 16i
        // class and the Series 15 `*data_num` first.
        let slots = || -> Result<Vec<usize>> {
            match r#type {
                -1 => Ok(vec![0, 1, 2, 3]),
                0..=3 => Ok(vec![r#type as usize]),
                _ => Err(Error::local(EW_ATTRIB, "type must be -1..3")),
            }
        };
        let room = || {
            if limit < 1 {
                Err(Error::length())
            } else {
                Ok(())
            }
        };
        let slots = if class.is_16i() {
            room()?;
            slots()?
        } else {
            let s = slots()?;
            room()?;
            s
        };
        let put_elem = |i: usize, slot: usize, e: POSELM| {
            let p = unsafe { out.add(i).cast::<POSELM>().add(slot) };
            unsafe { put(p, e) };
        };
        if class.is_16i() {
            let axes = h.call(&Position16 {
                s15: class == CncClass::Series16 { kind: 2 },
                limit,
            })?;
            for (i, axis) in axes.iter().enumerate() {
                for &slot in &slots {
                    let v = axis[slot];
                    let e = POSELM {
                        data: v.data,
                        dec: v.dec,
                        unit: v.unit,
                        disp: v.disp,
                        name: v.name[0] as c_char,
                        suff: v.name[1] as c_char,
                    };
                    put_elem(i, slot, e);
                }
            }
            unsafe { put(data_num, axes.len() as c_short) };
            return Ok(());
        }
        let codes = slots.iter().map(|s| POS_TYPES[*s]).collect();
        let r = h.call(&AxisDataCall {
            what: AxisData::Positions(codes),
            limit,
        })?;
        for (slot, row) in slots.iter().zip(&r.values) {
            for (i, v) in row.iter().enumerate() {
                let e = POSELM {
                    data: v.data,
                    dec: v.dec,
                    unit: v.unit,
                    // Bit 0 of FANUC's display flag (cnc_rdaxisdata's flag).
                    disp: v.flag & 1,
                    name: v.name[0] as c_char,
                    suff: v.name[1] as c_char,
                };
                put_elem(i, *slot, e);
            }
        }
        unsafe { put(data_num, r.count as c_short) };
        r.error.map_or(Ok(()), Err)
    })
}

// ---------------------------------------------------------------------------
// Positions (ODBAXIS)
// ---------------------------------------------------------------------------

/// FANUC's order: an axis above MAX_AXIS is EW_ATTRIB before any traffic
/// (0, -2 ... go to the CNC); after the exchange `length`, read as an
/// unsigned short, must hold the header and every whole record received
/// (else EW_LENGTH, nothing written). Then `type` = axis and the values;
/// an empty answer writes `type` alone.
fn axis_values(
    code: i32,
    h: c_ushort,
    axis: c_short,
    length: c_short,
    out: *mut ODBAXIS,
) -> Result<()> {
    {
        let h = handles::get(h)?;
        let base = nonnull(out)?.cast::<u8>();
        if axis > MAX_AXIS as c_short {
            return Err(Error::local(EW_ATTRIB, "axis beyond MAX_AXIS"));
        }
        let data = offset_of!(ODBAXIS, data);
        let recs = h.call(&position(code, axis))?;
        // More values than MAX_AXIS: the first MAX_AXIS count, as FANUC's
        // library reads them (the rest is ignored, not a length error).
        if (length as c_ushort as usize) < data + 4 * recs.len().min(MAX_AXIS) {
            return Err(Error::local(
                EW_LENGTH,
                "length too small for the values received",
            ));
        }
        unsafe {
            put_at(base, offset_of!(ODBAXIS, r#type), axis);
            // Never past the struct (FANUC writes every record received).
            for (i, r) in recs.iter().take(MAX_AXIS).enumerate() {
                put_at(base, data + 4 * i, r.value);
            }
        }
        Ok(())
    }
}

/// Reads the absolute position of one axis (`length` ≥ 8) or all axes (-1).
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_absolute(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBAXIS,
) -> c_short {
    ffi_read!("cnc_absolute", {
        axis_values(pos::ABSOLUTE, FlibHndl, axis, length, buf)
    })
}

/// Reads the absolute position (form 2: 0x26 code 0).
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_absolute2(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBAXIS,
) -> c_short {
    ffi_read!("cnc_absolute2", {
        axis_values(pos::ABSOLUTE2, FlibHndl, axis, length, buf)
    })
}

/// Reads the machine position.
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_machine(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBAXIS,
) -> c_short {
    ffi_read!("cnc_machine", {
        axis_values(pos::MACHINE, FlibHndl, axis, length, buf)
    })
}

/// Reads the relative position.
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_relative(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBAXIS,
) -> c_short {
    ffi_read!("cnc_relative", {
        axis_values(pos::RELATIVE, FlibHndl, axis, length, buf)
    })
}

/// Reads the relative position (form 2: 0x26 code 2).
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_relative2(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBAXIS,
) -> c_short {
    ffi_read!("cnc_relative2", {
        axis_values(pos::RELATIVE2, FlibHndl, axis, length, buf)
    })
}

/// Reads the distance to go.
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_distance(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBAXIS,
) -> c_short {
    ffi_read!("cnc_distance", {
        axis_values(pos::DISTANCE, FlibHndl, axis, length, buf)
    })
}

/// Reads the skip position of one axis or all axes (-1).
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_skip(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBAXIS,
) -> c_short {
    ffi_boundary!("cnc_skip", {
        axis_values(pos::SKIP, FlibHndl, axis, length, buf)
    })
}

/// Reads the servo delay (position deviation) of one axis or all axes (-1).
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_srvdelay(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBAXIS,
) -> c_short {
    ffi_boundary!("cnc_srvdelay", {
        axis_values(pos::SERVO_DELAY, FlibHndl, axis, length, buf)
    })
}

/// Reads the acceleration/deceleration delay of one axis or all axes (-1).
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_accdecdly(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBAXIS,
) -> c_short {
    ffi_boundary!("cnc_accdecdly", {
        axis_values(pos::ACCDEC_DELAY, FlibHndl, axis, length, buf)
    })
}

/// Reads the input (`dec_fig_in`) and output (`dec_fig_out`) decimal
/// figures of every axis; `*valid_fig` = the number of axes.
///
/// # Safety
/// `valid_fig` must point to a writable short, `dec_fig_in` and
/// `dec_fig_out` to 32 writable shorts each (MAX_AXIS).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_getfigure(
    FlibHndl: c_ushort,
    data_type: c_short,
    valid_fig: *mut c_short,
    dec_fig_in: *mut c_short,
    dec_fig_out: *mut c_short,
) -> c_short {
    ffi_read!("cnc_getfigure", {
        let h = handles::get(FlibHndl)?;
        let (v, fin, fout) = (
            nonnull(valid_fig)?,
            nonnull(dec_fig_in)?,
            nonnull(dec_fig_out)?,
        );
        let f = h.call(&getfigure(data_type))?;
        unsafe {
            put(v, f.count as c_short);
            for (i, a) in f.axes.iter().take(MAX_AXIS).enumerate() {
                put(fin.add(i), a.input);
                put(fout.add(i), a.output);
            }
        }
        Ok(())
    })
}
