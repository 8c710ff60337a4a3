//! The machine information functions.

use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

// The commands of this area's entries (the simulator answers by them).
/// cnc_rdproctime: processing times.
pub const RDPROCTIME: u16 = 0x0075;
/// cnc_rdetherinfo: the Ethernet board.
pub const RDETHERINFO: u16 = 0x0159;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdproctime",
        doc: "Reads the machining times of the last programs run.",
        params: &[Param::Out("proc_time", "ODBPTIME")],
        forms: &[every_class(RDPROCTIME, &[])],
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
        forms: &[every_class(RDETHERINFO, &[])],
        reply: &[to_out(0, I16, "", I16), to_out(1, I16, "", I16)],
        ..COMMAND
    },
];
