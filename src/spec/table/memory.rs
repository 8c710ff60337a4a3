//! The programs in memory functions.

use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

// The commands of this area's entries (the simulator answers by them).
/// cnc_search.
pub const SEARCH: u16 = 0x0003;
/// cnc_delete.
pub const DELETE: u16 = 0x0005;
/// cnc_delall.
pub const DELALL: u16 = 0x0004;
/// cnc_copyprog.
pub const COPYPROG: u16 = 0x01c6;
/// cnc_renameprog.
pub const RENAMEPROG: u16 = 0x01c7;
/// cnc_condense.
pub const CONDENSE: u16 = 0x01c8;
/// cnc_wrmdipntr.
pub const WRMDIPNTR: u16 = 0x0039;
/// cnc_rdmdipntr.
pub const RDMDIPNTR: u16 = 0x0038;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_search",
        doc: "Selects program `prog_no` as the main program.",
        params: &[Param::Short("prog_no")],
        forms: &[every_class(SEARCH, &[Word::Arg(0)])],
        dims: &["100|1234|0|-1|7|9999|10000|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_delete",
        doc: "Deletes program `prog_no`.",
        params: &[Param::Short("prog_no")],
        forms: &[every_class(DELETE, &[Word::Arg(0)])],
        dims: &["100|1234|0|-1|7|9999|10000|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_delall",
        doc: "Deletes every program (those protected or in use stay).",
        forms: &[every_class(DELALL, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_copyprog",
        doc: "Copies program `top_prog` to a new program `bottom_prog`.",
        params: &[Param::Long("top_prog"), Param::Long("bottom_prog")],
        forms: &[every_class(COPYPROG, &[Word::Arg(0), Word::Arg(1)])],
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
        forms: &[every_class(RENAMEPROG, &[Word::Arg(0), Word::Arg(1)])],
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
        forms: &[every_class(CONDENSE, &[Word::Arg(0), Word::Arg(1)])],
        dims: &["0|1|-1|2", "100|0|-1|1234|7"],
        ..COMMAND
    },
    Func {
        name: "cnc_wrmdipntr",
        doc: "Sets the execution pointer of MDI operation.",
        params: &[Param::Long("exe_pntr")],
        forms: &[every_class(WRMDIPNTR, &[Word::Arg(0)])],
        dims: &["0|1|-1|10|100|1000"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdmdipntr",
        doc: "Reads the execution pointers of MDI operation.",
        params: &[Param::Out("mdipntr", "ODBMDIP")],
        forms: &[every_class(RDMDIPNTR, &[])],
        reply: &[
            to(I32, "mdiprog", I16),
            to(I32, "mdipntr", I32),
            to(I32, "crntprog", I16),
            to(I32, "crntpntr", I32),
        ],
        ..COMMAND
    },
];
