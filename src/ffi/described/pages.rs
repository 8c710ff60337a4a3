//! Paging functions (spec::Pages: cnc_rdmagazine, cnc_regmagazine,
//! cnc_delmagazine, cnc_regtool ...): one request per slice of the caller's records.

use super::at::{PayloadAt, RecordsAt, write_fields};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::{EW_DATA, EW_FUNC, EW_NUMBER};
use crate::ffi::put;
use crate::proto::described::{Described, payload_values};
use crate::spec::{End, Func, Int, LAST, PLACES};
use std::os::raw::c_short;

/// The exchanges of a paging function ([`Func::pages`]): each request
/// carries the next slice of the caller's records (its count argument the
/// slice's length, [`crate::spec::Pages::advance`]'s argument moved on by
/// the records done), each answer's records go to the caller's array from
/// the slice's first, and its first integer advances `done`; `*count`
/// becomes `done` whatever the end ([`crate::spec::Pages::until_short`]:
/// as that says). `class`: the CNC is of the 16i class, of Series 15.
///
/// # Safety
/// As [`exec`]: `pay.input` holds `*count` records of `pay.stride` bytes,
/// and the records' output (with [`Param::InOut`](crate::spec::Param::InOut)
/// the same array) `*count` elements of `rec.stride` bytes.
#[allow(clippy::too_many_arguments)]
pub(super) unsafe fn pages(
    f: &'static Func,
    h: &handles::Handle,
    args: &[i32],
    outs: &[*mut u8],
    offsets: &[usize],
    rec: &RecordsAt<'_>,
    pay: &PayloadAt<'_>,
    (count, class): (Option<*mut c_short>, (bool, bool)),
) -> Result<()> {
    let (Some(pg), Some(per_page), Some(ci), Some(count)) =
        (f.pages, f.per_page(), f.count(), count)
    else {
        return Err(Error::local(EW_FUNC, "a paging function without its count"));
    };
    // As FANUC's library counts: the records still to do, an `int` less
    // each answer's count; the slice's start moves by the records written
    // (a read) or sent (a write); the count becomes the caller's less what
    // remains, cut to a `short`.
    let mut total = args[ci];
    if pg.until_short {
        // Cut to the end of the start's range, compared unsigned.
        let s = pg.advance.map_or(0, |a| args[usize::from(a)]);
        if let Some(End::At(end)) = f.end_of(s, class.0, class.1) {
            let room = end.wrapping_sub(s).wrapping_add(1) as u32;
            total = room.min(total as u32) as i32;
        }
    }
    // Records to do, the next slice's start, answers of none in a row,
    // the records the answers did (until_short).
    let (mut left, mut next, mut empty, mut did) = (total, 0usize, 0, 0i32);
    let r = loop {
        if left <= 0 {
            break Ok(());
        }
        let k = (left as usize).min(per_page.max(1));
        let start = next;
        if start + k > usize::try_from(total).unwrap_or(0) {
            // FANUC's library sends the records after the caller's array.
            break Ok(());
        }
        let mut a = args.to_vec();
        a[ci] = k as i32;
        if let Some(i) = pg.advance {
            let i = usize::from(i);
            a[i] = a[i].wrapping_add(total.wrapping_sub(left));
        }
        let payload = match f.payload {
            Some(_) if !pay.input.is_null() => {
                // SAFETY: records start..start + k of the caller's `*count`.
                let b = unsafe {
                    std::slice::from_raw_parts(pay.input.add(start * pay.stride), k * pay.stride)
                };
                payload_values(f, b, pay.stride, pay.offsets, k)
            }
            _ => Vec::new(),
        };
        let call = Described {
            f,
            args: &a,
            payload: &payload,
            text: &[],
            late: None,
        };
        let values = match h.call(&call) {
            Ok(v) => v,
            // EW_NUMBER after answers that did some ends the call.
            Err(Error::Cnc {
                code: EW_NUMBER, ..
            }) if pg.until_short && did > 0 => break Ok(()),
            // The count as the caller gave it.
            Err(e) if pg.until_short => return Err(e),
            Err(e) => break Err(e),
        };
        // The answer's count (an i32); without reply fields, the records
        // it holds.
        let n = match (f.reply.is_empty(), &f.records) {
            (true, Some(r)) => (values.len() / r.values().max(1)) as i32,
            _ => values.first().copied().unwrap_or(0) as i32,
        };
        let mut v = values.into_iter();
        // SAFETY: the caller's contract (offsets and elements in the outputs).
        unsafe { write_fields(f.reply, outs, |j| offsets[j], &mut v) };
        let mut written = 0;
        if let Some(r) = &f.records {
            let per = r.values();
            // At most the slice's (FANUC's library writes every record the
            // count announces, past the caller's array).
            while v.len() >= per && per > 0 && (written as i64) < i64::from(n).min(k as i64) {
                let at = |j: usize| rec.base + (start + written) * rec.stride + rec.offsets[j];
                // SAFETY: start + written < start + k <= `*count`.
                unsafe { write_fields(r.fields, outs, at, &mut v) };
                written += 1;
            }
        }
        if pg.until_short {
            // The next slice after this one; a short answer ends.
            did = did.wrapping_add(if f.records.is_some() {
                written as i32
            } else {
                n
            });
            next += k;
            left = left.wrapping_sub(k as i32);
            if n < k as i32 {
                break Ok(());
            }
            continue;
        }
        if !pg.from_done {
            next += k;
            left = left.wrapping_sub(n);
            continue;
        }
        if n == 0 {
            // FANUC's library asks the same again, for ever while the CNC
            // answers none: ours once more.
            empty += 1;
            if empty == 2 {
                break Ok(());
            }
            continue;
        }
        empty = 0;
        next += written;
        // Ours: more than asked counts as the records asked (FANUC's
        // library counts them all).
        left = left.wrapping_sub(n.min(k as i32));
    };
    let done = match pg.until_short {
        true => did,
        false => total.wrapping_sub(left),
    };
    // SAFETY: the caller's count, checked non-NULL (4 bytes of a
    // Param::LongCount).
    match f.long_count() {
        true => unsafe { put(count.cast::<i32>(), done) },
        false => unsafe { put(count, done as c_short) },
    }
    r
}

/// The exchanges of a range write ([`crate::spec::Pages`] without a count
/// parameter, over [`Func::span`]): the span's records, its end cut to the
/// end of its start's range ([`Func::span_cut`] on this class: `class` is
/// (16i class, Series 15)), in slices of at most [`Func::per_page`]; before
/// each request the room ([`crate::spec::Pages::room`]: EW_LENGTH) and the
/// slice's value records' places ([`PLACES`]: EW_DATA); its start and end
/// words are the slice's first and last numbers. An error (a refusal or
/// the CNC's) ends the write, the requests before it done.
///
/// # Safety
/// `pay.input` is a readable input whose records, from `pay.base` on,
/// `pay.stride` bytes each, hold every record the span writes (within the
/// room's bytes when the function has one).
pub(crate) unsafe fn span_pages(
    f: &'static Func,
    h: &handles::Handle,
    args: &[i32],
    pay: &PayloadAt<'_>,
    class: (bool, bool),
) -> Result<()> {
    let (Some(pg), Some(per_page), Some((si, ei)), Some(p)) =
        (f.pages, f.per_page(), f.span, f.payload)
    else {
        return Err(Error::local(EW_FUNC, "a range write without its span"));
    };
    let (si, ei) = (usize::from(si), usize::from(ei));
    let total = f.span_cut(args, class.0, class.1).unwrap_or(0);
    // Where one record's last field ends: the bytes of the last record read.
    let end = p
        .fields
        .iter()
        .zip(pay.offsets)
        .map(|(x, off)| off + x.c.size() * usize::from(x.n))
        .max()
        .unwrap_or(0);
    let mut done = 0usize;
    while done < total {
        let k = (total - done).min(per_page.max(1));
        if let Some((a, head)) = pg.room {
            let room = args.get(usize::from(a)).copied().unwrap_or(0);
            if usize::from(head) + pay.stride * (done + k) > usize::try_from(room).unwrap_or(0) {
                return Err(Error::length());
            }
        }
        // SAFETY: records done..done + k of the caller's (contract); the
        // last one read up to its last field.
        let b = unsafe {
            std::slice::from_raw_parts(
                pay.input.add(pay.base + done * pay.stride),
                (k - 1) * pay.stride + end,
            )
        };
        let payload = payload_values(f, b, pay.stride, pay.offsets, k);
        // Each value record's places (the BaseExp fields' integers).
        let per: usize = p.fields.iter().map(|x| usize::from(x.n)).sum();
        let mut at = 0;
        let mut places = Vec::new();
        for x in p.fields {
            if x.wire == Int::BaseExp {
                places.push(at);
            }
            at += usize::from(x.n);
        }
        let bad = payload.chunks(per.max(1)).any(|r| {
            places.iter().any(|&i| {
                r.get(i)
                    .is_some_and(|v| !(PLACES.0..=PLACES.1).contains(&(*v as i32)))
            })
        });
        if bad {
            return Err(Error::local(
                EW_DATA,
                "decimal places outside a signed byte",
            ));
        }
        let mut a = args.to_vec();
        a[si] = args[si].wrapping_add(done as i32);
        a[ei] = a[si].wrapping_add(k as i32 - 1);
        let call = Described {
            f,
            args: &a,
            payload: &payload,
            text: &[],
            late: None,
        };
        h.call(&call)?;
        done += k;
    }
    Ok(())
}

/// The further answers of a range read cut per answer
/// ([`crate::spec::Word::Upto`]`(s, e, n)`, cnc_rdpmacror), as FANUC's
/// library reads them: while an answer holds `n + 1` records (the most a
/// request asks for) and the range (its end cut to the end of its start's
/// range, [`Func::ends`]) goes on, it asks again from the number after
/// them; their records are appended to `values` and the `LAST` field
/// moved on. After each answer the records so far must fit the room
/// ([`crate::spec::Records::room`]), counted from 2 bytes before their
/// array (FANUC's library takes IODBPR's head as 10 bytes: `10 + 8 ·
/// records`): else EW_LENGTH, the earlier answers' records written (not
/// the reply's fields). A CNC's error answer after the first ends the
/// read: EW_OK with the records before it. `once`: the first answer
/// alone (a batch's one exchange).
///
/// # Safety
/// As [`exec`](super::exec): the records' output holds `room` bytes.
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn read_on(
    f: &'static Func,
    h: &handles::Handle,
    args: &[i32],
    values: &mut Vec<i64>,
    (si, ei, n): (u8, u8, i32),
    (class, once): ((bool, bool), bool),
    rec: &RecordsAt<'_>,
    outs: &[*mut u8],
) -> Result<()> {
    let Some(r) = f.records else {
        return Ok(());
    };
    let per = r.values().max(1);
    let fixed: usize = f.reply.iter().map(|x| usize::from(x.n)).sum();
    let room = r.room.map_or(usize::MAX, |a| {
        usize::try_from(args[usize::from(a)]).unwrap_or(0)
    });
    let head = rec.base.saturating_sub(2);
    let fits = |k: usize| head + k * rec.stride <= room;
    let at = |i: u8| args.get(usize::from(i)).copied().unwrap_or(0);
    let (s, e) = (at(si), at(ei));
    let end = match f.end_of(s, class.0, class.1) {
        Some(End::At(x)) => e.min(x),
        _ => e,
    };
    let full = usize::try_from(i64::from(n) + 1).unwrap_or(usize::MAX);
    let mut last = values.len().saturating_sub(fixed) / per;
    let mut total = last;
    if !fits(total) {
        return Err(Error::length());
    }
    while !once && last == full && i64::from(s) + (total as i64) <= i64::from(end) {
        let mut a = args.to_vec();
        a[usize::from(si)] = s.wrapping_add(total as i32);
        let call = Described::new(f, &a);
        let more = match h.call(&call) {
            Ok(v) => v,
            Err(crate::error::Error::Cnc { .. }) => break,
            Err(e) => return Err(e),
        };
        last = more.len().saturating_sub(fixed) / per;
        if !fits(total + last) {
            // The earlier answers' records, as FANUC's library wrote them.
            let mut v = values[fixed..fixed + total * per].iter().copied();
            for i in 0..total {
                let at = |k: usize| rec.base + i * rec.stride + rec.offsets[k];
                // SAFETY: record i lies within the room (checked).
                unsafe { write_fields(r.fields, outs, at, &mut v) };
            }
            return Err(Error::length());
        }
        values.extend_from_slice(&more[fixed..fixed + last * per]);
        total += last;
    }
    // The last number answered.
    let mut k = 0;
    for field in f.reply {
        if field.arg == Some(LAST) {
            values[k] = i64::from(s.wrapping_add(total as i32 - 1));
        }
        k += usize::from(field.n);
    }
    Ok(())
}
