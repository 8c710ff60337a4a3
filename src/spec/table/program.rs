//! The program functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_exeprgname",
        doc: "Reads the name and O number of the running program. The name as a C string: the characters up to its NUL, zeros after (FANUC's library copies it so, whatever follows in the answer).",
        params: &[Param::Out("exeprg", "ODBEXEPRG")],
        forms: &[every_class(cmd::EXEPRGNAME, &[])],
        reply: &[to(I32, "o_num", I32), text(36, "name")],
        ..COMMAND
    },
    Func {
        name: "cnc_exeprgname2",
        doc: "Reads the full path name of the running program (\"//CNC_MEM/USER/PATH1/O1234\") into 256 bytes: the name's characters up to its NUL, zeros after; a name of 256 characters or more fills all 256 with no NUL, as FANUC's library writes it.",
        params: &[Param::Out("path_name", "text[256]")],
        forms: &[every_class(cmd::EXEPRGNAME2, &[])],
        reply: &[text(256, "")],
        ..COMMAND
    },
    Func {
        name: "cnc_rdprgnum",
        doc: "Reads the running and main program numbers (the low 16 bits of each, as FANUC's library stores them in the default ODBPRO's shorts).",
        params: &[Param::Out("prgnum", "ODBPRO")],
        forms: &[every_class(cmd::PRGNUM, &[])],
        reply: &[to(I32, "data", I16), to(I32, "mdata", I16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdprgnumo8",
        doc: "Reads the running and main program numbers, 8 digits each (all 32 bits of each).",
        params: &[Param::Out("prgnum", "ODBPROO8")],
        forms: &[every_class(cmd::PRGNUM, &[])],
        reply: &[to(I32, "data", I32), to(I32, "mdata", I32)],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdmdiprgstat",
        doc: "Reads the MDI program's status bits: 0 no MDI program, 2 one is stored, 4 it starts from its top (the execution pointer at 0).",
        params: &[Param::Out("stat", "unsigned short")],
        forms: &[every_class(cmd::RDMDIPRGSTAT, &[])],
        reply: &[to(U16, "", U16)],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdmultipieceno",
        doc: "Reads the multiple-piece machining number (4 bytes written into the `long`).",
        params: &[Param::Out("number", "long")],
        forms: &[every_class(cmd::RDMULTIPIECENO, &[])],
        reply: &[to(I32, "", I32)],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdseqnum",
        doc: "Reads the sequence number of the block being executed.",
        params: &[Param::Out("seqnum", "ODBSEQ")],
        forms: &[every_class(cmd::SEQNUM, &[])],
        reply: &[to(I32, "data", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdblkcount",
        doc: "Reads the number of blocks executed (4 bytes written into the `long`).",
        params: &[Param::Out("prog_bc", "long")],
        forms: &[every_class(cmd::RDBLKCOUNT, &[])],
        reply: &[to(I32, "", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdactpt",
        doc: "Reads the execution pointer: program number and block number (4 bytes written into each `long`).",
        params: &[Param::Out("prog_no", "long"), Param::Out("blk_no", "long")],
        forms: &[every_class(cmd::RDACTPT, &[])],
        reply: &[to_out(0, I32, "", I32), to_out(1, I32, "", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdtimer",
        doc: "Reads a timer (`type` 0 power-on, 1 operating, 2 cutting, 3 cycle, 4 free) as minutes and milliseconds.",
        params: &[Param::Short("type"), Param::Out("time", "IODBTIME")],
        forms: &[every_class(cmd::RDTIMER, &[Word::Arg(0)])],
        reply: &[to(I32, "minute", I32), to(I32, "msec", I32)],
        dims: &["0|1|2|3|4|-1|5"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdcommand",
        learnt: Some(&["reply: out 2 : [Const(1), Const(0)]"]),
        doc: "Reads the commanded values of block `block` (0: the block in execution) for address `type` (-1: every address commanded): one ODBCMD per value, at most `*num` (`*num` = how many were written).",
        params: &[
            Param::Short("type"),
            Param::Short("block"),
            Param::Count("num"),
            Param::Out("command", "ODBCMD"),
        ],
        forms: &[every_class(cmd::RDCOMMAND, &[Word::Arg(0), Word::Arg(1)])],
        records: Some(&Records {
            fields: &[
                to(I8, "adrs", I8),
                to(I8, "num", I8),
                to(I16, "flag", I16),
                to(I32, "cmd_val", I32),
                to(I32, "dec_val", I32),
            ],
            out: 0,
            to: "",
            elem: "ODBCMD",
            max: 26,
            count: None,
            room: None,
        }),
        overflow: Overflow::Refuse,
        dims: &["-1|0|5|6|12|18|19|25|26|-2", "0|1|2|-1", "8|1|0|-1|26|27"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdopmode",
        doc: "Reads the operation mode word (of the spindle: 0 others, 1 normal, 2 orientation, 3 synchronous, 4 rigid tap, 5 Cs contour, 6 positioning, by FANUC's Windows header). An answer without a whole word writes nothing (EW_OK), as FANUC's library; further words are not written (FANUC's library writes them all, past the short).",
        params: &[Param::Out("mode", "short")],
        forms: &[every_class(cmd::RDOPMODE, &[])],
        // One whole word, if the answer holds one.
        records: Some(&Records {
            fields: &[to(I16, "", I16)],
            out: 0,
            to: "",
            elem: "short",
            max: 1,
            count: None,
            room: None,
        }),
        ..COMMAND
    },
];
