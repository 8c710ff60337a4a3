//! The PMC units functions.

use super::super::types::Int::*;
use super::super::types::*;

// The commands of this area's entries (the simulator answers by them).
/// pmc_get_number_of_pmc: the PMC units.
pub const GET_NUMBER_OF_PMC: u16 = 0x800e;

pub const FUNCS: &[Func] = &[Func {
    name: "pmc_get_number_of_pmc",
    doc: "Reads how many PMC units the CNC has (4 bytes written into the `long`).",
    params: &[Param::Out("piNum", "long")],
    checks: &[],
    forms: &[pmc(GET_NUMBER_OF_PMC, &[])],
    reply: &[to(I32, "", I32)],
    records: None,
    payload: None,
    short: Short::Zeros,
    dims: &[],
    zero_without_first: false,
}];
