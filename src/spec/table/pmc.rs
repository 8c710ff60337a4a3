//! The PMC units functions.

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;

/// A text of the reply: `n` characters into member `to` (its first `n`).
pub(super) const fn text(to: &'static str, n: u16) -> Field {
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
pub(super) const fn zeros(to: &'static str, n: u16) -> Field {
    Field { n, ..zero(to, I8) }
}

/// The timer functions' checks: timers `s_number..=e_number` from 1 on,
/// else EW_NUMBER before any traffic.
const TIMER_RANGE: &[Check] = &[
    Check {
        arg: 0,
        lo: 1,
        hi: i32::MAX,
        code: crate::ew::EW_NUMBER,
    },
    ordered(0, 1),
];

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
        name: "pmc_get_current_pmc_unit",
        doc: "Reads the PMC unit this handle's PMC calls address (1 until one is selected), without traffic. Writes 4 bytes into the `long`.",
        params: &[Param::Out("unittype", "long")],
        reply: &[to(I32, "", I32)],
        local: Some(&Local {
            classes: Classes::All,
            values: &[Learnt::PmcUnit],
        }),
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_get_timer_type",
        doc: "Reads the types (accuracy codes) of PMC timers `s_number..=e_number` into `types`, one short each. No more than the range holds is written (FANUC's library copies the whole answer). `s_number` below 1 or after `e_number`: EW_NUMBER before any traffic.",
        params: &[
            Param::UShort("s_number"),
            Param::UShort("e_number"),
            Param::Out("types", "short"),
        ],
        checks: TIMER_RANGE,
        forms: &[pmc(cmd::GET_TIMER_TYPE, &[Word::Arg(0), Word::Arg(1)])],
        // As many whole words as the answer holds, at most the range's.
        records: Some(&Records {
            fields: &[to(I16, "", I16)],
            out: 0,
            to: "",
            elem: "short",
            max: u16::MAX,
            count: None,
            room: None,
        }),
        span: Some((0, 1)),
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_set_timer_type",
        doc: "Sets the types (accuracy codes) of PMC timers `s_number..=e_number` from `types`, one short each (sent as the request's payload). `s_number` below 1 or after `e_number`: EW_NUMBER before any traffic.",
        params: &[
            Param::UShort("s_number"),
            Param::UShort("e_number"),
            Param::In("types", "short"),
        ],
        checks: TIMER_RANGE,
        forms: &[pmc(cmd::SET_TIMER_TYPE, &[Word::Arg(0), Word::Arg(1)])],
        payload: Some(&Payload {
            fields: &[to(I16, "", I16)],
            elem: "short",
            count: SPAN,
            max: u16::MAX,
        }),
        span: Some((0, 1)),
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
    Func {
        name: "pmc_rdcntlgrp",
        learnt: Some(&[]),
        doc: "Reads the group number of the PMC data table's control data (the low 16 bits of the 32-bit answer).",
        params: &[Param::Out("s_number", "short")],
        forms: &[pmc(cmd::RDCNTLGRP, &[])],
        reply: &[skip(I16), to(I16, "", I16)],
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_wrcntlgrp",
        learnt: Some(&[]),
        doc: "Sets the group number of the PMC data table's control data, as pmc_rdcntlgrp reads it.",
        params: &[Param::Short("s_number")],
        forms: &[pmc(cmd::WRCNTLGRP, &[Word::Arg(0)])],
        dims: &["1|0|-1|2|16|2000|32767"],
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_rdcntl_exrelay_grp",
        learnt: Some(&[]),
        doc: "Reads the group number of the PMC extended relay's control data (the low 16 bits of the 32-bit answer).",
        params: &[Param::Out("s_number", "short")],
        forms: &[pmc(cmd::RDCNTL_EXRELAY_GRP, &[])],
        reply: &[skip(I16), to(I16, "", I16)],
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_wrcntl_exrelay_grp",
        learnt: Some(&[]),
        doc: "Sets the group number of the PMC extended relay's control data, as pmc_rdcntl_exrelay_grp reads it.",
        params: &[Param::Short("s_number")],
        forms: &[pmc(cmd::WRCNTL_EXRELAY_GRP, &[Word::Arg(0)])],
        dims: &["1|0|-1|2|16|2000|32767"],
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_kpmsiz",
        learnt: Some(&[]),
        doc: "Reads the maximum size of the PMC's extended backup memory (4 bytes written into the `unsigned long`).",
        params: &[Param::Out("size", "unsigned long")],
        forms: &[pmc(cmd::KPMSIZ, &[])],
        reply: &[to(U32, "", U32)],
        ..super::base::COMMAND
    },
    Func {
        name: "pmc_get_number_of_ladder",
        learnt: Some(&[]),
        doc: "Reads how many divided ladders the PMC's sequence program has (4 bytes written into the `long`).",
        params: &[Param::Out("number", "long")],
        forms: &[pmc(cmd::NUMBER_OF_LADDER, &[])],
        reply: &[to(I32, "", I32)],
        ..super::base::COMMAND
    },
];
