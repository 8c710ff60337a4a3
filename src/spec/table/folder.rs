//! The program data folders of the 30i ("//CNC_MEM/USER/PATH1/O1234"):
//! each function one request (learnt from FANUC's library with the
//! oracle), its names C strings sent as NUL-padded fields of fixed size
//! ([`Param::Text`]: a longer name cut to its field, as FANUC's library
//! cuts it).

use super::super::commands as cmd;
use super::super::types::Int::*;
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
    Func {
        name: "cnc_pdf_rename",
        doc: "Renames a program or folder (`from` sent in a 256-byte field; `to`, the new name, in a 36-byte field).",
        params: &[Param::Text("from", 256), Param::Text("to", 36)],
        forms: &[every_class(cmd::PDF_RENAME, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_pdf_copy",
        doc: "Copies a program (`to`: a program or a folder; each name sent in a 256-byte field).",
        params: &[Param::Text("from", 256), Param::Text("to", 256)],
        forms: &[every_class(cmd::PDF_COPY, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_pdf_move",
        doc: "Moves a program (`to`: a program or a folder; each name sent in a 256-byte field).",
        params: &[Param::Text("from", 256), Param::Text("to", 256)],
        forms: &[every_class(cmd::PDF_MOVE, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_wrpdf_curdir",
        doc: "Sets the current directory of `type` (1 foreground, 2 background) to `dir_name` (sent in a 256-byte field).",
        params: &[Param::Short("type"), Param::Text("dir_name", 256)],
        forms: &[every_class(cmd::PDF_WRCURDIR, &[Word::Arg(0)])],
        ..COMMAND
    },
    Func {
        name: "cnc_rdpdf_subdirn",
        doc: "Reads how many directories and files the directory `path` (sent in a 256-byte field) holds (the low 16 bits of each answered word).",
        params: &[
            Param::Text("path", 256),
            Param::Out("num_fil", "ODBPDFNFIL"),
        ],
        forms: &[every_class(cmd::PDF_SUBDIRN, &[])],
        reply: &[to(I32, "dir_num", I16), to(I32, "file_num", I16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdpdf_inf",
        doc: "Reads a drive's used and total capacity (pages) and directories (`drv_name` sent in a 12-byte field; a short answer is EW_PROTOCOL, nothing written).",
        params: &[
            Param::Text("drv_name", 12),
            Param::Short("type"),
            Param::Out("inf", "ODBPDFINF"),
        ],
        forms: &[every_class(cmd::PDF_INF, &[Word::Arg(0)])],
        reply: &[
            to(I32, "used_page", I32),
            to(I32, "all_page", I32),
            to(I32, "used_dir", I32),
            to(I32, "all_dir", I32),
        ],
        short: Short::Error,
        ..COMMAND
    },
    Func {
        name: "cnc_rdpdf_curdir",
        doc: "Reads the current directory of `type` (1 foreground, 2 background): 256 bytes written, the answer's up to its NUL and zeros after.",
        params: &[Param::Short("type"), Param::Out("dir_name", "text[256]")],
        forms: &[every_class(cmd::PDF_RDCURDIR, &[Word::Arg(0)])],
        reply: &[text(256, "")],
        ..COMMAND
    },
    Func {
        name: "cnc_pdf_rdmain",
        doc: "Reads the main program's path name: 256 bytes written, the answer's up to its NUL and zeros after.",
        params: &[Param::Out("path_name", "text[256]")],
        forms: &[every_class(cmd::PDF_RDMAIN, &[])],
        reply: &[text(256, "")],
        ..COMMAND
    },
    Func {
        name: "cnc_rdpdf_drive",
        doc: "Reads the program drives (\"CNC_MEM\" ...): the answer's 12-byte names, as many as it holds (16 at most), each up to its NUL and zeros after, and their number into `max_num` (`dummy` not written).",
        params: &[Param::Out("drive", "ODBPDFDRV")],
        forms: &[every_class(cmd::PDF_DRIVE, &[])],
        records: Some(&Records {
            fields: &[text(12, "")],
            out: 0,
            to: "drive",
            elem: "char[12]",
            max: 16,
            count: Some("max_num"),
            room: None,
        }),
        ..COMMAND
    },
];
