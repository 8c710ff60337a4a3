//! The operation functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// A general purpose switch's name: its 8 characters (the C member has a
/// ninth, for the NUL).
const fn switch_name(to: &'static str) -> Field {
    Field {
        wire: U8,
        n: 8,
        out: 0,
        to: Some(to),
        c: I8,
        arg: None,
    }
}

/// The eight names as the write sends them.
const SWITCH_NAMES: &[Field] = &[
    switch_name("sgnl1_name"),
    switch_name("sgnl2_name"),
    switch_name("sgnl3_name"),
    switch_name("sgnl4_name"),
    switch_name("sgnl5_name"),
    switch_name("sgnl6_name"),
    switch_name("sgnl7_name"),
    switch_name("sgnl8_name"),
];

/// The sixteen names as cnc_wropnlgsname2 sends them.
const SWITCH_NAMES2: &[Field] = &[
    switch_name("sgnl1_name"),
    switch_name("sgnl2_name"),
    switch_name("sgnl3_name"),
    switch_name("sgnl4_name"),
    switch_name("sgnl5_name"),
    switch_name("sgnl6_name"),
    switch_name("sgnl7_name"),
    switch_name("sgnl8_name"),
    switch_name("sgnl9_name"),
    switch_name("sgnl10_name"),
    switch_name("sgnl11_name"),
    switch_name("sgnl12_name"),
    switch_name("sgnl13_name"),
    switch_name("sgnl14_name"),
    switch_name("sgnl15_name"),
    switch_name("sgnl16_name"),
];

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_start",
        doc: "Cycle start: the CNC runs the selected main program (MEMORY mode, no alarm; else EW_REJECT).",
        forms: &[every_class(cmd::START, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_reset",
        doc: "Resets the CNC: the running program stops, reset-clearable alarms are cleared.",
        forms: &[every_class(cmd::RESET, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_reset2",
        doc: "Resets the CNC as cnc_reset does (needs the FOCAS option, else EW_NOOPT).",
        checks: &[NEEDS_OPTION],
        forms: &[every_class(cmd::RESET2, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_clralm",
        doc: "Clears the CNC's active alarms of type `id` (cnc_rdalmmsg's types).",
        params: &[Param::Short("id")],
        forms: &[every_class(cmd::CLRALM, &[Word::Arg(0)])],
        dims: &["3|0|1|2|-1|100|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdopnlsgnl",
        doc: "Reads the software operator panel's signals (`type` written back; `datano` left as it was).",
        params: &[Param::Short("type"), Param::Out("buf", "IODBSGNL")],
        forms: &[every_class(cmd::RDOPNLSGNL, &[Word::Arg(0)])],
        reply: &[
            echo(0, "type", I16),
            to(I16, "mode", I16),
            to(I16, "hndl_ax", I16),
            to(I16, "hndl_mv", I16),
            to(I16, "rpd_ovrd", I16),
            to(I16, "jog_ovrd", I16),
            to(I16, "feed_ovrd", I16),
            to(I16, "spdl_ovrd", I16),
            to(I16, "blck_del", I16),
            to(I16, "sngl_blck", I16),
            to(I16, "machn_lock", I16),
            to(I16, "dry_run", I16),
            to(I16, "mem_prtct", I16),
            to(I16, "feed_hold", I16),
        ],
        dims: &["-1|0|1|4096|8191"],
        learnt: Some(&[]),
        ..COMMAND
    },
    Func {
        name: "cnc_wropnlsgnl",
        learnt: Some(&["input 0's type goes in word 0"]),
        doc: "Writes the software operator panel's signals: `type` (sent as the first request word) selects them, bit 0 `mode` .. bit 12 `feed_hold` as cnc_rdopnlsgnl reads them; the 13 words are sent, then three zero words, `datano` is not.",
        params: &[Param::In("buf", "IODBSGNL")],
        forms: &[every_class(cmd::WROPNLSGNL, &[Word::Input("type", I16)])],
        payload: Some(&Payload {
            fields: &[
                to(I16, "mode", I16),
                to(I16, "hndl_ax", I16),
                to(I16, "hndl_mv", I16),
                to(I16, "rpd_ovrd", I16),
                to(I16, "jog_ovrd", I16),
                to(I16, "feed_ovrd", I16),
                to(I16, "spdl_ovrd", I16),
                to(I16, "blck_del", I16),
                to(I16, "sngl_blck", I16),
                to(I16, "machn_lock", I16),
                to(I16, "dry_run", I16),
                to(I16, "mem_prtct", I16),
                to(I16, "feed_hold", I16),
                // Three words more, always 0 (Series 15's manual_rpd and
                // dummy[2]; FANUC's library does not read past feed_hold).
                skip(I16),
                skip(I16),
                skip(I16),
            ],
            elem: "IODBSGNL",
            count: ONE,
            max: 1,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdopnlgnrl",
        learnt: Some(&[]),
        doc: "Reads the software operator panel's general purpose switches: `sgnal` bit k is switch k + 1 (`type` sent and written back as its low byte, 0..255; `datano` left as it was).",
        params: &[Param::ShortAs("type", U8), Param::Out("buf", "IODBGNRL")],
        forms: &[every_class(cmd::RDOPNLGNRL, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I16), skip(U8), to(I8, "sgnal", I8)],
        dims: &["255|0|1|128|-1|256"],
        ..COMMAND
    },
    Func {
        name: "cnc_wropnlgnrl",
        learnt: Some(&[
            "input out 0 type: [At(3), Kept]",
            "reply: out 0 type: [Kept, Const(0)]",
        ]),
        doc: "Writes the software operator panel's general purpose switches `type` selects (bit k: switch k + 1, from `sgnal` bit k); only `type`'s low byte is sent, and left in `type` (its high byte cleared); `sgnal` goes as a sign-extended word.",
        params: &[Param::In("buf", "IODBGNRL")],
        forms: &[every_class(cmd::WROPNLGNRL, &[Word::Input("type", U8)])],
        payload: Some(&Payload {
            fields: &[to(I16, "sgnal", I8)],
            elem: "IODBGNRL",
            count: ONE,
            max: 1,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdopnlgsname",
        learnt: Some(&[
            "reply: out 1 sgnl1_name[8]: [Const(0)]",
            "reply: out 1 sgnl2_name[8]: [Const(0)]",
            "reply: out 1 sgnl3_name[8]: [Const(0)]",
            "reply: out 1 sgnl4_name[8]: [Const(0)]",
            "reply: out 1 sgnl5_name[8]: [Const(0)]",
            "and 3 more of these kinds",
        ]),
        doc: "Reads the names of the software operator panel's eight general purpose switches: 8 characters each, then a NUL; only whole names answered are written (`type` sent and written back as its low byte; `datano` left as it was).",
        params: &[Param::ShortAs("type", U8), Param::Out("buf", "IODBRDNA")],
        forms: &[every_class(cmd::RDOPNLGSNAME, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I16)],
        // Whole names only: a short answer leaves the names after it.
        records: Some(&Records {
            fields: &[switch_name(""), zero("[8]", I8)],
            out: 0,
            to: "sgnl1_name",
            elem: "char[9]",
            max: 8,
            count: None,
            room: None,
        }),
        dims: &["255|0|1|128|-1|256"],
        ..COMMAND
    },
    Func {
        name: "cnc_wropnlgsname",
        learnt: Some(&[
            "input out 0 type: [At(3), Kept]",
            "reply: out 0 type: [Kept, Const(0)]",
        ]),
        doc: "Writes the names of the general purpose switches `type` selects (bit k: switch k + 1): the first 8 characters of each of the eight names are sent; only `type`'s low byte is sent, and left in `type`.",
        params: &[Param::In("buf", "IODBRDNA")],
        forms: &[every_class(cmd::WROPNLGSNAME, &[Word::Input("type", U8)])],
        payload: Some(&Payload {
            fields: SWITCH_NAMES,
            elem: "IODBRDNA",
            count: ONE,
            max: 1,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdopnlgnrl2",
        learnt: Some(&[]),
        doc: "Reads the software operator panel's general purpose switches as cnc_rdopnlgnrl, into shorts: `type` sent whole and written back, `sgnal` the answer's second byte sign-extended, as FANUC's library writes it (switch 8 on reads negative; `datano` left as it was).",
        params: &[Param::Short("type"), Param::Out("buf", "IODBGNRL2")],
        forms: &[every_class(cmd::RDOPNLGNRL, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I16), skip(U8), to(I8, "sgnal", I16)],
        dims: &["255|0|1|128|-1|256|32767|-32768"],
        ..COMMAND
    },
    Func {
        name: "cnc_wropnlgnrl2",
        learnt: Some(&[]),
        doc: "Writes the software operator panel's general purpose switches `type` selects (bit k: switch k + 1, from `sgnal` bit k); `type` is sent whole as the first word, `sgnal` as a word.",
        params: &[Param::In("buf", "IODBGNRL2")],
        forms: &[every_class(cmd::WROPNLGNRL, &[Word::Input("type", I16)])],
        payload: Some(&Payload {
            fields: &[to(I16, "sgnal", I16)],
            elem: "IODBGNRL2",
            count: ONE,
            max: 1,
        }),
        ..COMMAND
    },
    Func {
        name: "cnc_rdopnlgsname2",
        learnt: Some(&[]),
        doc: "Reads the names of the software operator panel's sixteen general purpose switches: 8 characters each, then a NUL; only whole names answered are written (`type` sent whole and written back; `datano` left as it was).",
        params: &[Param::Short("type"), Param::Out("buf", "IODBRDNA2")],
        forms: &[every_class(cmd::RDOPNLGSNAME, &[Word::Arg(0)])],
        reply: &[echo(0, "type", I16)],
        records: Some(&Records {
            fields: &[switch_name(""), zero("[8]", I8)],
            out: 0,
            to: "sgnl1_name",
            elem: "char[9]",
            max: 16,
            count: None,
            room: None,
        }),
        dims: &["255|0|1|128|-1|256|32767|-32768"],
        ..COMMAND
    },
    Func {
        name: "cnc_wropnlgsname2",
        learnt: Some(&[]),
        doc: "Writes the names of the general purpose switches `type` selects (bit k: switch k + 1): the first 8 characters of each of the sixteen names are sent; `type` is sent whole as the first word.",
        params: &[Param::In("buf", "IODBRDNA2")],
        forms: &[every_class(cmd::WROPNLGSNAME, &[Word::Input("type", I16)])],
        payload: Some(&Payload {
            fields: SWITCH_NAMES2,
            elem: "IODBRDNA2",
            count: ONE,
            max: 1,
        }),
        ..COMMAND
    },
];
