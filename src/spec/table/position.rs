//! The per-axis position reads: (1,0x0026)[code, axis] into ODBAXIS
//! (cnc_absolute & co.).

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;
use crate::ew::EW_ATTRIB;

/// What every per-axis read shares (its doc: `doc!`): the axis
/// checked against 32 (FANUC's MAX_AXIS; 0, -2 ... go to the CNC), `type`
/// the axis echoed, then each whole value record's value word (its base
/// and exponent not read), the records held to the caller's `length`.
const AXIS_VALUES: Func = Func {
    params: &[
        Param::Short("axis"),
        // Read unsigned: -1 is 65535 bytes.
        Param::ShortAs("length", U16),
        Param::Out("buf", "ODBAXIS"),
    ],
    checks: &[Check {
        arg: 0,
        lo: i16::MIN as i32,
        hi: 32,
        code: EW_ATTRIB,
    }],
    reply: &[echo(0, "type", I16)],
    records: Some(&Records {
        fields: &[to(I32, "", I32), skip(U16), skip(I16)],
        out: 0,
        to: "data",
        elem: "long",
        max: 32,
        count: None,
        room: Some(1),
    }),
    dims: &[AXIS, AXLEN],
    ..COMMAND
};

/// The oracle's dimensions: the axis, then `length`.
const AXIS: &str = "1|-1|2|3|0|4|32|33|-2";
const AXLEN: &str = "8|4|7|12|0|-1|132|136";
/// The dimensions the skip and delay reads were recorded with.
const FEWER: &[&str] = &["1|-1|0|2|3|4|33", "8|4|12|0|-1|132"];

/// A position read's doc: what it reads, then what they all do.
macro_rules! doc {
    ($what:literal) => {
        concat!(
            "Reads ",
            $what,
            " of axis `axis` (1..) or of every axis (-1): an axis above 32 is EW_ATTRIB before any traffic; every whole value record answered (at most 32) must fit in `length` (4 + 4 bytes a record, read as an unsigned short), else EW_LENGTH, nothing written; then `type` = `axis` and the records' values (an empty answer writes `type` alone)."
        )
    };
}

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_absolute",
        doc: doc!("the absolute position"),
        forms: &[every_class(cmd::POSITION, &[Word::Const(4), Word::Arg(0)])],
        ..AXIS_VALUES
    },
    Func {
        name: "cnc_absolute2",
        doc: doc!("the absolute position (second form)"),
        forms: &[every_class(cmd::POSITION, &[Word::Const(0), Word::Arg(0)])],
        ..AXIS_VALUES
    },
    Func {
        name: "cnc_machine",
        doc: doc!("the machine position"),
        forms: &[every_class(cmd::POSITION, &[Word::Const(1), Word::Arg(0)])],
        ..AXIS_VALUES
    },
    Func {
        name: "cnc_relative",
        doc: doc!("the relative position"),
        forms: &[every_class(cmd::POSITION, &[Word::Const(6), Word::Arg(0)])],
        ..AXIS_VALUES
    },
    Func {
        name: "cnc_relative2",
        doc: doc!("the relative position (second form)"),
        forms: &[every_class(cmd::POSITION, &[Word::Const(2), Word::Arg(0)])],
        ..AXIS_VALUES
    },
    Func {
        name: "cnc_distance",
        doc: doc!("the distance to go"),
        forms: &[every_class(cmd::POSITION, &[Word::Const(7), Word::Arg(0)])],
        ..AXIS_VALUES
    },
    Func {
        name: "cnc_skip",
        doc: doc!("the skip position (where the skip signal came)"),
        forms: &[every_class(cmd::POSITION, &[Word::Const(8), Word::Arg(0)])],
        dims: FEWER,
        ..AXIS_VALUES
    },
    Func {
        name: "cnc_srvdelay",
        doc: doc!("the servo delay (position deviation)"),
        forms: &[every_class(cmd::POSITION, &[Word::Const(9), Word::Arg(0)])],
        dims: FEWER,
        ..AXIS_VALUES
    },
    Func {
        name: "cnc_accdecdly",
        doc: doc!("the acceleration/deceleration delay"),
        forms: &[every_class(cmd::POSITION, &[Word::Const(10), Word::Arg(0)])],
        dims: FEWER,
        ..AXIS_VALUES
    },
];
