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
];
