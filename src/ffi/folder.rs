//! Program data folders of the 30i ("//CNC_MEM/USER/PATH1/O1234"): each
//! function is one request (learnt from FANUC's library with the oracle):
//! the command, a number word, the strings as NUL-padded fields of fixed
//! size (a longer string cut to the field, as FANUC's library cuts it).

use super::{ffi_boundary, nonnull, put};
use crate::client::handles;
use crate::error::Result;
use crate::proto::call::Single;
use crate::proto::packet::ReqSub;
use crate::proto::program::{self as pp, PathName};
use crate::proto::wire::{Reader, Wire};
use crate::types::{IDBPDFADIR, IDBPDFSDIR, ODBPDFADIR, ODBPDFSDIR};
use std::os::raw::{c_char, c_long, c_short, c_ulong, c_ushort};

/// Sends folder command `cmd` with `words` and the strings, each as a field
/// of its size; the answer's bytes.
///
/// # Safety
/// Each string pointer is NULL (EW_NULL... as `nonnull`) or readable up to
/// its NUL or its field size.
unsafe fn pdf(
    h: c_ushort,
    cmd: u16,
    words: &[i32],
    strs: &[(*const c_char, usize)],
) -> Result<Vec<u8>> {
    unsafe { pdf_with(h, cmd, words, strs, &[]) }
}

/// [`pdf`] with bytes after the strings.
unsafe fn pdf_with(
    h: c_ushort,
    cmd: u16,
    words: &[i32],
    strs: &[(*const c_char, usize)],
    tail: &[u8],
) -> Result<Vec<u8>> {
    let h = handles::get(h)?;
    let mut payload = Vec::new();
    for &(p, n) in strs {
        let p = nonnull(p.cast_mut())?;
        let mut field = vec![0u8; n];
        for (i, b) in field.iter_mut().enumerate() {
            match unsafe { p.add(i).read() } {
                0 => break,
                c => *b = c as u8,
            }
        }
        payload.extend(field);
    }
    payload.extend_from_slice(tail);
    let mut sub = ReqSub::cnc(cmd, words);
    if !payload.is_empty() {
        sub = sub.with_payload(payload);
    }
    Ok(h.call(&Single::<PathName>::new(sub))?.0)
}

/// The first `n` big-endian words of an answer; missing bytes read as
/// zeros with `zeros` (as FANUC's library reads them), else EW_PROTOCOL.
fn words(b: &[u8], n: usize, zeros: bool) -> Result<Vec<i32>> {
    let mut b = b.to_vec();
    if zeros {
        b.resize(b.len().max(4 * n), 0);
    }
    let mut r = Reader::new(&b);
    Ok((0..n)
        .map(|_| i32::decode(&mut r))
        .collect::<std::result::Result<_, _>>()?)
}

/// Reads the execution pointer: the program's path name (the answer's
/// bytes after the block, at most 256) and its block.
///
/// # Safety
/// `path` must have 256 writable bytes, `block` 4 writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_pdf_rdactpt(
    FlibHndl: c_ushort,
    path: *mut c_char,
    block: *mut c_long,
) -> c_short {
    ffi_boundary!("cnc_pdf_rdactpt", {
        let (out, blk) = (nonnull(path)?, nonnull(block)?);
        let b = unsafe { pdf(FlibHndl, pp::PDF_RDACTPT, &[], &[]) }?;
        let v = words(&b, 1, true)?;
        // The name as answered (at most 256 bytes), 256 zeros for an answer
        // without one, as FANUC's library writes it.
        let name = b
            .get(4..)
            .map_or(&[0u8; 256][..], |n| &n[..n.len().min(256)]);
        unsafe {
            put(blk.cast::<i32>(), v[0]);
            std::ptr::copy_nonoverlapping(name.as_ptr(), out.cast::<u8>(), name.len());
        }
        Ok(())
    })
}

/// Sets the execution pointer to block `*block` of a program (the name
/// goes with its NUL, as FANUC's library sends it); `*block` is then the
/// block the CNC answers (0 for an empty answer).
///
/// # Safety
/// `path` readable up to its NUL, `block` 4 readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_pdf_wractpt(
    FlibHndl: c_ushort,
    path: *mut c_char,
    r#type: c_short,
    block: *mut c_long,
) -> c_short {
    ffi_boundary!("cnc_pdf_wractpt", {
        let b = unsafe { nonnull(block)?.cast::<i32>().read_unaligned() };
        let n = unsafe { std::ffi::CStr::from_ptr(nonnull(path)?) }
            .to_bytes()
            .len()
            .min(255)
            + 1;
        let a = unsafe { pdf(FlibHndl, pp::PDF_WRACTPT, &[r#type.into(), b], &[(path, n)]) }?;
        unsafe { put(block.cast::<i32>(), words(&a, 1, true)?[0]) };
        Ok(())
    })
}

/// Reads `*line_len` lines of a program from line `line_no` into `data`:
/// the answer up to its first '%' or NUL (included), at most `*data_len`
/// bytes; out: the
/// bytes and the whole lines read (line ends and the '%'), as FANUC's
/// library counts them.
///
/// # Safety
/// `line_len` and `data_len` must point to 4 readable and writable bytes
/// each; `data` must have `*data_len` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdpdf_line(
    FlibHndl: c_ushort,
    path: *mut c_char,
    line_no: c_ulong,
    data: *mut c_char,
    line_len: *mut c_ulong,
    data_len: *mut c_ulong,
) -> c_short {
    ffi_boundary!("cnc_rdpdf_line", {
        let (out, ll, dl) = (
            nonnull(data)?.cast::<u8>(),
            nonnull(line_len)?.cast::<u32>(),
            nonnull(data_len)?.cast::<u32>(),
        );
        let lines = unsafe { ll.read_unaligned() };
        let b = unsafe {
            pdf(
                FlibHndl,
                pp::PDF_RDLINE,
                &[line_no as i32, lines as i32],
                &[(path, 256)],
            )
        }?;
        // Up to the first '%' (the end of the program) or NUL, that byte
        // included, at most `*data_len` bytes; the lines read are its line
        // ends and that '%'.
        let end = (b.iter().position(|&c| c == b'%' || c == 0)).map_or(b.len(), |i| i + 1);
        let n = end.min(unsafe { dl.read_unaligned() } as usize);
        let read = b[..n].iter().filter(|&&c| c == b'\n' || c == b'%').count();
        unsafe {
            std::ptr::copy_nonoverlapping(b.as_ptr(), out, n);
            put(dl, n as u32);
            put(ll, read as u32);
        }
        Ok(())
    })
}

/// Writes `len` bytes of lines into a program after line `line_no`.
/// `len` of 2^31 or more: EW_LENGTH without traffic (FANUC's library
/// aborts); so is one whose request would not fit in a frame (a frame's
/// body is at most 65535 bytes, the 256-byte path included).
///
/// # Safety
/// `path` readable up to its NUL or 256 bytes; `data` `len` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrpdf_line(
    FlibHndl: c_ushort,
    path: *mut c_char,
    line_no: c_ulong,
    data: *mut c_char,
    len: c_ulong,
) -> c_short {
    ffi_boundary!("cnc_wrpdf_line", {
        let n = usize::try_from(len as u32)
            .ok()
            .filter(|n| *n <= u16::MAX as usize - 2 - 28 - 256);
        let n = n.ok_or(crate::error::Error::local(
            crate::ew::EW_LENGTH,
            "len too large",
        ))?;
        unsafe {
            pdf(
                FlibHndl,
                pp::PDF_WRLINE,
                &[line_no as i32],
                &[(path, 256), (data, n)],
            )
        }
        .map(drop)
    })
}

/// Sends a directory read (cmd, words, the 212-byte path field as a
/// 256-byte one) and gives the answer's whole `size`-byte records, at most
/// `*num` of them; `*num` ≤ 0: EW_LENGTH without traffic.
unsafe fn dir_records(
    h: c_ushort,
    cmd: u16,
    num: *mut c_short,
    path: &[c_char; 212],
    words: &[i32],
    size: usize,
) -> Result<Vec<Vec<u8>>> {
    let want = unsafe { nonnull(num)?.read_unaligned() };
    if want <= 0 {
        return Err(crate::error::Error::local(
            crate::ew::EW_LENGTH,
            "*num must be at least 1",
        ));
    }
    let mut field: Vec<u8> = path
        .iter()
        .map(|&c| c as u8)
        .take_while(|&c| c != 0)
        .collect();
    field.resize(256, 0);
    let b = unsafe { pdf_with(h, cmd, words, &[], &field) }?;
    let recs: Vec<Vec<u8>> = b
        .chunks_exact(size)
        .take(want as usize)
        .map(<[u8]>::to_vec)
        .collect();
    unsafe { put(num, recs.len() as c_short) };
    Ok(recs)
}

/// Reads up to `*num` sub-folders of `in->path` from entry `in->req_num`
/// (at most 72 asked per call, as FANUC's library asks); `*num` = read
/// (none: the first `sub_exist` is set to 0, as FANUC's library does).
///
/// # Safety
/// `num` must point to a readable and writable short, `inp` to a readable
/// IDBPDFSDIR, `out` to `*num` writable ODBPDFSDIR.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdpdf_subdir(
    FlibHndl: c_ushort,
    num: *mut c_short,
    inp: *mut IDBPDFSDIR,
    out: *mut ODBPDFSDIR,
) -> c_short {
    ffi_boundary!("cnc_rdpdf_subdir", {
        let (i, o) = (
            unsafe { nonnull(inp)?.read_unaligned() },
            nonnull(out)?.cast::<u8>(),
        );
        let n = unsafe { nonnull(num)?.read_unaligned() }.min(72);
        let w = [i.req_num.into(), n.into()];
        let recs = unsafe { dir_records(FlibHndl, pp::PDF_SUBDIR, num, &i.path, &w, 40) }?;
        if recs.is_empty() {
            // FANUC's library writes the first sub_exist (0) whatever came.
            unsafe { put(o.cast::<i16>(), 0) };
        }
        for (k, r) in recs.iter().enumerate() {
            let at = unsafe { o.add(k * std::mem::size_of::<ODBPDFSDIR>()) };
            unsafe {
                put(
                    at.cast::<i16>(),
                    i32::from_be_bytes(r[..4].try_into().expect("4")) as i16,
                );
                put(
                    at.add(4).cast::<[u8; 36]>(),
                    r[4..40].try_into().expect("36"),
                );
            }
        }
        Ok(())
    })
}

/// Reads up to `*num` folders and programs of `in->path` from entry
/// `in->req_num` (at most 20 asked per call, as FANUC's library asks):
/// 128-byte records: kind and date (7 shorts), 6 bytes not read, size,
/// attribute, then name, comment and machining time stamp as they are
/// (`dummy`, `dummy2` not written); `*num` = read.
///
/// # Safety
/// `num` must point to a readable and writable short, `inp` to a readable
/// IDBPDFADIR, `out` to `*num` writable ODBPDFADIR.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdpdf_alldir(
    FlibHndl: c_ushort,
    num: *mut c_short,
    inp: *mut IDBPDFADIR,
    out: *mut ODBPDFADIR,
) -> c_short {
    ffi_boundary!("cnc_rdpdf_alldir", {
        let (i, o) = (
            unsafe { nonnull(inp)?.read_unaligned() },
            nonnull(out)?.cast::<u8>(),
        );
        let n = unsafe { nonnull(num)?.read_unaligned() }.min(20);
        let w = [
            i.req_num.into(),
            n.into(),
            i.r#type.into(),
            i.size_kind.into(),
        ];
        for (k, r) in unsafe { dir_records(FlibHndl, pp::PDF_ALLDIR, num, &i.path, &w, 128) }?
            .iter()
            .enumerate()
        {
            let at = unsafe { o.add(k * std::mem::size_of::<ODBPDFADIR>()) };
            let be16 = |x: usize| i16::from_be_bytes([r[x], r[x + 1]]);
            let be32 = |x: usize| i32::from_be_bytes(r[x..x + 4].try_into().expect("4"));
            unsafe {
                for f in 0..7 {
                    put(at.add(2 * f).cast::<i16>(), be16(2 * f));
                }
                put(at.add(20).cast::<i32>(), be32(20));
                put(at.add(24).cast::<i32>(), be32(24));
                std::ptr::copy_nonoverlapping(r[28..].as_ptr(), at.add(28), 100);
            }
        }
        Ok(())
    })
}
