//! Robot connection (`cnc_robo_*`): groups, signals, alarms, settings.
//!
//! Types of functions FANUC's header declares and no FANUC Ethernet library implements
//! (ours answer EW_VERSION: src/spec/table/absent.rs).

use std::os::raw::{c_char, c_uchar, c_ushort};

/// Data of `cnc_robo_wrgroup`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IDBRBGROUP {
    pub robot_program: c_uchar,
    pub nc_program_folder: [c_char; 213],
    pub nc_program_name: [c_char; 33],
}

/// Data of `cnc_robo_rdalmmsg`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBRBALMMSG {
    pub msg: [c_char; 152],
}

/// Data of `cnc_robo_rdcomsetting`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRBCOMSET {
    pub di_top: IODBRBTOPSIG,
    pub do_top: IODBRBTOPSIG,
    pub power_on: IODBRBPOWERSIG,
    pub di_offset: c_ushort,
    pub do_offset: c_ushort,
    pub property: c_uchar,
    pub reserve: [c_char; 3],
}

/// Data of `cnc_robo_rdsignals2`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IODBRBSIGNAL2 {
    pub r#type: c_char,
    pub state: c_char,
    pub no: c_ushort,
    pub name: [c_char; 73],
    pub reserve: [c_char; 3],
}

/// Data of `cnc_robo_rdselectedsignals`, `cnc_robo_wrselectedsignals`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRBSUMMARY {
    pub signal_type: c_char,
    pub reserve: c_char,
    pub no: c_ushort,
}

/// Data of `cnc_robo_rdgrouplist`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBRBGRPLIST {
    pub select: c_char,
    pub robot_program: c_uchar,
    pub nc_program_folder: [c_char; 213],
    pub nc_program_name: [c_char; 33],
    pub comment: [c_char; 52],
}

/// Data of `cnc_robo_rdsignals`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ODBRBSIGNAL {
    pub r#type: c_char,
    pub state: c_char,
    pub no: c_ushort,
    pub name: [c_char; 76],
}

/// Data of `cnc_robo_rdcomsetting`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRBPOWERSIG {
    pub unit_type: c_char,
    pub adr_type: c_char,
    pub address: c_ushort,
    pub bit: c_char,
    pub reserve: [c_char; 3],
}

/// Data of `cnc_robo_rdcomsetting`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct IODBRBTOPSIG {
    pub unit_type: c_char,
    pub adr_type: c_char,
    pub address: c_ushort,
}
