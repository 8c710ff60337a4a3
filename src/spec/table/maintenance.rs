//! Periodic maintenance: the item names and the items
//! (docs/protocol/machine.md, "Periodic maintenance").

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// A 62-byte item name.
const NAME: Field = Field {
    wire: U8,
    n: 62,
    out: 0,
    to: Some(""),
    c: U8,
    arg: None,
};

/// An item (IODBPMAINTE's layout): its name, two bytes nobody reads (sent
/// as zeros), then type, total, remain and stat.
const ITEM: &[Field] = &[
    Field {
        to: Some("name"),
        ..NAME
    },
    skip(U16),
    to(I32, "type", I32),
    to(I32, "total", I32),
    to(I32, "remain", I32),
    to(I32, "stat", I32),
];

/// The count as the second number parameter (every entry but
/// cnc_wrpm_item's) below 1: EW_LENGTH before any traffic.
const COUNTED: &[Check] = &[at_least_one(1)];

/// The request words of every read: `[start, asked]`.
const READ: &[Word] = &[Word::Arg(0), Word::Asked];

/// cnc_rdpm_cncitem / cnc_rdpm_mcnitem: `(1,cmd)[start, asked]`, answered
/// by whole 62-byte names; at most 23 asked (23 × 62 fill one answer).
const fn names(
    name: &'static str,
    doc: &'static str,
    forms: &'static [Form],
    dims: &'static [&'static str],
) -> Func {
    Func {
        name,
        doc,
        params: &[
            Param::Short("start_num"),
            Param::Count("data_num"),
            Param::Out("item", "char[62]"),
        ],
        checks: COUNTED,
        forms,
        records: Some(&Records {
            fields: &[NAME],
            out: 0,
            to: "",
            elem: "char[62]",
            max: 23,
            count: None,
            room: None,
        }),
        dims,
        ..COMMAND
    }
}

pub const FUNCS: &[Func] = &[
    names(
        "cnc_rdpm_cncitem",
        "Reads the names of the CNC's maintenance items from the `start_num`-th on: `*data_num` in is how many (at most 23 are asked), out how many were written; below 1 it is EW_LENGTH without traffic. Never more names than asked are written (FANUC's library writes every name the CNC sends).",
        &[every_class(cmd::RDPM_CNCITEM, READ)],
        &["1|0|-1|2|6|7", "4|1|0|-1|20|23|24|100"],
    ),
    names(
        "cnc_rdpm_mcnitem",
        "Reads the machine tool builder's maintenance item names from the `start_num`-th on, as cnc_rdpm_cncitem.",
        &[every_class(cmd::RDPM_MCNITEM, READ)],
        &["1|0|-1|2|20|21", "4|1|0|-1|20|23|24|100"],
    ),
    Func {
        name: "cnc_rdpm_item",
        doc: "Reads maintenance items from the `start_num`-th on: `*data_num` in is how many (at most 17 are asked), out how many were written; below 1 it is EW_LENGTH without traffic. Each item's name and its four longs are written, the two bytes between them are left as they were, as FANUC's library.",
        params: &[
            Param::Short("start_num"),
            Param::Count("data_num"),
            Param::Out("item", "IODBPMAINTE"),
        ],
        checks: COUNTED,
        forms: &[every_class(cmd::RDPM_ITEM, READ)],
        records: Some(&Records {
            fields: ITEM,
            out: 0,
            to: "",
            elem: "IODBPMAINTE",
            max: 17,
            count: None,
            room: None,
        }),
        dims: &["1|0|-1|2|10|11", "4|1|0|-1|10|17|18|100"],
        ..COMMAND
    },
    Func {
        name: "cnc_wrpm_mcnitem",
        doc: "Writes `data_num` machine tool builder's item names from the `start_num`-th on (at most 22 are sent). `data_num` < 1 is EW_LENGTH without traffic.",
        params: &[
            Param::Short("start_num"),
            Param::Short("data_num"),
            Param::In("item", "char[62]"),
        ],
        checks: COUNTED,
        forms: &[every_class(cmd::WRPM_MCNITEM, &[Word::Arg(0)])],
        payload: Some(&Payload {
            fields: &[NAME],
            elem: "char[62]",
            count: 1,
            max: 22,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_wrpm_item",
        doc: "Writes `data_num` maintenance items from the `start_num`-th on (at most 17 are sent): name, type, total and remain (stat is sent, the CNC keeps its own; the two bytes after the name go as zeros). `reset` 1 starts each item's life anew. `data_num` < 1 is EW_LENGTH without traffic.",
        params: &[
            Param::Short("reset"),
            Param::Short("start_num"),
            Param::Short("data_num"),
            Param::In("item", "IODBPMAINTE"),
        ],
        checks: &[at_least_one(2)],
        forms: &[every_class(cmd::WRPM_ITEM, &[Word::Arg(0), Word::Arg(1)])],
        payload: Some(&Payload {
            fields: ITEM,
            elem: "IODBPMAINTE",
            count: 2,
            max: 17,
        }),
        ..COMMAND
    },
];
