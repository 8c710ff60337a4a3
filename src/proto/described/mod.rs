//! The codec of the functions described as data (crate::spec): the request
//! from a [`Func`]'s form, the reply decoded (client) or encoded (simulator)
//! by its reply layout. Decoding and encoding are exact inverses: the
//! payload is the layout's big-endian integers, one after another.

use super::call::{Call, Ctx, sub};
use super::open::CncClass;
use super::packet::{CLASS_PMC, ReqSub, RespSub};
use super::value::BASE_2;
use super::wire::{DecodeError, Reader, Writer};
use crate::error::Result;
use crate::spec::{Columns, Field, Func, Int, Key, LAST, Overflow, Pick, Short, Word};

pub mod block;
mod encode;
mod fields;
mod payload;
pub use encode::{args_of, encode, for_request, form};
use encode::{binary_records, write_fields, write_fields_in};
use fields::read_fields;
pub use payload::{
    asked, encode_in, payload_in, payload_numbers, payload_of, payload_records, payload_values,
};

/// One call of a described function with the caller's number arguments
/// (then the input members its request words carry, [`Func::inputs`];
/// and, for a write, its payload records' integers, [`Func::payload`]'s
/// fields in order, record after record).
pub struct Described<'a> {
    pub f: &'static Func,
    pub args: &'a [i32],
    pub payload: &'a [i64],
    /// The text parameters' fields ([`Func::texts`]), sent before the
    /// payload's records.
    pub text: &'a [u8],
    /// With [`Func::more`]: where an error of a later subpacket goes, the
    /// earlier ones' integers being returned (FANUC's library writes each
    /// subpacket's fields before it reads the next). None: the error is
    /// the call's.
    pub late: Option<&'a std::sync::Mutex<Option<crate::error::Error>>>,
}

impl<'a> Described<'a> {
    /// A call without payload.
    pub const fn new(f: &'static Func, args: &'a [i32]) -> Self {
        Described {
            f,
            args,
            payload: &[],
            text: &[],
            late: None,
        }
    }
}

/// The request a function sends before its own ([`crate::spec::First`]):
/// its command alone, no words; its answer is not read (an error answer
/// too, as FANUC's library ignores it).
pub struct Prelude {
    pub cmd: u16,
}

impl Call for Prelude {
    type Output = ();
    fn request(&self, _cx: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(self.cmd, &[0; 5])]
    }
    fn decode(&self, _cx: &Ctx, _resp: &[RespSub]) -> Result<()> {
        Ok(())
    }
}

/// The exchange FANUC's library makes for a payload record before the
/// request ([`crate::spec::Each`]): its one subpacket, no payload; the
/// answer's payload.
pub struct EachCall {
    pub each: &'static crate::spec::Each,
    /// The record's key field's integer.
    pub key: i64,
}

impl Call for EachCall {
    type Output = Vec<u8>;
    fn request(&self, _cx: &Ctx) -> Vec<ReqSub> {
        let mut words = [0i32; 5];
        for (w, v) in words.iter_mut().zip(self.each.words) {
            *w = *v;
        }
        let mut s = ReqSub::cnc(self.each.cmd, &words);
        if self.each.tens {
            s.path = (1 + self.key / 10) as u16;
        }
        vec![s]
    }
    fn decode(&self, _cx: &Ctx, resp: &[RespSub]) -> Result<Vec<u8>> {
        Ok(sub(resp, 0)?.payload.clone())
    }
}

/// A record's value in its [`EachCall`] answer `p` (`key`: the record's
/// key field), as [`crate::spec::Each::value`] places it; None without one.
pub fn each_value(e: &crate::spec::Each, p: &[u8], key: i64) -> Option<i64> {
    let (at, stride, c) = e.value?;
    let i = usize::try_from(if e.tens { key % 10 } else { key } - 1).ok()?;
    let at = usize::from(at) + usize::from(stride) * i;
    let b = |k: usize| p.get(at + k).copied().unwrap_or(0);
    let v = match c.size() {
        1 => i64::from(b(0)),
        2 => i64::from(u16::from_be_bytes([b(0), b(1)])),
        _ => i64::from(u32::from_be_bytes([b(0), b(1), b(2), b(3)])),
    };
    Some(c.cut(v))
}

impl Call for Described<'_> {
    /// The reply's integers, in layout order (each field's `n` elements).
    type Output = Vec<i64>;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let mut v = Vec::new();
        self.request_into(cx, &mut v);
        v
    }
    fn request_into(&self, cx: &Ctx, out: &mut Vec<ReqSub>) {
        // The caller checked that a form exists for this class.
        let Some(form) = form(self.f, cx.class) else {
            return;
        };
        let sub_of = |cmd: u16, ws: &[Word]| {
            let mut words = [0i32; 5];
            for (w, f) in words.iter_mut().zip(ws) {
                *w = match *f {
                    Word::Const(c) => c,
                    Word::Asked => asked(self.f, self.args).unwrap_or(0) as i32,
                    Word::Last(s) => {
                        let s = self.args.get(usize::from(s)).copied().unwrap_or(0);
                        let n = asked(self.f, self.args).unwrap_or(0) as i32;
                        s.wrapping_add(n).wrapping_sub(1)
                    }
                    Word::Plus(i, c) => {
                        let v = self.args.get(usize::from(i)).copied().unwrap_or(0);
                        v.wrapping_add(c)
                    }
                    Word::Upto(s, e, n, _) => {
                        let at = |i: u8| self.args.get(usize::from(i)).copied().unwrap_or(0);
                        let (s16, s15) = (
                            cx.class.is_16i(),
                            matches!(cx.class, CncClass::Series16 { kind: 2 }),
                        );
                        self.f.upto(at(s), at(e), n, s16, s15)
                    }
                    Word::Nonzero(i, v) => {
                        let set = self.args.get(usize::from(i)).is_some_and(|a| *a != 0);
                        if set { v } else { 0 }
                    }
                    Word::Arg(_) | Word::Input(..) => self
                        .f
                        .word_arg(f)
                        .and_then(|i| self.args.get(i).copied())
                        .unwrap_or(0),
                };
            }
            if form.class == CLASS_PMC {
                ReqSub::pmc(cmd, &words)
            } else {
                ReqSub::cnc(cmd, &words)
            }
        };
        let sub = sub_of(form.cmd, form.words);
        if self.f.block.is_some_and(|b| b.attributes.is_some()) {
            // A typed parameter block: its integers are the block's.
            out.push(sub.with_payload(block::write_payload(cx, self.payload)));
            return;
        }
        out.push(match &self.f.payload {
            None if self.f.texts().next().is_some() => sub.with_payload(self.text.to_vec()),
            Some(p) => {
                let mut w = Writer::new();
                w.bytes(self.text);
                let per: usize = p.fields.iter().map(|x| usize::from(x.n)).sum();
                let binary = self.f.binary.is_some_and(|c| {
                    c.matches(
                        cx.class.is_16i(),
                        matches!(cx.class, CncClass::Series16 { kind: 2 }),
                    )
                });
                for rec in self.payload.chunks(per.max(1)) {
                    if binary {
                        let rec = binary_records(p.fields, rec);
                        write_fields_in(&mut w, p.fields, &mut rec.iter(), BASE_2);
                    } else {
                        write_fields(&mut w, p.fields, &mut rec.iter());
                    }
                }
                sub.with_payload(w.into_vec())
            }
            None => sub,
        });
        out.extend(self.f.more.iter().enumerate().map(|(i, ws)| {
            let cmd = self.f.more_cmds.get(i).copied().unwrap_or(form.cmd);
            sub_of(cmd, ws)
        }));
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Vec<i64>> {
        match self.f.block {
            Some(b) if b.range.is_some() => return block::range(cx, resp),
            Some(b) if b.attributes.is_none() => {
                // What a short answer's missing bytes read as ([`Short`]).
                let request = match self.f.short {
                    Short::Request => crate::proto::packet::encode_request(&self.request(cx)),
                    Short::Zeros | Short::Error | Short::PerSpindle(_) => Vec::new(),
                };
                return block::read(cx, resp, self.f.short, &request, b.diag);
            }
            Some(_) => return sub(resp, 0).map(|_| Vec::new()),
            None => {}
        }
        if let Some(c) = self.f.columns {
            return columns(self.f, c, resp, self.late);
        }
        if self.f.more.is_empty() {
            let payload = &sub(resp, 0)?.payload;
            if let Short::PerSpindle(unit) = self.f.short
                && (payload.len() < usize::from(unit) || cx.max_spindles == 0)
            {
                return Ok(Vec::new());
            }
            if self.f.short == Short::Request {
                // The response body's payload starts at byte 18, where
                // the request body held its subpacket's byte 16: the bytes
                // past the answer's end are the request's from there.
                let body = crate::proto::packet::encode_request(&self.request(cx));
                let tail = body.get(18 + payload.len()..).unwrap_or_default();
                return decode_tail(self.f, self.args, payload, tail);
            }
            return decode(self.f, self.args, payload);
        }
        // Each subpacket's answer is its share of the reply's fields.
        let mut out = Vec::new();
        for i in 0..=self.f.more.len() {
            let fields = self.f.share(i);
            let need: usize = fields.iter().map(Field::wire_len).sum();
            let part = sub(resp, i).and_then(|s| padded(self.f.short, &s.payload, need));
            match (part, self.late) {
                (Ok(p), _) => read_fields(&mut Reader::new(&p), fields, self.args, &mut out)?,
                (Err(e), Some(late)) if i > 0 => {
                    if let Ok(mut l) = late.lock() {
                        *l = Some(e);
                    }
                    break;
                }
                (Err(e), _) => return Err(e),
            }
        }
        Ok(out)
    }
}

/// The elements of a reply of columns ([`Columns`]), column after column,
/// as many in each: the first column's elements the count. An error of a
/// later subpacket (past the columns) goes to `late`, the columns being
/// returned.
fn columns(
    f: &Func,
    c: &Columns,
    resp: &[RespSub],
    late: Option<&std::sync::Mutex<Option<crate::error::Error>>>,
) -> Result<Vec<i64>> {
    let stride = |k: usize| usize::from(c.stride.get(k).copied().unwrap_or(1).max(1));
    let cols = f.reply.len();
    for k in 0..cols {
        sub(resp, k)?;
    }
    let n = f.reply.first().map_or(0, |first| {
        (resp[0].payload.len() / stride(0)).min(usize::from(first.n))
    });
    let mut out = Vec::with_capacity(n * cols);
    for (k, field) in f.reply.iter().enumerate() {
        let p = padded(Short::Zeros, &resp[k].payload, n * stride(k))?;
        for i in 0..n {
            let one = Field { n: 1, ..*field };
            let mut r = Reader::new(&p[i * stride(k)..]);
            read_fields(&mut r, &[one], &[], &mut out)?;
        }
    }
    // The first later subpacket answering `none` ends the reply.
    let ended = resp.get(cols).is_some_and(|s| s.error == c.none);
    let later = (cols..=f.more.len())
        .filter(|_| !ended)
        .find_map(|k| sub(resp, k).err());
    match (later, late) {
        (Some(e), Some(l)) => {
            if let Ok(mut l) = l.lock() {
                *l = Some(e);
            }
        }
        (Some(e), None) => return Err(e),
        (None, _) => {}
    }
    Ok(out)
}

/// A subpacket's payload at least `need` bytes long, as [`Short`] says
/// (zeros after it, or EW_PROTOCOL).
fn padded(short: Short, payload: &[u8], need: usize) -> Result<Vec<u8>> {
    let mut p = payload.to_vec();
    if p.len() < need {
        match short {
            Short::Error => {
                return Err(DecodeError::Short {
                    need,
                    have: p.len(),
                }
                .into());
            }
            Short::Zeros | Short::Request | Short::PerSpindle(_) => p.resize(need, 0),
        }
    }
    Ok(p)
}

/// The reply payload's integers (client side); echo fields give the
/// call's `args` back.
pub fn decode(f: &Func, args: &[i32], payload: &[u8]) -> Result<Vec<i64>> {
    decode_tail(f, args, payload, &[])
}

/// [`decode`] of an answer whose missing bytes ([`Short::Request`]) read as
/// `tail` (the request's bytes from the answer's end on), then zeros: the
/// fixed fields', and [`Func::counted`]'s records' past the payload.
fn decode_tail(f: &Func, args: &[i32], payload: &[u8], tail: &[u8]) -> Result<Vec<i64>> {
    let need = f.reply_len();
    let ext = [payload, tail].concat();
    let mut zeros;
    let mut p = payload;
    if p.len() < need {
        match f.short {
            Short::Error => {
                return Err(DecodeError::Short {
                    need,
                    have: p.len(),
                }
                .into());
            }
            Short::Zeros | Short::Request | Short::PerSpindle(_) => {
                zeros = ext.clone();
                zeros.resize(need, 0);
                p = &zeros;
            }
        }
    }
    let mut r = Reader::new(p);
    let mut out = Vec::new();
    read_fields(&mut r, f.reply, args, &mut out)?;
    if f.zero_without_first && out.first().is_some_and(|v| *v as u16 == 0) {
        // No such group: its `data` (or `zeroed`) reads 0 (the other
        // fields as sent).
        let mut at = 0;
        for field in f.reply {
            let n = usize::from(field.n);
            let zeroed = match f.zeroed {
                [] => &["data"][..],
                z => z,
            };
            if field.to.is_some_and(|m| zeroed.contains(&m)) {
                out[at..at + n].iter_mut().for_each(|v| *v = 0);
            }
            at += n;
        }
    }
    zero_unless(f, &mut out);
    if let Some(rec) = &f.records {
        let size = rec.wire_len().max(1);
        let most = match f.overflow {
            Overflow::Cut => asked(f, args).unwrap_or(rec.max as usize),
            // As many as the answer holds: the caller's side refuses more
            // than it asked for.
            Overflow::Refuse => usize::MAX,
        }
        .min(f.span_len(args).unwrap_or(usize::MAX));
        let rest;
        let (n, mut r) = match f.counted {
            None => ((r.remaining() / size).min(most), r),
            // As many as the CNC's count says, read past the payload's end
            // as a short answer is.
            Some(k) => {
                let at: usize = f.reply[..usize::from(k)]
                    .iter()
                    .map(|x| usize::from(x.n))
                    .sum();
                let n = out
                    .get(at)
                    .map_or(0, |v| usize::try_from(*v).unwrap_or(0))
                    .min(most);
                let at = p.len() - r.remaining();
                let from = match f.short {
                    Short::Request => ext.get(at..).unwrap_or_default(),
                    _ => &p[at..],
                };
                rest = padded(f.short, from, n * size)?;
                (n, Reader::new(&rest))
            }
        };
        for _ in 0..n {
            read_fields(&mut r, rec.fields, args, &mut out)?;
        }
        // The last number answered: argument 0 + records - 1, the records
        // counted as FANUC's library counts them, `(length - head) / size`
        // in C's division: an answer shorter than the head by a record or
        // more counts below 0 (cnc_rdusetlno's empty answer: -1).
        let n = match (n, f.counted) {
            (0, None) => ((payload.len() as i64 - need as i64) / size as i64).min(0),
            _ => n as i64,
        };
        let mut at = 0;
        for field in f.reply {
            if field.arg == Some(LAST) {
                let n = i32::try_from(n).unwrap_or(i32::MAX);
                out[at] = i64::from(args.first().copied().unwrap_or(0).wrapping_add(n - 1));
            }
            at += usize::from(field.n);
        }
    }
    if !f.lookups.is_empty() {
        let found = lookups(f, &out);
        out.extend(found);
    }
    Ok(out)
}

/// The integers of [`Func::lookups`], lookup after lookup, from the reply
/// fields' decoded integers (`reply`, in layout order).
pub fn lookups(f: &Func, reply: &[i64]) -> Vec<i64> {
    // Reply field k's elements.
    let field = |k: u8| -> &[i64] {
        let at: usize = f.reply[..usize::from(k).min(f.reply.len())]
            .iter()
            .map(|x| usize::from(x.n))
            .sum();
        let n = f.reply.get(usize::from(k)).map_or(0, |x| usize::from(x.n));
        reply.get(at..at + n).unwrap_or(&[])
    };
    let elem = |k: u8, i: usize| field(k).get(i).copied().unwrap_or(0);
    let mut out: Vec<i64> = Vec::new();
    // Where each lookup's integers start in `out`.
    let mut starts = Vec::with_capacity(f.lookups.len());
    for l in f.lookups {
        let start = out.len();
        starts.push(start);
        let per = l.pick.per();
        out.resize(start + l.values(), l.fill);
        for i in 0..usize::from(l.n) {
            let key = match l.key {
                Key::Field(k) => elem(k, i),
                Key::Own => i as i64,
                Key::Lookup(k) => match starts.get(usize::from(k)) {
                    Some(&s) if usize::from(k) < starts.len() - 1 => out[s + i],
                    _ => i64::from(l.end),
                },
            } as u8;
            if key == l.end {
                break;
            }
            let at = start + i * per;
            match l.pick {
                Pick::Index { field, stride, n } => {
                    let hit = (0..usize::from(n))
                        .find(|j| elem(field, j * usize::from(stride)) as u8 == key);
                    if let Some(j) = hit {
                        out[at] = j as i64;
                    }
                }
                Pick::Split { mask, low, high } => {
                    let from = if key < 0x80 { low } else { high };
                    out[at] = elem(from, usize::from(key & mask));
                }
                Pick::Chars {
                    field,
                    stride,
                    at: first,
                    width,
                } => {
                    let from = usize::from(key) * usize::from(stride) + usize::from(first);
                    for e in 0..usize::from(width) {
                        out[at + e] = elem(field, from + e);
                    }
                    out[at + usize::from(width)] = 0;
                }
            }
        }
    }
    out
}

/// [`Func::zero_unless`] applied to the decoded reply's integers: the
/// member FANUC's library writes as 0 unless the other one is in range.
pub fn zero_unless(f: &Func, out: &mut [i64]) {
    if let Some(z) = f.zero_unless {
        let at = |m: &str| {
            let mut i = 0;
            for field in f.reply {
                if field.to == Some(m) {
                    return Some((i, field.c));
                }
                i += usize::from(field.n);
            }
            None
        };
        if let (Some((ia, c)), Some((ib, _))) = (at(z.of), at(z.zero))
            && out
                .get(ia)
                .is_some_and(|v| !(i64::from(z.lo)..=i64::from(z.hi)).contains(&cast(*v, c)))
        {
            out[ib] = 0;
        }
    }
}

/// `v` as a C field of type `c` holds it.
fn cast(v: i64, c: Int) -> i64 {
    match c {
        Int::I8 | Int::IdChar => i64::from(v as i8),
        Int::U8 | Int::Char => i64::from(v as u8),
        Int::I16 => i64::from(v as i16),
        Int::U16 => i64::from(v as u16),
        Int::I32 => i64::from(v as i32),
        Int::U32 => i64::from(v as u32),
        Int::BaseExp => i64::from(v as i16),
        Int::F64 => v,
    }
}
