//! The operation and operator-message histories functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdophisno",
        doc: "Reads the number of operation history entries.",
        params: &[Param::Out("hisno", "unsigned short")],
        forms: &[every_class(cmd::RDOPHISNO, &[])],
        reply: &[to(I32, "", U16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdophisno3",
        learnt: Some(&[]),
        doc: "Reads the number of operation history entries (the 30i's history): the low 16 bits of the CNC's 32-bit count.",
        params: &[Param::Out("hisno", "unsigned short")],
        forms: &[every_class(cmd::RDOPHISNO3, &[])],
        reply: &[to(I32, "", U16)],
        ..COMMAND
    },
    Func {
        name: "cnc_startophis",
        doc: "Starts recording the operation history.",
        forms: &[every_class(cmd::STARTOPHIS, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_stopophis",
        doc: "Stops recording the operation history.",
        forms: &[every_class(cmd::STOPOPHIS, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clearophis",
        doc: "Clears the operation history.",
        params: &[Param::Short("type")],
        forms: &[every_class(cmd::CLEAROPHIS, &[Word::Arg(0)])],
        dims: &["0|1|2|-1|3"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdomhisno",
        doc: "Reads the number of operator message history entries.",
        params: &[Param::Out("hisno", "unsigned short")],
        forms: &[every_class(cmd::RDOMHISNO, &[])],
        reply: &[to(U16, "", U16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdomhisinfo",
        doc: "Reads the operator message history's size: most entries, entries held, characters per message.",
        params: &[Param::Out("ominfo", "ODBOMIF")],
        forms: &[every_class(cmd::RDOMHISINFO, &[])],
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
        forms: &[every_class(cmd::STARTOMHIS, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_stopomhis",
        doc: "Stops recording the operator message history.",
        forms: &[every_class(cmd::STOPOMHIS, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clearomhis",
        doc: "Clears the operator message history.",
        // The 30i class names the history to clear (2); the 16i sends 0.
        forms: &[
            Form {
                classes: Classes::S30,
                class: cmd::CLASS_CNC,
                cmd: cmd::CLEAROMHIS,
                words: &[Word::Const(2)],
            },
            every_class(cmd::CLEAROMHIS, &[]),
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_rdhissgnl",
        learnt: Some(&[
            "records: i32 entry and signal numbers (low halves), then a byte, the name, the mask, a byte, as cnc_rdhissgnl3's without the PMC number (recorded; the draft read i16 at bytes 0 and 4)",
        ]),
        doc: "Reads the signals the operation history records, the 16i's form (as many 12-byte records as the CNC sends, at most 20; datano and type untouched).",
        params: &[Param::Out("sig", "IODBSIG")],
        forms: &[every_class(cmd::RDHISSGNL, &[])],
        records: Some(&Records {
            fields: &[
                to(I32, "ent_no", I16),
                to(I32, "sig_no", I16),
                skip(U8),
                to(U8, "sig_name", I8),
                to(U8, "mask_pat", I8),
                skip(U8),
            ],
            out: 0,
            to: "data",
            elem: "IODBSIG_DATA",
            max: 20,
            count: None,
            room: None,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdhissgnl3",
        doc: "Reads the signals the operation history records (as many 16-byte records as the CNC sends, at most 60; datano and type untouched).",
        params: &[Param::Out("sig", "IODBSIG3")],
        forms: &[every_class(cmd::RDHISSGNL3, &[])],
        records: Some(&Records {
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
