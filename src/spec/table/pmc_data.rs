//! The PMC's long tail: its program's title and type, and the message
//! functions FANUC's Linux library does not implement.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;
use super::pmc::{text, zeros};
use crate::ew::EW_FUNC;

/// A message function: EW_FUNC (1) on every call, without traffic.
const NO_MESSAGES: Func = Func {
    checks: &[answers(EW_FUNC)],
    ..super::base::COMMAND
};

pub const FUNCS: &[Func] = &[
    Func {
        name: "pmc_rdpmctitle2",
        learnt: Some(&[]),
        doc: "Reads the PMC program's title data with ODBPMCTITLE2's longer program number and version: pmc_rdpmctitle's texts as the CNC sent them (32, 32, 32, 4, 2, 32, 16, 32, 32 and 32 bytes), then 4 more characters of the program number and 6 more of the version, each at the start of its member, the rest of each member zeroed, as FANUC's library; a short answer reads as zeros.",
        params: &[Param::Out("title", "ODBPMCTITLE2")],
        forms: &[pmc(cmd::RDPMCTITLE2, &[])],
        reply: &[
            text("mtb", 32),
            zeros("mtb[32]", 16),
            text("machine", 32),
            zeros("machine[32]", 16),
            text("type", 32),
            zeros("type[32]", 16),
            text("prgno", 4),
            text("prgvers", 2),
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
            text("prgno[4]", 4),
            zeros("prgno[8]", 8),
            text("prgvers[2]", 6),
            zeros("prgvers[8]", 8),
        ],
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_read_seq_program_and_memory_type",
        learnt: Some(&[]),
        doc: "Reads the type of the PMC's sequence program and of its memory: four 32-bit codes (4 bytes written into each `unsigned long`), then the two 32-byte texts as the CNC sent them.",
        params: &[Param::Out("type", "ODBPMCLADMEMTYPE")],
        forms: &[pmc(cmd::SEQ_PROGRAM_TYPE, &[])],
        reply: &[
            to(U32, "SystemType", U32),
            to(U32, "SystemAttribute", U32),
            to(U32, "TargetType", U32),
            to(U32, "TargetAttribute", U32),
            text("SystemTypeStr", 32),
            text("TargetTypeStr", 32),
        ],
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_rdmsg",
        doc: "Reads a message from the PMC: not implemented by FANUC's Linux library, which answers EW_FUNC (1) without traffic, writing nothing.",
        params: &[Param::Out("data", "short"), Param::Out("length", "short")],
        ..NO_MESSAGES
    },
    Func {
        name: "pmc_crdmsg",
        doc: "Reads a message from the PMC, conditionally: not implemented by FANUC's Linux library, which answers EW_FUNC (1) without traffic, writing nothing.",
        params: &[Param::Out("data", "short"), Param::Out("length", "short")],
        ..NO_MESSAGES
    },
    Func {
        name: "pmc_wrmsg",
        doc: "Writes a message to the PMC: not implemented by FANUC's Linux library, which answers EW_FUNC (1) without traffic, reading nothing.",
        params: &[Param::Short("length"), Param::Out("data", "short")],
        dims: &["1|0|-1|32767"],
        ..NO_MESSAGES
    },
    Func {
        name: "pmc_cwrmsg",
        doc: "Writes a message to the PMC, conditionally: not implemented by FANUC's Linux library, which answers EW_FUNC (1) without traffic, reading nothing.",
        params: &[Param::Short("length"), Param::Out("data", "short")],
        dims: &["1|0|-1|32767"],
        ..NO_MESSAGES
    },
];
