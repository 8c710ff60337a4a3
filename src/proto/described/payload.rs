//! A described write's payload: the records and numbers it sends, read
//! from the caller's memory (client), and read back from a request
//! (simulator) with the same layout.

use super::block;
use super::encode::{encode, form};
use super::fields::read_fields;
use crate::proto::open::CncClass;
use crate::proto::wire::{DecodeError, Reader};
use crate::spec::{Field, Func, Int, NUMBERS, ONE, SPAN, TEXT};

/// The records asked for ([`Word::Asked`](crate::spec::Word::Asked)): the count parameter's value,
/// at most the records' `max`; None without a count parameter.
pub fn asked(f: &Func, args: &[i32]) -> Option<usize> {
    let n = *args.get(f.count()?)?;
    let max = f.records.map_or(0, |r| r.max as usize);
    Some(usize::try_from(n).unwrap_or(0).min(max))
}

/// The integers of a write's payload records (see [`Described`](super::Described)): `n`
/// records of `bytes` (the caller's array, native byte order), each
/// `stride` bytes, field k's member at `offsets[k]` in it.
pub fn payload_values(
    f: &Func,
    bytes: &[u8],
    stride: usize,
    offsets: &[usize],
    n: usize,
) -> Vec<i64> {
    let Some(p) = &f.payload else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for i in 0..n {
        for (field, off) in p.fields.iter().zip(offsets) {
            for e in 0..usize::from(field.n) {
                let at = i * stride + off + e * field.c.size();
                let b = |k: usize| bytes.get(at + k).copied().unwrap_or(0);
                out.push(match (field.to, field.c) {
                    (None, _) => 0,
                    (_, Int::I8 | Int::IdChar) => i64::from(b(0) as i8),
                    (_, Int::U8 | Int::Char) => i64::from(b(0)),
                    (_, Int::I16) => i64::from(i16::from_ne_bytes([b(0), b(1)])),
                    (_, Int::U16) => i64::from(u16::from_ne_bytes([b(0), b(1)])),
                    (_, Int::I32) => i64::from(i32::from_ne_bytes([b(0), b(1), b(2), b(3)])),
                    (_, Int::U32) => i64::from(u32::from_ne_bytes([b(0), b(1), b(2), b(3)])),
                    // A native double's bits.
                    (_, Int::F64) => i64::from_ne_bytes(std::array::from_fn(b)),
                    // A C member is never of this wire kind.
                    (_, Int::BaseExp) => i64::from(i16::from_ne_bytes([b(0), b(1)])),
                });
            }
        }
    }
    out
}

/// The integers of the one payload record of a write whose payload is
/// its numbers ([`NUMBERS`]): the number arguments no request word of the
/// class's form carries, in order; None for another write.
pub fn payload_numbers(f: &Func, class: CncClass, args: &[i32]) -> Option<Vec<i64>> {
    if f.payload?.count != NUMBERS {
        return None;
    }
    let carried: Vec<usize> = form(f, class)
        .map(|fm| fm.words.iter().filter_map(|w| f.word_arg(w)).collect())
        .unwrap_or_default();
    Some(
        (0..f.numbers().count())
            .filter(|i| !carried.contains(i))
            .map(|i| i64::from(args.get(i).copied().unwrap_or(0)))
            .collect(),
    )
}

/// How many payload records a write sends: its count argument ([`ONE`]:
/// one), at most the payload's `max` (0 without a payload).
pub fn payload_records(f: &Func, args: &[i32]) -> usize {
    f.payload.map_or(0, |p| {
        let n = match p.count {
            ONE | NUMBERS | TEXT => 1,
            SPAN => f
                .span_len(args)
                .map_or(0, |n| i32::try_from(n).unwrap_or(i32::MAX)),
            c => args.get(usize::from(c)).copied().unwrap_or(0),
        };
        usize::try_from(n).unwrap_or(0).min(usize::from(p.max))
    })
}

/// [`payload_of`] on a CNC of this class: a typed parameter block's
/// integers ([`block::wire_values`]; none when it does not decode).
pub fn payload_in(f: &Func, class: CncClass, bytes: &[u8]) -> Vec<i64> {
    match f.block {
        Some(_) => block::wire_values(class, true, bytes).unwrap_or_default(),
        None => payload_of(f, bytes),
    }
}

/// [`encode`] on a CNC of this class: a typed parameter block's answer
/// in the class's form ([`block::encode`]).
pub fn encode_in(
    f: &Func,
    class: CncClass,
    values: &[i64],
) -> std::result::Result<Vec<u8>, DecodeError> {
    match f.block {
        Some(_) => block::encode(class, false, values),
        None => encode(f, values),
    }
}

/// The integers of a write's request payload (simulator side): whole
/// records of [`Func::payload`]'s fields, as [`Described`](super::Described) sent them
/// (after the text parameters' fields); a trailing part record is left out.
pub fn payload_of(f: &Func, bytes: &[u8]) -> Vec<i64> {
    let Some(p) = &f.payload else {
        return Vec::new();
    };
    let texts: usize = f.texts().map(|(_, n)| n).sum();
    let bytes = bytes.get(texts..).unwrap_or_default();
    let size: usize = p.fields.iter().map(Field::wire_len).sum();
    let mut out = Vec::new();
    let mut r = Reader::new(bytes);
    for _ in 0..bytes.len() / size.max(1) {
        if read_fields(&mut r, p.fields, &[], &mut out).is_err() {
            break;
        }
    }
    out
}
