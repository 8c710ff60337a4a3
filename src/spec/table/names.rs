//! The names of the axes and spindles.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

/// A name character: the byte the CNC sends, as a `char`.
const fn ch(to: &'static str) -> Field {
    Field {
        wire: U8,
        n: 1,
        out: 0,
        to: Some(to),
        c: I8,
        arg: None,
    }
}

/// Whole 4-byte entries, as many as `*data_num` holds (no other cap).
const fn entries(fields: &'static [Field], elem: &'static str, max: u16) -> Records {
    Records {
        fields,
        out: 0,
        to: "",
        elem,
        max,
        count: None,
        room: None,
    }
}

// FANUC's library writes at most 32 names (its MAX_AXIS) [fuzz, rdaxisname
// `s0Ln350`].
const AXIS_NAMES: Records = entries(
    &[ch("name"), ch("suff"), skip(U8), skip(U8)],
    "ODBAXISNAME",
    32,
);
// FANUC's library writes at most 8 names (its maximum spindles) [fuzz,
// rdspdlname `s0Ln350`].
const SPINDLE_NAMES: Records = entries(
    &[ch("name"), ch("suff1"), ch("suff2"), ch("suff3")],
    "ODBSPDLNAME",
    8,
);

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdaxisname",
        doc: "Reads the names of the controlled axes: `*data_num` in is the room in `axisname`, out the names written (at most the CNC's axis count); below 1 it is EW_LENGTH without traffic.",
        params: &[
            Param::Count("data_num"),
            Param::Out("axisname", "ODBAXISNAME"),
        ],
        checks: &[at_least_one(0)],
        forms: &[every_class(cmd::RDAXISNAME, &[])],
        records: Some(&AXIS_NAMES),
        dims: &["4|1|0|-1|2|3|32|33"],
        ..COMMAND
    },
    Func {
        name: "cnc_rdspdlname",
        doc: "Reads the names of the spindles: `*data_num` in is the room in `spdlname`, out the names written; below 1 it is EW_LENGTH without traffic.",
        params: &[
            Param::Count("data_num"),
            Param::Out("spdlname", "ODBSPDLNAME"),
        ],
        checks: &[at_least_one(0)],
        forms: &[every_class(cmd::RDSPDLNAME, &[])],
        records: Some(&SPINDLE_NAMES),
        dims: &["4|1|0|-1|2|8|9"],
        ..COMMAND
    },
];
