//! Functions FANUC's header declares but none of its Ethernet libraries
//! implements. They are exported so that programs calling them link and
//! load, and they answer as FANUC's Windows library does on an Ethernet
//! handle: `EW_VERSION` (-7), without traffic, writing nothing
//! ([`answers`]). A bad handle is `EW_HANDLE` (-8) first, as for every call.

use super::super::types::*;
use crate::ew::EW_VERSION;

/// An entry answering EW_VERSION on every call (its name, doc and
/// parameters set by each).
const ABSENT: Func = Func {
    checks: &[answers(EW_VERSION)],
    ..super::base::COMMAND
};

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdexecpt",
        doc: "Reads the execution pointer: HSSB only; `EW_VERSION` (-7) on Ethernet.",
        params: &[Param::Out("pact", "PRGPNT"), Param::Out("pnext", "PRGPNT")],
        ..ABSENT
    },
    Func {
        name: "cnc_rdprogline",
        doc: "Reads program lines: HSSB only; `EW_VERSION` (-7) on Ethernet.",
        params: &[
            Param::Long("prog_no"),
            Param::ULong("line_no"),
            Param::Out("prog_data", "char"),
            Param::Out("line_len", "unsigned long"),
            Param::Out("data_len", "unsigned long"),
        ],
        dims: &["1", "1"],
        ..ABSENT
    },
    Func {
        name: "cnc_svdtstartrd",
        doc: "Starts reading servo data: HSSB only; `EW_VERSION` (-7) on Ethernet.",
        params: &[Param::Short("axis")],
        dims: &["1"],
        ..ABSENT
    },
    Func {
        name: "cnc_svdtrddata",
        doc: "Reads servo data: HSSB only; `EW_VERSION` (-7) on Ethernet.",
        params: &[
            Param::Out("stat", "short"),
            Param::Out("length", "long"),
            Param::Out("data", "void"),
        ],
        ..ABSENT
    },
    Func {
        name: "cnc_svdtendrd",
        doc: "Ends reading servo data: HSSB only; `EW_VERSION` (-7) on Ethernet.",
        ..ABSENT
    },
    Func {
        name: "cnc_rdspdlnamem",
        doc: "Reads spindle names (multi-path form): `EW_VERSION` (-7) on Ethernet.",
        params: &[
            Param::Out("data_num", "short"),
            Param::Out("spdlname", "ODBSPDLNAME"),
        ],
        ..ABSENT
    },
    Func {
        name: "cnc_rdalmmsg3",
        doc: "Reads alarm messages with 256-character texts: `EW_VERSION` (-7) on Ethernet.",
        params: &[
            Param::Short("type"),
            Param::Out("num", "short"),
            Param::Out("almmsg", "ODBALMMSG3"),
        ],
        dims: &["-1"],
        ..ABSENT
    },
];
