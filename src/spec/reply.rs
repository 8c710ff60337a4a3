//! A reply's layout, as data: the wire integers ([`Int`]), the fields
//! that carry them into C outputs ([`Field`] and its constructors), the
//! records after them ([`Records`], [`Columns`]), and what a short or
//! overlong answer means ([`Short`], [`Overflow`]). Read by the codec, the
//! export writer (build.rs), the simulator and the oracle, through
//! [`super::types`].
//!
//! Compiled into build.rs too (`#[path]`): plain data only.

/// An integer of the wire (big-endian) or of a C struct (native).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Int {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    /// A wire kind only: the base (u16) and exponent (i16) words of a
    /// value record (`value · base^-exp`: base 10, or 2 for a binary
    /// record), after the record's value, an `I32` field of one element
    /// right before it ([`digits`], [`places`]). Decoded, the pair is the
    /// number's decimal digits (the `I32` field's integer) and decimal
    /// places (this one's), as FANUC's library converts a binary record
    /// (`crate::proto::value::Value::to_decimal`); sent (a write's payload,
    /// the simulator's answer), the digits and places become a base-10
    /// record, or a binary one where [`Func::binary`](super::Func::binary) says. Its C type
    /// (`c`) is the places' member, an `I16`.
    BaseExp,
    /// A character of a text field: a byte on the wire and in C (as
    /// `U8`); decoded, the field's characters after its first NUL read as
    /// 0 (a C string as FANUC's library copies it, whatever the answer
    /// holds after the NUL).
    Char,
    /// A character of an ID (a series or edition): a byte, read as 0
    /// where the CNC sent 0xff (FANUC's library writes a series' or
    /// edition's unset characters as NULs, cnc_rdsyssoft). Its C type
    /// (`c`) is `I8`.
    IdChar,
    /// An IEEE double: 8 bytes, big-endian on the wire, a native `double`
    /// in C, copied bit-exact both ways (NaN included: FANUC's library
    /// swaps the bytes, nothing more; cnc_rdmacror2). Its integer is the
    /// double's bit pattern (`f64::to_bits` as `i64`).
    F64,
}

impl Int {
    pub const fn size(self) -> usize {
        match self {
            Int::I8 | Int::U8 | Int::Char | Int::IdChar => 1,
            Int::I16 | Int::U16 => 2,
            Int::I32 | Int::U32 | Int::BaseExp => 4,
            Int::F64 => 8,
        }
    }
    /// `v` converted to this integer, as a C cast converts it.
    pub const fn cut(self, v: i64) -> i64 {
        match self {
            Int::I8 | Int::IdChar => v as i8 as i64,
            Int::U8 | Int::Char => v as u8 as i64,
            Int::I16 => v as i16 as i64,
            Int::U16 => v as u16 as i64,
            Int::I32 => v as i32 as i64,
            Int::U32 => v as u32 as i64,
            Int::BaseExp => v as i16 as i64,
            // The bits as they are.
            Int::F64 => v,
        }
    }
    /// The Rust type of a C field of this width.
    pub const fn rust(self) -> &'static str {
        match self {
            Int::I8 | Int::IdChar => "i8",
            Int::U8 | Int::Char => "u8",
            Int::I16 => "i16",
            Int::U16 => "u16",
            Int::I32 => "i32",
            Int::U32 => "u32",
            Int::BaseExp => "i16",
            Int::F64 => "f64",
        }
    }
}

/// `n` consecutive integers of the reply payload. Each is written, converted
/// as a C cast converts it, to output `out` (index among the `Out`
/// parameters) at member `to` (`""`: the pointee itself; `name[i]`:
/// element i of array member `name`, elements of `c`'s width; `[i]`:
/// element i of the pointee, an array) and the
/// `n - 1` elements after it; `to: None` skips them.
#[derive(Debug, Clone, Copy)]
pub struct Field {
    pub wire: Int,
    pub n: u16,
    pub out: u8,
    pub to: Option<&'static str>,
    pub c: Int,
    /// `Some(a)`: not on the wire; the value is number argument `a`, which
    /// FANUC's library writes back into the output with the reply
    /// ([`ZERO`]: the value 0, as it writes a string's terminating NUL).
    pub arg: Option<u8>,
}

/// [`Field::arg`] of a field not on the wire that FANUC's library writes
/// as 0 ([`zero`]).
pub const ZERO: u8 = u8::MAX;

/// [`Field::arg`] of a field not on the wire that FANUC's library writes
/// as the last number the records answered: number argument 0 plus the
/// records decoded, less one ([`last`]; no record: argument 0 less one).
pub const LAST: u8 = u8::MAX - 1;

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
    /// bytes, its value as the parameter gives it (negative: no room; a
    /// `short` FANUC's library reads unsigned is a
    /// [`Param::ShortAs`](super::Param::ShortAs)`(_, U16)`): records ending
    /// past it are EW_LENGTH with nothing written, checked after the reply.
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

/// What a payload shorter than the reply layout means.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Short {
    /// The missing bytes read as zeros, as FANUC's library reads them from
    /// its zeroed buffer.
    Zeros,
    /// EW_PROTOCOL, nothing written.
    Error,
    /// The missing bytes read as the request's at the same offsets of the
    /// frame body (FANUC's library reads the answer into the buffer that
    /// held its request): payload byte k is the request subpacket's byte
    /// 16 + k (its third argument word on, then its payload), zeros past
    /// the request (cnc_rd2tlifedata: an empty answer's `datano` is the
    /// use number asked for). So do the records a
    /// [`Func::counted`](super::Func::counted) count announces past the
    /// answer's end (cnc_rdmagazine: its own request's pots).
    Request,
    /// The answer is one unit of `.0` bytes per spindle: FANUC's library
    /// reads as many units as it holds, at most the CNC's maximum spindles
    /// (the open answer's); none (an answer shorter than a unit, or a CNC
    /// without spindles) writes nothing, EW_OK; else as [`Short::Zeros`]
    /// (cnc_rdctrldi: its length counted in 2-byte units, 4-byte words read).
    PerSpindle(u8),
}

/// What a reply holding more records than the caller's count
/// ([`Param::Count`](super::Param::Count)) asked for means.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Overflow {
    /// The records past the count are left out.
    Cut,
    /// EW_LENGTH, nothing written (the count untouched); the records are
    /// as many as the answer holds (`max` bounds only what the simulator
    /// sends).
    Refuse,
}

/// A reply of columns (with [`Func::more`](super::Func::more)): reply field k (its `n` the
/// most elements, its `to` an array member of output 0) is read from
/// subpacket k's answer (the form's first, then `more`'s), one element
/// every `stride[k]` bytes (the field's integer first, the rest of the
/// element skipped: the base and exponent of a value record). The
/// elements are as many as subpacket 0's payload holds (its length /
/// `stride[0]`), at most the field's `n`; a column's answer shorter than
/// that reads zeros past its end. A column's subpacket answering an error
/// makes it the call's, nothing written. The subpackets past the reply's
/// fields are not read into the outputs (cnc_rd3dtooltip's second pair,
/// which FANUC's library writes past the caller's struct): the first of
/// them answering error `none` ends the reply; another error of theirs is
/// the call's, returned once the columns are written.
#[derive(Debug, Clone, Copy)]
pub struct Columns {
    pub stride: &'static [u8],
    pub none: i16,
}

/// An array member of output 0 that FANUC's library fills by looking its
/// elements up in the reply (cnc_rdsyssoft: the logical slot of each
/// physical slot, the module ID by slot): every element first holds
/// `fill`; then element i, for each key i in turn until the first key
/// (its low byte) equal to `end`, is what `pick` finds for key i (nothing
/// found: `fill` stays). Elements are `c`, `n` of them, each
/// [`Pick::per`] integers; not on the wire: the decoded reply's integers
/// are followed by the lookups', in order.
#[derive(Debug, Clone, Copy)]
pub struct Lookup {
    pub to: &'static str,
    pub c: Int,
    pub n: u16,
    pub fill: i64,
    pub key: Key,
    pub end: u8,
    pub pick: Pick,
}

/// Where a [`Lookup`]'s keys come from: key i is element i of it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Key {
    /// Reply field k (an index in `reply`), as decoded.
    Field(u8),
    /// The elements [`Lookup`] k (an index in `lookups`, an earlier one)
    /// wrote.
    Lookup(u8),
    /// The element's own index i (a run of fixed places).
    Own,
}

/// What a [`Lookup`] finds for a key (its low byte, `k`). A reply field
/// is an index in `reply`; an element past a field's end reads 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pick {
    /// The first `j` whose element `j · stride` of reply field `field`
    /// equals `k` (its low byte), `j` below `n`.
    Index { field: u8, stride: u8, n: u8 },
    /// Element `k & mask` of reply field `low` for a `k` below 0x80, of
    /// reply field `high` from 0x80.
    Split { mask: u8, low: u8, high: u8 },
    /// `width` elements of reply field `field` from element `k · stride +
    /// at` on, then a 0 (each lookup element `width + 1` integers).
    Chars {
        field: u8,
        stride: u8,
        at: u8,
        width: u8,
    },
}

impl Pick {
    /// The integers of one element.
    pub const fn per(&self) -> usize {
        match *self {
            Pick::Chars { width, .. } => width as usize + 1,
            Pick::Index { .. } | Pick::Split { .. } => 1,
        }
    }
}

impl Lookup {
    /// The integers this lookup adds to the decoded reply.
    pub const fn values(&self) -> usize {
        self.n as usize * self.pick.per()
    }
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

/// A value record's value word (its first 4 bytes), followed by
/// [`places`]: decoded, the number's decimal digits, written to output
/// `out`'s member `to` (a `long`, 32 bits).
pub const fn digits(out: u8, to: &'static str) -> Field {
    to_out(out, Int::I32, to, Int::I32)
}

/// A value record's base and exponent words ([`Int::BaseExp`]), right
/// after its [`digits`]: decoded, the number's decimal places, written to
/// output `out`'s member `to` (a `short`).
pub const fn places(out: u8, to: &'static str) -> Field {
    to_out(out, Int::BaseExp, to, Int::I16)
}

/// `n` IEEE doubles ([`Int::F64`]) written to output `out`'s member `to`
/// (`""`: the output itself, an array of them).
pub const fn doubles(out: u8, n: u16, to: &'static str) -> Field {
    Field {
        wire: Int::F64,
        n,
        out,
        to: Some(to),
        c: Int::F64,
        arg: None,
    }
}

/// `n` characters of a text ([`Int::Char`]: up to its first NUL, zeros
/// after) written to output 0's member `to`.
pub const fn text(n: u16, to: &'static str) -> Field {
    Field {
        wire: Int::Char,
        n,
        out: 0,
        to: Some(to),
        c: Int::Char,
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

/// The number of the last record answered (not on the wire, [`LAST`])
/// written to output 0's member `to`.
pub const fn last(to: &'static str, c: Int) -> Field {
    Field {
        wire: c,
        n: 1,
        out: 0,
        to: Some(to),
        c,
        arg: Some(LAST),
    }
}

/// A 0 written to output 0's member `to` (not on the wire): the NUL after
/// a name's characters. `to` may name an element of an array member,
/// `name[i]` (elements of `c`'s width).
pub const fn zero(to: &'static str, c: Int) -> Field {
    Field {
        wire: c,
        n: 1,
        out: 0,
        to: Some(to),
        c,
        arg: Some(ZERO),
    }
}
