//! The operation functions.

use super::super::types::*;
use super::base::COMMAND;

// The commands of this area's entries (the simulator answers by them).
/// cnc_start: cycle start.
pub const START: u16 = 0x0001;
/// cnc_reset.
pub const RESET: u16 = 0x0002;
/// cnc_reset2.
pub const RESET2: u16 = 0x02c5;
/// cnc_clralm: clear alarms of a type.
pub const CLRALM: u16 = 0x0087;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_start",
        doc: "Cycle start: the CNC runs the selected main program (MEMORY mode, no alarm; else EW_REJECT).",
        forms: &[every_class(START, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_reset",
        doc: "Resets the CNC: the running program stops, reset-clearable alarms are cleared.",
        forms: &[every_class(RESET, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_reset2",
        doc: "Resets the CNC as cnc_reset does (needs the FOCAS option, else EW_NOOPT).",
        checks: &[NEEDS_OPTION],
        forms: &[every_class(RESET2, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clralm",
        doc: "Clears the CNC's active alarms of type `id` (cnc_rdalmmsg's types).",
        params: &[Param::Short("id")],
        forms: &[every_class(CLRALM, &[Word::Arg(0)])],
        dims: &["3|0|1|2|-1|100|32767"],
        ..COMMAND
    },
];
