//! What a FOCAS function is, as data: its C parameters, local checks,
//! request form per CNC class, and reply layout.
//!
//! One [`Func`] per function (src/spec/table/) is read by every layer:
//! build.rs writes the exported C function (and so its header declaration)
//! from it, the codec builds the request and decodes or encodes the reply
//! with it (src/proto/described/), the simulator dispatches its command by
//! it, and the oracle generates the probe's call and the cases from it.
//!
//! This file is compiled into build.rs too (`#[path]`): plain data only, no
//! `crate::` paths but `crate::ew` (build.rs includes src/ew.rs at its root).

pub use super::reply::*;
pub use super::rules::*;

use super::commands::{CLASS_CNC, CLASS_PMC};
use crate::ew::{EW_LENGTH, EW_NOOPT};

/// A C parameter after the handle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Param {
    /// `short NAME`: a number the caller passes.
    Short(&'static str),
    /// `long NAME`: a number the caller passes (32 bits go on the wire).
    Long(&'static str),
    /// `unsigned long NAME`: as [`Param::Long`] (32 bits go on the wire).
    ULong(&'static str),
    /// `char NAME`: a number the caller passes as a C `char` (signed on
    /// x86-64, where FANUC's library runs; unsigned on aarch64, as C has it).
    Char(&'static str),
    /// `unsigned short NAME`: a number the caller passes, 0..=65535 (its
    /// checks and request word see it unsigned).
    UShort(&'static str),
    /// `short NAME` that FANUC's library converts to `.1` (as a C cast)
    /// before anything else: its request word and any echo of it carry
    /// the converted value.
    ShortAs(&'static str, Int),
    /// `TYPE *NAME`: an output the reply fills. TYPE is a struct of
    /// src/types, or `char`, `short`, `unsigned short` or `long` (4 bytes written,
    /// as FANUC's x86-64 library writes a `long *`), or `char[N]`, or
    /// `text[N]`: a `char *` to N bytes (a text of [`Int::Char`]s).
    Out(&'static str, &'static str),
    /// `short *NAME`: the records' count, in and out. In, how many records
    /// the caller's array holds (a number parameter, read once the pointers
    /// are checked); out, how many were written. The records' output is
    /// then an array of that many elements.
    Count(&'static str),
    /// `unsigned long *NAME`: a count as [`Param::Count`], of which FANUC's
    /// x86-64 library reads and writes 4 bytes (its number the 32 bits as
    /// an `int`; cnc_rdmacror2's `num`).
    LongCount(&'static str),
    /// `TYPE *NAME`: the records a write sends, read from the caller's
    /// array ([`Func::payload`]). TYPE as for [`Param::Out`].
    In(&'static str, &'static str),
    /// `char *NAME`: a C string the request's payload carries in a field
    /// of `.1` bytes: its characters up to its NUL, cut to the field,
    /// zeros after (bytes past the NUL, or past the field, never read).
    /// The text parameters' fields go first, in parameter order, before
    /// any [`Func::payload`] records; NULL is EW_DATA before any traffic.
    Text(&'static str, u16),
    /// `short *NAME`: a number the caller passes by pointer (read once the
    /// pointers are checked, as [`Param::Count`]'s)
    /// and the reply writes back ([`Range`]: the numbers read and the
    /// bytes used).
    Io(&'static str),
    /// `TYPE *NAME`: the caller's records, both sent (the payload reads
    /// them, as from a [`Param::In`]) and answered (the records are written
    /// back into them, as into a [`Param::Out`]): cnc_rdmagazine sends the
    /// pots and reads back their tools. It is an output and the input.
    InOut(&'static str, &'static str),
}

impl Param {
    /// The argument a caller's value `v` of this number parameter becomes
    /// (a `short` cut to 16 bits, a `long` to 32, then [`Param::ShortAs`]'s
    /// conversion); None for a pointer.
    pub const fn conv(&self, v: i64) -> Option<i32> {
        match *self {
            Param::Short(_) | Param::Count(_) | Param::Io(_) => Some(v as i16 as i32),
            Param::Long(_) | Param::ULong(_) | Param::LongCount(_) => Some(v as i32),
            Param::UShort(_) => Some(v as u16 as i32),
            Param::Char(_) => Some(v as i8 as i32),
            Param::ShortAs(_, c) => Some(c.cut(v as i16 as i64) as i32),
            Param::Out(..) | Param::In(..) | Param::InOut(..) | Param::Text(..) => None,
        }
    }
    pub const fn name(&self) -> &'static str {
        match *self {
            Param::Short(n)
            | Param::Long(n)
            | Param::ULong(n)
            | Param::UShort(n)
            | Param::Char(n)
            | Param::ShortAs(n, _)
            | Param::Out(n, _)
            | Param::Count(n)
            | Param::LongCount(n)
            | Param::In(n, _)
            | Param::Io(n)
            | Param::Text(n, _)
            | Param::InOut(n, _) => n,
        }
    }
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
    /// Member `.0` (a `short`) of a write's input (its first element,
    /// [`Param::In`]) converted to `.1` as a C cast converts it: FANUC's
    /// library sends it as a request word, not in the payload, and leaves
    /// the converted value in the member (the caller sees it when `.1` is
    /// narrower than a `short`). With `.1` [`Int::I32`] or [`Int::U32`] the
    /// member is a 32-bit `long` (cnc_wrpmacror's `datano_s`), read as it is.
    Input(&'static str, Int),
    /// Number parameter `.1`'s value (`e`) cut to the end of the range
    /// number parameter `.0` (`s`) starts in ([`Func::ends`], on the CNC's
    /// class), then to `.2` past `s` when the range holds more than `.2 + 1`
    /// numbers, counted as FANUC's library counts them (`e - s + 1` in 32
    /// bits, wrapping: a range from a negative start to near `i32::MAX`
    /// is not cut): the end of a range FANUC's library asks for, cut to the
    /// most one answer carries (cnc_rdpmacror). [`Func::upto`] computes it.
    /// `.3`: an answer holding `.2 + 1` records is followed by a request
    /// for the rest, from the next number on, while the range lasts
    /// (cnc_rdpmacror, recorded); false: one request (cnc_rdgrpinfo, whose
    /// doc gives at most 44 groups a call).
    Upto(u8, u8, i32, bool),
    /// `.1` when number parameter `.0` is not 0, else 0: a flag FANUC's
    /// library sends for a nonzero argument (cnc_rdparam3's `type`).
    Nonzero(u8, i32),
    /// The last number asked: number parameter `.0` (the first) plus the
    /// records asked ([`Word::Asked`]) less one, in 32 bits (cnc_rdtltool's
    /// `s + num - 1`).
    Last(u8),
    /// Number parameter `.0` plus `.1`, in 32 bits (cnc_tofs_rnge's
    /// `1000 + type`).
    Plus(u8, i32),
}

/// Where a range of numbers ends, for a start in `lo..=hi` on `classes`
/// ([`Func::ends`]): FANUC's library asks for no number past the end of
/// the start's range ([`Word::Upto`]); a start in no listed range is not
/// cut. P-code macro variables: #0..#99, #100..#499, #500..#999,
/// #10000..#19999 ... ([`End`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Ends {
    pub classes: Classes,
    pub lo: i32,
    pub hi: i32,
    pub end: End,
}

/// The end of a range of numbers ([`Ends`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// The range ends at this number: a further end is cut to it.
    At(i32),
    /// The start is read alone: an end past it is EW_NUMBER before any
    /// traffic (the 16i class's #1000..#9999 and negative P-code numbers).
    Alone,
}

/// A request sent before the function's own on `classes` when number
/// parameter `arg` is in one of the `(lo, hi)` ranges ([`Func::first`]):
/// its command with no words, its answer not read (an error answer
/// neither ends the call nor changes what follows). It goes before the
/// local checks; a batch (fwlib32_ext.h) leaves it out. cnc_rdpmacror's
/// `(1,0x00e7)` on the 30i class for #20000.. and #200000.. (why FANUC's
/// library asks is not known).
#[derive(Debug, Clone, Copy)]
pub struct First {
    pub classes: Classes,
    pub cmd: u16,
    pub arg: u8,
    pub ranges: &'static [(i32, i32)],
    /// How many of the function's [`Func::checks`] FANUC's library makes
    /// before it (cnc_wrpmacror's `length`), the others after it.
    pub after: u8,
}

/// A figure FANUC's library learnt from the CNC at connect (the open
/// answer), which some functions answer from without traffic.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Learnt {
    /// The CNC's maximum spindles.
    MaxSpindles,
    /// The PMC unit the handle's PMC calls address: kept by the library
    /// for the handle (pmc_select_pmc_unit's, 1 until one is selected),
    /// not learnt from the CNC.
    PmcUnit,
}

/// The answer of a function that sends nothing on some classes: the
/// reply's integers, in layout order, are these learnt figures.
#[derive(Debug, Clone, Copy)]
pub struct Local {
    pub classes: Classes,
    pub values: &'static [Learnt],
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
/// `arg` outside `lo..=hi` returns `code`, an `EW_*` constant of src/ew.rs
/// (`lo` above `hi`: the range wraps, values from `lo` up or to `hi` pass,
/// [`nonzero`]).
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

/// [`Check::arg`] of an order check: number parameter `lo` (an index)
/// greater than number parameter `hi` (an index) returns `code` (a range
/// asked backwards, cnc_rdpmacror's `s_no` after `e_no`).
pub const ORDERED: u8 = u8::MAX - 1;

/// [`Check::arg`] of a check every call fails: the function answers
/// `code` once the handle is checked, whatever its arguments, without
/// traffic, writing nothing ([`Func::answers`]): FANUC's Linux library
/// implements it so (pmc_rdmsg: EW_FUNC, src/spec/table/pmc_data.rs).
pub const ALWAYS: u8 = u8::MAX - 2;

/// The one check of a function that answers `code` on every call ([`ALWAYS`]).
pub const fn answers(code: i16) -> Check {
    Check {
        arg: ALWAYS,
        lo: 0,
        hi: 0,
        code,
    }
}

/// A range's start (`s`, number parameter `s`) at most its end (`e`):
/// else EW_NUMBER before any traffic.
pub const fn ordered(s: u8, e: u8) -> Check {
    Check {
        arg: ORDERED,
        lo: s as i32,
        hi: e as i32,
        code: crate::ew::EW_NUMBER,
    }
}

/// A count (number parameter `arg`) of 0: EW_LENGTH before any traffic,
/// any other value passes (cnc_rdmacror2's `*num`, which FANUC's library
/// tests for 0 alone).
pub const fn nonzero(arg: u8) -> Check {
    Check {
        arg,
        lo: 1,
        hi: -1,
        code: EW_LENGTH,
    }
}

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

/// [`Payload::count`] of a write without a count parameter: it sends one
/// element, the one its [`Param::In`] points to.
pub const ONE: u8 = u8::MAX;

/// [`Payload::count`] of a write without an input array ([`Param::In`]):
/// it sends one record whose fields' integers are its number parameters
/// that no request word carries, in order (cnc_wrpmacro's `mcr_val` and
/// `dec_val`); the fields' `to` and `elem` are not read.
pub const NUMBERS: u8 = u8::MAX - 1;

/// [`Payload::count`] of an input that is a C string (cnc_rdmacronum's
/// name): one record, its one `U8` field of `n` bytes the string up to
/// its NUL and zeros after it (the caller's bytes past the NUL are never
/// read); a string with no NUL in its first `n` bytes is EW_DATA before
/// any traffic.
pub const TEXT: u8 = u8::MAX - 2;

/// [`Payload::count`] of a write whose records are as many as its range
/// holds ([`Func::span`]): pmc_set_timer_type's timers `s..=e`.
pub const SPAN: u8 = u8::MAX - 3;

/// The records a write sends as its request's payload, read from its
/// [`Param::In`] array: number parameter `count` of them ([`ONE`]: one),
/// at most `max`.
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

/// A typed parameter block instead of reply fields or a payload
/// ([`Func::block`]): IODBPSD's layout, `short datano`, `short type`, then
/// one value or one per axis, each of the size the parameter's type decides
/// (bit and byte 1, word 2, 2-word 4, real 8: value and decimals). On the
/// wire it is the parameter answer or write block (`i32` number, `i16`
/// axis, `u16` type, then 8-byte value records on the 30i class, `i32`
/// words on the 16i class and Series 15), as cnc_rdparam reads and
/// cnc_wrparam writes it (src/proto/param, whose codec it uses).
///
/// A read (`attributes` None): the answer's axis word decides how many
/// values (negative: max axes, else one); `length` below 4 writes nothing,
/// else `datano` and `type` (the answer's axis word; from a Series 15,
/// `(type << 8) | (axis & 0xff)`) are written, then `length` below 4 + the
/// values' size is EW_LENGTH, else the values are written.
///
/// A write (`attributes` Some): the block is read from the [`Param::In`]
/// struct; on the classes `attributes` names, the parameter's attributes
/// are read first (cnc_wrparam's exchange) and decide the values' type and
/// size, `length` having to be 4 + their size (`type` -1: per axis) else
/// EW_LENGTH and no write; the write is the form's command with the block
/// as its payload.
#[derive(Debug, Clone, Copy)]
pub struct Block {
    /// Number parameter: the caller's `length`.
    pub length: u8,
    /// A write: the classes whose CNC is asked for the attributes first.
    pub attributes: Option<Classes>,
    /// A range read instead of one item ([`Range`]).
    pub range: Option<Range>,
    /// Diagnosis data: the answer's type word names the value's kind by
    /// the diagnosis codes (0 byte, 1 word, 2 2-word, 3 and 4 bit, 5
    /// real), not the parameter codes (cnc_diagnoss).
    pub diag: bool,
}

/// A range read of typed parameter blocks ([`Block::range`]), as
/// cnc_rdparar reads parameters: number parameters `s` and `e` (the start
/// and end numbers) and the block's `length` (the output's room in bytes)
/// are [`Param::Io`]. The request's words carry the start, the end and the
/// axis; each answer block becomes a packed record in the output (i16
/// number, i16 `(type << 8) | (axis & 0xff)`, the values, padded to a
/// multiple of 4; src/proto/param/packed.rs), and the CNC is asked again
/// from the last number answered + 1 (its whole 32-bit number, 0 before
/// any) while that is not above the end (an EW_NUMBER answer after some
/// records ends the read; a request answered without a block is sent once
/// more, FANUC's library repeating it while the CNC answers so). Then `s`
/// is the first number read (none: the output's first short, as FANUC's
/// library), `e` the last and `length` the bytes used. A start
/// above the end is EW_NUMBER before any traffic; a record that does not
/// fit is EW_LENGTH (the records before it written, its 4-byte header too
/// if that fits; the pointers keep their values).
#[derive(Debug, Clone, Copy)]
pub struct Range {
    pub s: u8,
    pub e: u8,
}

/// A function that pages ([`Func::pages`]): it repeats its request and
/// reply over the caller's records, as many per request as `bytes` of the
/// payload hold ([`Func::payload`]'s records; none: the reply's
/// [`Records`]', by their wire size), the count parameter's value
/// ([`Param::Count`]) the records in that request: the caller's records
/// still to do, at most that many. The reply's first integer is the
/// records the answer did (read or registered), taken from those still to
/// do (an `int`, as FANUC's library counts; a read writes its records only
/// for a count above 0); it asks again while some remain, the next slice
/// starting after the records written (a read) or sent (a write), and the
/// count becomes the caller's less those remaining, cut to a `short` (as
/// the CNC counted, past the caller's count too). An error answer returns
/// its code, the records before it kept (and the count as at the end).
///
/// Ours where FANUC's library is broken: a request whose slice would start
/// before or end past the caller's array is not sent, the call ending
/// there with EW_OK (FANUC's library sends the bytes after the array: a
/// write answered with fewer than it sent, a read with a negative count);
/// a read answered with none asks once more and
/// ends at the second in a row (FANUC's library asks for ever), and
/// answered with more records than it asked writes and counts those it
/// asked (FANUC's library writes them all, past the caller's array).
///
/// A write over a range, without a count parameter ([`Func::span`]): the
/// records are the range's, `s..=e`, its end first cut to the end of
/// `s`'s range ([`Func::ends`]; a start after the end is EW_NUMBER before
/// any traffic, a [`Func::checks`] `ORDERED`); each request carries the
/// next slice of them, its start and end words (the span's two arguments)
/// the slice's first and last numbers, and an answer (no count) did all it
/// was sent. Before each request, [`Pages::room`] is checked, then every
/// value record of the slice ([`Int::BaseExp`]) whose places are outside
/// [`PLACES`] is EW_DATA. An error answer ends the write: the requests
/// before it stay written (cnc_wrpmacror).
#[derive(Debug, Clone, Copy)]
pub struct Pages {
    /// The most payload bytes one request carries.
    pub bytes: u16,
    /// Number parameter `a` goes on the wire as its value plus `done`
    /// (cnc_regtool's first data number), if any.
    pub advance: Option<u8>,
    /// Where the next request's slice starts: true, after the records the
    /// answers wrote (a read: cnc_rdmagazine); false, after the records
    /// sent (a write: cnc_regmagazine).
    pub from_done: bool,
    /// `Some((a, head))`: number parameter `a` is the caller's buffer size
    /// in bytes, checked before each request: `head` + the records sent so
    /// far and this request's (the input's element size each) above it is
    /// EW_LENGTH, the requests before it staying done (cnc_wrpmacror:
    /// `10 + 8 · records` against `length`).
    pub room: Option<(u8, u16)>,
    /// As FANUC's library reads and writes IEEE-double macro variables
    /// (cnc_rdmacror2, cnc_wrmacror2): the count is first cut to the end
    /// of the range [`Pages::advance`]'s argument starts in ([`Func::ends`];
    /// the two compared unsigned) and nothing is sent for a cut count of 0
    /// or below (as an `int`: the count becomes 0); each request's slice
    /// starts after the records sent or asked before it; an answer that did
    /// fewer records than its slice ends the call; the count becomes the
    /// records the answers did (a read: those written; a write: the sum of
    /// its answers' counts). An error answer returns its code, the count
    /// as the caller gave it (a read's earlier records written), except
    /// EW_NUMBER after answers that did some: EW_OK, the count theirs.
    pub until_short: bool,
}

/// The places a value record ([`Int::BaseExp`]) of a range write's input
/// may have ([`Pages`]): a signed byte, as FANUC's library checks them
/// (cnc_wrpmacro's `dec_val` too); others are EW_DATA before the request.
pub const PLACES: (i32, i32) = (i8::MIN as i32, i8::MAX as i32);

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
    pub records: Option<&'static Records>,
    /// The records a write sends, if any.
    pub payload: Option<&'static Payload>,
    /// Further subpackets of the same request: the form's class and
    /// command with these words, one subpacket each (cnc_rdposerrs2 asks
    /// `[1]` and `[2]`). Each subpacket's answer carries an equal share of
    /// `reply`'s fields, in order (the simulator answers each with the
    /// first share's layout); no records.
    pub more: &'static [&'static [Word]],
    /// The command of each of [`Func::more`]'s subpackets, in order (empty:
    /// the form's command for all): subpackets of alternating commands
    /// (cnc_rd3dtooltip asks 0x0110 and 0x0111, twice).
    pub more_cmds: &'static [u16],
    /// The reply as columns, one per subpacket ([`Columns`]); `None`: the
    /// fields as [`Func::more`] shares them.
    pub columns: Option<&'static Columns>,
    /// Classes on which no request is sent (no form of theirs): the
    /// answer is what the library learnt at connect.
    pub local: Option<&'static Local>,
    pub short: Short,
    /// More records than the caller's count asked for.
    pub overflow: Overflow,
    /// The oracle's dimensions, one per number parameter: "|"-separated
    /// values, the base first.
    pub dims: &'static [&'static str],
    /// The first reply field is the number the CNC answered for (a tool
    /// group); when its low 16 bits are 0 the `data` member reads as 0, as
    /// FANUC's library writes it (no such group).
    pub zero_without_first: bool,
    /// The members [`Func::zero_without_first`] writes as 0 (empty: `data`).
    pub zeroed: &'static [&'static str],
    /// Learnt from FANUC's library (`oracle learn`, tools/oracle/learn.rs):
    /// what the learner's draft left unsettled, which review settled by
    /// probing (empty: nothing); `None` for entries written from the
    /// recordings by hand. COMPATIBILITY.md shows it.
    pub learnt: Option<&'static [&'static str]>,
    /// A member FANUC's library writes as 0 unless another member's value
    /// is in a range.
    pub zero_unless: Option<&'static ZeroUnless>,
    /// The classes to which a write sends its value records ([`Int::BaseExp`]
    /// fields of its payload) binary, `m · 2^-e` as FANUC's library
    /// converts the digits and places (`crate::proto::macros::to_base2`,
    /// as for cnc_wrmacro); base 10 to the others.
    pub binary: Option<Classes>,
    /// `Some(k)`: the number of records is reply field k's value (the
    /// count the CNC sends before them), not what the payload's length
    /// holds: that many are read (at most the caller's count, with
    /// [`Overflow::Cut`]; none below 1), records past the payload's end
    /// read as [`Func::short`] says (zeros: FANUC's library reads them from
    /// its zeroed buffer) (cnc_rdsyshard, cnc_rdsyssoft3).
    pub counted: Option<u8>,
    /// `Some((s, e))`: the function asks for a range, number parameters
    /// `s..=e`: the records written are at most `e - s + 1` (the caller's
    /// array holds that many), and a write ([`SPAN`]) sends that many
    /// (pmc_get_timer_type, pmc_set_timer_type).
    pub span: Option<(u8, u8)>,
    /// The reply (a read) or the payload (a write) is a typed parameter
    /// block ([`Block`]), not `reply`'s fields.
    pub block: Option<Block>,
    /// Output members filled by looking values up in the reply
    /// ([`Lookup`]), after the reply's fields are read (cnc_rdsyssoft).
    pub lookups: &'static [Lookup],
    /// The request repeated over the caller's records ([`Pages`]).
    pub pages: Option<Pages>,
    /// Where the ranges a [`Word::Upto`] asks for end, per class
    /// ([`Ends`]; a start in none: not cut).
    pub ends: &'static [Ends],
    /// A request sent before the function's own ([`First`]), if any.
    pub first: Option<&'static First>,
    /// Checks with detail codes, of number parameters and of each payload
    /// record ([`Rule`]).
    pub rules: &'static [Rule],
    /// An exchange per payload record before the request ([`Each`]).
    pub each: &'static [Each],
    /// Payload fields computed, not copied ([`Code`]).
    pub codes: &'static [Code],
    /// The member of the [`Param::In`] struct whose elements are the
    /// payload's records (cnc_wrpmacror's IODBPR `data`); `""`: the input
    /// is the records' array.
    pub payload_in: &'static str,
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
