//! Dynamic data: cnc_rddynamic2, cnc_rddynamic and cnc_rddynamico8, one
//! frame written into ODBDY2 / ODBDY / ODBDYO8.

use super::{ffi_read, nonnull, put_at};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::EW_ATTRIB;
use crate::proto::position::{Dynamic, DynamicData, low16};
use crate::types::{MAX_AXIS, ODBDY, ODBDY_FAXIS, ODBDY_OAXIS, ODBDY2, ODBDYO8};
use std::mem::{offset_of, size_of};
use std::os::raw::{c_short, c_ushort};

/// How alarm, prgnum and prgmnum are written.
#[derive(Clone, Copy)]
enum Num {
    /// The low 16 bits, sign-extended into a 4-byte `long` (ODBDY2;
    /// ODBDYO8's program numbers).
    Low16,
    /// The low 16 bits into a `short` (ODBDY; ODBDYO8's alarm).
    Short,
}

/// Byte offsets of the fields the dynamic functions write.
struct DynLayout {
    axis: usize,
    /// alarm, prgnum, prgmnum, each written as `widths` says.
    numbers: [usize; 3],
    widths: [Num; 3],
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
    widths: [Num::Low16; 3],
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
    widths: [Num::Short; 3],
    seqnum: offset_of!(ODBDY, seqnum),
    actf: offset_of!(ODBDY, actf),
    acts: offset_of!(ODBDY, acts),
    pos: offset_of!(ODBDY, pos),
    one: offset_of!(ODBDY, pos) + size_of::<ODBDY_OAXIS>(),
    all: size_of::<ODBDY>(),
};

const DYO8: DynLayout = DynLayout {
    axis: offset_of!(ODBDYO8, axis),
    numbers: [
        offset_of!(ODBDYO8, alarm),
        offset_of!(ODBDYO8, prgnum),
        offset_of!(ODBDYO8, prgmnum),
    ],
    // FANUC's library keeps the low 16 bits of the program numbers here
    // too [code: inter_rddynamic<odbdyo8>, movswl/cwtl; fuzz
    // rddynamico8 `s1L`, `s1Tw`]: no 8 digits despite the name.
    widths: [Num::Short, Num::Low16, Num::Low16],
    seqnum: offset_of!(ODBDYO8, seqnum),
    actf: offset_of!(ODBDYO8, actf),
    acts: offset_of!(ODBDYO8, acts),
    pos: offset_of!(ODBDYO8, pos),
    one: offset_of!(ODBDYO8, pos) + size_of::<ODBDY_OAXIS>(),
    all: size_of::<ODBDYO8>(),
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
                    // Each kind's first record at its place, an empty kind's
                    // place untouched (FANUC packs them here too: an empty
                    // machine answer puts relative in machine's place; README).
                    for (k, vals) in pos.iter().enumerate() {
                        if let Some(v) = vals.first() {
                            put_at(base, l.pos + 4 * k, *v);
                        }
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
/// sign-extended (4 bytes in ODBDY2, 2 in ODBDY; ODBDYO8 the alarm 2 and
/// the program numbers 4).
///
/// # Safety
/// `base` must point to a writable struct of layout `l`.
unsafe fn put_number(l: &DynLayout, base: *mut u8, k: usize, v: i32) {
    unsafe {
        match l.widths[k] {
            Num::Low16 => put_at(base, l.numbers[k], low16(v)),
            Num::Short => put_at(base, l.numbers[k], v as i16),
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

/// cnc_rddynamic2 with the alarm status as a short (ODBDYO8; `length` ≥ 44
/// for one axis, 540 for all): the same nine subpackets. The program numbers
/// are their low 16 bits sign-extended, as FANUC's library writes them
/// (despite the name, no 8 digits).
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rddynamico8(
    FlibHndl: c_ushort,
    axis: c_short,
    length: c_short,
    buf: *mut ODBDYO8,
) -> c_short {
    ffi_read!("cnc_rddynamico8", {
        dynamic(&DYO8, FlibHndl, axis, length, buf.cast())
    })
}
