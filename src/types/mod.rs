//! The C structures of `fwlib32.h` (default variant), with FANUC's names.
//!
//! Fields FANUC's header spells `long` are 32-bit here (`LONG`/`ULONG`):
//! FANUC's x86-64 library reads and writes them as 4 bytes, and so do we
//! (the `l32` layouts of layouts.json, checked by tests/artifacts/abi.rs).

#![allow(non_camel_case_types)]

use std::os::raw::c_char;

// One file per API area, as in src/ffi/ (cbindgen reads them all).
mod alarm;
mod axes;
mod axis_ext;
mod compensation;
mod diagnosis;
mod energy;
mod fssb;
mod history;
mod ieee64;
mod machining;
mod macros;
mod main_menu;
mod maintenance;
mod offset;
mod panel;
mod param;
mod pmc;
mod position;
mod power_mate;
mod program;
mod restart;
mod robot;
mod safety_io;
mod servo;
mod status;
mod status_ext;
mod storage;
mod tool;
mod tool_mgmt;
mod upload;

#[allow(unused_imports)]
pub use {
    alarm::*, axes::*, axis_ext::*, compensation::*, diagnosis::*, energy::*, fssb::*, history::*,
    ieee64::*, machining::*, macros::*, main_menu::*, maintenance::*, offset::*, panel::*,
    param::*, pmc::*, position::*, power_mate::*, program::*, restart::*, robot::*, safety_io::*,
    servo::*, status::*, status_ext::*, storage::*, tool::*, tool_mgmt::*, upload::*,
};

/// FANUC's LONG: 32 bits on every platform, as its Linux documentation defines it.
pub type LONG = i32;
/// FANUC's ULONG: 32 bits on every platform.
pub type ULONG = u32;

/// Maximum number of axes (Linux Ethernet build).
pub const MAX_AXIS: usize = 32;
/// Maximum number of paths (ODBSYSEX).
pub const MAX_CNCPATH: usize = 15;
/// Maximum number of spindles.
pub const MAX_SPINDLE: usize = 8;
/// The axis argument meaning "every axis".
pub const ALL_AXES: i16 = -1;
/// The spindle argument meaning "every spindle".
pub const ALL_SPINDLES: i16 = -1;

/// Copies wire characters into a C char array.
pub(crate) fn chars<const N: usize>(b: [u8; N]) -> [c_char; N] {
    b.map(|x| x as c_char)
}
