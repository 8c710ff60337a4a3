//! The PMC units functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;

pub const FUNCS: &[Func] = &[Func {
    name: "pmc_get_number_of_pmc",
    doc: "Reads how many PMC units the CNC has (4 bytes written into the `long`).",
    params: &[Param::Out("piNum", "long")],
    checks: &[],
    forms: &[pmc(cmd::PMC_COUNT, &[])],
    reply: &[to(I32, "", I32)],
    ..super::base::COMMAND
}];
