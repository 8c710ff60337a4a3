//! The operation and operator-message histories functions.

use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

// The commands of this area's entries (the simulator answers by them).
/// cnc_rdophisno.
pub const RDOPHISNO: u16 = 0x0069;
/// cnc_startophis.
pub const STARTOPHIS: u16 = 0x0068;
/// cnc_stopophis.
pub const STOPOPHIS: u16 = 0x0067;
/// cnc_clearophis.
pub const CLEAROPHIS: u16 = 0x006d;
/// cnc_rdomhisno.
pub const RDOMHISNO: u16 = 0x01b4;
/// cnc_rdomhisinfo.
pub const RDOMHISINFO: u16 = 0x0072;
/// cnc_startomhis.
pub const STARTOMHIS: u16 = 0x0071;
/// cnc_stopomhis.
pub const STOPOMHIS: u16 = 0x0070;
/// cnc_clearomhis.
pub const CLEAROMHIS: u16 = 0x0074;
/// cnc_rdhissgnl3.
pub const RDHISSGNL3: u16 = 0x01b2;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdophisno",
        doc: "Reads the number of operation history entries.",
        params: &[Param::Out("hisno", "unsigned short")],
        forms: &[every_class(RDOPHISNO, &[])],
        reply: &[to(I32, "", U16)],
        ..COMMAND
    },
    Func {
        name: "cnc_startophis",
        doc: "Starts recording the operation history.",
        forms: &[every_class(STARTOPHIS, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_stopophis",
        doc: "Stops recording the operation history.",
        forms: &[every_class(STOPOPHIS, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clearophis",
        doc: "Clears the operation history.",
        params: &[Param::Short("type")],
        forms: &[every_class(CLEAROPHIS, &[Word::Arg(0)])],
        dims: &["0|1|2|-1|3"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdomhisno",
        doc: "Reads the number of operator message history entries.",
        params: &[Param::Out("hisno", "unsigned short")],
        forms: &[every_class(RDOMHISNO, &[])],
        reply: &[to(U16, "", U16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdomhisinfo",
        doc: "Reads the operator message history's size: most entries, entries held, characters per message.",
        params: &[Param::Out("ominfo", "ODBOMIF")],
        forms: &[every_class(RDOMHISINFO, &[])],
        reply: &[
            to(I32, "om_max", U16),
            to(I32, "om_sum", U16),
            to(I32, "om_char", U16),
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_startomhis",
        doc: "Starts recording the operator message history.",
        forms: &[every_class(STARTOMHIS, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_stopomhis",
        doc: "Stops recording the operator message history.",
        forms: &[every_class(STOPOMHIS, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clearomhis",
        doc: "Clears the operator message history.",
        // The 30i class names the history to clear (2); the 16i sends 0.
        forms: &[
            Form {
                classes: Classes::S30,
                class: 1,
                cmd: CLEAROMHIS,
                words: &[Word::Const(2)],
            },
            every_class(CLEAROMHIS, &[]),
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_rdhissgnl3",
        doc: "Reads the signals the operation history records (as many 16-byte records as the CNC sends, at most 60; datano and type untouched).",
        params: &[Param::Out("sig", "IODBSIG3")],
        forms: &[every_class(RDHISSGNL3, &[])],
        records: Some(Records {
            fields: &[
                to(I32, "ent_no", I16),
                to(I32, "pmc_no", I16),
                to(I32, "sig_no", I16),
                skip(U8),
                to(U8, "sig_name", I8),
                to(U8, "mask_pat", I8),
                skip(U8),
            ],
            out: 0,
            to: "data",
            elem: "IODBSIG3_DATA",
            max: 60,
            count: None,
            room: None,
        }),
        ..COMMAND
    },
];
