//! The exported functions described as data (crate::spec). build.rs writes
//! each one's `extern "C"` function from its table entry (signature plainly,
//! body one `exec` call) into `$OUT_DIR/described.rs`, included here; the
//! header's declarations come from the same file (cbindgen reads it).

use super::{nonnull, put};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::{EW_DATA, EW_FUNC};
use crate::proto::described::{
    Described, Prelude, form, payload_numbers, payload_records, payload_values,
};
use crate::proto::open::CncClass;
use crate::proto::packet::CLASS_PMC;
use crate::spec::{Field, Func, Learnt, Overflow};
#[allow(unused_imports)]
use crate::types::*;
#[allow(unused_imports)]
use std::mem::offset_of;
#[allow(unused_imports)]
use std::os::raw::{c_char, c_long, c_short, c_ulong, c_ushort, c_void};

/// Most number parameters a described function has (build.rs checks).
pub(crate) const MAX_NUMBERS: usize = 8;
/// Most outputs, numbers by pointer ([`Param::Io`](crate::spec::Param::Io))
/// and text parameters a described function has (build.rs checks).
pub(crate) const MAX_POINTERS: usize = 4;

/// What a described export passes to [`exec`] that is not the caller's:
/// build.rs writes one `static` per export. The caller's values go in a
/// [`Call`], and every export runs through [`run`]: one body, and one
/// closure for the C boundary and the batch, for all of them (a closure
/// each, with its vtable, unwind tables and `call_once` shim, cost about
/// 400 bytes a function in the installed library).
pub(crate) struct Site {
    /// Its entry: `crate::spec::FUNCS[func]`.
    pub func: u16,
    /// A read that may join a batch (`ffi_read!`), else `ffi_boundary!`'s.
    pub batch: bool,
    /// How many of [`Call`]'s numbers, outputs, numbers by pointer and
    /// texts the function has.
    pub numbers: u8,
    pub outs: u8,
    pub io: u8,
    pub texts: u8,
    /// [`RecordsAt`]'s `base`, `stride` and `count`.
    pub rec_base: u16,
    pub rec_stride: u16,
    pub rec_count: Option<u16>,
    /// [`PayloadAt`]'s `base` and `stride`.
    pub pay_base: u16,
    pub pay_stride: u16,
    /// How many of [`Site::data`] are [`exec`]'s `offsets`, then
    /// [`RecordsAt`]'s `offsets`, [`PayloadAt`]'s `offsets` and `words`.
    pub lens: [u16; 4],
    /// Those four lists one after another. Offsets and sizes are `u16`s
    /// ([`at`]) and the lists one slice: a `Site` a function, so it is
    /// kept small.
    pub data: &'static [u16],
}

/// A byte offset or size as a [`Site`] keeps it (build.rs writes these in
/// constants: one past 65535 fails the build).
pub(crate) const fn at(x: usize) -> u16 {
    assert!(x <= u16::MAX as usize, "an offset past 65535");
    x as u16
}

/// [`Site::data`]'s four lists, as [`exec`] takes them.
fn lists(site: &Site) -> [Vec<usize>; 4] {
    let mut rest = site.data.iter().map(|&x| usize::from(x));
    site.lens
        .map(|n| rest.by_ref().take(usize::from(n)).collect())
}

/// The caller's values of one call of a described export (the first of
/// each array that its [`Site`] says): kept by value, as a batched read
/// keeps its arguments.
#[derive(Clone, Copy)]
pub(crate) struct Call {
    pub numbers: [i32; MAX_NUMBERS],
    pub outs: [*mut u8; MAX_POINTERS],
    /// [`RecordsAt`]'s `asked`.
    pub asked: *mut c_short,
    pub io: [*mut c_short; MAX_POINTERS],
    /// [`PayloadAt`]'s `input`.
    pub input: *const u8,
    pub texts: [*const c_char; MAX_POINTERS],
}

/// Runs described export `site` for handle `h` with the caller's values,
/// at the C boundary (a read that may join a batch as `ffi_read!` runs
/// it, another as `ffi_boundary!`).
///
/// # Safety
/// As [`exec`]'s, for `site`'s offsets and `call`'s pointers.
pub(crate) unsafe fn run(site: &'static Site, h: c_ushort, call: Call) -> c_short {
    let f = &crate::spec::FUNCS[usize::from(site.func)];
    let [offsets, rec_offsets, pay_offsets, pay_words] = lists(site);
    let mut body = move || -> Result<()> {
        let c = &call;
        // SAFETY: as this function's caller promises.
        unsafe {
            exec(
                f,
                h,
                &c.numbers[..usize::from(site.numbers)],
                &c.outs[..usize::from(site.outs)],
                &offsets,
                RecordsAt {
                    base: usize::from(site.rec_base),
                    stride: usize::from(site.rec_stride),
                    offsets: &rec_offsets,
                    count: site.rec_count.map(usize::from),
                    asked: c.asked,
                    io: &c.io[..usize::from(site.io)],
                },
                PayloadAt {
                    input: c.input,
                    base: usize::from(site.pay_base),
                    stride: usize::from(site.pay_stride),
                    offsets: &pay_offsets,
                    words: &pay_words,
                    texts: &c.texts[..usize::from(site.texts)],
                },
            )
        }
    };
    if site.batch && crate::client::batch::active() {
        super::read_boundary(f.name, Box::new(body))
    } else {
        super::boundary(f.name, &mut body)
    }
}

/// Runs described function `f`: the handle, its checks and NULL outputs
/// before any traffic, the request for the CNC's class, then the reply's
/// integers into the caller's outputs (only when the whole reply decoded).
/// A function with a [`Param::Count`](crate::spec::Param::Count) checks
/// its pointers first, since the count is read from one, and gets the
/// number of records written back there; so does a write, before its
/// count is checked, then reads its payload records from `pay`.
///
/// # Safety
/// Each `outs[i]` is NULL or points to writable memory of output i's C
/// type; `offsets[k]` is the byte offset of reply field k's member in its
/// output, and its `n` elements fit there; `rec` places `f.records`' at
/// most `max` records inside their output (build.rs asserts both at
/// compile time where the output is a struct), or, with a count, at most
/// `*rec.asked` records in the caller's array; `rec.asked` is the caller's
/// `short *` (NULL: EW_DATA), or NULL for a function without one;
/// `pay.input` is NULL or holds the records its count argument says (at
/// most the payload's `max` are read; one without a count parameter),
/// `pay.stride` bytes each, and `pay.words` are offsets of `short`
/// members inside its first (written back converted); each of
/// `pay.texts` is NULL or readable up to its NUL or its field's size.
pub(crate) unsafe fn exec(
    f: &'static Func,
    h: c_ushort,
    args: &[i32],
    outs: &[*mut u8],
    offsets: &[usize],
    rec: RecordsAt<'_>,
    pay: PayloadAt<'_>,
) -> Result<()> {
    let io = rec.io;
    let h = handles::get(h)?;
    let mut a = [0i32; MAX_NUMBERS];
    a[..args.len()].copy_from_slice(args);
    let numbers = args.len();
    let args = &mut a[..numbers + pay.words.len()];
    let outs_set = || {
        if outs.iter().any(|p| p.is_null()) {
            return Err(Error::null());
        }
        Ok(())
    };
    // A count is read from its pointer: the pointers are checked first.
    let count = match f.count() {
        Some(i) => {
            let c = nonnull(rec.asked)?;
            outs_set()?;
            // SAFETY: the caller's count, checked above (4 bytes of a
            // Param::LongCount).
            args[i] = match f.long_count() {
                true => unsafe { c.cast::<i32>().read_unaligned() },
                false => i32::from(unsafe { c.read_unaligned() }),
            };
            Some(c)
        }
        None => None,
    };
    // Numbers passed by pointer: the pointers are checked first.
    let io_at: Vec<usize> = f
        .params
        .iter()
        .filter_map(|p| match *p {
            crate::spec::Param::Io(n) => f.numbers().position(|m| m == n),
            _ => None,
        })
        .collect();
    if !io.is_empty() {
        for p in io {
            nonnull(*p)?;
        }
        outs_set()?;
        for (p, i) in io.iter().zip(&io_at) {
            // SAFETY: the caller's short, checked non-NULL.
            args[*i] = i32::from(unsafe { p.read_unaligned() });
        }
    }
    if f.input().is_some() {
        let input = nonnull(pay.input.cast_mut())?;
        outs_set()?;
        // The leading checks of plain number arguments come before the
        // struct is read (cnc_wrpmacror's `length` below 12: FANUC's
        // library checks it before anything, and the caller's buffer may
        // be that small).
        let plain = f
            .checks
            .iter()
            .take_while(|c| usize::from(c.arg) < numbers)
            .count();
        if let Some(code) = f.checks_fail(plain, args, h.pair.info.option & 1 == 1) {
            return Err(Error::local(code, "argument out of range"));
        }
        for ((_, c), (at, off)) in f.inputs().zip(args[numbers..].iter_mut().zip(pay.words)) {
            if c.size() == 4 {
                // A 32-bit `long` member, read as it is.
                // SAFETY: the member lies in the caller's struct (build.rs).
                let p = unsafe { input.cast::<u8>().add(*off).cast::<i32>() };
                *at = unsafe { p.read_unaligned() };
                continue;
            }
            // SAFETY: the `short` member lies in the caller's first element
            // (build.rs), read and written unaligned.
            let p = unsafe { input.cast::<u8>().add(*off).cast::<i16>() };
            let v = c.cut(i64::from(unsafe { p.read_unaligned() }));
            // FANUC's library leaves the converted value in the member.
            unsafe { p.write_unaligned(v as i16) };
            *at = v as i32;
        }
    }
    let class = {
        let c = h.ctx().class;
        (c.is_16i(), matches!(c, CncClass::Series16 { kind: 2 }))
    };
    // A request before the function's own, before the local checks; its
    // answer changes nothing, so a batch (one exchange a call) leaves it out.
    let batching = h.batching.load(std::sync::atomic::Ordering::Acquire);
    let option = h.pair.info.option & 1 == 1;
    // The checks FANUC's library makes before that request.
    let early = f.first.map_or(0, |fr| usize::from(fr.after));
    if let Some(code) = f.checks_fail(early, args, option) {
        return Err(Error::local(code, "argument out of range"));
    }
    if let Some(fr) = f
        .first
        .filter(|_| !batching && f.sends_first(args, class.0, class.1))
    {
        h.call(&Prelude { cmd: fr.cmd })?;
    }
    if let Some((code, detail)) = f.refusal_detail(args, class.0, class.1, option) {
        if let Some(d) = detail {
            h.set_detail(d);
        }
        return Err(Error::local(code, "argument out of range"));
    }
    outs_set()?;
    // The text parameters' fields: each string up to its NUL, cut to its
    // field, zeros after.
    let mut fields = Vec::new();
    for (&p, (_, n)) in pay.texts.iter().zip(f.texts()) {
        let p = nonnull(p.cast_mut())?;
        let at = fields.len();
        fields.resize(at + n, 0);
        for (i, b) in fields[at..].iter_mut().enumerate() {
            // SAFETY: the caller's string, read up to its NUL and at most
            // its field's bytes (contract).
            match unsafe { p.add(i).read() } {
                0 => break,
                c => *b = c as u8,
            }
        }
    }
    let cx = h.ctx();
    let Some(form) = form(f, cx.class) else {
        // No request on this class: FANUC's library answers from what it
        // learnt at connect, where it does.
        let class = (
            cx.class.is_16i(),
            matches!(cx.class, CncClass::Series16 { kind: 2 }),
        );
        let Some(l) = f.local.filter(|l| l.classes.matches(class.0, class.1)) else {
            return Err(Error::local(EW_FUNC, "not on this CNC class"));
        };
        let mut v = l.values.iter().map(|x| match x {
            Learnt::MaxSpindles => i64::from(cx.max_spindles),
            Learnt::PmcUnit => i64::from(h.state.lock().pmc_unit),
        });
        // SAFETY: the caller's contract (offsets and elements in the outputs).
        unsafe { write_fields(f.reply, outs, |k| offsets[k], &mut v) };
        return Ok(());
    };
    if let Some(b) = f.block {
        // SAFETY: the caller's contract (output 0 an IODBPSD; the input one).
        if let Some(r) = b.range {
            let at = |k: u8| {
                let i = io_at.iter().position(|i| *i == usize::from(k));
                i.map_or(std::ptr::null_mut(), |i| io[i])
            };
            let ptrs = [at(r.s), at(r.e), at(b.length)];
            // SAFETY: the caller's contract (`*length` bytes at output 0).
            return unsafe { range(f, r, &h, args, outs[0], ptrs) };
        }
        return unsafe { block(f, b, &h, args, outs, pay.input) };
    }
    // A C string input: up to its NUL, at most the field's bytes.
    let text = match f.payload {
        Some(p) if p.count == crate::spec::TEXT && !pay.input.is_null() => {
            let room = pay.stride;
            // SAFETY: the caller's string, read up to its NUL and at most
            // the field's `room` bytes.
            let len = (0..room).find(|&k| unsafe { pay.input.add(k).read() } == 0);
            let Some(len) = len else {
                // FANUC's library reports detail 1 (the first argument).
                h.set_detail(1);
                return Err(Error::local(EW_DATA, "no NUL in the text field"));
            };
            let mut b = unsafe { std::slice::from_raw_parts(pay.input, len) }.to_vec();
            b.resize(room, 0);
            Some(b)
        }
        _ => None,
    };
    if f.pages.is_some() {
        // SAFETY: the caller's contract, as for the rest of exec.
        if f.count().is_none() {
            // A range write (spec::Pages over Func::span).
            // SAFETY: the caller's contract, as for the rest of exec.
            return unsafe { span_pages(f, &h, args, &pay, class) };
        }
        return unsafe { pages(f, &h, args, outs, offsets, &rec, &pay, (count, class)) };
    }
    let n = payload_records(f, args);
    let payload = match n {
        0 => Vec::new(),
        _ if text.is_some() => {
            let b = text.as_deref().unwrap_or_default();
            payload_values(f, b, pay.stride, pay.offsets, 1)
        }
        _ if f.input().is_none() => payload_numbers(f, cx.class, args).unwrap_or_default(),
        // SAFETY: the caller's array holds at least `n` records (contract).
        n => payload_values(
            f,
            unsafe { std::slice::from_raw_parts(pay.input, n * pay.stride) },
            pay.stride,
            pay.offsets,
            n,
        ),
    };
    let mut payload = payload;
    if !f.rules.is_empty() || !f.each.is_empty() || !f.codes.is_empty() {
        records::prepare(f, &h, args, &mut payload, class)?;
    }
    let late = std::sync::Mutex::new(None);
    let call = Described {
        f,
        args,
        payload: &payload,
        text: &fields,
        late: Some(&late),
    };
    let mut values = if form.class == CLASS_PMC {
        h.call_pmc(&call)?
    } else {
        h.call(&call)?
    };
    // The lookups' integers follow the reply's (decode).
    let looked: usize = f.lookups.iter().map(|l| l.values()).sum();
    let looked = values.split_off(values.len().saturating_sub(looked));
    // A range read cut per answer that reads on (Word::Upto, `.3`).
    let upto = form.words.iter().find_map(|w| match *w {
        crate::spec::Word::Upto(s, e, n, true) => Some((s, e, n)),
        _ => None,
    });
    if let Some(u) = upto.filter(|_| f.records.is_some()) {
        // SAFETY: the caller's contract, as for the rest of exec.
        // A batch (one exchange a call) reads the first answer alone.
        let once = batching;
        unsafe { read_on(f, &h, args, &mut values, u, (class, once), &rec, outs) }?;
    } else if let Some(r) = f.records.as_ref().filter(|r| r.room.is_some()) {
        let fixed: usize = f.reply.iter().map(|x| usize::from(x.n)).sum();
        let n = values.len().saturating_sub(fixed) / r.values().max(1);
        let room = r
            .room
            .map_or(0, |a| usize::try_from(args[usize::from(a)]).unwrap_or(0));
        if rec.base + n * rec.stride > room {
            return Err(Error::length());
        }
    }
    if let (Some(r), Overflow::Refuse) = (&f.records, f.overflow) {
        let fixed: usize = f.reply.iter().map(|x| usize::from(x.n)).sum();
        let n = values.len().saturating_sub(fixed) / r.values().max(1);
        let asked = f.count().map_or(0, |i| args[i]);
        if n as i64 > i64::from(asked) {
            return Err(Error::length());
        }
    }
    if f.columns.is_some() {
        // Columns: as many elements in each (at most its field's `n`).
        let n = values.len() / f.reply.len().max(1);
        for (k, field) in f.reply.iter().enumerate() {
            let one = [Field {
                n: n as u16,
                ..*field
            }];
            let mut v = values[k * n..].iter().copied();
            // SAFETY: the caller's contract; `n` is at most the field's `n`.
            unsafe { write_fields(&one, outs, |_| offsets[k], &mut v) };
        }
        if let Some(e) = late.into_inner().ok().flatten() {
            h.note(&e);
            return Err(e);
        }
        return Ok(());
    }
    let mut v = values.into_iter();
    // SAFETY: the caller's contract (offsets and elements in the outputs).
    unsafe { write_fields(f.reply, outs, |k| offsets[k], &mut v) };
    let mut l = looked.into_iter();
    for (k, x) in f.lookups.iter().enumerate() {
        let all = [Field {
            wire: x.c,
            n: x.values() as u16,
            out: 0,
            to: Some(x.to),
            c: x.c,
            arg: None,
        }];
        // SAFETY: the caller's contract: the lookup's offset (after the
        // reply fields') and its elements lie in output 0 (build.rs).
        unsafe { write_fields(&all, outs, |_| offsets[f.reply.len() + k], &mut l) };
    }
    if let Some(e) = late.into_inner().ok().flatten() {
        h.note(&e);
        return Err(e);
    }
    if let Some(r) = &f.records {
        let per = r.values();
        let mut i = 0;
        while v.len() >= per && per > 0 {
            let at = |k: usize| rec.base + i * rec.stride + rec.offsets[k];
            // SAFETY: as above; decode returned at most `max` records (and
            // with a count, at most the `*count` the caller's array holds).
            unsafe { write_fields(r.fields, outs, at, &mut v) };
            i += 1;
        }
        if let Some(c) = rec.count {
            // SAFETY: the count member lies in its output (build.rs).
            unsafe { put(outs[r.out as usize].add(c).cast::<i16>(), i as i16) };
        }
        if let Some(c) = count {
            // SAFETY: the caller's count, checked non-NULL.
            unsafe { put(c, i as c_short) };
        }
    }
    Ok(())
}
mod at;
mod block;
mod pages;
mod records;

use at::write_fields;
pub(crate) use at::{PayloadAt, RecordsAt};
use block::{block, range};
use pages::{pages, read_on, span_pages};

include!(concat!(env!("OUT_DIR"), "/described.rs"));
