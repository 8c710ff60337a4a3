//! The servo functions.

use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;
use super::base::SERVO_LONGS;

// The commands of this area's entries (the simulator answers by them).
/// cnc_rdspdlalm: the spindle alarms.
pub const RDSPDLALM: u16 = 0x005a;
/// cnc_rdpitchinfo: the pitch error compensation data.
pub const RDPITCHINFO: u16 = 0x0014;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdloopgain",
        doc: "Reads the servo loop gain of each axis (4 bytes written per `long`).",
        forms: &[every_class(0x0056, &[Word::Const(0)])],
        ..SERVO_LONGS
    },
    Func {
        name: "cnc_rdsrvspeed",
        doc: "Reads the actual servo motor speed of each axis (4 bytes written per `long`).",
        forms: &[every_class(0x0056, &[Word::Const(2)])],
        ..SERVO_LONGS
    },
    Func {
        name: "cnc_rdcurrent",
        doc: "Reads the actual servo current of each axis.",
        params: &[Param::Out("data", "short")],
        forms: &[every_class(0x0056, &[Word::Const(1)])],
        records: Some(Records {
            fields: &[to(I32, "", I16), skip(I32)],
            out: 0,
            to: "",
            elem: "short",
            max: 32,
            count: None,
            room: None,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdspdlalm",
        doc: "Reads the alarm state of each spindle, one byte per spindle (at most 8).",
        params: &[Param::Out("data", "char")],
        forms: &[every_class(RDSPDLALM, &[])],
        // The low byte of each i16, as many as the answer holds.
        records: Some(Records {
            fields: &[to(I16, "", I8)],
            out: 0,
            to: "",
            elem: "char",
            max: 8,
            count: None,
            room: None,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdpitchinfo",
        doc: "Reads the number of pitch error compensation points.",
        params: &[Param::Out("datano", "short")],
        forms: &[every_class(RDPITCHINFO, &[])],
        reply: &[to(I32, "", I16)],
        ..COMMAND
    },
];
