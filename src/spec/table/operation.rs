//! The operation functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_start",
        doc: "Cycle start: the CNC runs the selected main program (MEMORY mode, no alarm; else EW_REJECT).",
        forms: &[every_class(cmd::START, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_reset",
        doc: "Resets the CNC: the running program stops, reset-clearable alarms are cleared.",
        forms: &[every_class(cmd::RESET, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_reset2",
        doc: "Resets the CNC as cnc_reset does (needs the FOCAS option, else EW_NOOPT).",
        checks: &[NEEDS_OPTION],
        forms: &[every_class(cmd::RESET2, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clralm",
        doc: "Clears the CNC's active alarms of type `id` (cnc_rdalmmsg's types).",
        params: &[Param::Short("id")],
        forms: &[every_class(cmd::CLRALM, &[Word::Arg(0)])],
        dims: &["3|0|1|2|-1|100|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdopnlsgnl",
        doc: "Reads the software operator panel's signals (`type` written back; `datano` left as it was).",
        params: &[Param::Short("type"), Param::Out("buf", "IODBSGNL")],
        forms: &[every_class(cmd::RDOPNLSGNL, &[Word::Arg(0)])],
        reply: &[
            echo(0, "type", I16),
            to(I16, "mode", I16),
            to(I16, "hndl_ax", I16),
            to(I16, "hndl_mv", I16),
            to(I16, "rpd_ovrd", I16),
            to(I16, "jog_ovrd", I16),
            to(I16, "feed_ovrd", I16),
            to(I16, "spdl_ovrd", I16),
            to(I16, "blck_del", I16),
            to(I16, "sngl_blck", I16),
            to(I16, "machn_lock", I16),
            to(I16, "dry_run", I16),
            to(I16, "mem_prtct", I16),
            to(I16, "feed_hold", I16),
        ],
        dims: &["-1|0|1|4096|8191"],
        learnt: Some(&[]),
        ..COMMAND
    },
];
