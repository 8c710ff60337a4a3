//! Tool numbers, tool life and counters.
//!
//! Recorded from FANUC's library against a fake CNC (src/proto/tool.rs);
//! outputs written field by field at their l32 offsets, only on success.

use super::{ffi_boundary, len_of, nonnull, put_at};
use crate::client::handles;
use crate::error::Error;
use crate::ew::EW_FUNC;
use crate::proto::tool::{tlctl as tlctl_call, tlgroup, tlinsert, tltools};
use crate::types::{IDBITD, IODBTLCTL, ODBTG};
use std::os::raw::{c_short, c_ushort};

/// Reads a tool life group with its tools: number of tools, life, counter,
/// then per tool its use number (1, 2, ...), tool number, length and radius
/// offset numbers and information. `length` must hold the 20-byte head
/// (else the code EW_LENGTH before any traffic) and every tool the CNC sent (else
/// the code EW_LENGTH with nothing written, as FANUC's library).
///
/// # Safety
/// `toolgrp` must point to `length` writable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdtoolgrp(
    FlibHndl: c_ushort,
    number: c_short,
    length: c_short,
    toolgrp: *mut ODBTG,
) -> c_short {
    ffi_boundary!("cnc_rdtoolgrp", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(toolgrp)?.cast::<u8>();
        let room = len_of(length);
        if room < 20 {
            return Err(Error::length());
        }
        let g = h.call(&tlgroup(number))?;
        let t = h.call(&tltools(g.grp, g.ntool.value))?;
        if 20 + 20 * t.tools.len() > room {
            return Err(Error::length());
        }
        unsafe {
            put_at(out, 0, g.grp as c_short);
            put_at(out, 8, g.ntool.value);
            put_at(out, 12, g.life.value);
            put_at(out, 16, g.count.value);
            for (i, x) in t.tools.iter().enumerate() {
                let o = 20 + 20 * i;
                put_at(out, o, i as i32 + 1);
                put_at(out, o + 4, x.tool_num);
                put_at(out, o + 8, x.length_num);
                put_at(out, o + 12, x.radius_num);
                put_at(out, o + 16, x.tinfo);
            }
        }
        Ok(())
    })
}

/// Reads the tool control data of a punch press (or laser). Other machines
/// get the code EW_FUNC without any traffic, as from FANUC's library.
///
/// # Safety
/// `tlctl` must point to a writable IODBTLCTL.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdtlctldata(FlibHndl: c_ushort, tlctl: *mut IODBTLCTL) -> c_short {
    ffi_boundary!("cnc_rdtlctldata", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(tlctl)?.cast::<u8>();
        let mt = h.sysinfo().map(|s| s.mt_type);
        if !matches!(mt, Some([b' ', b'P' | b'L'])) {
            return Err(Error::local(EW_FUNC, "not a punch press"));
        }
        let c = h.call(&tlctl_call())?;
        unsafe {
            put_at(out, 0, c.slct as i16);
            put_at(out, 2, c.used_tool as i16);
            put_at(out, 4, c.turret_indx as i16);
            put_at(out, 8, c.zero_tl_no);
            put_at(out, 12, c.t_axis_move);
            put_at(out, 16, c.total_punch0);
            put_at(out, 20, c.total_punch1);
            put_at(out, 24, c.t_axis_dec as u8);
        }
        Ok(())
    })
}

/// Inserts tool number `data` into tool life group `datano` as its
/// `type`-th tool (the later tools move down).
///
/// # Safety
/// `tool` must point to a readable IDBITD.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_instlifedt(FlibHndl: c_ushort, tool: *mut IDBITD) -> c_short {
    ffi_boundary!("cnc_instlifedt", {
        let h = handles::get(FlibHndl)?;
        let t = unsafe { nonnull(tool)?.read_unaligned() };
        h.call(&tlinsert(t.datano, t.r#type, t.data))?;
        Ok(())
    })
}
