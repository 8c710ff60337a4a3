//! The programs in memory functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_search",
        doc: "Selects program `prog_no` as the main program.",
        params: &[Param::Short("prog_no")],
        forms: &[every_class(cmd::SEARCH, &[Word::Arg(0)])],
        dims: &["100|1234|0|-1|7|9999|10000|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_searcho8",
        learnt: Some(&[]),
        doc: "Selects program `prog_no` (8 digits) as the main program.",
        params: &[Param::Long("prog_no")],
        forms: &[every_class(cmd::SEARCH, &[Word::Arg(0)])],
        dims: &["100|1234|12345678|0|-1|7|9999|10000|99999999|100000000"],
        ..COMMAND
    },
    Func {
        name: "cnc_delete",
        doc: "Deletes program `prog_no`.",
        params: &[Param::Short("prog_no")],
        forms: &[every_class(cmd::DELETE, &[Word::Arg(0)])],
        dims: &["100|1234|0|-1|7|9999|10000|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_deleteo8",
        learnt: Some(&[]),
        doc: "Deletes program `prog_no` (8 digits).",
        params: &[Param::Long("prog_no")],
        forms: &[every_class(cmd::DELETE, &[Word::Arg(0)])],
        dims: &["100|1234|12345678|0|-1|7|9999|10000|99999999|100000000"],
        ..COMMAND
    },
    Func {
        name: "cnc_delall",
        doc: "Deletes every program (those protected or in use stay).",
        forms: &[every_class(cmd::DELALL, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_copyprog",
        doc: "Copies program `top_prog` to a new program `bottom_prog`.",
        params: &[Param::Long("top_prog"), Param::Long("bottom_prog")],
        forms: &[every_class(cmd::COPYPROG, &[Word::Arg(0), Word::Arg(1)])],
        dims: &[
            "100|0|-1|7|1234|99999999|100000000",
            "200|0|-1|100|1234|9999|10000|99999999|100000000",
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_renameprog",
        doc: "Renumbers program `old_num` as `new_num`.",
        params: &[Param::Long("old_num"), Param::Long("new_num")],
        forms: &[every_class(cmd::RENAMEPROG, &[Word::Arg(0), Word::Arg(1)])],
        dims: &[
            "100|0|-1|7|1234|99999999|100000000",
            "200|0|-1|100|1234|9999|10000|99999999|100000000",
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_condense",
        doc: "Condenses program memory (`type` 0, program `prog_num`).",
        params: &[Param::Short("type"), Param::Long("prog_num")],
        forms: &[every_class(cmd::CONDENSE, &[Word::Arg(0), Word::Arg(1)])],
        dims: &["0|1|-1|2", "100|0|-1|1234|7"],
        ..COMMAND
    },
    Func {
        name: "cnc_wrmdipntr",
        doc: "Sets the execution pointer of MDI operation.",
        params: &[Param::Long("exe_pntr")],
        forms: &[every_class(cmd::WRMDIPNTR, &[Word::Arg(0)])],
        dims: &["0|1|-1|10|100|1000"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdmdipntr",
        doc: "Reads the execution pointers of MDI operation.",
        params: &[Param::Out("mdipntr", "ODBMDIP")],
        forms: &[every_class(cmd::RDMDIPNTR, &[])],
        reply: &[
            to(I32, "mdiprog", I16),
            to(I32, "mdipntr", I32),
            to(I32, "crntprog", I16),
            to(I32, "crntpntr", I32),
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_rdmdipntro8",
        learnt: Some(&[]),
        doc: "Reads the execution pointers of MDI operation, program numbers of 8 digits.",
        params: &[Param::Out("mdipntr", "ODBMDIPO8")],
        forms: &[every_class(cmd::RDMDIPNTR, &[])],
        reply: &[
            to(I32, "mdiprog", I32),
            to(I32, "mdipntr", I32),
            to(I32, "crntprog", I32),
            to(I32, "crntpntr", I32),
        ],
        ..COMMAND
    },
];
