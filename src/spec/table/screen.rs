//! The CNC's screen and operator state (family A of the long tail): its
//! model, display language, operation and protection levels, menu
//! switches, the counts of its axes, additional work coordinate systems
//! and program repeats, and the cursor of the main program.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_getcncmodel",
        learnt: Some(&[]),
        doc: "Reads the CNC's model code (the low 16 bits of the 32-bit answer).",
        params: &[Param::Out("model", "short")],
        forms: &[every_class(cmd::GETCNCMODEL, &[])],
        reply: &[to(I32, "", I16)],
        ..COMMAND
    },
    Func {
        name: "cnc_getlanguage",
        learnt: Some(&[]),
        doc: "Reads the CNC's display language code.",
        params: &[Param::Out("lang", "short")],
        forms: &[every_class(cmd::GETLANGUAGE, &[])],
        reply: &[to(I16, "", I16)],
        ..COMMAND
    },
    Func {
        name: "cnc_chglang",
        learnt: Some(&[]),
        doc: "Changes the CNC's display language to `lang` (cnc_getlanguage's codes).",
        params: &[Param::Char("lang")],
        forms: &[every_class(cmd::CHGLANG, &[Word::Arg(0)])],
        dims: &["1|0|-1|2|15|16|127|128|255"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdope_lvl",
        learnt: Some(&[]),
        doc: "Reads the current operation level (the password's level).",
        params: &[Param::Out("lvl", "short")],
        forms: &[every_class(cmd::RDOPE_LVL, &[])],
        reply: &[to(I16, "", I16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdprt_lvl",
        learnt: Some(&[]),
        doc: "Reads the operation levels data kind `kind` needs to be modified (`rd_lvl`) and output (`wt_lvl`).",
        params: &[
            Param::Short("kind"),
            Param::Out("rd_lvl", "short"),
            Param::Out("wt_lvl", "short"),
        ],
        forms: &[every_class(cmd::RDPRT_LVL, &[Word::Arg(0)])],
        reply: &[to(I16, "", I16), to_out(1, I16, "", I16)],
        dims: &["1|0|-1|2|3|20|32767"],
        ..COMMAND
    },
    Func {
        name: "cnc_wrprt_lvl",
        learnt: Some(&[]),
        doc: "Sets the operation levels data kind `kind` needs to be modified (`rd_lvl`) and output (`wt_lvl`), as cnc_rdprt_lvl reads them.",
        params: &[
            Param::Short("kind"),
            Param::Short("rd_lvl"),
            Param::Short("wt_lvl"),
        ],
        forms: &[every_class(
            cmd::WRPRT_LVL,
            &[Word::Arg(0), Word::Arg(1), Word::Arg(2)],
        )],
        dims: &["1|0|-1|2|20", "4|0|-1|7|8", "5|0|-1|7|8"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdmenuswitch",
        learnt: Some(&[]),
        doc: "Reads the menu switch signals, bit k the k-th switch (the low 16 bits of the 32-bit answer).",
        params: &[Param::Out("data", "short")],
        forms: &[every_class(cmd::RDMENUSWITCH, &[])],
        reply: &[to(I32, "", I16)],
        ..COMMAND
    },
    Func {
        name: "cnc_wrmenuswitch",
        learnt: Some(&[]),
        doc: "Writes the menu switch signals `mask` selects (bit k: switch k) from `data`'s bits: `data` goes as a request word, `mask` as the payload (32 bits, sign-extended).",
        params: &[Param::Short("data"), Param::Short("mask")],
        forms: &[every_class(cmd::WRMENUSWITCH, &[Word::Arg(0)])],
        payload: Some(&Payload {
            fields: &[to(I32, "", I16)],
            elem: "",
            count: NUMBERS,
            max: 1,
        }),
        dims: &["5|0|-1|255", "7|0|-1|255"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdcoordnum",
        learnt: Some(&[]),
        doc: "Reads how many additional work coordinate systems (G54.1 P1..) the CNC has (the low 16 bits of the 32-bit answer).",
        params: &[Param::Out("num", "short")],
        forms: &[every_class(cmd::RDCOORDNUM, &[])],
        reply: &[to(I32, "", I16)],
        ..COMMAND
    },
    Func {
        name: "cnc_rdrepeatval",
        learnt: Some(&[]),
        doc: "Reads how many times the running program has repeated (4 bytes written into the `long`).",
        params: &[Param::Out("val", "long")],
        forms: &[every_class(cmd::RDREPEATVAL, &[])],
        reply: &[to(I32, "", I32)],
        ..COMMAND
    },
    Func {
        name: "cnc_axisnum",
        learnt: Some(&[]),
        doc: "Reads a count of the path as cnc_rdaxisdata's counts: `kind` 0 its axes, 1 its spindles.",
        params: &[Param::Short("kind"), Param::Out("num", "short")],
        forms: &[every_class(cmd::COUNT, &[Word::Arg(0)])],
        reply: &[to(I16, "", I16)],
        dims: &["0|1|2|3|-1|4"],
        ..COMMAND
    },
    Func {
        name: "cnc_rewind",
        learnt: Some(&[]),
        doc: "Rewinds the cursor of the path's main program to its top (the path stopped).",
        forms: &[every_class(cmd::REWIND, &[])],
        ..COMMAND
    },
    Func {
        name: "cnc_seqsrch",
        learnt: Some(&[]),
        doc: "Searches the path's main program for sequence number `seq`: the cursor goes to its block (the path stopped).",
        params: &[Param::Long("seq")],
        forms: &[every_class(cmd::SEQSRCH, &[Word::Arg(0)])],
        dims: &["30|0|-1|1|99999|100000|2147483647"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdfixcycle",
        learnt: Some(&[]),
        doc: "Reads the canned cycle in force: its mode (G code), the plane's two axes and the drilling axis (the low 16 bits of each word), the repetitions commanded and done, then the initial level, R point, Z point, cut-in depth and two shifts (the value word of each value record).",
        params: &[Param::Out("fix", "ODBFIX")],
        forms: &[every_class(cmd::RDFIXCYCLE, &[])],
        reply: &[
            to(I32, "mode", I16),
            Field {
                n: 2,
                ..to(I32, "pln_axes", I16)
            },
            to(I32, "drl_axes", I16),
            to(I32, "cmd_cnt", I32),
            to(I32, "act_cnt", I32),
            to(I32, "i_pos", I32),
            skip(I32),
            to(I32, "r_pos", I32),
            skip(I32),
            to(I32, "z_pos", I32),
            skip(I32),
            to(I32, "cut", I32),
            skip(I32),
            to(I32, "shift[0]", I32),
            skip(I32),
            to(I32, "shift[1]", I32),
            skip(I32),
        ],
        ..COMMAND
    },
];
