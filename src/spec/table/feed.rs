//! The feed and speed functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_actf",
        doc: "Reads the actual feed rate (F).",
        params: &[Param::Out("actualfeed", "ODBACT")],
        forms: &[every_class(cmd::ACTF, &[])],
        reply: &[to(I32, "data", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_acts",
        doc: "Reads the actual spindle speed (S).",
        params: &[Param::Out("actualspindle", "ODBACT")],
        forms: &[every_class(cmd::ACTS, &[])],
        reply: &[to(I32, "data", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdspcss",
        doc: "Reads the commanded spindle speed, constant surface speed and maximum spindle speed.",
        params: &[Param::Out("css", "ODBCSS")],
        forms: &[every_class(cmd::RDSPCSS, &[])],
        reply: &[
            to(I32, "srpm", I32),
            to(I32, "sspm", I32),
            to(I32, "smax", I32),
        ],
        learnt: Some(&[]),
        ..COMMAND
    },
];
