//! The writing side of the described codec: a reply encoded from a
//! function's integers (simulator), the fields of a write's payload
//! (client), and, for the simulator, a request's arguments and payload read
//! back and the function a request subpacket belongs to.

use crate::proto::macros::to_base2;
use crate::proto::open::CncClass;
use crate::proto::packet::ReqSub;
use crate::proto::value::BASE_10;
use crate::proto::wire::{DecodeError, Writer};
use crate::spec::{Field, Form, Func, Int, Word};

/// The reply payload for these integers (simulator side): the fixed
/// fields, then whole records; each integer cut to its wire width, as the
/// CNC sends it (echo fields' integers are not sent).
pub fn encode(f: &Func, values: &[i64]) -> std::result::Result<Vec<u8>, DecodeError> {
    let bad = DecodeError::Invalid("value count differs from the reply layout");
    // With further subpackets, each answer is one share of the fields.
    let reply = f.share(0);
    let fixed: usize = reply.iter().map(|x| x.n as usize).sum();
    let extra = values.len().checked_sub(fixed).ok_or(bad)?;
    let records = match f.records {
        None if extra == 0 => 0,
        Some(r)
            if r.values() > 0
                && extra % r.values() == 0
                && extra / r.values() <= r.max as usize =>
        {
            extra / r.values()
        }
        _ => return Err(bad),
    };
    let mut w = Writer::new();
    let mut v = values.iter();
    write_fields(&mut w, reply, &mut v);
    if let Some(rec) = &f.records {
        for _ in 0..records {
            write_fields(&mut w, rec.fields, &mut v);
        }
    }
    Ok(w.into_vec())
}

/// One record's integers with each value record ([`Int::BaseExp`] and
/// the digits before it) as FANUC's library sends it binary: the
/// digits and places become `m` and `e` of `m · 2^-e`.
pub(super) fn binary_records(fields: &[Field], rec: &[i64]) -> Vec<i64> {
    let mut v = rec.to_vec();
    let mut at = 0;
    for field in fields {
        if field.wire == Int::BaseExp && at > 0 && at < v.len() {
            let (m, e) = to_base2(v[at - 1] as i32, v[at] as i16);
            v[at - 1] = i64::from(m);
            v[at] = i64::from(e);
        }
        at += usize::from(field.n);
    }
    v
}

pub(super) fn write_fields<'a>(
    w: &mut Writer,
    fields: &[Field],
    v: &mut impl Iterator<Item = &'a i64>,
) {
    write_fields_in(w, fields, v, BASE_10)
}

/// [`write_fields`], value records in `base`.
pub(super) fn write_fields_in<'a>(
    w: &mut Writer,
    fields: &[Field],
    v: &mut impl Iterator<Item = &'a i64>,
    base: u16,
) {
    for field in fields {
        for x in v.by_ref().take(field.n as usize) {
            if field.arg.is_some() {
                continue;
            }
            match field.wire {
                Int::I8 | Int::U8 | Int::Char | Int::IdChar => w.u8(*x as u8),
                Int::I16 | Int::U16 => w.u16(*x as u16),
                Int::I32 | Int::U32 => w.u32(*x as u32),
                Int::F64 => w.bytes(&x.to_be_bytes()),
                // The digits went as the value.
                Int::BaseExp => {
                    w.u16(base);
                    w.u16(*x as i16 as u16);
                }
            }
        }
    }
}

/// The described function a request subpacket asks for, on a CNC of this
/// class (simulator dispatch). Where functions share a command and their
/// forms' constant words tell them apart (cnc_rdposerrs \[0\] and
/// cnc_rdposerrz \[3\] on 0x0058), the ones whose constants the request
/// carries (words a form leaves out are 0; a write's fifth word, its
/// payload's length, is not compared). Among those (or, when none, among
/// all of the command's) the one with the longest reply layout (`longest`) describes
/// the whole answer and the others read a prefix of it (cnc_rdtofsinfo and
/// cnc_rdtofsinfo2). A subpacket no function sends first is the later
/// subpacket of the function whose frame carries it, then any of the
/// command's.
pub fn for_request(sub: &ReqSub, class: CncClass) -> Option<&'static Func> {
    let of_cmd = || {
        crate::spec::FUNCS.iter().filter(|f| {
            form(f, class).is_some_and(|form| form.cmd == sub.cmd && form.class == sub.class)
        })
    };
    // Whether the request carries the constants of these words.
    let carries = |f: &Func, words: &[Word]| {
        (0..5).all(|k| {
            let want = match words.get(k) {
                Some(Word::Const(c)) => *c,
                Some(_) => return true,
                None if k == 4 && f.sends_payload() => return true,
                None => 0,
            };
            sub.args.get(k).copied().unwrap_or(0) == want
        })
    };
    let carried = |f: &&Func| form(f, class).is_some_and(|form| carries(f, form.words));
    // A later subpacket of a function's frame (cnc_rdposerrs2's \[2\]).
    let later = |f: &&Func| {
        form(f, class).is_some_and(|form| {
            form.class == sub.class
                && f.more.iter().enumerate().any(|(i, ws)| {
                    f.more_cmds.get(i).copied().unwrap_or(form.cmd) == sub.cmd && carries(f, ws)
                })
        })
    };
    of_cmd()
        .filter(carried)
        .max_by_key(|f| longest(f))
        .or_else(|| {
            crate::spec::FUNCS
                .iter()
                .filter(later)
                .max_by_key(|f| longest(f))
        })
        .or_else(|| of_cmd().max_by_key(|f| longest(f)))
}

/// The longest answer a function's layout describes: its fixed fields and
/// as many records as it takes (cnc_rdpmacror's records before
/// cnc_rdpmacro's one record, on the same command).
fn longest(f: &Func) -> usize {
    f.reply_len() + f.records.map_or(0, |r| r.wire_len() * usize::from(r.max))
}

/// The arguments the request carries (inverse of the form's words:
/// `Arg(i)` words give argument i back, `Input` words the input members
/// after the numbers; simulator side).
pub fn args_of(f: &Func, class: CncClass, sub: &ReqSub) -> Vec<i32> {
    let mut args = vec![0; f.numbers().count() + f.inputs().count()];
    if let Some(form) = form(f, class) {
        for (k, w) in form.words.iter().enumerate() {
            let Some(i) = f.word_arg(w) else {
                continue;
            };
            if let (Some(a), Some(v)) = (args.get_mut(i), sub.args.get(k)) {
                *a = *v;
            }
        }
    }
    args
}

/// The request form for the CNC's class, if the function has one.
pub fn form(f: &Func, class: CncClass) -> Option<&'static Form> {
    f.form(
        class.is_16i(),
        matches!(class, CncClass::Series16 { kind: 2 }),
    )
}
