//! The program data folders of the 30i ("//CNC_MEM/USER/PATH1/O1234"):
//! each function one request (learnt from FANUC's library with the
//! oracle), its names C strings sent as NUL-padded fields of fixed size
//! ([`Param::Text`]: a longer name cut to its field, as FANUC's library
//! cuts it).

use super::super::commands as cmd;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_pdf_add",
        doc: "Creates a program or (a name ending in '/') a folder: `path` sent in a 256-byte field.",
        params: &[Param::Text("path", 256)],
        forms: &[every_class(cmd::PDF_ADD, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_pdf_del",
        doc: "Deletes a program or an empty folder: `path` sent in a 256-byte field.",
        params: &[Param::Text("path", 256)],
        forms: &[every_class(cmd::PDF_DEL, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_pdf_slctmain",
        doc: "Selects a program as the main program: `path` sent in a 256-byte field.",
        params: &[Param::Text("path", 256)],
        forms: &[every_class(cmd::PDF_SLCTMAIN, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_pdf_delall",
        doc: "Deletes every program of a folder (`type` as FANUC's: sent after a 1; `path` in a 256-byte field).",
        params: &[Param::Short("type"), Param::Text("path", 256)],
        forms: &[every_class(
            cmd::PDF_DELALL,
            &[Word::Const(1), Word::Arg(0)],
        )],
        ..COMMAND
    },
    Func {
        name: "cnc_pdf_delline",
        doc: "Deletes `count` lines of a program (`path`, in a 256-byte field) from line `line_no`.",
        params: &[
            Param::Text("path", 256),
            Param::ULong("line_no"),
            Param::ULong("count"),
        ],
        forms: &[every_class(cmd::PDF_DELLINE, &[Word::Arg(0), Word::Arg(1)])],
        ..COMMAND
    },
];
