//! The area's request codes: 0x26 position types ([`pos`]), 0x40 spindle
//! data codes ([`spdl`]), and the all-axes / all-spindles argument.

/// 0x26 type codes.
pub mod pos {
    /// cnc_absolute2, rdaxisdata / rdposition type 0.
    pub const ABSOLUTE2: i32 = 0;
    pub const MACHINE: i32 = 1;
    /// cnc_relative2, rdaxisdata / rdposition type 2.
    pub const RELATIVE2: i32 = 2;
    /// rdaxisdata / rdposition type 3.
    pub const DISTANCE2: i32 = 3;
    pub const ABSOLUTE: i32 = 4;
    pub const RELATIVE: i32 = 6;
    pub const DISTANCE: i32 = 7;
    /// cnc_skip: the position where the skip signal came.
    pub const SKIP: i32 = 8;
    /// cnc_srvdelay: the servo delay (position deviation).
    pub const SERVO_DELAY: i32 = 9;
    /// cnc_accdecdly: the acceleration/deceleration delay.
    pub const ACCDEC_DELAY: i32 = 10;
}

/// 0x40 codes.
pub mod spdl {
    /// cnc_rdspload: serial spindle load.
    pub const LOAD_SERIAL: i32 = 0;
    /// cnc_rdspmaxrpm: maximum r.p.m. ratio.
    pub const MAX_RPM_RATIO: i32 = 1;
    /// cnc_rdspgear: gear ratio.
    pub const GEAR_RATIO: i32 = 2;
    /// cnc_acts2: actual speed.
    pub const SPEED_ACT: i32 = 3;
    /// cnc_rdspmeter / rdaxisdata cls 3 type 0: load meter (%).
    pub const LOAD_METER: i32 = 4;
    /// cnc_rdspmeter / rdaxisdata cls 3 type 1: motor speed.
    pub const SPEED_METER: i32 = 5;
}

/// All axes / all spindles.
pub const ALL: i32 = -1;
