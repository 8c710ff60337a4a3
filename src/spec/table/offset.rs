//! The offsets, macros functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdtofsinfo",
        doc: "Reads the tool offset memory type and the number of offsets.",
        params: &[Param::Out("tlinf", "ODBTLINF")],
        forms: &[every_class(cmd::RDTOFSINFO, &[])],
        reply: &[skip(I16), to(I16, "use_no", I16), to(I16, "ofs_type", I16)],
        short: Short::Zeros,
        ..COMMAND
    },
    Func {
        name: "cnc_rdzofsinfo",
        doc: "Reads the number of work zero offsets.",
        params: &[Param::Out("ofs_no", "short")],
        forms: &[every_class(cmd::RDZOFSINFO, &[])],
        reply: &[to(I32, "", I16)],
        short: Short::Zeros,
        ..COMMAND
    },
    Func {
        name: "cnc_rdmacroinfo",
        doc: "Reads how many common variables the CNC has: `use_no1` (#100..), `use_no2` (#500..).",
        params: &[Param::Out("buf", "ODBMVINF")],
        forms: &[every_class(cmd::RDMACROINFO, &[])],
        reply: &[to(I32, "use_no1", I16), to(I32, "use_no2", I16)],
        short: Short::Zeros,
        ..COMMAND
    },
    Func {
        name: "cnc_rdpmacroinfo",
        learnt: Some(&["reply: out 0 use_no2: [Const(0), Const(0)]"]),
        doc: "Reads the P-code macro variables' information: `use_no1` the variables #10000.., `use_no2` the extended variables #20000.. (0 when `v2_type` is 2 or more, as FANUC's library writes it), `v2_type` their type.",
        params: &[Param::Out("pmacinfo", "ODBPMINF")],
        forms: &[every_class(cmd::RDPMACROINFO, &[])],
        reply: &[
            skip(I32),
            skip(I32),
            skip(I32),
            to(I32, "use_no1", I16),
            to(I32, "use_no2", I16),
            to(I32, "v2_type", I16),
        ],
        zero_unless: Some(ZeroUnless {
            zero: "use_no2",
            of: "v2_type",
            lo: i16::MIN as i32,
            hi: 1,
        }),
        ..COMMAND
    },
];
