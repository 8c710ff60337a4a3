//! Tool life groups read by range or by count: their tools, life and
//! counters, the tool in use, the groups to exchange.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;
use crate::ew::{EW_ATTRIB, EW_NUMBER};

/// A group range's start below 1, or after its end: EW_NUMBER before any
/// traffic (cnc_rdgrpinfo's checks).
const GROUP_RANGE: &[Check] = &[
    Check {
        arg: 0,
        lo: 1,
        hi: i32::MAX,
        code: EW_NUMBER,
    },
    ordered(0, 1),
];

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdtoolrng",
        doc: "Reads tool life groups `s_grp..=e_grp` (cnc_rdgrpinfo's request and answer, at most 44 per call): for each, its number of tools, life and life counter; `datano_s` = `s_grp`, `datano_e` the last group the CNC answered. `s_grp` below 1 or `e_grp` below it: EW_NUMBER without traffic; `length` (bytes) must hold the 8-byte head and 12 bytes per group answered, else EW_LENGTH with nothing written.",
        params: &[
            Param::Short("s_grp"),
            Param::Short("e_grp"),
            Param::Short("length"),
            Param::Out("tooldata", "IODBTR"),
        ],
        checks: GROUP_RANGE,
        forms: &[every_class(
            cmd::TLGROUP,
            &[Word::Arg(0), Word::Upto(0, 1, 43, false)],
        )],
        // The first group's number (not read), then 32-byte group records.
        reply: &[echo(0, "datano_s", I16), last("datano_e", I16), skip(I32)],
        records: Some(&Records {
            fields: &[
                to(I32, "ntool", I32),
                skip(I32),
                to(I32, "life", I32),
                skip(I32),
                to(I32, "count", I32),
                skip(I32),
                skip(I32),
                skip(I32),
            ],
            out: 0,
            to: "data",
            elem: "IODBTR_DATA",
            max: 44,
            count: None,
            room: Some(2),
        }),
        dims: &[
            "1|0|-1|2|3|9999",
            "2|1|0|-1|3|44|45|9999",
            "68|0|-1|8|20|32|1000",
        ],
        learnt: Some(&[
            "records: 32-byte group records after a 4-byte head (the draft's record left three words out); the request's end cut to s_grp + 43 (recorded)",
            "written past the pointee: `length` is the room, checked after the answer (cnc_rdgrpinfo's)",
        ]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdusetlno",
        doc: "Reads the use number of the tool in use of each tool life group `s_grp..=e_grp` into `data` (at most 357 per call: the request asks `s_grp + 356` at most); `s_grp` is written back, `e_grp` as the last group the CNC answered (`s_grp - 2` for an empty answer, as FANUC's library counts it). `s_grp` below 1 or `e_grp` below it: EW_NUMBER without traffic; `length` (bytes) must hold the 8-byte head and 4 bytes per group answered, else EW_LENGTH with nothing written.",
        params: &[
            Param::Short("s_grp"),
            Param::Short("e_grp"),
            Param::Short("length"),
            Param::Out("tlusenum", "ODBTLUSE"),
        ],
        checks: GROUP_RANGE,
        forms: &[every_class(
            cmd::RDUSETLNO,
            &[Word::Arg(0), Word::Upto(0, 1, 356, false)],
        )],
        // The first group's number (not read), then one word per group.
        reply: &[echo(0, "s_grp", I16), last("e_grp", I16), skip(I32)],
        records: Some(&Records {
            fields: &[to(I32, "", I32)],
            out: 0,
            to: "data",
            elem: "long",
            max: 357,
            count: None,
            room: Some(2),
        }),
        dims: &[
            "1|0|-1|2|3|9999",
            "2|1|0|-1|3|357|358|9999",
            "28|0|-1|8|12|16|4096",
        ],
        learnt: Some(&[
            "records: one word per group after a 4-byte head (the draft mapped 28-byte records); the request's end cut to s_grp + 356 (recorded)",
            "e_grp of an empty answer: s_grp - 2 (recorded)",
            "written past the pointee: `length` is the room, checked after the answer",
        ]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdtltool",
        doc: "Reads tools `s_num..` of tool life group `grp_num` (cnc_rdtoolgrp's request `[grp, s, s + num - 1]`): each one's number, H and D codes and information; `*num` in is how many (at most 89 are asked), out how many were written. `grp_num` below 1: EW_NUMBER, `s_num` below 1: EW_ATTRIB, `*num` below 1: EW_LENGTH, without traffic.",
        params: &[
            Param::Long("grp_num"),
            Param::Long("s_num"),
            Param::Count("num"),
            Param::Out("tltool", "IODBTLTOOL"),
        ],
        checks: &[
            Check {
                arg: 0,
                lo: 1,
                hi: i32::MAX,
                code: EW_NUMBER,
            },
            Check {
                arg: 1,
                lo: 1,
                hi: i32::MAX,
                code: EW_ATTRIB,
            },
            at_least_one(2),
        ],
        forms: &[every_class(
            cmd::TLTOOLS,
            &[Word::Arg(0), Word::Arg(1), Word::Last(1)],
        )],
        // The group and the first use number (not read), then 16-byte tools.
        reply: &[skip(I32), skip(I32)],
        records: Some(&Records {
            fields: &[
                to(I32, "tool_num", I32),
                to(I32, "h_code", I32),
                to(I32, "d_code", I32),
                to(I32, "tool_inf", I32),
            ],
            out: 0,
            to: "",
            elem: "IODBTLTOOL",
            max: 89,
            count: None,
            room: None,
        }),
        dims: &["1|0|-1|2|3|9999", "1|0|-1|2|3|99", "4|1|0|-1|2|89|90|200"],
        learnt: Some(&[
            "word 2 computed: s_num + *num - 1, *num asked at most 89 (recorded: Word::Last)",
            "written past the pointee: records past *num (fuzz: a deviation)",
        ]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdexchgtgrp",
        doc: "Reads the tool life groups whose tools are to be exchanged, each with its optional group number; `*num` in is how many (at most 179 are asked), out how many were written; below 1: EW_LENGTH without traffic.",
        params: &[Param::Count("num"), Param::Out("exgp", "ODBEXGP")],
        checks: &[at_least_one(0)],
        forms: &[every_class(cmd::RDEXCHGTGRP, &[Word::Asked])],
        records: Some(&Records {
            fields: &[to(I32, "grp_no", I32), to(I32, "opt_grpno", I32)],
            out: 0,
            to: "",
            elem: "ODBEXGP",
            max: 179,
            count: None,
            room: None,
        }),
        dims: &["4|1|0|-1|2|179|180|1000"],
        learnt: Some(&[
            "*num asked at most 179 (recorded)",
            "written past the pointee: records past *num (fuzz: a deviation)",
        ]),
        ..COMMAND
    },
    Func {
        name: "cnc_wr1tlifedata",
        doc: "Writes tool `type` (its use number) of tool life group `datano`: its number, H and D codes and information; `datano` and `type` go as the request's first two words.",
        params: &[Param::In("tldata", "IODBTD")],
        forms: &[every_class(
            cmd::WR1TLIFEDATA,
            &[Word::Input("datano", I16), Word::Input("type", I16)],
        )],
        payload: Some(&Payload {
            fields: TOOL_DATA,
            elem: "IODBTD",
            count: ONE,
            max: 1,
        }),
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_wr1tlifedat2",
        doc: "Writes tool `type` (its use number, a long) of tool life group `datano` as cnc_wr1tlifedata (its request; `dummy` not sent).",
        params: &[Param::In("tldata", "IODBTD2")],
        forms: &[every_class(
            cmd::WR1TLIFEDATA,
            &[Word::Input("datano", I16), Word::Input("type", I32)],
        )],
        payload: Some(&Payload {
            fields: TOOL_DATA,
            elem: "IODBTD2",
            count: ONE,
            max: 1,
        }),
        learnt: Some(&["type sent as a 32-bit word (recorded; the draft had its low half)"]),
        ..COMMAND
    },
];

/// A tool's number, H and D codes and information, as the writes send them.
const TOOL_DATA: &[Field] = &[
    to(I32, "tool_num", I32),
    to(I32, "h_code", I32),
    to(I32, "d_code", I32),
    to(I32, "tool_inf", I32),
];
