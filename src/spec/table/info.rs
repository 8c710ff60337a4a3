//! The machine information functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdproctime",
        doc: "Reads the machining times of the last programs run.",
        params: &[Param::Out("proc_time", "ODBPTIME")],
        forms: &[every_class(cmd::RDPROCTIME, &[])],
        // Whole 12-byte records, their number written to `num`.
        records: Some(Records {
            fields: &[
                to(I32, "prg_no", I32),
                to(I16, "hour", I16),
                to(I16, "minute", I8),
                to(I16, "second", I8),
                skip(I16),
            ],
            out: 0,
            to: "data",
            elem: "ODBPTIME_DATA",
            max: 10,
            count: Some("num"),
            room: None,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdetherinfo",
        doc: "Reads the Ethernet board's type and device.",
        params: &[Param::Out("type", "short"), Param::Out("device", "short")],
        forms: &[every_class(cmd::RDETHERINFO, &[])],
        reply: &[to_out(0, I16, "", I16), to_out(1, I16, "", I16)],
        ..COMMAND
    },
];
