//! PMC areas.

use super::{ffi_boundary, ffi_read, nonnull, put};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::{EW_ATTRIB, EW_DATA, EW_LENGTH, EW_NUMBER};
use crate::proto::pmc::{ALMMSG_LEN, ALMMSG_MAX, AlarmMsgs};
use crate::proto::pmc::{
    PMCINFO_MAX, PmcRange, ReadPmc, SelectUnit, UnitTypes, WritePmc, elem_size, rdpmcinfo,
    swap_elements,
};
use crate::types::{IODBPMC, ODBPMCALM, ODBPMCERR, ODBPMCINF, ODBPMCINF_info};
use std::os::raw::c_char;
use std::os::raw::{c_long, c_short, c_ushort};
use std::ptr::addr_of_mut;

/// Bytes of IODBPMC before the data.
const HEAD: usize = 8;

/// Data bytes a buffer of `length` bytes holds.
fn room(length: c_ushort) -> Result<usize> {
    (length as usize).checked_sub(HEAD).ok_or(Error::local(
        EW_LENGTH,
        "length is smaller than the IODBPMC header",
    ))
}

/// Reads PMC addresses `s_number`..`e_number` (byte addresses) of area
/// `adr_type` (0 G, 1 F, 2 Y, 3 X, 4 A, 5 R, 6 T, 7 K, 8 C, 9 D, ...) as
/// `data_type` elements (0 byte, 1 word, 2 long (4 bytes), 4 float,
/// 5 double) into `buf->u`. `length` is the buffer's size: `8 +` the data
/// bytes. The header is set from the arguments; no more data than the range
/// spans and the buffer holds is written (FANUC's library copies the whole
/// reply).
///
/// # Safety
/// `buf` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pmc_rdpmcrng(
    FlibHndl: c_ushort,
    adr_type: c_short,
    data_type: c_short,
    s_number: c_ushort,
    e_number: c_ushort,
    length: c_ushort,
    buf: *mut IODBPMC,
) -> c_short {
    ffi_read!("pmc_rdpmcrng", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(buf)?;
        // FANUC's library checks before any traffic: the data type, the
        // order of the numbers, then that `length` holds the header and
        // every address of the range (one byte each).
        if elem_size(data_type).is_none() {
            return Err(Error::local(EW_ATTRIB, "unknown PMC data type"));
        }
        if e_number < s_number {
            return Err(Error::local(EW_NUMBER, "end address below start address"));
        }
        let range = PmcRange {
            adr_type,
            data_type,
            s: s_number,
            e: e_number,
        };
        if (length as usize) < HEAD + range.span() {
            return Err(Error::local(EW_LENGTH, "length does not hold the range"));
        }
        let room = room(length)?;
        let mut data = h.call_pmc(&ReadPmc(range))?;
        let size = elem_size(data_type).unwrap_or(1);
        let n = data.len().min(range.span()).min(room) / size * size;
        data.truncate(n);
        swap_elements(data_type, &mut data);
        unsafe {
            put(addr_of_mut!((*out).type_a), adr_type);
            put(addr_of_mut!((*out).type_d), data_type);
            put(addr_of_mut!((*out).datano_s), s_number as c_short);
            put(addr_of_mut!((*out).datano_e), e_number as c_short);
            let dst = addr_of_mut!((*out).u).cast::<u8>();
            std::ptr::copy_nonoverlapping(data.as_ptr(), dst, n);
        }
        Ok(())
    })
}

/// Writes PMC addresses `buf->datano_s`..`buf->datano_e` of area
/// `buf->type_a` from `buf->u`, as `buf->type_d` elements (see
/// pmc_rdpmcrng). Sends exactly the bytes the range spans; `length` must
/// cover them (`8 +` bytes), else EW_LENGTH without traffic.
///
/// # Safety
/// `buf` must point to `length` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pmc_wrpmcrng(
    FlibHndl: c_ushort,
    length: c_ushort,
    buf: *mut IODBPMC,
) -> c_short {
    ffi_boundary!("pmc_wrpmcrng", {
        let h = handles::get(FlibHndl)?;
        let inp = nonnull(buf)?;
        let room = room(length)?;
        let (range, data) = unsafe {
            let range = PmcRange {
                adr_type: addr_of_mut!((*inp).type_a).read_unaligned(),
                data_type: addr_of_mut!((*inp).type_d).read_unaligned(),
                s: addr_of_mut!((*inp).datano_s).read_unaligned() as u16,
                e: addr_of_mut!((*inp).datano_e).read_unaligned() as u16,
            };
            let n = range.span();
            if n > room {
                return Err(Error::local(EW_LENGTH, "length does not cover the range"));
            }
            let src = addr_of_mut!((*inp).u).cast::<u8>();
            (range, std::slice::from_raw_parts(src, n).to_vec())
        };
        let mut data = data;
        swap_elements(range.data_type, &mut data);
        h.call_pmc(&WritePmc { range, data })
    })
}

/// The detail of the last PMC error on this handle (pmc_* functions only;
/// cnc_getdtailerr keeps the CNC's).
///
/// # Safety
/// `err` must point to a writable ODBPMCERR.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pmc_getdtailerr(FlibHndl: c_ushort, err: *mut ODBPMCERR) -> c_short {
    ffi_read!("pmc_getdtailerr", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(err)?;
        let (err_no, err_dtno) = h.state.lock().pmc_detail;
        unsafe { put(out, ODBPMCERR { err_no, err_dtno }) };
        Ok(())
    })
}

/// Reads the PMC's address areas (letter, attribute, first and last
/// address). At most 64 areas, and no more than the reply holds, are
/// written (FANUC's library trusts the reply's count and can read past its
/// buffer). `datano` is the reply's count (low 16 bits, as FANUC's library
/// writes it, a negative count included) whenever that many records were
/// written; when the count is larger than what was written (more than 64
/// areas, or fewer records than the count), `datano` is the number of
/// records written, so it never points past the data.
///
/// # Safety
/// `buf` must point to a writable ODBPMCINF.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pmc_rdpmcinfo(
    FlibHndl: c_ushort,
    adr_type: c_short,
    buf: *mut ODBPMCINF,
) -> c_short {
    ffi_read!("pmc_rdpmcinfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(buf)?;
        let info = h.call_pmc(&rdpmcinfo(adr_type))?;
        let n = info.areas.len().min(PMCINFO_MAX);
        let count = info.count as c_short;
        let datano = if i32::from(count) <= n as i32 {
            count
        } else {
            n as c_short
        };
        unsafe {
            put(addr_of_mut!((*out).datano), datano);
            let dst = addr_of_mut!((*out).info).cast::<ODBPMCINF_info>();
            for (i, a) in info.areas[..n].iter().enumerate() {
                let rec = ODBPMCINF_info {
                    pmc_adr: a.adr as u8 as c_char,
                    adr_attr: a.attr as u8 as c_char,
                    top_num: a.top as c_ushort,
                    last_num: a.last as c_ushort,
                };
                put(dst.add(i), rec);
            }
        }
        Ok(())
    })
}

// ---------------------------------------------------------------------------
// PMC units: after pmc_select_pmc_unit the handle's PMC requests address the
// selected unit (their path word), as FANUC's library sends them.
// ---------------------------------------------------------------------------

/// Selects the PMC unit of type `unittype` for this handle's later PMC calls
/// (the CNC is asked first; on its refusal the selection stays).
#[unsafe(no_mangle)]
pub extern "C" fn pmc_select_pmc_unit(FlibHndl: c_ushort, unittype: c_long) -> c_short {
    ffi_boundary!("pmc_select_pmc_unit", {
        let h = handles::get(FlibHndl)?;
        let unit = unittype as i32;
        h.call_pmc(&SelectUnit { unit })?;
        h.state.lock().pmc_unit = unit as u16;
        Ok(())
    })
}

/// Reads the types of the CNC's PMC units: `*count` in is the room in
/// `unittypes` (4 bytes per `long`), out the number written; an answer
/// with none leaves `*count` as it was, as FANUC's library does.
///
/// # Safety
/// `count` must point to 4 readable and writable bytes, `unittypes` to
/// `*count` writable 4-byte elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pmc_get_pmc_unit_types(
    FlibHndl: c_ushort,
    unittypes: *mut c_long,
    count: *mut c_long,
) -> c_short {
    ffi_boundary!("pmc_get_pmc_unit_types", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(unittypes)?.cast::<i32>();
        let count = nonnull(count)?.cast::<i32>();
        let room = unsafe { count.read_unaligned() };
        let types = h.call_pmc(&UnitTypes { most: room })?;
        let n = types.len().min(room.max(0) as usize);
        unsafe {
            for (i, t) in types.iter().take(n).enumerate() {
                put(out.add(i), *t);
            }
            if n > 0 {
                put(count, n as i32);
            }
        }
        Ok(())
    })
}

/// Reads the PMC's alarm messages from the `s_number`-th on: `*read_num`
/// in is how many (`pmcalm` holds that many ODBPMCALM), out how many were
/// written; `*exist` is -1 (no alarm), 0 (all read) or 1 (more alarms
/// after these). FANUC's library asks for at most 11 per exchange and asks
/// again from where the answer ended while the CNC says more exist and
/// fewer than `*read_num` were read. `s_number` < 1 is EW_NUMBER,
/// `*read_num` < 1 EW_DATA, before any traffic; a CNC error sets
/// `*read_num` to 0. Never more messages than `*read_num` are written
/// (FANUC's library writes all an answer announces).
///
/// # Safety
/// `read_num` and `exist` must point to writable shorts, `pmcalm` to
/// `*read_num` writable ODBPMCALM.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn pmc_rdalmmsg(
    FlibHndl: c_ushort,
    s_number: c_short,
    read_num: *mut c_short,
    exist: *mut c_short,
    pmcalm: *mut ODBPMCALM,
) -> c_short {
    ffi_boundary!("pmc_rdalmmsg", {
        let h = handles::get(FlibHndl)?;
        let num = nonnull(read_num)?;
        let exist = nonnull(exist)?;
        let out = nonnull(pmcalm)?.cast::<u8>();
        if s_number < 1 {
            return Err(Error::local(EW_NUMBER, "s_number below 1"));
        }
        let want = i32::from(unsafe { num.read_unaligned() });
        if want < 1 {
            return Err(Error::local(EW_DATA, "read_num below 1"));
        }
        let (mut text, mut total) = (Vec::new(), 0i32);
        let mut more;
        loop {
            let ask = AlarmMsgs {
                s: i32::from(s_number) + total,
                n: (want - total).min(ALMMSG_MAX),
            };
            let a = match h.call_pmc(&ask) {
                Ok(a) => a,
                Err(e) => {
                    unsafe { put(num, 0) };
                    return Err(e);
                }
            };
            let k = a.records() as i32;
            text.extend_from_slice(&a.text);
            // FANUC's library keeps the exist word's low 16 bits, and ends
            // on those [fuzz seed 0x202e1129: exist 0x80000000 ends it].
            (total, more) = (total + k, a.exist as i16);
            if more == 0 || more == -1 || k == 0 || total >= want {
                break;
            }
        }
        unsafe {
            // SAFETY: `total` ≤ `*read_num` messages of 128 bytes.
            std::ptr::copy_nonoverlapping(text.as_ptr(), out, total as usize * ALMMSG_LEN);
            put(num, total as c_short);
            put(exist, more);
        }
        Ok(())
    })
}
