//! The servo functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;
use super::base::SERVO_LONGS;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdloopgain",
        doc: "Reads the servo loop gain of each axis (4 bytes written per `long`).",
        forms: &[every_class(cmd::SERVO_LOAD, &[Word::Const(0)])],
        ..SERVO_LONGS
    },
    Func {
        name: "cnc_rdsrvspeed",
        doc: "Reads the actual servo motor speed of each axis (4 bytes written per `long`).",
        forms: &[every_class(cmd::SERVO_LOAD, &[Word::Const(2)])],
        ..SERVO_LONGS
    },
    Func {
        name: "cnc_rdcurrent",
        doc: "Reads the actual servo current of each axis.",
        params: &[Param::Out("data", "short")],
        forms: &[every_class(cmd::SERVO_LOAD, &[Word::Const(1)])],
        records: Some(&Records {
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
        forms: &[every_class(cmd::RDSPDLALM, &[])],
        // The low byte of each i16, as many as the answer holds.
        records: Some(&Records {
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
        forms: &[every_class(cmd::RDPITCHINFO, &[])],
        reply: &[to(I32, "", I16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdnspdl",
        learnt: Some(&[
            "no request on v2: no traffic (returns 0 locally) (a local answer on that class)",
            "no request on s15: no traffic (returns 0 locally) (a local answer on that class)",
        ]),
        doc: "Reads the number of controlled spindles of the path (16i class and Series 15: the CNC's maximum spindles, learnt at connect, without traffic).",
        params: &[Param::Out("spdl", "short")],
        forms: &[Form {
            classes: Classes::S30,
            class: cmd::CLASS_CNC,
            cmd: cmd::COUNT,
            words: &[Word::Const(1)],
        }],
        reply: &[to(I16, "", I16)],
        local: Some(&Local {
            classes: Classes::S16,
            values: &[Learnt::MaxSpindles],
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdposerrs",
        learnt: Some(&[
            "written past the pointee: argument 0: 32 bytes written into a N-byte pointee",
        ]),
        doc: "Reads the position deviation of each spindle (spindle position control), one `long` per spindle (at most 8; 4 bytes written per `long`).",
        params: &[Param::Out("data", "long")],
        forms: &[every_class(cmd::POSERR, &[Word::Const(0)])],
        records: Some(&Records {
            fields: &[to(I32, "", I32), skip(I32)],
            out: 0,
            to: "",
            elem: "long",
            max: 8,
            count: None,
            room: None,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdposerrs2",
        learnt: Some(&[
            "the reply maps otherwise on S16",
            "the reply maps otherwise on S15",
            "1 more subpackets or frames after the first",
            "S16: every coded reply was refused (a count, length or type tag inside)",
            "S15: every coded reply was refused (a count, length or type tag inside)",
        ]),
        doc: "Reads the position deviations of spindles 1 and 2 (spindle position control).",
        params: &[Param::Out("poserr", "ODBPSER")],
        forms: &[every_class(cmd::POSERR, &[Word::Const(1)])],
        more: &[&[Word::Const(2)]],
        reply: &[to(I32, "poserr1", I32), to(I32, "poserr2", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdposerrz",
        learnt: Some(&[]),
        doc: "Reads the position deviation of the Z axis in the rigid tapping mode.",
        params: &[Param::Out("data", "long")],
        forms: &[every_class(cmd::POSERR, &[Word::Const(3)])],
        reply: &[to(I32, "", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_rd3dtooltip",
        learnt: Some(&[
            "3 more subpackets or frames after the first",
            "every coded reply was refused (a count, length or type tag inside)",
            "no output written and no input read",
        ]),
        doc: "Reads the tool tip of the 3D handle feed (needs the FOCAS option, else EW_NOOPT; the elements past the CNC's axes are not written).",
        params: &[Param::Out("data", "ODB3DHDL")],
        checks: &[NEEDS_OPTION],
        forms: &[every_class(cmd::HDL3D_AXES, &[Word::Const(1)])],
        more: &[&[Word::Const(1)], &[Word::Const(2)], &[Word::Const(2)]],
        more_cmds: &[cmd::HDL3D_TIP, cmd::HDL3D_AXES, cmd::HDL3D_TIP],
        // The axes from 0x0110[1], the value word of each 0x0111[1] record;
        // the second pair ([2]) is not read (deviation 3dtooltip_second).
        reply: &[
            Field {
                n: 5,
                ..to(I16, "axes", I16)
            },
            Field {
                n: 5,
                ..to(I32, "data", I32)
            },
        ],
        columns: Some(&Columns {
            stride: &[2, 8],
            none: crate::ew::EW_NOOPT,
        }),
        ..COMMAND
    },
];
