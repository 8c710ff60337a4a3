//! Positions: cnc_rdposition, cnc_getfigure (cnc_absolute & co. are
//! described as data: src/spec/table/position.rs).
//! The rest of the axes and spindles area: dynamic data (dynamic.rs),
//! spindles, feed and speed (spindle.rs), load meters and axis data
//! (axisdata.rs).
//!
//! Outputs are written field by field at their l32 offsets, only the bytes
//! FANUC's library writes (so a caller's buffer of `length` bytes is never
//! overrun), and only on success; so in the other three files.

use super::{ffi_read, nonnull, put};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::EW_ATTRIB;
use crate::proto::open::CncClass;
use crate::proto::position::{AxisData, AxisDataCall, Position16, getfigure, pos};
use crate::types::{MAX_AXIS, ODBPOS, POSELM};
use std::os::raw::{c_char, c_short, c_ushort};

/// A `short *` in/out count, read before any traffic.
pub(super) fn read_count(p: *mut c_short) -> Result<c_short> {
    Ok(unsafe { nonnull(p)?.read_unaligned() })
}

/// Position types of rdaxisdata class 1 / rdposition: 0 absolute,
/// 1 machine, 2 relative, 3 distance to go (0x26 codes 0..3).
pub(super) const POS_TYPES: [i32; 4] =
    [pos::ABSOLUTE2, pos::MACHINE, pos::RELATIVE2, pos::DISTANCE2];

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
