//! Entries other entries start from (`..COMMAND`).

use super::super::types::Int::*;
use super::super::types::*;

/// A command: no argument, no answer.
pub const COMMAND: Func = Func {
    name: "",
    doc: "",
    params: &[],
    checks: &[],
    forms: &[],
    reply: &[],
    records: None,
    payload: None,
    more: &[],
    more_cmds: &[],
    columns: None,
    local: None,
    short: Short::Zeros,
    overflow: Overflow::Cut,
    dims: &[],
    zero_without_first: false,
    zeroed: &[],
    learnt: None,
    zero_unless: None,
    binary: None,
    counted: None,
    span: None,
    block: None,
    lookups: &[],
    pages: None,
};

/// A servo figure of each axis into `long data[]`: the value word of each
/// 0x0056 value record (value, then base and exponent).
pub const SERVO_LONGS: Func = Func {
    name: "",
    doc: "",
    params: &[Param::Out("data", "long")],
    checks: &[],
    forms: &[],
    reply: &[],
    records: Some(Records {
        fields: &[to(I32, "", I32), skip(I32)],
        out: 0,
        to: "",
        elem: "long",
        max: 32,
        count: None,
        room: None,
    }),
    payload: None,
    more: &[],
    more_cmds: &[],
    columns: None,
    local: None,
    short: Short::Zeros,
    overflow: Overflow::Cut,
    dims: &[],
    zero_without_first: false,
    zeroed: &[],
    learnt: None,
    zero_unless: None,
    binary: None,
    counted: None,
    span: None,
    block: None,
    lookups: &[],
    pages: None,
};
