//! What a FOCAS function is, as data: its C parameters, local checks,
//! request form per CNC class, and reply layout.
//!
//! One [`Func`] per function (src/spec/table/) is read by every layer:
//! build.rs writes the exported C function (and so its header declaration)
//! from it, the codec builds the request and decodes or encodes the reply
//! with it (src/proto/described.rs), the simulator dispatches its command by
//! it, and the oracle generates the probe's call and the cases from it.
//!
//! This file is compiled into build.rs too (`#[path]`): plain data only, no
//! `crate::` paths but `crate::ew` (build.rs includes src/ew.rs at its root).

use super::commands::{CLASS_CNC, CLASS_PMC};
use crate::ew::{EW_LENGTH, EW_NOOPT};

/// A C parameter after the handle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    /// `short NAME`: a number the caller passes.
    Short(&'static str),
    /// `long NAME`: a number the caller passes (32 bits go on the wire).
    Long(&'static str),
    /// `TYPE *NAME`: an output the reply fills. TYPE is a struct of
    /// src/types, or `char`, `short`, `unsigned short` or `long` (4 bytes written,
    /// as FANUC's x86-64 library writes a `long *`), or `char[N]`.
    Out(&'static str, &'static str),
    /// `short *NAME`: the records' count, in and out. In, how many records
    /// the caller's array holds (a number parameter, read once the pointers
    /// are checked); out, how many were written. The records' output is
    /// then an array of that many elements.
    Count(&'static str),
    /// `TYPE *NAME`: the records a write sends, read from the caller's
    /// array ([`Func::payload`]). TYPE as for [`Param::Out`].
    In(&'static str, &'static str),
}

impl Param {
    pub const fn name(&self) -> &'static str {
        match *self {
            Param::Short(n)
            | Param::Long(n)
            | Param::Out(n, _)
            | Param::Count(n)
            | Param::In(n, _) => n,
        }
    }
}

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
}

/// One word of a request's argument block.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Word {
    /// The value of number parameter `n` (index into `params`).
    Arg(u8),
    /// A constant.
    Const(i32),
    /// The records asked for: the [`Param::Count`] parameter's value, at
    /// most the records' `max`.
    Asked,
}

/// How the request is formed on some classes.
#[derive(Debug, Clone, Copy)]
pub struct Form {
    pub classes: Classes,
    /// The subpacket class: `CLASS_CNC` (the handle's path), `CLASS_PMC` (path 1).
    pub class: u16,
    pub cmd: u16,
    /// Up to five argument words; the rest are 0.
    pub words: &'static [Word],
}

/// A check FANUC's library makes before any traffic: number parameter
/// `arg` outside `lo..=hi` returns `code`, an `EW_*` constant of src/ew.rs.
/// `arg` [`OPTION`] checks the CNC's FOCAS option bit (0 or 1) instead.
#[derive(Debug, Clone, Copy)]
pub struct Check {
    pub arg: u8,
    pub lo: i32,
    pub hi: i32,
    pub code: i16,
}

/// [`Check::arg`] for the CNC's FOCAS option bit, which FANUC's library
/// learns at connect.
pub const OPTION: u8 = u8::MAX;

/// A count (number parameter `arg`) below 1: EW_LENGTH before any traffic.
pub const fn at_least_one(arg: u8) -> Check {
    Check {
        arg,
        lo: 1,
        hi: i32::MAX,
        code: EW_LENGTH,
    }
}

/// The check of a function that needs the FOCAS option: EW_NOOPT without.
pub const NEEDS_OPTION: Check = Check {
    arg: OPTION,
    lo: 1,
    hi: 1,
    code: EW_NOOPT,
};

/// An integer of the wire (big-endian) or of a C struct (native).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Int {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
}

impl Int {
    pub const fn size(self) -> usize {
        match self {
            Int::I8 | Int::U8 => 1,
            Int::I16 | Int::U16 => 2,
            Int::I32 | Int::U32 => 4,
        }
    }
    /// The Rust type of a C field of this width.
    pub const fn rust(self) -> &'static str {
        match self {
            Int::I8 => "i8",
            Int::U8 => "u8",
            Int::I16 => "i16",
            Int::U16 => "u16",
            Int::I32 => "i32",
            Int::U32 => "u32",
        }
    }
}

/// `n` consecutive integers of the reply payload. Each is written, converted
/// as a C cast converts it, to output `out` (index among the `Out`
/// parameters) at member `to` (`""`: the pointee itself) and the `n - 1`
/// elements after it; `to: None` skips them.
#[derive(Debug, Clone, Copy)]
pub struct Field {
    pub wire: Int,
    pub n: u16,
    pub out: u8,
    pub to: Option<&'static str>,
    pub c: Int,
    /// `Some(a)`: not on the wire; the value is number argument `a`, which
    /// FANUC's library writes back into the output with the reply.
    pub arg: Option<u8>,
}

impl Field {
    /// The bytes of this field on the wire.
    pub const fn wire_len(&self) -> usize {
        match self.arg {
            Some(_) => 0,
            None => self.wire.size() * self.n as usize,
        }
    }
}

/// An array of records after the fixed fields of the reply: as many whole
/// records as the rest of the payload holds, at most `max`, written from
/// output `out`'s member `to` (`""`: the output itself is the array) on,
/// one `elem` (a struct of src/types, or `short`/`long`) per record. The
/// `to` of each field names a member of `elem` (`""`: the element itself).
#[derive(Debug, Clone, Copy)]
pub struct Records {
    pub fields: &'static [Field],
    pub out: u8,
    pub to: &'static str,
    pub elem: &'static str,
    pub max: u16,
    /// The `short` member of output `out` the number of records written
    /// goes to, if any.
    pub count: Option<&'static str>,
    /// Number parameter `room` is the caller's size of output `out` in
    /// bytes (read as an unsigned short): records ending past it are
    /// EW_LENGTH with nothing written, checked after the reply.
    pub room: Option<u8>,
}

impl Records {
    /// The bytes of one record on the wire.
    pub fn wire_len(&self) -> usize {
        self.fields.iter().map(Field::wire_len).sum()
    }
    /// The integers of one record.
    pub fn values(&self) -> usize {
        self.fields.iter().map(|f| f.n as usize).sum()
    }
}

/// The records a write sends as its request's payload, read from its
/// [`Param::In`] array: number parameter `count` of them, at most `max`.
/// Each field is read as `c` from member `to` of `elem` (`""`: the element
/// itself; `None`: nothing read, zeros sent) and sent as `wire`. The
/// request's fifth word is the payload's length.
#[derive(Debug, Clone, Copy)]
pub struct Payload {
    pub fields: &'static [Field],
    pub elem: &'static str,
    pub count: u8,
    pub max: u16,
}

/// What a payload shorter than the reply layout means.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Short {
    /// The missing bytes read as zeros, as FANUC's library reads them from
    /// its zeroed buffer.
    Zeros,
    /// EW_PROTOCOL, nothing written.
    Error,
}

/// One FOCAS function.
#[derive(Debug, Clone, Copy)]
pub struct Func {
    /// The C name (`cnc_rdseqnum`).
    pub name: &'static str,
    /// One line for the header and rustdoc.
    pub doc: &'static str,
    /// The C parameters after `unsigned short FlibHndl`.
    pub params: &'static [Param],
    pub checks: &'static [Check],
    /// The request: the first form whose classes match the CNC's.
    pub forms: &'static [Form],
    pub reply: &'static [Field],
    /// Records after `reply`'s fields, if any.
    pub records: Option<Records>,
    /// The records a write sends, if any.
    pub payload: Option<Payload>,
    pub short: Short,
    /// The oracle's dimensions, one per number parameter: "|"-separated
    /// values, the base first.
    pub dims: &'static [&'static str],
    /// The first reply field is the number the CNC answered for (a tool
    /// group); when its low 16 bits are 0 the `data` member reads as 0, as
    /// FANUC's library writes it (no such group).
    pub zero_without_first: bool,
    /// A member FANUC's library writes as 0 unless another member's value
    /// is in a range.
    pub zero_unless: Option<ZeroUnless>,
}

/// Output 0's member `zero` reads 0 unless member `of` (its value cut to
/// its C type) is within `lo..=hi`, as FANUC's library writes it
/// (cnc_rdpmacroinfo: `use_no2` only with a `v2_type` below 2).
#[derive(Debug, Clone, Copy)]
pub struct ZeroUnless {
    pub zero: &'static str,
    pub of: &'static str,
    pub lo: i32,
    pub hi: i32,
}

impl Func {
    /// The probe word the oracle and the vectors call this function by.
    pub fn word(&self) -> &'static str {
        self.name.strip_prefix("cnc_").unwrap_or(self.name)
    }
    /// The number parameters, in order (the values a caller passes).
    pub fn numbers(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.params.iter().filter_map(|p| match *p {
            Param::Short(n) | Param::Long(n) | Param::Count(n) => Some(n),
            Param::Out(..) | Param::In(..) => None,
        })
    }
    /// The [`Param::Count`] parameter, if any: its index among the number
    /// parameters.
    pub fn count(&self) -> Option<usize> {
        self.numbers()
            .position(|n| self.params.contains(&Param::Count(n)))
    }
    /// The [`Param::In`] parameter, if any: (name, C type).
    pub fn input(&self) -> Option<(&'static str, &'static str)> {
        self.params.iter().find_map(|p| match *p {
            Param::In(n, t) => Some((n, t)),
            _ => None,
        })
    }
    /// The output parameters, in order: (name, C type).
    pub fn outs(&self) -> impl Iterator<Item = (&'static str, &'static str)> + '_ {
        self.params.iter().filter_map(|p| match *p {
            Param::Out(n, t) => Some((n, t)),
            _ => None,
        })
    }
    /// The reply payload's length in bytes.
    pub fn reply_len(&self) -> usize {
        self.reply.iter().map(Field::wire_len).sum()
    }
}

/// A reply field written to output 0's member `to`.
pub const fn to(wire: Int, to: &'static str, c: Int) -> Field {
    Field {
        wire,
        n: 1,
        out: 0,
        to: Some(to),
        c,
        arg: None,
    }
}

/// A reply field written to output `out`'s member `to`.
pub const fn to_out(out: u8, wire: Int, to: &'static str, c: Int) -> Field {
    Field {
        wire,
        n: 1,
        out,
        to: Some(to),
        c,
        arg: None,
    }
}

/// A reply field nobody reads.
pub const fn skip(wire: Int) -> Field {
    Field {
        wire,
        n: 1,
        out: 0,
        to: None,
        c: wire,
        arg: None,
    }
}

/// Number argument `arg` written back to output 0's member `to` (not on
/// the wire).
pub const fn echo(arg: u8, to: &'static str, c: Int) -> Field {
    Field {
        wire: c,
        n: 1,
        out: 0,
        to: Some(to),
        c,
        arg: Some(arg),
    }
}

/// The one request form of a function that sends the same on every class.
pub const fn every_class(cmd: u16, words: &'static [Word]) -> Form {
    Form {
        classes: Classes::All,
        class: CLASS_CNC,
        cmd,
        words,
    }
}

/// The one request form of a PMC function (subpacket class 2, path 1).
pub const fn pmc(cmd: u16, words: &'static [Word]) -> Form {
    Form {
        classes: Classes::All,
        class: CLASS_PMC,
        cmd,
        words,
    }
}
