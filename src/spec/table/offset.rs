//! The offsets, macros functions.

use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

// The commands of this area's entries (the simulator answers by them).
/// cnc_rdtofsinfo / cnc_rdtofsinfo2: the tool offset memory.
pub const RDTOFSINFO: u16 = 0x000a;
/// cnc_rdzofsinfo: the workpiece coordinate systems.
pub const RDZOFSINFO: u16 = 0x000d;
/// cnc_rdmacroinfo: the custom macro variables.
pub const RDMACROINFO: u16 = 0x0017;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdtofsinfo",
        doc: "Reads the tool offset memory type and the number of offsets.",
        params: &[Param::Out("tlinf", "ODBTLINF")],
        forms: &[every_class(RDTOFSINFO, &[])],
        reply: &[skip(I16), to(I16, "use_no", I16), to(I16, "ofs_type", I16)],
        short: Short::Zeros,
        ..COMMAND
    },
    Func {
        name: "cnc_rdzofsinfo",
        doc: "Reads the number of work zero offsets.",
        params: &[Param::Out("ofs_no", "short")],
        forms: &[every_class(RDZOFSINFO, &[])],
        reply: &[to(I32, "", I16)],
        short: Short::Zeros,
        ..COMMAND
    },
    Func {
        name: "cnc_rdmacroinfo",
        doc: "Reads how many common variables the CNC has: `use_no1` (#100..), `use_no2` (#500..).",
        params: &[Param::Out("buf", "ODBMVINF")],
        forms: &[every_class(RDMACROINFO, &[])],
        reply: &[to(I32, "use_no1", I16), to(I32, "use_no2", I16)],
        short: Short::Zeros,
        ..COMMAND
    },
];
