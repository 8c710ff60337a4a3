//! Program execution: numbers, names, blocks, modal data, timers.

// --- program ---

use super::{ffi_boundary, ffi_read, nonnull, put};
use crate::client::handles;
use crate::error::Error;
use crate::ew::{EW_ATTRIB, EW_LENGTH, EW_NUMBER};
use crate::proto::program::{self as pp, AUX_ORDER, Clock, Modal, ModalCall, ModalKind};
use crate::types::{IODBTIMER, ODBMDL, PRGDIR, PRGDIR3};
use std::os::raw::{c_char, c_long, c_short, c_ushort};

/// The low 16 bits, as FANUC's library stores 32-bit numbers in shorts.
pub(crate) fn low16(v: i32) -> c_short {
    v as u32 as u16 as c_short
}

/// Reads the text of the block being executed and the blocks after it.
/// `*length` in: size of `data` in bytes; out: characters read (the text
/// is NUL-terminated and, unlike FANUC's library, never longer than
/// `*length - 1` characters, so `data` is never overrun). At most 1428
/// bytes are asked for (one answer), as FANUC's library. A CNC answering
/// with no text gives `*length` 0, an empty string and `*blknum` 0 (FANUC's
/// library reads past its receive buffer there). `*length` 0 is sent as
/// is; then only `*blknum` and `*length` 0 are written (FANUC's library
/// writes `*length` 65535 and text past the buffer).
///
/// # Safety
/// `length` and `blknum` must point to readable and writable shorts; `data`
/// must have `*length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdexecprog(
    FlibHndl: c_ushort,
    length: *mut c_ushort,
    blknum: *mut c_short,
    data: *mut c_char,
) -> c_short {
    ffi_read!("cnc_rdexecprog", {
        let h = handles::get(FlibHndl)?;
        let (len, blk, out) = (nonnull(length)?, nonnull(blknum)?, nonnull(data)?);
        let room = unsafe { len.read_unaligned() };
        let e = h.call(&pp::rdexecprog(room))?;
        let n = e.text.len().min((room as usize).saturating_sub(1));
        unsafe {
            if room > 0 {
                std::ptr::copy_nonoverlapping(e.text.as_ptr(), out.cast::<u8>(), n);
                put(out.add(n), 0);
            }
            put(len, n as c_ushort);
            put(blk, low16(e.blknum.unwrap_or(0)));
        }
        Ok(())
    })
}

/// Reads modal data: G-code groups (`type` 0.., −1 all, −4/−5 one-shot,
/// 300..) or other codes (100..126, 200..299, −2 all in raux1 order, −3 all
/// as sent), of `block` (0 active, 1 next ...). `datano` = `type`, `type` =
/// `block`, written whatever the result. Writes never exceed the union (35
/// G-code bytes, 32 records), where FANUC's library writes whatever arrives;
/// an answer without records writes only the header. Other types:
/// EW_NUMBER without traffic.
///
/// # Safety
/// `modal` must point to a writable ODBMDL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_modal(
    FlibHndl: c_ushort,
    r#type: c_short,
    block: c_short,
    modal: *mut ODBMDL,
) -> c_short {
    ffi_read!("cnc_modal", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(modal)?;
        // The header is written first, whatever follows (an unknown type,
        // an error from the CNC), as FANUC's library does.
        unsafe {
            put(&raw mut (*out).datano, r#type);
            put(&raw mut (*out).r#type, block);
        }
        let kind =
            pp::modal_kind(r#type).ok_or(Error::local(EW_NUMBER, "no such modal data type"))?;
        let m = h.call(&ModalCall { kind, block })?;
        let base = out.cast::<u8>();
        // The other-code records to write, in raux order.
        let records: Vec<pp::AuxCode> = match (&m, kind) {
            // Every raux1 slot, in FANUC's order; a record the CNC did not
            // send (a shorter answer) is written as zeros, as FANUC's library
            // does.
            (Modal::Aux(a), ModalKind::AuxAll) => AUX_ORDER
                .iter()
                .map(|i| a.0.get(*i as usize).copied().unwrap_or_default())
                .collect(),
            (Modal::Aux(a), _) => a.0.iter().take(32).copied().collect(),
            (Modal::G(_), _) => Vec::new(),
        };
        unsafe {
            match &m {
                Modal::G(g) => {
                    for (i, c) in g.0.iter().take(35).enumerate() {
                        let v = if c.flag & 1 != 0 {
                            c.code | 0x80
                        } else {
                            c.code
                        };
                        put(base.add(4 + i), v);
                    }
                }
                Modal::Aux(_) => {
                    for (i, r) in records.iter().enumerate() {
                        let at = base.add(4 + 8 * i);
                        put(at.cast::<i32>(), r.value);
                        put(at.add(4), r.flag1);
                        put(at.add(5), r.flag2);
                    }
                }
            }
        }
        Ok(())
    })
}

fn timer_type(t: c_short) -> crate::error::Result<c_short> {
    if t == 0 || t == 1 {
        Ok(t)
    } else {
        Err(Error::local(EW_NUMBER, "type must be 0 (date) or 1 (time)"))
    }
}

/// Reads the CNC's date (`time->type` 0: year, month, date) or time of day
/// (1: hour, minute, second). Other types: EW_NUMBER without traffic
/// (unverified: no recording has another type; FANUC's cnc_settimer refuses
/// them this way, so we do the same here).
///
/// # Safety
/// `time` must point to a readable and writable IODBTIMER.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_gettimer(FlibHndl: c_ushort, time: *mut IODBTIMER) -> c_short {
    ffi_read!("cnc_gettimer", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(time)?;
        let t = timer_type(unsafe { (&raw const (*out).r#type).read_unaligned() })?;
        let c = h.call(&pp::gettimer(t))?;
        let words = if t == 0 {
            [c.year, c.month, c.day]
        } else {
            [c.hour, c.minute, c.second]
        };
        unsafe { put((&raw mut (*out).data).cast::<[c_short; 3]>(), words) };
        Ok(())
    })
}

/// Sets the CNC's date (`time->type` 0) or time of day (1). Other types:
/// EW_NUMBER without traffic. The caller's struct is not modified.
///
/// # Safety
/// `time` must point to a readable IODBTIMER.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_settimer(FlibHndl: c_ushort, time: *mut IODBTIMER) -> c_short {
    ffi_boundary!("cnc_settimer", {
        let h = handles::get(FlibHndl)?;
        let inp = nonnull(time)?;
        let t = timer_type(unsafe { (&raw const (*inp).r#type).read_unaligned() })?;
        let w = unsafe {
            (&raw const (*inp).data)
                .cast::<[c_short; 3]>()
                .read_unaligned()
        };
        // FANUC's library sends its stale static buffer in the other half;
        // we send zeros there.
        let clock = if t == 0 {
            Clock {
                year: w[0],
                month: w[1],
                day: w[2],
                ..Clock::default()
            }
        } else {
            Clock {
                hour: w[0],
                minute: w[1],
                second: w[2],
                ..Clock::default()
            }
        };
        h.call(&pp::SetTimer { kind: t, clock })
    })
}

/// Reads the program directory as text: the programs numbered `datano_s`
/// to `datano_e`, `type` 0 "O1O1000%", 1 "%\nO1\nO1000(COMMENT)\n%", 2
/// "O1100O1000(COMMENT)2048%" (number, comment, size in bytes run
/// together), at most `length` bytes, no NUL terminator (all as FANUC's
/// library writes it, learnt from it against a fake CNC). An entry that does
/// not fit ends the text ("%" still written) with EW_LENGTH. Type not 0..2:
/// EW_ATTRIB, `datano_s` > `datano_e`: EW_NUMBER, `length` 0: EW_LENGTH, all
/// without traffic. Asks the CNC for 19 programs per exchange, as FANUC's.
/// (FANUC's library calls cnc_rdprogdiro8 with the numbers sign-extended.)
///
/// # Safety
/// `prg_dir` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdprogdir(
    FlibHndl: c_ushort,
    r#type: c_short,
    datano_s: c_short,
    datano_e: c_short,
    length: c_ushort,
    prg_dir: *mut PRGDIR,
) -> c_short {
    ffi_boundary!("cnc_rdprogdir", {
        progdir_text(
            FlibHndl,
            r#type,
            i32::from(datano_s),
            i32::from(datano_e),
            length,
            prg_dir,
        )
    })
}

/// cnc_rdprogdir with 8-digit program numbers: the programs numbered
/// `datano_s` to `datano_e` (32 bits each, sent as they are), the same text,
/// checks and exchanges.
///
/// # Safety
/// `prg_dir` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdprogdiro8(
    FlibHndl: c_ushort,
    r#type: c_short,
    datano_s: c_long,
    datano_e: c_long,
    length: c_ushort,
    prg_dir: *mut PRGDIR,
) -> c_short {
    ffi_boundary!("cnc_rdprogdiro8", {
        // FANUC's x86-64 library reads the low 32 bits of a `long` argument.
        progdir_text(
            FlibHndl,
            r#type,
            datano_s as i32,
            datano_e as i32,
            length,
            prg_dir,
        )
    })
}

/// The exchanges of cnc_rdprogdir / cnc_rdprogdiro8 at most: 77824
/// programs, more than a CNC's directory holds (FANUC's library would ask
/// for ever of a CNC answering the same numbers again and again).
const PROGDIR_EXCHANGES: usize = 4096;

/// cnc_rdprogdir / cnc_rdprogdiro8.
fn progdir_text(
    hndl: c_ushort,
    r#type: c_short,
    datano_s: i32,
    datano_e: i32,
    length: c_ushort,
    prg_dir: *mut PRGDIR,
) -> crate::error::Result<()> {
    let h = handles::get(hndl)?;
    let out = nonnull(prg_dir)?.cast::<u8>();
    if !(0..=2).contains(&r#type) {
        return Err(Error::local(EW_ATTRIB, "type must be 0, 1 or 2"));
    }
    if datano_s > datano_e {
        return Err(Error::local(EW_NUMBER, "datano_s is after datano_e"));
    }
    if length == 0 {
        return Err(Error::local(EW_LENGTH, "length must be at least 1"));
    }
    let mut text = pp::DirText::new(r#type, length);
    let mut start = datano_s;
    'exchanges: for _ in 0..PROGDIR_EXCHANGES {
        let d = h.call(&pp::progdir(start, pp::PROGDIR_CHUNK, i32::from(r#type)))?;
        let Some(last) = d.0.last().map(|e| e.number) else {
            break;
        };
        // A number past datano_e ends this answer's entries, not the
        // exchanges [fuzz, rdprogdir `s0Tvwwww`; rdprogdiro8 `s0Tvwwww`:
        // the next answer's entries are written].
        for e in d.0.iter().take(pp::PROGDIR_CHUNK as usize) {
            if e.number > datano_e || !text.push(e) {
                if text.full {
                    break 'exchanges;
                }
                break;
            }
        }
        // FANUC's library asks on from the last number answered + 1 (32
        // bits, wrapping: after 2147483647 from -2147483648), whatever the
        // number asked from, while that is not past datano_e [fuzz,
        // rdprogdiro8 `s0Tvwwww`, `s0Twwwwwmoreshort1`].
        start = last.wrapping_add(1);
        if start > datano_e {
            break;
        }
    }
    let b = text.finish();
    let n = b.len().min(length as usize);
    unsafe { std::ptr::copy_nonoverlapping(b.as_ptr(), out, n) };
    if text.full {
        return Err(Error::local(
            EW_LENGTH,
            "the directory does not fit in length bytes",
        ));
    }
    Ok(())
}

/// Up to `want` directory records from program `start` on, in exchanges
/// of 19 at most, as FANUC's library asks (cnc_rdprogdir2/3).
pub(crate) fn progdir_records(
    h: &handles::Handle,
    code: i32,
    mut start: i32,
    want: usize,
) -> crate::error::Result<Vec<pp::DirEntry>> {
    let mut got: Vec<pp::DirEntry> = Vec::new();
    while got.len() < want {
        let ask = (want - got.len()).min(pp::PROGDIR_CHUNK as usize);
        let d = h.call(&pp::progdir(start, ask as i32, code))?;
        let n = d.0.len().min(ask);
        got.extend_from_slice(&d.0[..n]);
        match d.0[..n].last() {
            Some(l) if n == ask && l.number >= start && l.number < i32::MAX => start = l.number + 1,
            _ => break,
        }
    }
    Ok(got)
}

/// Size of one PRGDIR3 record (l32).
const PRGDIR3_SIZE: usize = std::mem::size_of::<PRGDIR3>();

/// Reads up to `*num_prog` programs numbered `*top_prog` or more: `type` 0
/// the numbers, 1 also the comments, 2 also size and modification date
/// (`page` and `cdate` are never written). Out: `*num_prog` records read,
/// `*top_prog` the number of the first (when none was found, the number
/// the caller's first record held, as FANUC's library). Never writes more than `*num_prog` records. Type not
/// 0..2: EW_ATTRIB, `*num_prog` ≤ 0: EW_LENGTH, without traffic. Asks the
/// CNC for 19 programs per exchange at most, as FANUC's library.
///
/// # Safety
/// `top_prog` must point to 4 readable and writable bytes, `num_prog` to a
/// readable and writable short; `buf` must have `*num_prog` writable PRGDIR3.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdprogdir3(
    FlibHndl: c_ushort,
    r#type: c_short,
    top_prog: *mut c_long,
    num_prog: *mut c_short,
    buf: *mut PRGDIR3,
) -> c_short {
    ffi_boundary!("cnc_rdprogdir3", {
        let h = handles::get(FlibHndl)?;
        let top = nonnull(top_prog)?.cast::<i32>();
        let num = nonnull(num_prog)?;
        let out = nonnull(buf)?.cast::<u8>();
        let code =
            pp::progdir3_code(r#type).ok_or(Error::local(EW_ATTRIB, "type must be 0, 1 or 2"))?;
        let want = unsafe { num.read_unaligned() };
        if want <= 0 {
            return Err(Error::local(EW_LENGTH, "*num_prog must be at least 1"));
        }
        let got = progdir_records(&h, code, unsafe { top.read_unaligned() }, want as usize)?;
        for (i, e) in got.iter().enumerate() {
            let at = unsafe { out.add(i * PRGDIR3_SIZE) };
            unsafe {
                put(at.cast::<i32>(), e.number);
                if r#type >= 1 {
                    put(at.add(12).cast::<[u8; 52]>(), e.comment);
                }
                if r#type == 2 {
                    put(at.add(4).cast::<i32>(), e.length);
                    put(at.add(64).cast::<[u16; 6]>(), e.date);
                }
            }
        }
        unsafe {
            put(num, got.len() as c_short);
            // The first record's number, as FANUC's library takes it from
            // the caller's buffer: what the caller's first record held when
            // none was read.
            let first = got
                .first()
                .map_or_else(|| out.cast::<i32>().read_unaligned(), |f| f.number);
            put(top, first);
        }
        Ok(())
    })
}
