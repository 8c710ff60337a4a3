//! Alarms, alarm messages, operator messages and the alarm history.

// --- alarm history ---

use crate::proto::alarm::{AlmHisRecord, rdalmhisno, rdalmhistry};

/// Writes the checked history entries that fit in `length` (header `hdr`
/// bytes, `rec` bytes per record) and returns how many.
fn his_fit(
    length: std::os::raw::c_ushort,
    hdr: usize,
    rec: usize,
    have: usize,
) -> crate::error::Result<usize> {
    let length = usize::from(length);
    if length < hdr {
        return Err(crate::error::Error::length());
    }
    Ok(have.min((length - hdr) / rec))
}

fn his_call(
    h: &crate::client::handles::Handle,
    s_number: std::os::raw::c_ushort,
    e_number: std::os::raw::c_ushort,
) -> crate::error::Result<Vec<AlmHisRecord>> {
    if s_number > e_number {
        return Err(crate::error::Error::local(
            crate::ew::EW_NUMBER,
            "start number after end number",
        ));
    }
    Ok(h.call(&rdalmhistry(s_number, e_number))?.valid())
}

/// Reads the alarm history entries `s_number..=e_number` (1 = newest) into
/// ODBAHIS: year as year mod 100, the other time fields as bytes, as
/// FANUC's library writes them. `e_no` = `s_no` + entries written - 1.
/// Entries with an impossible time stamp are skipped; an entry whose message
/// length runs past its text ends the list; entries that do not fit in
/// `length` are not written.
///
/// # Safety
/// `alm_hst` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmhistry(
    FlibHndl: std::os::raw::c_ushort,
    s_number: std::os::raw::c_ushort,
    e_number: std::os::raw::c_ushort,
    length: std::os::raw::c_ushort,
    alm_hst: *mut crate::types::ODBAHIS,
) -> std::os::raw::c_short {
    use super::offset::put_at;
    super::ffi_boundary!("cnc_rdalmhistry", {
        let h = crate::client::handles::get(FlibHndl)?;
        let out = super::nonnull(alm_hst)?.cast::<u8>();
        let recs = his_call(&h, s_number, e_number)?;
        let n = his_fit(length, 6, 48, recs.len())?;
        unsafe {
            put_at(out, 0, s_number);
            put_at(out, 4, s_number.wrapping_add(n as u16).wrapping_sub(1));
            for (i, r) in recs[..n].iter().enumerate() {
                let o = 6 + 48 * i;
                put_at(out, o + 2, r.alm_grp);
                put_at(out, o + 4, r.alm_no as i16);
                put_at(out, o + 6, r.axis as u8);
                put_at(out, o + 7, r.year_his());
                put_at(out, o + 8, r.month as u8);
                put_at(out, o + 9, r.day as u8);
                put_at(out, o + 10, r.hour as u8);
                put_at(out, o + 11, r.minute as u8);
                put_at(out, o + 12, r.second as u8);
                put_at(out, o + 14, r.msg_len as i16);
                put_at(out, o + 16, r.msg);
            }
        }
        Ok(())
    })
}

/// Reads the alarm history into ODBAHIS2 (all fields shorts). The year is
/// FANUC's: the low byte of the year, sign-extended (2024 → -24). Entry
/// checks and `length` as cnc_rdalmhistry.
///
/// # Safety
/// `alm_hst` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmhistry2(
    FlibHndl: std::os::raw::c_ushort,
    s_number: std::os::raw::c_ushort,
    e_number: std::os::raw::c_ushort,
    length: std::os::raw::c_ushort,
    alm_hst: *mut crate::types::ODBAHIS2,
) -> std::os::raw::c_short {
    use super::offset::put_at;
    super::ffi_boundary!("cnc_rdalmhistry2", {
        let h = crate::client::handles::get(FlibHndl)?;
        let out = super::nonnull(alm_hst)?.cast::<u8>();
        let recs = his_call(&h, s_number, e_number)?;
        let n = his_fit(length, 4, 52, recs.len())?;
        unsafe {
            put_at(out, 0, s_number);
            put_at(out, 2, s_number.wrapping_add(n as u16).wrapping_sub(1));
            for (i, r) in recs[..n].iter().enumerate() {
                let o = 4 + 52 * i;
                put_at(out, o, r.alm_grp);
                put_at(out, o + 2, r.alm_no as i16);
                put_at(out, o + 4, r.axis as i16);
                put_at(out, o + 6, r.year_his2());
                put_at(out, o + 8, r.month as i16);
                put_at(out, o + 10, r.day as i16);
                put_at(out, o + 12, r.hour as i16);
                put_at(out, o + 14, r.minute as i16);
                put_at(out, o + 16, r.second as i16);
                put_at(out, o + 18, r.msg_len as i16);
                put_at(out, o + 20, r.msg);
            }
        }
        Ok(())
    })
}

/// Reads the number of alarm history entries. A negative count from the
/// CNC reads as 0 (an empty history).
///
/// # Safety
/// `hisno` must point to a writable unsigned short.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdalmhisno(
    FlibHndl: std::os::raw::c_ushort,
    hisno: *mut std::os::raw::c_ushort,
) -> std::os::raw::c_short {
    super::ffi_boundary!("cnc_rdalmhisno", {
        let h = crate::client::handles::get(FlibHndl)?;
        let out = super::nonnull(hisno)?;
        let c = h.call(&rdalmhisno())?;
        unsafe { super::put(out, c.value.max(0) as u16) };
        Ok(())
    })
}
