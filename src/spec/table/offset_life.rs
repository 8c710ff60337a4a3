//! The offsets and tool life functions.

use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

// The commands of this area's entries (the simulator answers by them).
/// cnc_rdngrp: the tool life groups.
pub const RDNGRP: u16 = 0x004a;

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdtofsinfo2",
        doc: "Reads the tool offset memory type, the number of offsets and which offsets are enabled.",
        params: &[Param::Out("tlinf", "ODBTLINF2")],
        forms: &[every_class(super::offset::RDTOFSINFO, &[])],
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
        forms: &[every_class(RDNGRP, &[])],
        reply: &[to(I32, "data", I32)],
        ..COMMAND
    },
];
