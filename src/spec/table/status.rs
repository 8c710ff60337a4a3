//! The status and identity functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdcncid",
        doc: "Reads the CNC's identification number: four 32-bit words. The pointer keeps FANUC's `unsigned long *` spelling, but, exactly as FANUC's x86-64 library does, four 4-byte words are written (16 bytes): pass a `uint32_t[4]` (or an `unsigned long[4]` read as 32-bit words). Only the words the CNC sent are written, at most four (FANUC's library writes every word of a longer answer, past the four).",
        params: &[Param::Out("cncid", "unsigned long")],
        forms: &[every_class(cmd::RDCNCID, &[])],
        // As many whole words as the answer holds, at most four.
        records: Some(&Records {
            fields: &[to(U32, "", U32)],
            out: 0,
            to: "",
            elem: "unsigned long",
            max: 4,
            count: None,
            room: None,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_getmacaddress",
        learnt: Some(&[
            "13 bytes written whatever the answer's length (fuzzed: zeros past a shorter answer; the draft read as many 1-byte records as sent)",
        ]),
        doc: "Reads the CNC's Ethernet MAC address as characters: 13 bytes written (12 hexadecimal digits and a NUL), the answer's first 13 as they are, zeros past a shorter answer.",
        params: &[Param::Out("mac", "char")],
        forms: &[every_class(cmd::GETMACADDRESS, &[])],
        reply: &[Field {
            n: 13,
            ..to(U8, "", I8)
        }],
        ..COMMAND
    },
];
