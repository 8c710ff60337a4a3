//! The setting data functions (the CNC's setting parameters,
//! docs/protocol/param.md "Setting data").

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::base::COMMAND;

pub const FUNCS: &[Func] = &[Func {
    name: "cnc_rdsetnum",
    learnt: Some(&[]),
    doc: "Reads the smallest and largest setting data numbers and how many setting data there are.",
    params: &[Param::Out("setnum", "ODBSETNUM")],
    forms: &[every_class(cmd::RDSETNUM, &[])],
    // Three 32-bit words; their low halves are the numbers.
    reply: &[
        skip(I16),
        to(U16, "set_min", U16),
        skip(I16),
        to(U16, "set_max", U16),
        skip(I16),
        to(U16, "total_no", U16),
    ],
    ..COMMAND
}];
