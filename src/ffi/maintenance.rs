//! Periodic maintenance: the maintenance items and the names they may take
//! (src/proto/maintenance.rs).

use super::{ffi_boundary, ffi_read, nonnull, put};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::EW_LENGTH;
use crate::proto::maintenance::{
    ITEM_LEN, ITEMS_MAX, NAME_LEN, NAMES_MAX, PmItem, RDPM_CNCITEM, RDPM_MCNITEM, ReadItems,
    ReadNames, WRITE_ITEMS_MAX, WRITE_NAMES_MAX, WriteItems, WriteNames,
};
use crate::types::IODBPMAINTE;
use std::os::raw::{c_char, c_short, c_ushort};

/// The count FANUC's library checks before any traffic: below 1 is
/// EW_LENGTH.
fn count(num: c_short) -> Result<c_short> {
    if num < 1 {
        return Err(Error::local(EW_LENGTH, "the number of items is below 1"));
    }
    Ok(num)
}

/// cnc_rdpm_cncitem / cnc_rdpm_mcnitem.
unsafe fn read_names(
    h: c_ushort,
    cmd: u16,
    start_num: c_short,
    data_num: *mut c_short,
    item: *mut [c_char; NAME_LEN],
) -> Result<()> {
    let h = handles::get(h)?;
    let num = nonnull(data_num)?;
    let out = nonnull(item)?.cast::<u8>();
    let want = count(unsafe { num.read_unaligned() })?;
    let names = h.call(&ReadNames {
        cmd,
        start: start_num,
        n: want.min(NAMES_MAX),
    })?;
    unsafe {
        // SAFETY: at most `*data_num` names of 62 bytes.
        for (i, n) in names.iter().enumerate() {
            std::ptr::copy_nonoverlapping(n.as_ptr(), out.add(i * NAME_LEN), NAME_LEN);
        }
        put(num, names.len() as c_short);
    }
    Ok(())
}

/// Reads the names of the CNC's maintenance items from the
/// `start_num`-th on: `*data_num` in is how many (at most 23 are asked),
/// out how many were written. `*data_num` < 1 is EW_LENGTH without
/// traffic. Never more names than asked are written (FANUC's library
/// writes every name the CNC sends).
///
/// # Safety
/// `data_num` must point to a writable short, `item` to `*data_num`
/// writable 62-byte names.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdpm_cncitem(
    FlibHndl: c_ushort,
    start_num: c_short,
    data_num: *mut c_short,
    item: *mut [c_char; 62],
) -> c_short {
    ffi_read!("cnc_rdpm_cncitem", {
        // SAFETY: the caller's pointers, as documented.
        unsafe { read_names(FlibHndl, RDPM_CNCITEM, start_num, data_num, item) }
    })
}

/// Reads the machine tool builder's maintenance item names from the
/// `start_num`-th on, as cnc_rdpm_cncitem.
///
/// # Safety
/// `data_num` must point to a writable short, `item` to `*data_num`
/// writable 62-byte names.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdpm_mcnitem(
    FlibHndl: c_ushort,
    start_num: c_short,
    data_num: *mut c_short,
    item: *mut [c_char; 62],
) -> c_short {
    ffi_read!("cnc_rdpm_mcnitem", {
        // SAFETY: the caller's pointers, as documented.
        unsafe { read_names(FlibHndl, RDPM_MCNITEM, start_num, data_num, item) }
    })
}

/// Writes `data_num` machine tool builder's item names from the
/// `start_num`-th on (at most 22 are sent). `data_num` < 1 is EW_LENGTH
/// without traffic.
///
/// # Safety
/// `item` must point to `data_num` readable 62-byte names.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrpm_mcnitem(
    FlibHndl: c_ushort,
    start_num: c_short,
    data_num: c_short,
    item: *mut [c_char; 62],
) -> c_short {
    ffi_boundary!("cnc_wrpm_mcnitem", {
        let h = handles::get(FlibHndl)?;
        let inp = nonnull(item)?;
        let n = count(data_num)?.min(WRITE_NAMES_MAX) as usize;
        // SAFETY: the caller's array holds `data_num` names.
        let names = (0..n)
            .map(|i| unsafe { inp.add(i).cast::<[u8; NAME_LEN]>().read_unaligned() })
            .collect();
        h.call(&WriteNames {
            start: start_num,
            names,
        })
    })
}

/// Reads maintenance items from the `start_num`-th on: `*data_num` in is
/// how many (at most 17 are asked), out how many were written. Each item's
/// name (62 bytes) and its four longs are written, the two bytes between
/// them are left as they were, as FANUC's library. `*data_num` < 1 is
/// EW_LENGTH without traffic.
///
/// # Safety
/// `data_num` must point to a writable short, `item` to `*data_num`
/// writable IODBPMAINTE.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdpm_item(
    FlibHndl: c_ushort,
    start_num: c_short,
    data_num: *mut c_short,
    item: *mut IODBPMAINTE,
) -> c_short {
    ffi_read!("cnc_rdpm_item", {
        let h = handles::get(FlibHndl)?;
        let num = nonnull(data_num)?;
        let out = nonnull(item)?.cast::<u8>();
        let want = count(unsafe { num.read_unaligned() })?;
        let items = h.call(&ReadItems {
            start: start_num,
            n: want.min(ITEMS_MAX),
        })?;
        unsafe {
            for (i, it) in items.iter().enumerate() {
                // SAFETY: item `i` < `*data_num` lies in the caller's array.
                let o = out.add(i * ITEM_LEN);
                std::ptr::copy_nonoverlapping(it.name.as_ptr(), o, NAME_LEN);
                for (k, v) in [it.r#type, it.total, it.remain, it.stat]
                    .into_iter()
                    .enumerate()
                {
                    put(o.add(64 + 4 * k).cast::<i32>(), v);
                }
            }
            put(num, items.len() as c_short);
        }
        Ok(())
    })
}

/// Writes `data_num` maintenance items from the `start_num`-th on (at most
/// 17 are sent): name, type, total and remain (stat is sent, the CNC keeps
/// its own). `reset` 1 starts each item's life anew. `data_num` < 1 is
/// EW_LENGTH without traffic.
///
/// # Safety
/// `item` must point to `data_num` readable IODBPMAINTE.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrpm_item(
    FlibHndl: c_ushort,
    reset: c_short,
    start_num: c_short,
    data_num: c_short,
    item: *mut IODBPMAINTE,
) -> c_short {
    ffi_boundary!("cnc_wrpm_item", {
        let h = handles::get(FlibHndl)?;
        let inp = nonnull(item)?.cast::<u8>();
        let n = count(data_num)?.min(WRITE_ITEMS_MAX) as usize;
        let items = (0..n)
            .map(|i| {
                // SAFETY: the caller's array holds `data_num` items.
                let b = unsafe { std::slice::from_raw_parts(inp.add(i * ITEM_LEN), ITEM_LEN) };
                let long = |o: usize| i32::from_ne_bytes([b[o], b[o + 1], b[o + 2], b[o + 3]]);
                let mut name = [0; NAME_LEN];
                name.copy_from_slice(&b[..NAME_LEN]);
                PmItem {
                    name,
                    r#type: long(64),
                    total: long(68),
                    remain: long(72),
                    stat: long(76),
                }
            })
            .collect();
        h.call(&WriteItems {
            reset,
            start: start_num,
            items,
        })
    })
}
