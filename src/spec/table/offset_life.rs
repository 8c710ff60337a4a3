//! The offsets and tool life functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdtofsinfo2",
        doc: "Reads the tool offset memory type, the number of offsets and which offsets are enabled.",
        params: &[Param::Out("tlinf", "ODBTLINF2")],
        forms: &[every_class(cmd::RDTOFSINFO, &[])],
        // The 0x000a answer of cnc_rdtofsinfo, with the enable word after it.
        reply: &[
            skip(I16),
            to(I16, "use_no", I16),
            to(I16, "ofs_type", I16),
            to(I16, "ofs_enable", I16),
        ],
        ..COMMAND
    },
    Func {
        name: "cnc_rdngrp",
        doc: "Reads the number of tool life groups.",
        params: &[Param::Out("grp", "ODBTLIFE2")],
        forms: &[every_class(cmd::RDNGRP, &[])],
        reply: &[to(I32, "data", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdtofsenbl",
        doc: "Reads whether the `[MEASURE]` and `[MEASURE+]` tool offset measurement can be used (`*enable` 1) or not (0).",
        params: &[Param::Out("enable", "char")],
        forms: &[every_class(cmd::RDTOFSENBL, &[])],
        reply: &[to(I8, "", I8)],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdtldata",
        doc: "Reads the TL value of the work zero point measurement (`tl`, with `tl_dp` decimals).",
        params: &[Param::Out("tldata", "ODBTLDATA")],
        forms: &[every_class(cmd::RDTLDATA, &[])],
        reply: &[to(I32, "tl", I32), to(I32, "tl_dp", I32)],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdtlmsinfo",
        doc: "Reads the tool length measurement information: T and M codes, the measured length `hm` (with `hm_dp` decimals) and the offset number it goes to.",
        params: &[Param::Out("tlmsinf", "ODBTLMSINF")],
        forms: &[every_class(cmd::RDTLMSINFO, &[])],
        reply: &[
            to(I32, "t", I32),
            to(I32, "m", I32),
            to(I32, "hm", I32),
            to(I32, "hm_dp", I32),
            to(I32, "tlofs_no", I32),
        ],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_clrtofs",
        doc: "Clears every tool offset of type `type` (as cnc_rdtofs numbers them).",
        params: &[Param::Short("type")],
        forms: &[every_class(cmd::CLRTOFS, &[Word::Arg(0)])],
        dims: &["0|-1|1|3|4|-2|32767"],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdbtofsinfo",
        doc: "Reads the B-axis tool offsets' memory type, how many there are and the sub function number of offset cancel.",
        params: &[Param::Out("btlinf", "ODBBTLINF")],
        forms: &[every_class(cmd::RDBTOFSINFO, &[])],
        reply: &[
            to(I32, "use_no", I16),
            to(I32, "sub_no", I16),
            to(I16, "ofs_type", I16),
        ],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdradofs",
        doc: "Reads the cutter compensation mode, the axes of its plane and the offset vector in that plane.",
        params: &[Param::Out("rofs", "ODBROFS")],
        forms: &[every_class(cmd::RDRADOFS, &[])],
        // The vector's values are value records: the first one's second
        // word is not read.
        reply: &[
            to(I32, "mode", I16),
            to(I32, "pln_axes[0]", I16),
            to(I32, "pln_axes[1]", I16),
            to(I32, "ofsvct[0]", I32),
            skip(I32),
            to(I32, "ofsvct[1]", I32),
        ],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rd3dtofs",
        doc: "Reads the 3-D tool offset mode, its three axes and the offset vector.",
        params: &[Param::Out("tofs", "ODB3DTO")],
        forms: &[every_class(cmd::RD3DTOFS, &[])],
        reply: &[
            to(I32, "mode", I16),
            to(I32, "ofs_axes[0]", I16),
            to(I32, "ofs_axes[1]", I16),
            to(I32, "ofs_axes[2]", I16),
            to(I32, "ofsvct[0]", I32),
            skip(I32),
            to(I32, "ofsvct[1]", I32),
            skip(I32),
            to(I32, "ofsvct[2]", I32),
        ],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdactfixofs",
        doc: "Reads the fixture offset in effect of axis `axis` (-1: all axes): `datano` the fixture offset number the CNC answered (the low half of its word), `type` = `axis`, `data` the value of each axis as sent (at most 32 written: FANUC's library writes as many as the answer holds).",
        params: &[Param::Short("axis"), Param::Out("ofs", "IODBZOFS")],
        forms: &[every_class(cmd::RDACTFIXOFS, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I16), to(I32, "datano", I16)],
        // A value record per axis: its base and exponent words not read.
        records: Some(&Records {
            fields: &[to(I32, "", I32), skip(I32)],
            out: 0,
            to: "data",
            elem: "long",
            max: 32,
            count: None,
            room: None,
        }),
        dims: &["1|-1|0|2|3|4|32|33|-2"],
        learnt: Some(&["written past the pointee: value records past 32 axes (fuzz: a deviation)"]),
        ..COMMAND
    },
    Func {
        name: "cnc_rdvolccomp",
        doc: "Reads the volumetric compensation amount of each axis into `comp`, one word per axis as sent (at most 5 written: FANUC's library writes as many as the answer holds).",
        params: &[Param::Out("comp", "ODBVOLCOMP")],
        forms: &[every_class(cmd::RDVOLCCOMP, &[])],
        records: Some(&Records {
            fields: &[to(I32, "", I32)],
            out: 0,
            to: "comp",
            elem: "long",
            max: 5,
            count: None,
            room: None,
        }),
        learnt: Some(&[
            "written past the pointee: the answer's words past the fifth (fuzz: a deviation)",
        ]),
        ..COMMAND
    },
];
