//! Axes, modes and settings (the long tail): the positions with extra
//! digits, the synchronous errors, the `[MEASURE]` keys' availability, the
//! tool interference check and the coordinate rotation in force.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// What the four positions with extra digits share: every axis's record
/// as the answer holds them (at most 32), the position an IEEE double.
const EXDGT: Func = Func {
    params: &[Param::Out("axis_data", "ODBEXPOS")],
    records: Some(&Records {
        fields: &[
            doubles(0, 1, "data"),
            to(I32, "dec", I32),
            to(I32, "digit", I32),
        ],
        out: 0,
        to: "",
        elem: "ODBEXPOS",
        max: 32,
        count: None,
        room: None,
    }),
    learnt: Some(&[]),
    ..COMMAND
};

/// A position with extra digits's doc.
macro_rules! exdgt {
    ($what:literal) => {
        concat!(
            "Reads ",
            $what,
            " of every axis with extra digits: one ODBEXPOS per axis the answer holds (at most 32), the position a double, its decimal places and digits."
        )
    };
}

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_absolute2_exdgt",
        doc: exdgt!("the absolute position"),
        forms: &[every_class(cmd::EXDGT, &[Word::Const(0)])],
        ..EXDGT
    },
    Func {
        name: "cnc_machine_exdgt",
        doc: exdgt!("the machine position"),
        forms: &[every_class(cmd::EXDGT, &[Word::Const(1)])],
        ..EXDGT
    },
    Func {
        name: "cnc_relative2_exdgt",
        doc: exdgt!("the relative position"),
        forms: &[every_class(cmd::EXDGT, &[Word::Const(2)])],
        ..EXDGT
    },
    Func {
        name: "cnc_distance_exdgt",
        doc: exdgt!("the distance to go"),
        forms: &[every_class(cmd::EXDGT, &[Word::Const(7)])],
        ..EXDGT
    },
    Func {
        name: "cnc_rdsynerrsy",
        learnt: Some(&[]),
        doc: "Reads the synchronous error of the synchronous control mode.",
        params: &[Param::Out("data", "long")],
        forms: &[every_class(cmd::SYNERR, &[Word::Const(0)])],
        reply: &[to(I32, "", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdsynerrrg",
        learnt: Some(&[]),
        doc: "Reads the synchronous error of the rigid tap mode.",
        params: &[Param::Out("data", "long")],
        forms: &[every_class(cmd::SYNERR, &[Word::Const(1)])],
        reply: &[to(I32, "", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdenblinfo",
        learnt: Some(&[]),
        doc: "Reads whether the `[MEASURE]` operation is available (one byte).",
        params: &[Param::Out("info", "char")],
        forms: &[every_class(cmd::RDENBLINFO, &[])],
        reply: &[to(I8, "", I8)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdcenblinfo",
        learnt: Some(&[]),
        doc: "Reads whether the `[MEASURE] [CENTER]` operation is available (one byte).",
        params: &[Param::Out("info", "char")],
        forms: &[every_class(cmd::RDCENBLINFO, &[])],
        reply: &[to(I8, "", I8)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdinterference",
        learnt: Some(&[]),
        doc: "Reads the tool interference check's two tools.",
        params: &[Param::Out("data", "IODBTLINTF")],
        forms: &[every_class(cmd::RDINTERFERENCE, &[])],
        reply: &[Field {
            n: 2,
            ..to(I16, "inf_tool", I16)
        }],
        ..COMMAND
    },
    Func {
        name: "cnc_rdcdrotate",
        learnt: Some(&[]),
        doc: "Reads the coordinate rotation in force: its mode and plane axes (the low 16 bits of each word), the center (the value word of two value records) and the angle.",
        params: &[Param::Out("rot", "ODBROT")],
        forms: &[every_class(cmd::RDCDROTATE, &[])],
        reply: &[
            to(I32, "mode", I16),
            Field {
                n: 2,
                ..to(I32, "pln_axes", I16)
            },
            to(I32, "center[0]", I32),
            skip(I32),
            to(I32, "center[1]", I32),
            skip(I32),
            to(I32, "angle", I32),
            skip(I32),
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_wrtimer",
        learnt: Some(&[]),
        doc: "Writes timer `type` (cnc_rdtimer's: 0 power-on, 1 operating, 2 cutting, 3 cycle, 4 free) from `time`'s minutes and milliseconds, sent as the payload (32 bits each).",
        params: &[Param::Short("type"), Param::In("time", "IODBTIME")],
        forms: &[every_class(cmd::WRTIMER, &[Word::Arg(0)])],
        payload: Some(&Payload {
            fields: &[to(I32, "minute", I32), to(I32, "msec", I32)],
            elem: "IODBTIME",
            count: ONE,
            max: 1,
        }),
        dims: &["4|0|1|2|3|-1|5"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdmdlconfig2",
        learnt: Some(&[
            "written past the pointee: argument 0: 128 bytes written into a 1-byte pointee",
        ]),
        doc: "Reads the CNC module configuration information (2): 128 bytes, the answer's first (a shorter answer's missing bytes as zeros).",
        params: &[Param::Out("data", "char")],
        forms: &[every_class(cmd::RDMDLCONFIG2, &[])],
        reply: &[Field {
            n: 128,
            ..to(I8, "", I8)
        }],
        ..COMMAND
    },
];
