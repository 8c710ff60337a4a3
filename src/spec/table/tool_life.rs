//! The tool life functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;
use crate::ew::{EW_ATTRIB, EW_NUMBER};

/// The reads of one word of tool `tuse_num` of tool life group `grp_num`
/// into ODBTLIFE4 `data`, by the tool's place (cnc_rd1tlifedata's
/// request); each entry names the word.
const BY_TOOL: Func = Func {
    params: TLIFE4,
    forms: &[every_class(
        cmd::RD1TLIFEDATA,
        &[Word::Arg(0), Word::Arg(1)],
    )],
    dims: &["1|0|-1|2|9999", "1|0|-1|2|99"],
    zero_without_first: true,
    learnt: Some(&[]),
    ..COMMAND
};

/// The same words by the tool's use number (cnc_toolnum's request, whose
/// short answer reads on from the request's bytes).
const BY_USE: Func = Func {
    forms: &[every_class(
        cmd::TLTOOLS,
        &[Word::Arg(0), Word::Arg(1), Word::Arg(1)],
    )],
    short: Short::Request,
    ..BY_TOOL
};

const TLIFE4: &[Param] = &[
    Param::Short("grp_num"),
    Param::Short("tuse_num"),
    Param::Out("tlife", "ODBTLIFE4"),
];

macro_rules! by_tool {
    ($what:literal) => {
        concat!(
            "Reads ",
            $what,
            " of tool `tuse_num` of tool life group `grp_num` (cnc_rd1tlifedata's request): `datano` the group and `type` the tool's number the CNC answered."
        )
    };
}

macro_rules! by_use {
    ($what:literal) => {
        concat!(
            "Reads ",
            $what,
            " of tool `tuse_num` of tool life group `grp_num` (cnc_toolnum's request): `datano` the group and `type` the use number the CNC answered."
        )
    };
}

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_toolnum",
        doc: "Reads the tool number of the `tuse_num`-th tool of tool-life group `grp_num`.",
        params: &[
            Param::Short("grp_num"),
            Param::Short("tuse_num"),
            Param::Out("toolnum", "ODBTLIFE4"),
        ],
        forms: &[every_class(
            cmd::TLTOOLS,
            &[Word::Arg(0), Word::Arg(1), Word::Arg(1)],
        )],
        reply: &[
            to(I32, "datano", I16),
            to(I32, "type", I16),
            to(I32, "data", I32),
        ],
        short: Short::Request,
        dims: &["1|0|-1|2|9999", "0|1|-1|2|99"],
        zero_without_first: true,
        ..COMMAND
    },
    Func {
        name: "cnc_rd1length",
        doc: by_tool!("the length offset number (H)"),
        reply: &[
            to(I32, "datano", I16),
            to(I32, "type", I16),
            skip(I32),
            to(I32, "data", I32),
        ],
        ..BY_TOOL
    },
    Func {
        name: "cnc_rd1radius",
        doc: by_tool!("the radius offset number (D)"),
        reply: &[
            to(I32, "datano", I16),
            to(I32, "type", I16),
            skip(I32),
            skip(I32),
            to(I32, "data", I32),
        ],
        ..BY_TOOL
    },
    Func {
        name: "cnc_t1info",
        doc: by_tool!("the information"),
        reply: &[
            to(I32, "datano", I16),
            to(I32, "type", I16),
            skip(I32),
            skip(I32),
            skip(I32),
            to(I32, "data", I32),
        ],
        ..BY_TOOL
    },
    Func {
        name: "cnc_rd1tlifedat2",
        doc: "Reads tool `tuse_num` of tool life group `grp_num` as cnc_rd1tlifedata (its request, `tuse_num` a long): `datano` the group the CNC answered, the tool's number, H and D codes and information (`dummy` and `type` untouched).",
        params: &[
            Param::Short("grp_num"),
            Param::Long("tuse_num"),
            Param::Out("tldata", "IODBTD2"),
        ],
        forms: &[every_class(
            cmd::RD1TLIFEDATA,
            &[Word::Arg(0), Word::Arg(1)],
        )],
        reply: &[
            to(I32, "datano", I16),
            to(I32, "tool_num", I32),
            skip(I32),
            to(I32, "h_code", I32),
            to(I32, "d_code", I32),
            to(I32, "tool_inf", I32),
        ],
        zero_without_first: true,
        zeroed: &["h_code", "d_code", "tool_inf"],
        dims: &["1|0|-1|2|9999", "1|0|-1|2|99|65537"],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rd2length",
        doc: by_use!("the length offset number (H)"),
        reply: &[
            to(I32, "datano", I16),
            to(I32, "type", I16),
            skip(I32),
            to(I32, "data", I32),
        ],
        ..BY_USE
    },
    Func {
        name: "cnc_rd2radius",
        doc: by_use!("the radius offset number (D)"),
        reply: &[
            to(I32, "datano", I16),
            to(I32, "type", I16),
            skip(I32),
            skip(I32),
            to(I32, "data", I32),
        ],
        ..BY_USE
    },
    Func {
        name: "cnc_t2info",
        doc: by_use!("the information"),
        reply: &[
            to(I32, "datano", I16),
            to(I32, "type", I16),
            skip(I32),
            skip(I32),
            skip(I32),
            to(I32, "data", I32),
        ],
        ..BY_USE
    },
    Func {
        name: "cnc_rdntool",
        doc: "Reads the number of tools in tool-life group `grp_num`.",
        params: &[Param::Short("grp_num"), Param::Out("tool", "ODBTLIFE3")],
        forms: &[every_class(cmd::TLGROUP, &[Word::Arg(0), Word::Arg(0)])],
        reply: &[to(I32, "datano", I16), to(I32, "data", I32)],
        short: Short::Zeros,
        dims: &["1|0|-1|2|9999"],
        zero_without_first: true,
        ..COMMAND
    },
    Func {
        name: "cnc_rdlife",
        doc: "Reads the tool life of tool group `number` (`data`; `dummy` untouched; `datano` the group number the CNC answered).",
        params: &[Param::Short("number"), Param::Out("life", "ODBTLIFE3")],
        forms: &[every_class(cmd::TLGROUP, &[Word::Arg(0), Word::Arg(0)])],
        // Group, then tools, life and counter as value records (value, base, exponent).
        reply: &[
            to(I32, "datano", I16),
            skip(I32),
            skip(I32),
            to(I32, "data", I32),
            skip(I32),
            skip(I32),
            skip(I32),
        ],
        short: Short::Zeros,
        dims: &["1|0|-1|2|9999"],
        zero_without_first: true,
        ..COMMAND
    },
    Func {
        name: "cnc_rdcount",
        doc: "Reads the tool life counter of tool group `number`.",
        params: &[Param::Short("number"), Param::Out("count", "ODBTLIFE3")],
        forms: &[every_class(cmd::TLGROUP, &[Word::Arg(0), Word::Arg(0)])],
        reply: &[
            to(I32, "datano", I16),
            skip(I32),
            skip(I32),
            skip(I32),
            skip(I32),
            to(I32, "data", I32),
            skip(I32),
        ],
        short: Short::Zeros,
        dims: &["1|0|-1|2|9999"],
        // As cnc_rdlife [fuzz, seed 0x202a1128 `s0Twwwshort1`: group 0,
        // counter word 0x376b988b, data written 0].
        zero_without_first: true,
        ..COMMAND
    },
    Func {
        name: "cnc_rdgrpid",
        doc: "Reads the tool life group of tool number `tno` (`type` = `tno`, `dummy` untouched; cnc_rdgrpid2's request).",
        params: &[Param::Short("tno"), Param::Out("tlife", "ODBTLIFE1")],
        forms: &[every_class(cmd::RDGRPID2, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I16), to(I32, "data", I32)],
        dims: &["11|0|-1|1|5|9999|32767"],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdgrpid2",
        doc: "Reads the tool life group of tool number `tno` (`type` = `tno`, `dummy` untouched).",
        params: &[Param::Long("tno"), Param::Out("tlife", "ODBTLIFE5")],
        forms: &[every_class(cmd::RDGRPID2, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I32), to(I32, "data", I32)],
        dims: &["11|0|-1|1|5|9999|99999999"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdwkcdshft",
        doc: "Reads the work coordinate shift of axis `axis` (-1: all axes) into `data` (`type` = `axis`; `length` must hold 4 bytes and the axes, else EW_LENGTH after the reply).",
        params: &[
            Param::Short("axis"),
            Param::ShortAs("length", U16),
            Param::Out("shift", "IODBWCSF"),
        ],
        checks: &[Check {
            arg: 0,
            lo: -32768,
            hi: 32,
            code: EW_ATTRIB,
        }],
        forms: &[every_class(cmd::RDWKCDSHFT, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I16)],
        records: Some(&Records {
            fields: &[to(I32, "", I32), skip(I32)],
            out: 0,
            to: "data",
            elem: "long",
            max: 32,
            count: None,
            room: Some(1),
        }),
        dims: &["1|-1|0|2|3|4|32|33|-2", "8|4|7|12|0|-1|132|136"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdgrpinfo",
        doc: "Reads tool life groups `s_grp..=e_grp` (at most 44 per call: the request asks `s_grp + 43` at most): for each, its number of tools, life, life counter and counter type; `e_grp` is written back as the last group the CNC answered. `s_grp` below 1 or `e_grp` below it: EW_NUMBER without traffic; `length` (bytes) must hold the 8-byte head and 16 bytes per group answered, else EW_LENGTH with nothing written (checked after the answer and compared signed, as FANUC's library).",
        params: &[
            Param::Short("s_grp"),
            Param::Short("e_grp"),
            Param::Short("length"),
            Param::Out("grpinfo", "IODBTGI"),
        ],
        checks: &[
            Check {
                arg: 0,
                lo: 1,
                hi: i32::MAX,
                code: EW_NUMBER,
            },
            ordered(0, 1),
        ],
        forms: &[every_class(
            cmd::TLGROUP,
            &[Word::Arg(0), Word::Upto(0, 1, 43, false)],
        )],
        // The first group's number (not read), then 32-byte group records.
        reply: &[echo(0, "s_grp", I16), last("e_grp", I16), skip(I32)],
        records: Some(&Records {
            fields: &[
                to(I32, "n_tool", I32),
                skip(I32),
                to(I32, "count_value", I32),
                to(I32, "count_type", I32),
                to(I32, "counter", I32),
                skip(I32),
                skip(I32),
                skip(I32),
            ],
            out: 0,
            to: "data",
            elem: "IODBTGI_DATA",
            max: 44,
            count: None,
            room: Some(2),
        }),
        dims: &["1|0|-1|2|3|9999", "2|1|0|-1|3|9999", "88|0|-1|8|24|40|1000"],
        ..COMMAND
    },
    // Base cases on group 2 (cnc_rdlife and others read group 1).
    Func {
        name: "cnc_deltlifedt",
        doc: "Deletes the `tuse_num`-th tool of tool life group `grpno`.",
        params: &[Param::Short("grpno"), Param::Short("tuse_num")],
        forms: &[every_class(cmd::DELTLIFEDT, &[Word::Arg(0), Word::Arg(1)])],
        dims: &["2|0|-1|1|9999", "1|0|-1|2|99"],
        ..COMMAND
    },
    Func {
        name: "cnc_deltlifegrp",
        doc: "Deletes tool life group `grpno`.",
        params: &[Param::Short("grpno")],
        forms: &[every_class(cmd::DELTLIFEGRP, &[Word::Arg(0)])],
        dims: &["2|0|-1|1|9999|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdtlinfo",
        doc: "Reads the tool life management's limits: groups, tools in a group, life in minutes and in cycles.",
        params: &[Param::Out("tlinfo", "ODBTLINFO")],
        forms: &[
            Form {
                classes: Classes::S30,
                class: cmd::CLASS_CNC,
                cmd: cmd::RDTLINFO,
                words: &[],
            },
            Form {
                classes: Classes::S16,
                class: cmd::CLASS_CNC,
                cmd: cmd::RDNGRP,
                words: &[
                    Word::Const(0),
                    Word::Const(0),
                    Word::Const(0),
                    Word::Const(0),
                    Word::Const(0x10000),
                ],
            },
        ],
        // The first word is the number of groups on the 16i class (cnc_rdngrp's).
        reply: &[
            skip(I32),
            to(I32, "max_group", I32),
            to(I32, "max_tool", I32),
            to(I32, "max_minute", I32),
            to(I32, "max_cycle", I32),
        ],
        learnt: Some(&[]),
        ..COMMAND
    },
];
