//! Where a function's facts depend on the CNC class ([`Classes`]), and the
//! checks with detail codes, exchanges per payload record and computed
//! payload fields a [`super::types::Func`] may carry ([`Rule`], [`Each`],
//! [`Code`]; cnc_sdtsetchnl).
//!
//! Compiled into build.rs too (`#[path]`): plain data only.

use super::reply::Int;

/// The CNC classes a request form is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Classes {
    /// Every class.
    All,
    /// The 30i class (open version 3).
    S30,
    /// The 16i class (open version 2), Series 15 included.
    S16,
    /// Series 15 alone (16i class, kind 2).
    S15,
    /// The 16i class without Series 15.
    S16Not15,
    /// Every class but Series 15.
    Not15,
}

impl Classes {
    /// Whether a CNC of the 16i class (`s16`) or Series 15 (`s15`) is of these.
    pub const fn matches(self, s16: bool, s15: bool) -> bool {
        match self {
            Classes::All => true,
            Classes::S30 => !s16,
            Classes::S16 => s16,
            Classes::S15 => s15,
            Classes::S16Not15 => s16 && !s15,
            Classes::Not15 => !s15,
        }
    }
}

/// What a [`Rule`] checks: a number parameter (its index) or, in each
/// payload record, a payload field (its index among [`Payload::fields`](super::types::Payload::fields),
/// its integer as read from the caller's member).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Of {
    Arg(u8),
    Field(u8),
}

/// [`Rule::ok`]'s `hi`: the path's controlled axes, as the connect answer
/// gives them (a 30i class path word).
pub const AXES: i32 = i32::MAX;

/// A check FANUC's library makes before sending, with a detail code
/// ([`Func::rules`](super::types::Func::rules)): on `classes`, the value of `of` must lie in one of
/// `ok` (`lo..=hi`, `hi` [`AXES`]: the path's axes), else the call returns
/// `code` and cnc_getdtailerr's first word is `detail`, nothing more sent.
/// `when` Some((k, lo, hi)): the rule is for records whose payload field
/// k is within `lo..=hi` (a number rule: number parameter k). Of the rules
/// of one target whose classes and `when` match, the first decides. Number
/// rules come after [`Func::checks`](super::types::Func::checks); then each payload record in order,
/// its rules (in the order listed) before its [`Each`] exchange, so a
/// later record refused returns after the earlier records' exchanges
/// (cnc_sdtsetchnl's channel members, details 20..23).
#[derive(Debug, Clone, Copy)]
pub struct Rule {
    pub classes: Classes,
    pub of: Of,
    pub when: Option<(u8, i32, i32)>,
    pub ok: &'static [(i32, i32)],
    pub code: i16,
    pub detail: i16,
}

/// An exchange FANUC's library makes for a payload record before the
/// function's request, once the record's [`Rule`]s pass ([`Func::each`](super::types::Func::each)):
/// on `classes`, for a record whose payload field `when.0` (the key) is
/// within `when.1..=when.2`, subpacket `(1, cmd)` with `words`, no
/// payload, on the handle's path; `tens`: on path `1 + key / 10` whatever
/// the handle's, the key's units the axis in it (the 16i class's axes
/// 1..8, 11..18, 21..28 of cnc_sdtsetchnl). Of the entries whose classes
/// and `when` match, the first is sent; none: no exchange. An error answer
/// ends the call with `error` (None: the answer's own code); an answer of
/// any length is used. `value` Some((at, stride, c)): the record's value
/// is the answer's bytes at `at + stride · (i − 1)`, `i` the key (with `tens`, its units), read as `c`
/// (big-endian; past the answer's end, 0), for its [`Code::negate`]
/// (cnc_sdtsetchnl's parameter 1023 of the channel's axis, its low byte).
#[derive(Debug, Clone, Copy)]
pub struct Each {
    pub classes: Classes,
    pub when: (u8, i32, i32),
    pub cmd: u16,
    pub words: &'static [i32],
    pub tens: bool,
    pub value: Option<(u16, u16, Int)>,
    pub error: Option<i16>,
}

/// Where a [`Code`] takes its value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CodeValue {
    /// Element `key` of the table, `key` the field's own integer as read
    /// from the caller's member (a [`Rule`] keeps it in the table; outside
    /// it, EW_DATA): a code table held as data.
    Table(&'static [i32]),
    /// Number parameter `a`'s value, in every record.
    Arg(u8),
}

/// A payload field FANUC's library computes rather than copies
/// ([`Func::codes`](super::types::Func::codes)): in each record, payload field `field` becomes
/// `value`. `when` Some((k, lo, hi)): for records whose payload field k
/// (as read) is within `lo..=hi`; the first code of a field that applies is
/// used (none: the integer as read). `negate`: the value is negated when
/// the record's [`Each`] value is even and above 0 (cnc_sdtsetchnl: an
/// axis whose servo axis number, parameter 1023, is even).
#[derive(Debug, Clone, Copy)]
pub struct Code {
    pub field: u8,
    pub when: Option<(u8, i32, i32)>,
    pub value: CodeValue,
    pub negate: bool,
}
