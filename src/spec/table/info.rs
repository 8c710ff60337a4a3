//! The machine information functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdproctime",
        doc: "Reads the machining times of the last programs run.",
        params: &[Param::Out("proc_time", "ODBPTIME")],
        forms: &[every_class(cmd::RDPROCTIME, &[])],
        // Whole 12-byte records, their number written to `num`.
        records: Some(Records {
            fields: &[
                to(I32, "prg_no", I32),
                to(I16, "hour", I16),
                to(I16, "minute", I8),
                to(I16, "second", I8),
                skip(I16),
            ],
            out: 0,
            to: "data",
            elem: "ODBPTIME_DATA",
            max: 10,
            count: Some("num"),
            room: None,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdetherinfo",
        doc: "Reads the Ethernet board's type and device.",
        params: &[Param::Out("type", "short"), Param::Out("device", "short")],
        forms: &[every_class(cmd::RDETHERINFO, &[])],
        reply: &[to_out(0, I16, "", I16), to_out(1, I16, "", I16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdsyshard",
        learnt: Some(&[
            "the answer's count (its 32-bit word's low half) is the records' number: probed",
        ]),
        doc: "Reads the CNC's boards (hardware IDs) from the `s_no`-th on: `*num` in is how many (sent as it is), out how many were written (the count the CNC answered). Never more boards than asked are written (FANUC's library writes as many as the CNC's count says).",
        params: &[
            Param::Short("s_no"),
            Param::Count("num"),
            Param::Out("syshard", "ODBSYSH"),
        ],
        forms: &[every_class(cmd::RDSYSHARD, &[Word::Arg(0), Word::Arg(1)])],
        // A 32-bit count: FANUC's library takes its low half as a short.
        reply: &[skip(I16), skip(I16)],
        records: Some(Records {
            fields: &[
                to(U32, "id1", U32),
                to(U32, "id2", U32),
                to(I16, "group_id", I16),
                to(I16, "hard_id", I16),
                to(I16, "hard_num", I16),
                to(I16, "slot_no", I16),
                to(I16, "id1_format", I16),
                to(I16, "id2_format", I16),
            ],
            out: 0,
            to: "",
            elem: "ODBSYSH",
            // As many as one answer holds.
            max: 71,
            count: None,
            room: None,
        }),
        counted: Some(1),
        dims: &["1|0|-1|2|6|7|100", "4|0|-1|1|2|71|72|200"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdsyssoft3",
        learnt: Some(&["the answer's first word is the records' number: probed"]),
        doc: "Reads the CNC's software series and editions from the `s_no`-th on: `*num` in is how many (sent as it is), out how many were written (the count the CNC answered); `*total` is how many the CNC has. Never more entries than asked are written (FANUC's library writes as many as the CNC's count says).",
        params: &[
            Param::Short("s_no"),
            Param::Count("num"),
            Param::Out("total", "short"),
            Param::Out("syssoft", "ODBSYSS3"),
        ],
        forms: &[every_class(cmd::RDSYSSOFT3, &[Word::Arg(0), Word::Arg(1)])],
        reply: &[skip(I16), to_out(0, I16, "", I16)],
        records: Some(Records {
            fields: &[
                to_out(1, I16, "soft_id", I16),
                Field {
                    wire: I8,
                    n: 5,
                    out: 1,
                    to: Some("soft_series"),
                    c: I8,
                    arg: None,
                },
                Field {
                    wire: I8,
                    n: 5,
                    out: 1,
                    to: Some("soft_edition"),
                    c: I8,
                    arg: None,
                },
            ],
            out: 1,
            to: "",
            elem: "ODBSYSS3",
            // As many as one answer holds.
            max: 118,
            count: None,
            room: None,
        }),
        counted: Some(0),
        dims: &["1|0|-1|2|8|9|100", "4|0|-1|1|2|118|119|200"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdservoid",
        learnt: Some(&[]),
        doc: "Reads the specification and serial number of the servo motor, pulse coder, servo amplifier and power supply of axis `axis` (`slct` sent as the second word); the characters as the CNC sent them.",
        params: &[
            Param::Short("axis"),
            Param::Short("slct"),
            Param::Out("servoid", "ODBCSVID"),
        ],
        forms: &[every_class(cmd::RDSERVOID, &[Word::Arg(0), Word::Arg(1)])],
        reply: SERVO_ID,
        dims: &["1|0|-1|2|3|4|32|33", "0|1|-1|2"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdspindleid",
        learnt: Some(&[]),
        doc: "Reads the specification and serial number of the motor, sub motor, amplifier and power supply of spindle `sp_no` (`slct` sent as the second word); the characters as the CNC sent them.",
        params: &[
            Param::Short("sp_no"),
            Param::Short("slct"),
            Param::Out("spindleid", "ODBCSPID"),
        ],
        forms: &[every_class(cmd::RDSPINDLEID, &[Word::Arg(0), Word::Arg(1)])],
        reply: SPINDLE_ID,
        dims: &["1|0|-1|2|8|9", "0|1|-1|2"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdfromservoid",
        learnt: Some(&[]),
        doc: "Reads the servo ID information of axis `axis` the CNC saved (its last ID check), as cnc_rdservoid.",
        params: &[Param::Short("axis"), Param::Out("servoid", "ODBCSVID")],
        forms: &[every_class(cmd::RDFROMSERVOID, &[Word::Arg(0)])],
        reply: SERVO_ID,
        dims: &["1|0|-1|2|3|4|32|33"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdfromspindleid",
        learnt: Some(&[]),
        doc: "Reads the spindle ID information of spindle `sp_no` the CNC saved (its last ID check), as cnc_rdspindleid.",
        params: &[Param::Short("sp_no"), Param::Out("spindleid", "ODBCSPID")],
        forms: &[every_class(cmd::RDFROMSPINDLEID, &[Word::Arg(0)])],
        reply: SPINDLE_ID,
        dims: &["1|0|-1|2|8|9"],
        ..COMMAND
    },
];

/// `n` characters of the answer into output 0's member `to`, as sent.
const fn chars(n: u16, to: &'static str) -> Field {
    Field {
        wire: I8,
        n,
        out: 0,
        to: Some(to),
        c: I8,
        arg: None,
    }
}

/// ODBCSVID's 129 bytes, copied as the CNC sent them.
const SERVO_ID: &[Field] = &[
    chars(20, "mt_spc"),
    chars(10, "mt_srn"),
    chars(22, "plc_spc"),
    chars(9, "plc_srn"),
    chars(22, "svm_spc"),
    chars(12, "svm_srn"),
    chars(22, "psm_spc"),
    chars(12, "psm_srn"),
];

/// ODBCSPID's 128 bytes, copied as the CNC sent them.
const SPINDLE_ID: &[Field] = &[
    chars(20, "mt_spc"),
    chars(10, "mt_srn"),
    chars(20, "sbmt_spc"),
    chars(10, "sbmt_srn"),
    chars(22, "spm_spc"),
    chars(12, "spm_srn"),
    chars(22, "psm_spc"),
    chars(12, "psm_srn"),
];
