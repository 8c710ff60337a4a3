//! Axes and spindles: names, positions, speeds, loads, dynamic data, figures.

use super::{LONG, MAX_AXIS};
use std::os::raw::{c_char, c_short};

/// cnc_rdaxisname: one axis name.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAXISNAME {
    pub name: c_char,
    pub suff: c_char,
}

/// cnc_rdspdlname: one spindle name.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSPDLNAME {
    pub name: c_char,
    pub suff1: c_char,
    pub suff2: c_char,
    pub suff3: c_char,
}

/// The all-axes form of the position union of ODBDY / ODBDY2.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDY_FAXIS {
    pub absolute: [LONG; MAX_AXIS],
    pub machine: [LONG; MAX_AXIS],
    pub relative: [LONG; MAX_AXIS],
    pub distance: [LONG; MAX_AXIS],
}

/// The one-axis form of the position union of ODBDY / ODBDY2.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBDY_OAXIS {
    pub absolute: LONG,
    pub machine: LONG,
    pub relative: LONG,
    pub distance: LONG,
}

/// The position union of ODBDY / ODBDY2 (`pos`): `faxis` for all axes
/// (axis -1), `oaxis` for one axis.
#[repr(C)]
#[derive(Clone, Copy)]
pub union ODBDY_POS {
    pub faxis: ODBDY_FAXIS,
    pub oaxis: ODBDY_OAXIS,
}

impl Default for ODBDY_POS {
    fn default() -> Self {
        ODBDY_POS {
            faxis: ODBDY_FAXIS::default(),
        }
    }
}

impl std::fmt::Debug for ODBDY_POS {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // Every bit pattern is a valid ODBDY_FAXIS (plain integers), and
        // faxis covers the whole union.
        f.debug_struct("ODBDY_POS")
            .field("faxis", unsafe { &self.faxis })
            .finish()
    }
}

/// cnc_rddynamic2: dynamic data (alarm, program numbers, feed, speed, positions).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ODBDY2 {
    pub dummy: c_short,
    pub axis: c_short,
    pub alarm: LONG,
    pub prgnum: LONG,
    pub prgmnum: LONG,
    pub seqnum: LONG,
    pub actf: LONG,
    pub acts: LONG,
    pub pos: ODBDY_POS,
}

/// cnc_rddynamic: dynamic data, program numbers as shorts.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ODBDY {
    pub dummy: c_short,
    pub axis: c_short,
    pub alarm: c_short,
    pub prgnum: c_short,
    pub prgmnum: c_short,
    pub seqnum: LONG,
    pub actf: LONG,
    pub acts: LONG,
    pub pos: ODBDY_POS,
}

/// cnc_rddynamico8: dynamic data, the alarm status as a short, the program
/// numbers `long` (FANUC's library writes only their low 16 bits there).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct ODBDYO8 {
    pub dummy: c_short,
    pub axis: c_short,
    pub alarm: c_short,
    pub prgnum: LONG,
    pub prgmnum: LONG,
    pub seqnum: LONG,
    pub actf: LONG,
    pub acts: LONG,
    pub pos: ODBDY_POS,
}

/// cnc_actf / cnc_acts: actual feed rate or spindle speed.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBACT {
    pub dummy: [c_short; 2],
    pub data: LONG,
}

/// cnc_acts2: actual speed of one or all spindles.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBACT2 {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [LONG; super::MAX_SPINDLE],
}

/// One speed of cnc_rdspeed.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SPEEDELM {
    pub data: LONG,
    pub dec: c_short,
    pub unit: c_short,
    pub disp: c_short,
    pub name: c_char,
    pub suff: c_char,
}

/// cnc_rdspeed: actual feed rate and spindle speed with units.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSPEED {
    pub actf: SPEEDELM,
    pub acts: SPEEDELM,
}

/// One load meter value (cnc_rdsvmeter, cnc_rdspmeter).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct LOADELM {
    pub data: LONG,
    pub dec: c_short,
    pub unit: c_short,
    pub name: c_char,
    pub suff1: c_char,
    pub suff2: c_char,
    pub reserve: c_char,
}

/// cnc_rdspmeter: one spindle's load and speed.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSPLOAD {
    pub spload: LOADELM,
    pub spspeed: LOADELM,
}

/// cnc_rdsvmeter: one axis's servo load.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSVLOAD {
    pub svload: LOADELM,
}

/// cnc_rdspload: serial spindle load.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBSPN {
    pub datano: c_short,
    pub r#type: c_short,
    pub data: [c_short; super::MAX_SPINDLE],
}

/// cnc_rdaxisdata: one value of one axis or spindle.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAXDT {
    pub name: [c_char; 4],
    pub data: LONG,
    pub dec: c_short,
    pub unit: c_short,
    pub flag: c_short,
    pub reserve: c_short,
}

/// One position of cnc_rdposition.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct POSELM {
    pub data: LONG,
    pub dec: c_short,
    pub unit: c_short,
    pub disp: c_short,
    pub name: c_char,
    pub suff: c_char,
}

/// cnc_rdposition: the four positions of one axis.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPOS {
    pub abs: POSELM,
    pub mach: POSELM,
    pub rel: POSELM,
    pub dist: POSELM,
}

/// cnc_absolute / machine / relative / distance (and the ...2 forms).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBAXIS {
    pub dummy: c_short,
    pub r#type: c_short,
    pub data: [LONG; MAX_AXIS],
}

/// cnc_rdspcss: the commanded spindle speed, constant surface speed and
/// maximum spindle speed.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBCSS {
    pub srpm: LONG,
    pub sspm: LONG,
    pub smax: LONG,
}

/// cnc_rdposerrs2: the position deviations of spindles 1 and 2.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBPSER {
    pub poserr1: LONG,
    pub poserr2: LONG,
}

/// cnc_rd3dtooltip: the tool tip of the 3D handle feed, `axes[i]` and
/// `data[i]` for each of the axes the CNC answers (at most 5; the elements
/// past them are not written).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODB3DHDL {
    pub axes: [c_short; 5],
    pub data: [LONG; 5],
}

/// cnc_sdtsetchnl: one servo data sampling channel: `type` the datum
/// sampled (0..37 of an axis, 0..12 of a spindle, `axis` -1), `chno` the
/// channel (1..8), `axis` the axis (-1 a spindle; 1..the path's axes on
/// the 30i class, 1..8, 11..18, 21..28, -2 or -3 on the 16i class),
/// `shift` 0..15 (sent as `0x0c | shift << 4`; a signed `char` is read
/// as FANUC's x86 library reads it, sign-extended).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IDBSDTCHAN {
    pub r#type: c_short,
    pub chno: c_char,
    pub axis: c_char,
    pub shift: std::os::raw::c_ushort,
}

/// cnc_rdfixcycle: the canned cycle in force: its mode (G code), the
/// plane's and the drilling axes, the initial level, R point and Z point,
/// the repetitions commanded and done, the cut-in depth and the shifts.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ODBFIX {
    pub mode: c_short,
    pub pln_axes: [c_short; 2],
    pub drl_axes: c_short,
    pub i_pos: LONG,
    pub r_pos: LONG,
    pub z_pos: LONG,
    pub cmd_cnt: LONG,
    pub act_cnt: LONG,
    pub cut: LONG,
    pub shift: [LONG; 2],
}
