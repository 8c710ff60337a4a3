//! The machine information functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// The reply of cnc_rdsyssoft (its 664 bytes; cnc_rdsyssoft2 reads 160
/// more, [`SYSSOFT2_MORE`]) as FANUC's library reads it (payload offsets):
/// the physical slots at 0 (0xff ends the list), module IDs by physical
/// slot at 16 (slots below 0x80) and 48, software IDs likewise at 80 and
/// 112, the logical slots' table at 144 (16 words, the high byte a physical
/// slot), series and version (4 + 4 characters) by logical slot at 208, the
/// pairs of boot, servo, PMC and ladder at 336, two more pairs at 368,
/// `soft_inst` the byte at 465, and 24 pairs from 472 on. Every character
/// 0xff reads as 0 ([`Int::IdChar`]); the pairs go to the members by the
/// lookups ([`SYSSOFT_LOOKUPS`]).
const SYSSOFT_REPLY: &[Field] = &[
    Field {
        wire: I8,
        n: 16,
        out: 0,
        to: Some("slot_no_p"),
        c: I8,
        arg: None,
    },
    skips(I16, 16),
    skips(I16, 16),
    skips(I16, 16),
    skips(I16, 16),
    skips(U8, 32),
    skips(U8, 32),
    skips(IdChar, 128),
    skips(IdChar, 32),
    skips(IdChar, 8),
    skips(U8, 89),
    to(U8, "soft_inst", I16),
    skips(U8, 6),
    skips(IdChar, 192),
];

/// cnc_rdsyssoft2's reply: cnc_rdsyssoft's, then 20 more pairs from 664.
const SYSSOFT2_REPLY: &[Field] = &[
    SYSSOFT_REPLY[0],
    SYSSOFT_REPLY[1],
    SYSSOFT_REPLY[2],
    SYSSOFT_REPLY[3],
    SYSSOFT_REPLY[4],
    SYSSOFT_REPLY[5],
    SYSSOFT_REPLY[6],
    SYSSOFT_REPLY[7],
    SYSSOFT_REPLY[8],
    SYSSOFT_REPLY[9],
    SYSSOFT_REPLY[10],
    SYSSOFT_REPLY[11],
    SYSSOFT_REPLY[12],
    SYSSOFT_REPLY[13],
    skips(IdChar, 160),
];

/// `SYSSOFT_REPLY`'s field of the physical slots.
pub const SLOTS: u8 = 0;
/// Its fields of the module IDs (slots below 0x80, then from 0x80).
pub const MODULES: (u8, u8) = (1, 2);
/// Its fields of the software IDs.
pub const SOFTS: (u8, u8) = (3, 4);
/// Its field of the logical slots' table (bytes: the high byte of word j
/// is element 2j).
pub const LOGICAL: u8 = 5;
/// Its field of the series and versions by logical slot (8 characters
/// each).
pub const SERIES: u8 = 7;
/// The fields of named pairs (a series, then a version, 4 characters
/// each), in wire order, and whose pairs they are (the members' names less
/// `_ser`/`_ver`; `""`: a reserved pair); the pairs go to consecutive
/// 5-byte members: field 8 from `boot_ser` on, 9 to `reserve[6]` and
/// `reserve[7]`, 13 from `mcrlib_ser` (to `reserve[5]`), cnc_rdsyssoft2's
/// 14 from `embEthe_ser`.
pub const SYSSOFT_PAIRS: &[(u8, &[&str])] = &[
    (8, &["boot", "servo", "pmc", "ladder"]),
    (9, &["", ""]),
    (13, NAMES13),
    (14, NAMES14),
];
const NAMES13: &[&str] = &[
    "mcrlib",
    "mcrapl",
    "spl1",
    "spl2",
    "spl3",
    "c_exelib",
    "c_exeapl",
    "int_vga",
    "out_vga",
    "pmm",
    "pmc_mng",
    "pmc_shin",
    "pmc_shout",
    "pmc_c",
    "pmc_edit",
    "lddr_mng",
    "lddr_apl",
    "spl4",
    "mcr2",
    "mcr3",
    "eth_boot",
    "",
    "",
    "",
];
const NAMES14: &[&str] = &[
    "embEthe", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "", "",
];

/// FANUC's library's lookups of cnc_rdsyssoft and cnc_rdsyssoft2: each
/// physical slot's logical slot (its index in the logical table; 0xff
/// none), module and software IDs by physical slot (0xffff past the
/// list), series and version by logical slot (zeros from the first slot
/// without one); then the named pairs, each 4 characters and a NUL.
const SYSSOFT_LOOKUPS: &[Lookup] = &[
    Lookup {
        to: "slot_no_l",
        c: I8,
        n: 16,
        fill: -1,
        key: Key::Field(SLOTS),
        end: 0xff,
        pick: Pick::Index {
            field: LOGICAL,
            stride: 2,
            n: 16,
        },
    },
    Lookup {
        to: "module_id",
        c: I16,
        n: 16,
        fill: -1,
        key: Key::Field(SLOTS),
        end: 0xff,
        pick: Pick::Split {
            mask: 0xf,
            low: MODULES.0,
            high: MODULES.1,
        },
    },
    Lookup {
        to: "soft_id",
        c: I16,
        n: 16,
        fill: -1,
        key: Key::Field(SLOTS),
        end: 0xff,
        pick: Pick::Split {
            mask: 0xf,
            low: SOFTS.0,
            high: SOFTS.1,
        },
    },
    Lookup {
        to: "soft_series",
        c: I8,
        n: 16,
        fill: 0,
        key: Key::Lookup(0),
        end: 0xff,
        pick: Pick::Chars {
            field: SERIES,
            stride: 8,
            at: 0,
            width: 4,
        },
    },
    Lookup {
        to: "soft_version",
        c: I8,
        n: 16,
        fill: 0,
        key: Key::Lookup(0),
        end: 0xff,
        pick: Pick::Chars {
            field: SERIES,
            stride: 8,
            at: 4,
            width: 4,
        },
    },
    pairs("boot_ser", 8, 8),
    pairs("reserve[30]", 9, 2),
    pairs("mcrlib_ser", 13, 48),
];

/// cnc_rdsyssoft2's lookups: cnc_rdsyssoft's, then its 20 more pairs.
const SYSSOFT2_LOOKUPS: &[Lookup] = &[
    SYSSOFT_LOOKUPS[0],
    SYSSOFT_LOOKUPS[1],
    SYSSOFT_LOOKUPS[2],
    SYSSOFT_LOOKUPS[3],
    SYSSOFT_LOOKUPS[4],
    SYSSOFT_LOOKUPS[5],
    SYSSOFT_LOOKUPS[6],
    SYSSOFT_LOOKUPS[7],
    pairs("embEthe_ser", 14, 40),
];

/// `n` runs of 4 characters of reply field `field`, each then a NUL, into
/// consecutive 5-byte members from `to` on.
const fn pairs(to: &'static str, field: u8, n: u16) -> Lookup {
    Lookup {
        to,
        c: I8,
        n,
        fill: 0,
        key: Key::Own,
        end: 0xff,
        pick: Pick::Chars {
            field,
            stride: 4,
            at: 0,
            width: 4,
        },
    }
}

/// `n` reply integers nobody reads as they are (a lookup's table).
const fn skips(wire: Int, n: u16) -> Field {
    Field {
        wire,
        n,
        out: 0,
        to: None,
        c: wire,
        arg: None,
    }
}

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdproctime",
        doc: "Reads the machining times of the last programs run.",
        params: &[Param::Out("proc_time", "ODBPTIME")],
        forms: &[every_class(cmd::RDPROCTIME, &[])],
        // Whole 12-byte records, their number written to `num`.
        records: Some(&Records {
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
        records: Some(&Records {
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
        records: Some(&Records {
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
        name: "cnc_rdsyssoft",
        learnt: Some(&[
            "slot_no_l, module_id, soft_id, soft_series and soft_version looked up by slot (Lookup): disassembled, probed",
            "series and versions: 4 characters, 0xff read as 0, then a NUL: probed",
            "reserve[6] and reserve[7] from offsets 368 and 372, eth_boot and reserve[0..6] from 632 on: probed",
        ]),
        doc: "Reads the CNC's slots and software: the physical slots as sent (0xff ends the list), each one's logical slot (its place in the CNC's logical table; 0xff none), module and software ID (0xffff past the list), the series and version of the software on each, then the named software's series and versions (4 characters, 0xff as 0, then a NUL).",
        params: &[Param::Out("syssoft", "ODBSYSS")],
        forms: &[every_class(cmd::RDSYSSOFT, &[])],
        reply: SYSSOFT_REPLY,
        lookups: SYSSOFT_LOOKUPS,
        ..COMMAND
    },
    Func {
        name: "cnc_rdsyssoft2",
        learnt: Some(&[
            "as cnc_rdsyssoft, then embEthe and reserve2 from offset 664 on: disassembled, probed",
        ]),
        doc: "Reads the CNC's slots and software as cnc_rdsyssoft, then the embedded Ethernet's series and version and the reserved pairs after it.",
        params: &[Param::Out("syssoft", "ODBSYSS2")],
        forms: &[every_class(cmd::RDSYSSOFT, &[])],
        reply: SYSSOFT2_REPLY,
        lookups: SYSSOFT2_LOOKUPS,
        ..COMMAND
    },
    Func {
        name: "cnc_rdsyssoft3_str",
        learnt: Some(&[
            "the answer's first word is the records' number, the second the total: disassembled, probed",
        ]),
        doc: "Reads the CNC's software IDs, names, series and editions from the `s_no`-th on: `*num` in is how many (sent as it is), out how many were written (the count the CNC answered); `*total` is how many the CNC has. The bytes are copied as the CNC sent them. Never more entries than asked are written (FANUC's library writes as many as the CNC's count says).",
        params: &[
            Param::Short("s_no"),
            Param::Count("num"),
            Param::Out("total", "short"),
            Param::Out("syssoft", "ODBSYSS3_STR"),
        ],
        forms: &[every_class(
            cmd::RDSYSSOFT3_STR,
            &[Word::Arg(0), Word::Arg(1)],
        )],
        reply: &[skip(I16), to_out(0, I16, "", I16)],
        records: Some(&Records {
            fields: &[
                to_out(1, I16, "soft_id", I16),
                bytes(13, "soft_name"),
                bytes(5, "soft_series"),
                bytes(5, "soft_edition"),
                bytes(3, "dummy"),
            ],
            out: 1,
            to: "",
            elem: "ODBSYSS3_STR",
            // As many as one answer holds.
            max: 50,
            count: None,
            room: None,
        }),
        counted: Some(0),
        dims: &["1|0|-1|2|8|9|100", "4|0|-1|1|2|50|51|200"],
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
    Func {
        name: "cnc_rdservoid2",
        learnt: Some(&[]),
        doc: "Reads the servo ID information of axis `axis` as cnc_rdservoid, with the software series and editions of the amplifier and power supply and the power modules' specifications and serial numbers.",
        params: &[
            Param::Short("axis"),
            Param::Short("slct"),
            Param::Out("servoid", "ODBCSVID2"),
        ],
        forms: &[every_class(cmd::RDSERVOID2, &[Word::Arg(0), Word::Arg(1)])],
        reply: SERVO_ID2,
        dims: &["1|0|-1|2|3|4|32|33", "0|1|-1|2"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdspindleid2",
        learnt: Some(&[]),
        doc: "Reads the spindle ID information of spindle `sp_no` as cnc_rdspindleid, with the power supply's software series and edition.",
        params: &[
            Param::Short("sp_no"),
            Param::Short("slct"),
            Param::Out("spindleid", "ODBCSPID2"),
        ],
        forms: &[every_class(
            cmd::RDSPINDLEID2,
            &[Word::Arg(0), Word::Arg(1)],
        )],
        reply: SPINDLE_ID2,
        dims: &["1|0|-1|2|8|9", "0|1|-1|2"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdfromservoid2",
        learnt: Some(&[]),
        doc: "Reads the servo ID information of axis `axis` the CNC saved (its last ID check), as cnc_rdservoid2.",
        params: &[Param::Short("axis"), Param::Out("servoid", "ODBCSVID2")],
        forms: &[every_class(cmd::RDFROMSERVOID2, &[Word::Arg(0)])],
        reply: SERVO_ID2,
        dims: &["1|0|-1|2|3|4|32|33"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdfromspindleid2",
        learnt: Some(&[]),
        doc: "Reads the spindle ID information of spindle `sp_no` the CNC saved (its last ID check), as cnc_rdspindleid2.",
        params: &[Param::Short("sp_no"), Param::Out("spindleid", "ODBCSPID2")],
        forms: &[every_class(cmd::RDFROMSPINDLEID2, &[Word::Arg(0)])],
        reply: SPINDLE_ID2,
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

/// `n` bytes of a record into output 1's member `to`, as sent.
const fn bytes(n: u16, to: &'static str) -> Field {
    Field {
        wire: I8,
        n,
        out: 1,
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

/// ODBCSVID2's 209 bytes: ODBCSVID's, then the software series/editions and
/// the power modules.
const SERVO_ID2: &[Field] = &[
    chars(20, "mt_spc"),
    chars(10, "mt_srn"),
    chars(22, "plc_spc"),
    chars(9, "plc_srn"),
    chars(22, "svm_spc"),
    chars(12, "svm_srn"),
    chars(22, "psm_spc"),
    chars(12, "psm_srn"),
    chars(9, "svs_see"),
    chars(9, "pss_see"),
    chars(22, "pm1_spc"),
    chars(9, "pm1_srn"),
    chars(22, "pm2_spc"),
    chars(9, "pm2_srn"),
];

/// ODBCSPID2's 137 bytes: ODBCSPID's, then the power supply's software.
const SPINDLE_ID2: &[Field] = &[
    chars(20, "mt_spc"),
    chars(10, "mt_srn"),
    chars(20, "sbmt_spc"),
    chars(10, "sbmt_srn"),
    chars(22, "spm_spc"),
    chars(12, "spm_srn"),
    chars(22, "psm_spc"),
    chars(12, "psm_srn"),
    chars(9, "pss_see"),
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
