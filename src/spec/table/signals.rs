//! The spindle control signals (docs/protocol/machine.md).

use super::super::commands as cmd;
use super::super::types::Int::*;
use super::super::types::*;

/// `(1,0x005b)[k]`: the first signal word into the caller's four bytes
/// (from `sgnl1` on, native)
/// (FANUC's library writes one word per two bytes of the answer, at most
/// the CNC's maximum spindles, past the struct: a listed deviation).
const SIGNALS: Func = Func {
    reply: &[to(I32, "sgnl1", I32)],
    short: Short::PerSpindle(2),
    ..super::base::COMMAND
};

pub const FUNCS: &[Func] = &[
    Func {
        name: "cnc_rdctrldi",
        doc: "Reads the spindle control input signals (four bytes, `sgnl1` the low byte of the CNC's first signal word).",
        params: &[Param::Out("spdi", "ODBSPDI")],
        forms: &[every_class(cmd::RDCTRLSIG, &[Word::Const(0)])],
        ..SIGNALS
    },
    Func {
        name: "cnc_rdctrldo",
        doc: "Reads the spindle control output signals (four bytes, as cnc_rdctrldi).",
        params: &[Param::Out("spdo", "ODBSPDO")],
        forms: &[every_class(cmd::RDCTRLSIG, &[Word::Const(1)])],
        ..SIGNALS
    },
];
