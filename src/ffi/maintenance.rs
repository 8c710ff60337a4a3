//! Periodic maintenance: writing the maintenance items and the names they
//! may take (src/proto/maintenance.rs). The reads are described as data
//! (src/spec/table/maintenance.rs).

use super::{ffi_boundary, nonnull};
use crate::client::handles;
use crate::error::{Error, Result};
use crate::ew::EW_LENGTH;
use crate::proto::maintenance::{
    ITEM_LEN, NAME_LEN, PmItem, WRITE_ITEMS_MAX, WRITE_NAMES_MAX, WriteItems, WriteNames,
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
