//! Typed parameter blocks (spec::Block: cnc_rdparam, cnc_wrparam, cnc_rdset,
//! cnc_wrset ...) and range reads (spec::Range: cnc_rdparar, cnc_rdsetr).

use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::EW_LENGTH;
use crate::ffi::{nonnull, put};
use crate::proto::described::Described;
use crate::proto::described::block::{fits, write_values};
use crate::proto::open::CncClass;
use crate::proto::param::{Elem, ParamInfo};
use crate::spec::{Block, Func};
use std::os::raw::c_short;

/// A typed parameter block ([`Block`]): a read into output 0, or a write
/// of the input's block (its attributes read first where the block says).
///
/// # Safety
/// A read's output 0 points to a writable IODBPSD; a write's `input` to a
/// readable one.
pub(super) unsafe fn block(
    f: &'static Func,
    b: Block,
    h: &handles::Handle,
    args: &[i32],
    outs: &[*mut u8],
    input: *const u8,
) -> Result<()> {
    let length = args.get(usize::from(b.length)).copied().unwrap_or(0) as i16;
    let Some(attributes) = b.attributes else {
        let values = h.call(&Described::new(f, args))?;
        // Below the 4-byte header nothing is written; else the header is,
        // before `length` is checked against the values (FANUC's library).
        if length < 4 {
            return Err(Error::local(EW_LENGTH, "length is below the 4-byte header"));
        }
        let out = outs[0];
        let head = |k: usize| values.get(k).copied().unwrap_or(0) as i16;
        // SAFETY: output 0 is an IODBPSD (the caller's contract).
        unsafe {
            put(out.cast::<i16>(), head(0));
            put(out.add(2).cast::<i16>(), head(1));
        }
        if !fits(&b, args, &values) {
            return Err(Error::local(
                EW_LENGTH,
                "length below 4 + the size of the values answered",
            ));
        }
        let data: Vec<u8> = values.iter().skip(2).map(|v| *v as u8).collect();
        // SAFETY: at most max-axes values of at most 8 bytes: IODBPSD's union.
        unsafe { std::ptr::copy_nonoverlapping(data.as_ptr(), out.add(4), data.len()) };
        return Ok(());
    };
    let input = nonnull(input.cast_mut())?;
    // SAFETY: the caller's IODBPSD, read unaligned.
    let raw: [u8; 260] = unsafe { input.cast::<[u8; 260]>().read_unaligned() };
    let number = i32::from(i16::from_le_bytes([raw[0], raw[1]]));
    let axis = i16::from_le_bytes([raw[2], raw[3]]);
    let cx = h.ctx();
    let class = (
        cx.class.is_16i(),
        matches!(cx.class, CncClass::Series16 { kind: 2 }),
    );
    // The type and its kind: from the attributes the CNC answers, or (a
    // Series 15) from the `type` member, `(type << 8) | (axis & 0xff)`.
    let (ptype, elem, axis) = if attributes.matches(class.0, class.1) {
        let info = h.call(&ParamInfo { number })?;
        (info.ptype, info.elem, axis)
    } else if length < 4 {
        // Not asked: below the 4-byte header, whatever the type, nothing
        // is sent (FANUC's library, Series 15: tests/vectors/
        // cnc_wrparam.s15length.json).
        return Err(Error::local(EW_LENGTH, "length is below the 4-byte header"));
    } else {
        let ptype = (axis as u16) >> 8;
        let elem = Elem::of_param(ptype).filter(|_| ptype <= 4);
        (ptype, elem, i16::from(axis as i8))
    };
    // A type FANUC's library does not know (not 0..4): no length
    // check, every value sent as zero, the CNC decides.
    let values = match elem {
        Some(elem) => {
            let count = if axis < 0 { cx.axes() } else { 1 };
            let size = elem.size();
            if i32::from(length) != (4 + size * count) as i32 {
                return Err(Error::local(
                    EW_LENGTH,
                    "length is not 4 + the size of the values",
                ));
            }
            (0..count).map(|i| elem.get(&raw[4 + i * size..])).collect()
        }
        None => Vec::new(),
    };
    let payload = write_values(number, axis, ptype, &values);
    h.call(&Described {
        f,
        args,
        payload: &payload,
        text: &[],
        late: None,
    })
    .map(|_| ())
}

/// A range read of typed parameter blocks ([`crate::spec::Range`]) into
/// `out` as packed records; `ptrs` are the start, end and length shorts,
/// written back on success. FANUC's library's loop [fuzz, seed
/// 0x21b01128]: `last` is the whole 32-bit number of the last block
/// received (0 before any); after each answer it asks on from last + 1
/// (wrapping) while that is not above the end, so an answer without a
/// block restarts from 1, or repeats the request (FANUC's library while
/// the CNC answers so; ours once, a second such answer in a row ending in
/// EW_PROTOCOL). Read without a block, `*s_number` is the caller's
/// buffer's first short, as FANUC's library takes it from there.
///
/// # Safety
/// `out` points to the `*length` writable bytes; `ptrs` are the caller's
/// shorts, checked non-NULL.
pub(super) unsafe fn range(
    f: &'static Func,
    r: crate::spec::Range,
    h: &handles::Handle,
    args: &mut [i32],
    out: *mut u8,
    [s_number, e_number, length]: [*mut c_short; 3],
) -> Result<()> {
    let (s, e) = (args[usize::from(r.s)], args[usize::from(r.e)]);
    let room = unsafe { length.read_unaligned() }.max(0) as usize;
    let mut used = 0usize;
    let mut first: Option<i16> = None;
    let mut last: i32 = 0;
    let mut next = s;
    // The request just answered without a block was sent again.
    let mut again = false;
    loop {
        args[usize::from(r.s)] = next;
        let values = match h.call(&Described::new(f, args)) {
            // No more numbers after some were read: done.
            Err(Error::Cnc {
                code: crate::ew::EW_NUMBER,
                ..
            }) if first.is_some() => break,
            v => v?,
        };
        let recs = records_of(&values);
        for (number, padded, bytes) in &recs {
            if used + padded > room {
                // Its header, as FANUC's library writes it, if it fits.
                if used + 4 <= room {
                    unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), out.add(used), 4) };
                }
                return Err(Error::length());
            }
            unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), out.add(used), bytes.len()) };
            used += padded;
            first.get_or_insert(*number as i16);
            last = *number;
        }
        let asked = next;
        next = last.wrapping_add(1);
        // A request answered without a block, sent again: ours once (every
        // record takes room in the buffer, so a CNC that goes back without
        // end ends in EW_LENGTH).
        if recs.is_empty() && next == asked {
            if again {
                return Err(Error::short(
                    "parameter range answered twice without a block",
                ));
            }
            again = true;
            continue;
        }
        again = false;
        if next > e {
            break;
        }
    }
    // None read: the buffer's first short (FANUC's library's first record).
    let first = first.unwrap_or_else(|| match room {
        // SAFETY: `*length` bytes of `out` (the caller's contract).
        2.. => unsafe { out.cast::<i16>().read_unaligned() },
        _ => s as i16,
    });
    unsafe {
        put(s_number, first);
        put(length, used as c_short);
        // The last block's number (low 16 bits), 0 before any.
        put(e_number, last as c_short);
    }
    Ok(())
}

/// The packed records of a range answer's integers
/// ([`crate::proto::described::block::range`]): number, bytes taken with
/// the padding, the record's bytes.
fn records_of(v: &[i64]) -> Vec<(i32, usize, Vec<u8>)> {
    let mut out = Vec::new();
    let mut at = 0;
    while at + 3 <= v.len() {
        let (number, padded, n) = (v[at] as i32, v[at + 1] as usize, v[at + 2] as usize);
        let end = (at + 3 + n).min(v.len());
        out.push((
            number,
            padded,
            v[at + 3..end].iter().map(|b| *b as u8).collect(),
        ));
        at = end;
    }
    out
}
