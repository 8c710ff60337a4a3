//! The tool management reads of the tool life state (the limits, the
//! groups in use, one tool of a group) and the magazine.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;
use crate::ew::EW_NUMBER;

/// One pot of the magazine management data as the wire carries it: i32
/// magazine, pot, tool management data number, each cut to a `short`.
const POT_RECORD: &[Field] = &[
    to(I32, "magazine", I16),
    to(I32, "pot", I16),
    to(I32, "tool_index", I16),
];

/// A `*num` below 1: EW_NUMBER before any traffic.
const NUM_AT_LEAST_ONE: Check = Check {
    arg: 0,
    lo: 1,
    hi: i32::MAX,
    code: EW_NUMBER,
};

/// One tool management record as cnc_wrtool sends it (the 39 words of
/// cnc_rdtool's answer): the `short` members sign-extended, the unsigned
/// ones zero-extended, `grp` and `edge` the two halves of one word, `edge_num`, `reserve_c` and
/// `reserved` not sent.
const TOOL_RECORD: &[Field] = &[
    to(I32, "T_code", I32),
    to(I32, "life_count", I32),
    to(I32, "max_life", I32),
    to(I32, "rest_life", I32),
    to(I32, "life_stat", U8),
    to(I32, "cust_bits", U8),
    to(I32, "tool_info", U16),
    to(I32, "H_code", I16),
    to(I32, "D_code", I16),
    to(I32, "spindle_speed", I32),
    to(I32, "feedrate", I32),
    to(I32, "magazine", I16),
    to(I32, "pot", I16),
    to(I32, "G_code", I16),
    to(I32, "W_code", I16),
    to(I32, "gno", I16),
    to(I16, "grp", I16),
    to(I16, "edge", I16),
    to(I32, "org_magazine", I16),
    to(I32, "org_pot", I16),
    to(I32, "custom1", I32),
    to(I32, "custom2", I32),
    to(I32, "custom3", I32),
    to(I32, "custom4", I32),
    to(I32, "custom5", I32),
    to(I32, "custom6", I32),
    to(I32, "custom7", I32),
    to(I32, "custom8", I32),
    to(I32, "custom9", I32),
    to(I32, "custom10", I32),
    to(I32, "custom11", I32),
    to(I32, "custom12", I32),
    to(I32, "custom13", I32),
    to(I32, "custom14", I32),
    to(I32, "custom15", I32),
    to(I32, "custom16", I32),
    to(I32, "custom17", I32),
    to(I32, "custom18", I32),
    to(I32, "custom19", I32),
    to(I32, "custom20", I32),
];

/// [`TOOL_RECORD`] with 40 custom data (cnc_regtool_f2's IODBTLMNG_F2).
const TOOL_RECORD_F2: &[Field] = &[
    to(I32, "T_code", I32),
    to(I32, "life_count", I32),
    to(I32, "max_life", I32),
    to(I32, "rest_life", I32),
    to(I32, "life_stat", U8),
    to(I32, "cust_bits", U8),
    to(I32, "tool_info", U16),
    to(I32, "H_code", I16),
    to(I32, "D_code", I16),
    to(I32, "spindle_speed", I32),
    to(I32, "feedrate", I32),
    to(I32, "magazine", I16),
    to(I32, "pot", I16),
    to(I32, "G_code", I16),
    to(I32, "W_code", I16),
    to(I32, "gno", I16),
    to(I16, "grp", I16),
    to(I16, "edge", I16),
    to(I32, "org_magazine", I16),
    to(I32, "org_pot", I16),
    to(I32, "custom1", I32),
    to(I32, "custom2", I32),
    to(I32, "custom3", I32),
    to(I32, "custom4", I32),
    to(I32, "custom5", I32),
    to(I32, "custom6", I32),
    to(I32, "custom7", I32),
    to(I32, "custom8", I32),
    to(I32, "custom9", I32),
    to(I32, "custom10", I32),
    to(I32, "custom11", I32),
    to(I32, "custom12", I32),
    to(I32, "custom13", I32),
    to(I32, "custom14", I32),
    to(I32, "custom15", I32),
    to(I32, "custom16", I32),
    to(I32, "custom17", I32),
    to(I32, "custom18", I32),
    to(I32, "custom19", I32),
    to(I32, "custom20", I32),
    to(I32, "custom21", I32),
    to(I32, "custom22", I32),
    to(I32, "custom23", I32),
    to(I32, "custom24", I32),
    to(I32, "custom25", I32),
    to(I32, "custom26", I32),
    to(I32, "custom27", I32),
    to(I32, "custom28", I32),
    to(I32, "custom29", I32),
    to(I32, "custom30", I32),
    to(I32, "custom31", I32),
    to(I32, "custom32", I32),
    to(I32, "custom33", I32),
    to(I32, "custom34", I32),
    to(I32, "custom35", I32),
    to(I32, "custom36", I32),
    to(I32, "custom37", I32),
    to(I32, "custom38", I32),
    to(I32, "custom39", I32),
    to(I32, "custom40", I32),
];

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdmaxgrp",
        doc: "Reads the most tool life groups the CNC manages (`data`; `datano` and `type` untouched).",
        params: &[Param::Out("maxgrp", "ODBLFNO")],
        forms: &[every_class(cmd::RDNGRP, &[])],
        // The number of groups, then the limits (cnc_rdtlinfo's on the 16i class).
        reply: &[skip(I32), to(I32, "data", I16)],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdmaxtool",
        doc: "Reads the most tools a tool life group holds (`data`; `datano` and `type` untouched).",
        params: &[Param::Out("maxtool", "ODBLFNO")],
        forms: &[every_class(cmd::RDNGRP, &[])],
        reply: &[skip(I32), skip(I32), to(I32, "data", I16)],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdusegrpid",
        doc: "Reads the next, in-use and selected tool life groups (`datano` and `type` untouched).",
        params: &[Param::Out("usegrp", "ODBUSEGR")],
        forms: &[every_class(cmd::TLUSEGRP, &[])],
        reply: &[
            to(I32, "next", I32),
            to(I32, "use", I32),
            to(I32, "slct", I32),
        ],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rd1tlifedata",
        doc: "Reads tool `tuse_num` of tool life group `grp_num`: its number, H and D codes and information (`datano` the group the CNC answered; `type` untouched).",
        params: &[
            Param::Short("grp_num"),
            Param::Short("tuse_num"),
            Param::Out("tldata", "IODBTD"),
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
        // An answer for group 0: H, D codes and information read 0.
        zero_without_first: true,
        zeroed: &["h_code", "d_code", "tool_inf"],
        dims: &["1|0|-1|2|9999", "1|0|-1|2|99"],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rd2tlifedata",
        doc: "Reads tool `tuse_num` of tool life group `grp_num` (cnc_toolnum's request): `datano` the group and `type` the use number the CNC answered, the tool's number, H and D codes and information.",
        params: &[
            Param::Short("grp_num"),
            Param::Short("tuse_num"),
            Param::Out("tldata", "IODBTD"),
        ],
        forms: &[every_class(
            cmd::TLTOOLS,
            &[Word::Arg(0), Word::Arg(1), Word::Arg(1)],
        )],
        reply: &[
            to(I32, "datano", I16),
            to(I32, "type", I16),
            to(I32, "tool_num", I32),
            to(I32, "h_code", I32),
            to(I32, "d_code", I32),
            to(I32, "tool_inf", I32),
        ],
        short: Short::Request,
        // An answer for group 0: the tool's fields read 0 (`type` as sent).
        zero_without_first: true,
        zeroed: &["tool_num", "h_code", "d_code", "tool_inf"],
        dims: &["1|0|-1|2|9999", "1|0|-1|2|99"],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_wrmagazine",
        doc: "Puts tool management data number `tool_index` in pot `pot` of magazine `magazine` (0: empties the pot); the three go as request words, no local check.",
        params: &[
            Param::Short("magazine"),
            Param::Short("pot"),
            Param::Short("tool_index"),
        ],
        forms: &[every_class(
            cmd::WRMAGAZINE,
            &[Word::Arg(0), Word::Arg(1), Word::Arg(2)],
        )],
        dims: &["1|0|-1|2|9999", "3|0|-1|1|9999", "2|0|-1|1|9999"],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_wrtool",
        doc: "Writes tool management data number `tool_no` from `tool` (the record cnc_rdtool reads; `edge_num`, `reserve_c` and `reserved` are not sent). `tool_no` < 1 is EW_NUMBER without traffic.",
        params: &[Param::Short("tool_no"), Param::In("tool", "IODBTLMNG")],
        checks: &[Check {
            arg: 0,
            lo: 1,
            hi: i32::MAX,
            code: EW_NUMBER,
        }],
        forms: &[every_class(cmd::WRTOOL, &[Word::Arg(0)])],
        payload: Some(&Payload {
            fields: TOOL_RECORD,
            elem: "IODBTLMNG",
            count: ONE,
            max: 1,
        }),
        dims: &["2|0|-1|1|3|99"],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdmagazine",
        doc: "Reads the tool management data number in each of the `*num` pots `data` names (`magazine`, `pot`) into its `tool_index`, 118 pots per request; `*num` becomes the pots read. `*num` < 1 is EW_NUMBER without traffic.",
        params: &[Param::Count("num"), Param::InOut("data", "IODBTLMAG")],
        checks: &[NUM_AT_LEAST_ONE],
        forms: &[every_class(cmd::RDMAGAZINE, &[])],
        // The pots answered, then their records.
        reply: &[skip(I32)],
        records: Some(&Records {
            fields: POT_RECORD,
            out: 0,
            to: "",
            elem: "IODBTLMAG",
            max: 118,
            count: None,
            room: None,
        }),
        payload: Some(&Payload {
            fields: &[to(I32, "magazine", I16), to(I32, "pot", I16), skip(I32)],
            elem: "IODBTLMAG",
            count: 0,
            max: i16::MAX as u16,
        }),
        counted: Some(0),
        // Records past the answer's end read as the request's bytes there.
        short: Short::Request,
        // At most 1416 payload bytes a request (118 pots of 12 bytes, 177
        // of 8, 9 tools of 156).
        pages: Some(Pages {
            bytes: 1416,
            advance: None,
            from_done: true,
            room: None,
            until_short: false,
        }),
        learnt: Some(&[
            "crashed on coded replies (8, 64, 1428 bytes): the answer's first word is the pots' count, which a coded reply makes huge (records past *num written); probed with counted answers (1, 2 of 4 with 1 record, 5 of 4)",
            "every coded reply was refused: the count and the pots asked again while done < *num; settled by recording",
        ]),
        ..COMMAND
    },
    Func {
        name: "cnc_regmagazine",
        doc: "Registers the `*num` pots of `data` (`magazine`, `pot` and the tool management data number `tool_index` put in it), 118 per request; `*num` becomes the pots the CNC registered. `*num` < 1 is EW_NUMBER without traffic;.",
        params: &[Param::Count("num"), Param::In("data", "IODBTLMAG")],
        checks: &[NUM_AT_LEAST_ONE],
        forms: &[every_class(cmd::REGMAGAZINE, &[])],
        // The pots registered.
        reply: &[skip(I32)],
        payload: Some(&Payload {
            fields: POT_RECORD,
            elem: "IODBTLMAG",
            count: 0,
            max: i16::MAX as u16,
        }),
        pages: Some(Pages {
            bytes: 1416,
            advance: None,
            from_done: false,
            room: None,
            until_short: false,
        }),
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_delmagazine",
        doc: "Deletes the `*num` pots of `data` (`magazine`, `pot`) from the magazine management data, 177 per request; `*num` becomes the pots the CNC deleted. `*num` < 1 is EW_NUMBER without traffic;.",
        params: &[Param::Count("num"), Param::In("data", "IODBTLMAG2")],
        checks: &[NUM_AT_LEAST_ONE],
        forms: &[every_class(cmd::DELMAGAZINE, &[])],
        // The pots deleted.
        reply: &[skip(I32)],
        payload: Some(&Payload {
            fields: &[to(I32, "magazine", I16), to(I32, "pot", I16)],
            elem: "IODBTLMAG2",
            count: 0,
            max: i16::MAX as u16,
        }),
        pages: Some(Pages {
            bytes: 1416,
            advance: None,
            from_done: false,
            room: None,
            until_short: false,
        }),
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_regtool",
        doc: "Registers the `*num` tools of `tool` as tool management data numbers `top`, `top` + 1 ... (cnc_wrtool's record each), 9 per request, each request's number moved on by the tools registered; `*num` becomes the tools the CNC registered. `top` < 1 is EW_NUMBER without traffic.",
        params: &[
            Param::Short("top"),
            Param::Count("num"),
            Param::In("tool", "IODBTLMNG"),
        ],
        checks: &[Check {
            arg: 0,
            lo: 1,
            hi: i32::MAX,
            code: EW_NUMBER,
        }],
        forms: &[every_class(cmd::REGTOOL, &[Word::Arg(0)])],
        // The tools registered.
        reply: &[skip(I32)],
        payload: Some(&Payload {
            fields: TOOL_RECORD,
            elem: "IODBTLMNG",
            count: 1,
            max: i16::MAX as u16,
        }),
        pages: Some(Pages {
            bytes: 1416,
            advance: Some(0),
            from_done: false,
            room: None,
            until_short: false,
        }),
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_regtool_f2",
        doc: "cnc_regtool with 40 custom data: registers the `*num` tools of `tool` as tool management data numbers `top`, `top` + 1 ... (59 words each), 6 per request, each request's number moved on by the tools registered; `*num` becomes the tools the CNC registered. `top` < 1 is EW_NUMBER without traffic.",
        params: &[
            Param::Short("top"),
            Param::Count("num"),
            Param::In("tool", "IODBTLMNG_F2"),
        ],
        checks: &[Check {
            arg: 0,
            lo: 1,
            hi: i32::MAX,
            code: EW_NUMBER,
        }],
        forms: &[every_class(cmd::REGTOOL_F2, &[Word::Arg(0)])],
        // The tools registered.
        reply: &[skip(I32)],
        payload: Some(&Payload {
            fields: TOOL_RECORD_F2,
            elem: "IODBTLMNG_F2",
            count: 1,
            max: i16::MAX as u16,
        }),
        pages: Some(Pages {
            bytes: 1416,
            advance: Some(0),
            from_done: false,
            room: None,
            until_short: false,
        }),
        learnt: Some(&[]),
        ..COMMAND
    },
];
