//! The PMC units functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;

/// A text of the reply: `n` characters into member `to` (its first `n`).
const fn text(to: &'static str, n: u16) -> Field {
    Field {
        wire: U8,
        n,
        out: 0,
        to: Some(to),
        c: I8,
        arg: None,
    }
}

/// `n` zeros written from member element `to` on (not on the wire).
const fn zeros(to: &'static str, n: u16) -> Field {
    Field { n, ..zero(to, I8) }
}

pub const FUNCS: &[Func] = &[
    Func {
        name: "pmc_get_number_of_pmc",
        doc: "Reads how many PMC units the CNC has (4 bytes written into the `long`).",
        params: &[Param::Out("piNum", "long")],
        checks: &[],
        forms: &[pmc(cmd::PMC_COUNT, &[])],
        reply: &[to(I32, "", I32)],
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_rdpmctitle",
        doc: "Reads the PMC program's title data: each text as the CNC sent it (32, 32, 32, 4, 2, 32, 16, 32, 32 and 32 bytes), the rest of its member zeroed, as FANUC's library; a short answer reads as zeros.",
        params: &[Param::Out("title", "ODBPMCTITLE")],
        forms: &[pmc(cmd::RDPMCTITLE, &[])],
        reply: &[
            text("mtb", 32),
            zeros("mtb[32]", 16),
            text("machine", 32),
            zeros("machine[32]", 16),
            text("type", 32),
            zeros("type[32]", 16),
            text("prgno", 4),
            zeros("prgno[4]", 4),
            text("prgvers", 2),
            zeros("prgvers[2]", 2),
            text("prgdraw", 32),
            zeros("prgdraw[32]", 16),
            text("date", 16),
            zeros("date[16]", 16),
            text("design", 32),
            zeros("design[32]", 16),
            text("written", 32),
            zeros("written[32]", 16),
            text("remarks", 32),
            zeros("remarks[32]", 16),
        ],
        ..super::base::COMMAND
    },
];
