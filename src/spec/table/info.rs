//! The machine information functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// The reply of cnc_rdsyssoft and cnc_rdsyssoft2 (command 0x0041), as
/// FANUC's library reads it (payload offsets): the physical slots at 0
/// (0xff ends the list), module IDs by physical slot at 16 (slots below
/// 0x80) and 48, software IDs likewise at 80 and 112, the logical slots'
/// table at 144 (16 words, the high byte a physical slot), series and
/// version (4 + 4 characters) by logical slot at 208, boot, servo, PMC
/// and ladder at 336, then two more pairs (into `reserve[6]` and
/// `reserve[7]`) at 368, `soft_inst` the byte at 465, and from 472 on the
/// pairs `$m`, each 4 characters (0xff as 0) into member `$m`, then a 0
/// at `$z`. Field indices: [`SLOTS`] 0, [`MODULES`] 1/2, [`SOFTS`] 3/4,
/// [`LOGICAL`] 5, [`SERIES`] 7.
macro_rules! syssoft_reply {
    ($($m:literal $z:literal)*) => {
        &[
            Field { wire: I8, n: 16, out: 0, to: Some("slot_no_p"), c: I8, arg: None },
            skips(I16, 16),
            skips(I16, 16),
            skips(I16, 16),
            skips(I16, 16),
            skips(U8, 32),
            skips(U8, 32),
            skips(Char, 128),
            chars4("boot_ser"), zero("boot_ser[4]", I8),
            chars4("boot_ver"), zero("boot_ver[4]", I8),
            chars4("servo_ser"), zero("servo_ser[4]", I8),
            chars4("servo_ver"), zero("servo_ver[4]", I8),
            chars4("pmc_ser"), zero("pmc_ser[4]", I8),
            chars4("pmc_ver"), zero("pmc_ver[4]", I8),
            chars4("ladder_ser"), zero("ladder_ser[4]", I8),
            chars4("ladder_ver"), zero("ladder_ver[4]", I8),
            chars4("reserve[30]"), zero("reserve[34]", I8),
            chars4("reserve[35]"), zero("reserve[39]", I8),
            skips(U8, 89),
            to(U8, "soft_inst", I16),
            skips(U8, 6),
            $(chars4($m), zero($z, I8),)*
        ]
    };
}

/// [`syssoft_reply`]'s field of the physical slots.
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

/// FANUC's library's lookups of cnc_rdsyssoft and cnc_rdsyssoft2: each
/// physical slot's logical slot (its index in the logical table; 0xff
/// none), module and software IDs by physical slot (0xffff past the
/// list), series and version by logical slot (zeros from the first slot
/// without one).
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
];

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

/// 4 characters into member `to`, 0xff read as 0.
const fn chars4(to: &'static str) -> Field {
    Field {
        wire: Char,
        n: 4,
        out: 0,
        to: Some(to),
        c: I8,
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
        name: "cnc_rdsyssoft",
        learnt: Some(&[
            "slot_no_l, module_id, soft_id, soft_series and soft_version looked up by slot (Lookup): disassembled, probed",
            "series and versions: 4 characters, 0xff read as 0, then a NUL: probed",
            "reserve[6] and reserve[7] from offsets 368 and 372, eth_boot and reserve[0..6] from 632 on: probed",
        ]),
        doc: "Reads the CNC's slots and software: the physical slots as sent (0xff ends the list), each one's logical slot (its place in the CNC's logical table; 0xff none), module and software ID (0xffff past the list), the series and version of the software on each, then the named software's series and versions (4 characters, 0xff as 0, then a NUL).",
        params: &[Param::Out("syssoft", "ODBSYSS")],
        forms: &[every_class(cmd::RDSYSSOFT, &[])],
        reply: syssoft_reply!(
            "mcrlib_ser" "mcrlib_ser[4]"
            "mcrlib_ver" "mcrlib_ver[4]"
            "mcrapl_ser" "mcrapl_ser[4]"
            "mcrapl_ver" "mcrapl_ver[4]"
            "spl1_ser" "spl1_ser[4]"
            "spl1_ver" "spl1_ver[4]"
            "spl2_ser" "spl2_ser[4]"
            "spl2_ver" "spl2_ver[4]"
            "spl3_ser" "spl3_ser[4]"
            "spl3_ver" "spl3_ver[4]"
            "c_exelib_ser" "c_exelib_ser[4]"
            "c_exelib_ver" "c_exelib_ver[4]"
            "c_exeapl_ser" "c_exeapl_ser[4]"
            "c_exeapl_ver" "c_exeapl_ver[4]"
            "int_vga_ser" "int_vga_ser[4]"
            "int_vga_ver" "int_vga_ver[4]"
            "out_vga_ser" "out_vga_ser[4]"
            "out_vga_ver" "out_vga_ver[4]"
            "pmm_ser" "pmm_ser[4]"
            "pmm_ver" "pmm_ver[4]"
            "pmc_mng_ser" "pmc_mng_ser[4]"
            "pmc_mng_ver" "pmc_mng_ver[4]"
            "pmc_shin_ser" "pmc_shin_ser[4]"
            "pmc_shin_ver" "pmc_shin_ver[4]"
            "pmc_shout_ser" "pmc_shout_ser[4]"
            "pmc_shout_ver" "pmc_shout_ver[4]"
            "pmc_c_ser" "pmc_c_ser[4]"
            "pmc_c_ver" "pmc_c_ver[4]"
            "pmc_edit_ser" "pmc_edit_ser[4]"
            "pmc_edit_ver" "pmc_edit_ver[4]"
            "lddr_mng_ser" "lddr_mng_ser[4]"
            "lddr_mng_ver" "lddr_mng_ver[4]"
            "lddr_apl_ser" "lddr_apl_ser[4]"
            "lddr_apl_ver" "lddr_apl_ver[4]"
            "spl4_ser" "spl4_ser[4]"
            "spl4_ver" "spl4_ver[4]"
            "mcr2_ser" "mcr2_ser[4]"
            "mcr2_ver" "mcr2_ver[4]"
            "mcr3_ser" "mcr3_ser[4]"
            "mcr3_ver" "mcr3_ver[4]"
            "eth_boot_ser" "eth_boot_ser[4]"
            "eth_boot_ver" "eth_boot_ver[4]"
            "reserve[0]" "reserve[4]"
            "reserve[5]" "reserve[9]"
            "reserve[10]" "reserve[14]"
            "reserve[15]" "reserve[19]"
            "reserve[20]" "reserve[24]"
            "reserve[25]" "reserve[29]"
        ),
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
        reply: syssoft_reply!(
            "mcrlib_ser" "mcrlib_ser[4]"
            "mcrlib_ver" "mcrlib_ver[4]"
            "mcrapl_ser" "mcrapl_ser[4]"
            "mcrapl_ver" "mcrapl_ver[4]"
            "spl1_ser" "spl1_ser[4]"
            "spl1_ver" "spl1_ver[4]"
            "spl2_ser" "spl2_ser[4]"
            "spl2_ver" "spl2_ver[4]"
            "spl3_ser" "spl3_ser[4]"
            "spl3_ver" "spl3_ver[4]"
            "c_exelib_ser" "c_exelib_ser[4]"
            "c_exelib_ver" "c_exelib_ver[4]"
            "c_exeapl_ser" "c_exeapl_ser[4]"
            "c_exeapl_ver" "c_exeapl_ver[4]"
            "int_vga_ser" "int_vga_ser[4]"
            "int_vga_ver" "int_vga_ver[4]"
            "out_vga_ser" "out_vga_ser[4]"
            "out_vga_ver" "out_vga_ver[4]"
            "pmm_ser" "pmm_ser[4]"
            "pmm_ver" "pmm_ver[4]"
            "pmc_mng_ser" "pmc_mng_ser[4]"
            "pmc_mng_ver" "pmc_mng_ver[4]"
            "pmc_shin_ser" "pmc_shin_ser[4]"
            "pmc_shin_ver" "pmc_shin_ver[4]"
            "pmc_shout_ser" "pmc_shout_ser[4]"
            "pmc_shout_ver" "pmc_shout_ver[4]"
            "pmc_c_ser" "pmc_c_ser[4]"
            "pmc_c_ver" "pmc_c_ver[4]"
            "pmc_edit_ser" "pmc_edit_ser[4]"
            "pmc_edit_ver" "pmc_edit_ver[4]"
            "lddr_mng_ser" "lddr_mng_ser[4]"
            "lddr_mng_ver" "lddr_mng_ver[4]"
            "lddr_apl_ser" "lddr_apl_ser[4]"
            "lddr_apl_ver" "lddr_apl_ver[4]"
            "spl4_ser" "spl4_ser[4]"
            "spl4_ver" "spl4_ver[4]"
            "mcr2_ser" "mcr2_ser[4]"
            "mcr2_ver" "mcr2_ver[4]"
            "mcr3_ser" "mcr3_ser[4]"
            "mcr3_ver" "mcr3_ver[4]"
            "eth_boot_ser" "eth_boot_ser[4]"
            "eth_boot_ver" "eth_boot_ver[4]"
            "reserve[0]" "reserve[4]"
            "reserve[5]" "reserve[9]"
            "reserve[10]" "reserve[14]"
            "reserve[15]" "reserve[19]"
            "reserve[20]" "reserve[24]"
            "reserve[25]" "reserve[29]"
            "embEthe_ser" "embEthe_ser[4]"
            "embEthe_ver" "embEthe_ver[4]"
            "reserve2[0]" "reserve2[4]"
            "reserve2[5]" "reserve2[9]"
            "reserve2[10]" "reserve2[14]"
            "reserve2[15]" "reserve2[19]"
            "reserve2[20]" "reserve2[24]"
            "reserve2[25]" "reserve2[29]"
            "reserve2[30]" "reserve2[34]"
            "reserve2[35]" "reserve2[39]"
            "reserve2[40]" "reserve2[44]"
            "reserve2[45]" "reserve2[49]"
            "reserve2[50]" "reserve2[54]"
            "reserve2[55]" "reserve2[59]"
            "reserve2[60]" "reserve2[64]"
            "reserve2[65]" "reserve2[69]"
            "reserve2[70]" "reserve2[74]"
            "reserve2[75]" "reserve2[79]"
            "reserve2[80]" "reserve2[84]"
            "reserve2[85]" "reserve2[89]"
            "reserve2[90]" "reserve2[94]"
            "reserve2[95]" "reserve2[99]"
            "reserve2[100]" "reserve2[104]"
            "reserve2[105]" "reserve2[109]"
            "reserve2[110]" "reserve2[114]"
            "reserve2[115]" "reserve2[119]"
            "reserve2[120]" "reserve2[124]"
            "reserve2[125]" "reserve2[129]"
            "reserve2[130]" "reserve2[134]"
            "reserve2[135]" "reserve2[139]"
            "reserve2[140]" "reserve2[144]"
            "reserve2[145]" "reserve2[149]"
            "reserve2[150]" "reserve2[154]"
            "reserve2[155]" "reserve2[159]"
            "reserve2[160]" "reserve2[164]"
            "reserve2[165]" "reserve2[169]"
            "reserve2[170]" "reserve2[174]"
            "reserve2[175]" "reserve2[179]"
            "reserve2[180]" "reserve2[184]"
            "reserve2[185]" "reserve2[189]"
        ),
        lookups: SYSSOFT_LOOKUPS,
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
        records: Some(Records {
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
