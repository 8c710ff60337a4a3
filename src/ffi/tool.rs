//! Tool numbers, tool life and counters.
//!
//! Recorded from FANUC's library against a fake CNC (src/proto/tool.rs);
//! outputs written field by field at their l32 offsets, only on success.

use super::{element, ffi_boundary, len_of, nonnull, put, put_at, put_member};
use crate::client::handles;
use crate::error::Error;
use crate::ew::{EW_FUNC, EW_NUMBER};
use crate::proto::tool::wrgrpinfo as wrgrpinfo_call;
use crate::proto::tool::{GROUPS_PER_WRITE, GroupWrite, MNG_WORDS, OptGroups, RdTool, usegrp};
use crate::proto::tool::{PunchData, PunchInfo};
use crate::proto::tool::{tlctl as tlctl_call, tlgroup, tlinsert, tltools};
use crate::types::{
    IDBITD, IODBTGI, IODBTGI_DATA, IODBTLCTL, IODBTLDT, IODBTLMNG, ODBPTLINF, ODBTG, ODBTG_DATA,
    ODBUSEGRP,
};
use std::mem::offset_of;
use std::os::raw::{c_char, c_short, c_ushort};

/// Reads a tool life group with its tools: number of tools, life, counter,
/// then per tool its use number (1, 2, ...), tool number, length and radius
/// offset numbers and information. A group answered without tools (its
/// number of tools 0 or less) gets the head only, and an answer under 4
/// bytes or of group 0 `grp_num` 0 only, both `EW_OK` without asking for tools, as from
/// FANUC's library; a record cut short reads its missing words as 0.
/// `length` must hold the 20-byte head
/// (else the code EW_LENGTH before any traffic) and every tool the CNC sent (else
/// the code EW_LENGTH). The head is written once the group is answered, before
/// the tools are asked for: an error answered for the tools (or EW_LENGTH)
/// leaves it written, as FANUC's library does.
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
        if room < offset_of!(ODBTG, data) {
            return Err(Error::length());
        }
        let Some(g) = h.call(&tlgroup(number))? else {
            // An answer under 4 bytes or of group 0: grp_num 0 and
            // nothing else, as FANUC's library writes.
            unsafe { put_at(out, 0, 0 as c_short) };
            return Ok(());
        };
        // The head, written before the tools are asked for (FANUC's
        // library leaves it written when that exchange or the length
        // check fails).
        unsafe {
            put_member!(out, ODBTG, grp_num, g.grp as c_short);
            put_member!(out, ODBTG, ntool, g.ntool.value);
            put_member!(out, ODBTG, life, g.life.value);
            put_member!(out, ODBTG, count, g.count.value);
        }
        if g.ntool.value <= 0 {
            // No tools: the head only, and no second exchange.
            return Ok(());
        }
        // The group asked for is the head's `grp_num` (the answer's low 16
        // bits) sign-extended [fuzz, seed 0x20271128 `s0L`: group word
        // 0x7fffffff asks 0x004d for group -1].
        let t = h.call(&tltools(i32::from(g.grp as c_short), g.ntool.value))?;
        if offset_of!(ODBTG, data) + size_of::<ODBTG_DATA>() * t.tools.len() > room {
            return Err(Error::length());
        }
        unsafe {
            for (i, x) in t.tools.iter().enumerate() {
                let o = element!(out, ODBTG, data[i]);
                put_member!(o, ODBTG_DATA, tuse_num, i as i32 + 1);
                put_member!(o, ODBTG_DATA, tool_num, x.tool_num);
                put_member!(o, ODBTG_DATA, length_num, x.length_num);
                put_member!(o, ODBTG_DATA, radius_num, x.radius_num);
                put_member!(o, ODBTG_DATA, tinfo, x.tinfo);
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
            put_member!(out, IODBTLCTL, slct, c.slct as i16);
            put_member!(out, IODBTLCTL, used_tool, c.used_tool as i16);
            put_member!(out, IODBTLCTL, turret_indx, c.turret_indx as i16);
            put_member!(out, IODBTLCTL, zero_tl_no, c.zero_tl_no);
            put_member!(out, IODBTLCTL, t_axis_move, c.t_axis_move);
            put_member!(out, IODBTLCTL, total_punch[0], c.total_punch0);
            put_member!(out, IODBTLCTL, total_punch[1], c.total_punch1);
            put_member!(out, IODBTLCTL, t_axis_dec, c.t_axis_dec as c_char);
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

/// Writes tool life groups `s_grp..=e_grp` from `grpinfo` (life, counter
/// and counter type; `n_tool` is not sent). `e_grp` below `s_grp`:
/// EW_NUMBER; `length` (bytes) below 8 + 16 per group: EW_LENGTH; both
/// without traffic, as FANUC's library.
///
/// # Safety
/// `grpinfo` must point to a readable IODBTGI with `e_grp - s_grp + 1`
/// groups.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_wrgrpinfo(
    FlibHndl: c_ushort,
    length: c_short,
    grpinfo: *mut IODBTGI,
) -> c_short {
    ffi_boundary!("cnc_wrgrpinfo", {
        let h = handles::get(FlibHndl)?;
        let p = nonnull(grpinfo)?.cast::<u8>();
        let (s, e) = unsafe { (get_at::<i16>(p, 0), get_at::<i16>(p, 4)) };
        if e < s {
            return Err(Error::local(EW_NUMBER, "e_grp below s_grp"));
        }
        let n = (i32::from(e) - i32::from(s) + 1) as usize;
        if offset_of!(IODBTGI, data) + size_of::<IODBTGI_DATA>() * n > len_of(length) {
            return Err(Error::length());
        }
        let groups: Vec<GroupWrite> = (0..n.min(GROUPS_PER_WRITE as usize))
            .map(|i| {
                let o = 8 + 16 * i;
                // SAFETY: the caller's `length` covers these groups.
                let g = |k: usize| unsafe { get_at::<i32>(p, o + k) };
                GroupWrite {
                    life: g(4),
                    count_type: g(12),
                    count: g(8),
                    w3: -1,
                    w4: -1,
                }
            })
            .collect();
        h.call(&wrgrpinfo_call(s, e, &groups))?;
        Ok(())
    })
}

/// Reads the next, in-use and selected tool life groups, then their
/// optional group numbers in a second exchange (the 30i class asks for
/// each group above 0 when the next group is above 0, the 16i class
/// reads the three group records, Series 15 asks nothing; a group not
/// asked, 0, answered with an error or after such a one reads -1). An
/// error answered for a
/// group is returned after all six numbers are written, as FANUC's
/// library does.
///
/// # Safety
/// `grp` must point to a writable ODBUSEGRP.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdtlusegrp(FlibHndl: c_ushort, grp: *mut ODBUSEGRP) -> c_short {
    ffi_boundary!("cnc_rdtlusegrp", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(grp)?.cast::<u8>();
        let u = h.call(&usegrp())?;
        let groups = OptGroups([u.next, u.used, u.slct]);
        let (opt, err) = if groups.needed(h.ctx().class) {
            h.call(&groups)?
        } else {
            ([-1; 3], None)
        };
        unsafe {
            put_member!(out, ODBUSEGRP, next, u.next);
            put_member!(out, ODBUSEGRP, r#use, u.used);
            put_member!(out, ODBUSEGRP, slct, u.slct);
            put_member!(out, ODBUSEGRP, opt_next, opt[0]);
            put_member!(out, ODBUSEGRP, opt_use, opt[1]);
            put_member!(out, ODBUSEGRP, opt_slct, opt[2]);
        }
        match err {
            Some(e) => {
                h.note(&e);
                Err(e)
            }
            None => Ok(()),
        }
    })
}

/// Reads a `T` at byte offset `off` of the caller's struct.
///
/// # Safety
/// `base + off .. + size_of::<T>()` must be readable.
unsafe fn get_at<T: Copy>(base: *const u8, off: usize) -> T {
    unsafe { base.add(off).cast::<T>().read_unaligned() }
}

/// Reads `*num` entries of the tool management data from data number
/// `top_no` on, in exchanges of at most 9 (each asks from where the last
/// answer ended); `*num` becomes the number read. `top_no` below 1:
/// EW_NUMBER; `*num` 0 or less: EW_OK, `*num` = 0, both without traffic,
/// as FANUC's library. An error answered ends the call with it, `*num` the
/// entries read before.
///
/// # Safety
/// `num` must point to a writable short, `tool` to `*num` writable
/// IODBTLMNG.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdtool(
    FlibHndl: c_ushort,
    top_no: c_short,
    num: *mut c_short,
    tool: *mut IODBTLMNG,
) -> c_short {
    ffi_boundary!("cnc_rdtool", {
        let h = handles::get(FlibHndl)?;
        let np = nonnull(num)?;
        let out = nonnull(tool)?.cast::<u8>();
        if top_no < 1 {
            return Err(Error::local(EW_NUMBER, "top_no below 1"));
        }
        let want = i32::from(unsafe { np.read_unaligned() });
        let (mut got, mut top, mut empty) = (0i32, i32::from(top_no), 0);
        let r = loop {
            if got >= want {
                break Ok(());
            }
            let recs = match h.call(&RdTool::new(top, want - got)) {
                Ok(r) => r,
                Err(e) => break Err(e),
            };
            // FANUC's library asks again after an answer with no records;
            // ours gives up after two in a row.
            if recs.is_empty() {
                empty += 1;
                if empty == 2 {
                    break Ok(());
                }
                continue;
            }
            empty = 0;
            for r in &recs {
                // SAFETY: `got` < `*num`, the caller's number of records.
                unsafe { put_mng(out.add(size_of::<IODBTLMNG>() * got as usize), &r.0) };
                got += 1;
            }
            top += recs.len() as i32;
        };
        unsafe { put(np, got as c_short) };
        r
    })
}

/// One IODBTLMNG (140 bytes) from a 0x014b record (src/proto/tool.rs).
///
/// # Safety
/// `o` must point to 140 writable bytes.
unsafe fn put_mng(o: *mut u8, w: &[i32; MNG_WORDS]) {
    unsafe {
        put_member!(o, IODBTLMNG, T_code, w[0]);
        put_member!(o, IODBTLMNG, life_count, w[1]);
        put_member!(o, IODBTLMNG, max_life, w[2]);
        put_member!(o, IODBTLMNG, rest_life, w[3]);
        put_member!(o, IODBTLMNG, life_stat, w[4] as u8);
        put_member!(o, IODBTLMNG, cust_bits, w[5] as u8);
        put_member!(o, IODBTLMNG, tool_info, w[6] as u16);
        put_member!(o, IODBTLMNG, H_code, w[7] as i16);
        put_member!(o, IODBTLMNG, D_code, w[8] as i16);
        put_member!(o, IODBTLMNG, spindle_speed, w[9]);
        put_member!(o, IODBTLMNG, feedrate, w[10]);
        put_member!(o, IODBTLMNG, magazine, w[11] as i16);
        put_member!(o, IODBTLMNG, pot, w[12] as i16);
        put_member!(o, IODBTLMNG, G_code, w[13] as i16);
        put_member!(o, IODBTLMNG, W_code, w[14] as i16);
        put_member!(o, IODBTLMNG, gno, w[15] as i16);
        put_member!(o, IODBTLMNG, grp, (w[16] >> 16) as i16);
        put_member!(o, IODBTLMNG, edge, w[16] as i16);
        put_member!(o, IODBTLMNG, org_magazine, w[17] as i16);
        put_member!(o, IODBTLMNG, org_pot, w[18] as i16);
        put_member!(o, IODBTLMNG, edge_num, 0u8);
        // custom1..custom20: consecutive LONGs.
        const _: () =
            assert!(offset_of!(IODBTLMNG, custom20) == offset_of!(IODBTLMNG, custom1) + 19 * 4);
        for (k, v) in w[19..].iter().enumerate() {
            put_at(o, offset_of!(IODBTLMNG, custom1) + 4 * k, *v);
        }
    }
}

/// True when the handle's current path is a punch press or laser
/// (sysinfo mt_type " P" / " L"): FANUC's library sends the punch-press
/// functions only to those, others get EW_FUNC without traffic.
fn punch(h: &crate::client::handles::Handle) -> Result<(), Error> {
    let mt = h.sysinfo().map(|s| s.mt_type);
    if matches!(mt, Some([b' ', b'P' | b'L'])) {
        Ok(())
    } else {
        Err(Error::local(EW_FUNC, "not a punch press"))
    }
}

/// Reads the tool data of a punch press from data number `tool_no` on, at
/// most `*num` (7 per call on the 30i class, 10 on the 16i class);
/// `*num` becomes the number read. Other machines: EW_FUNC; `*num` 0 or
/// less: EW_LENGTH; both without traffic, as FANUC's library.
///
/// # Safety
/// `num` must point to a writable short, `tool` to `*num` writable
/// IODBTLDT.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdtooldata(
    FlibHndl: c_ushort,
    tool_no: c_short,
    num: *mut c_short,
    tool: *mut IODBTLDT,
) -> c_short {
    ffi_boundary!("cnc_rdtooldata", {
        let h = handles::get(FlibHndl)?;
        let np = nonnull(num)?;
        let out = nonnull(tool)?.cast::<u8>();
        punch(&h)?;
        let n = unsafe { np.read_unaligned() };
        if n <= 0 {
            return Err(Error::length());
        }
        let recs = h.call(&PunchData { tool_no, n })?;
        let decimals = !h.ctx().class.is_16i();
        unsafe {
            for (i, w) in recs.iter().enumerate() {
                let o = out.add(size_of::<IODBTLDT>() * i);
                put_member!(o, IODBTLDT, slct, w[0] as i16);
                put_member!(o, IODBTLDT, tool_no, w[1]);
                put_member!(o, IODBTLDT, x_axis_ofs, w[3]);
                put_member!(o, IODBTLDT, y_axis_ofs, w[5]);
                put_member!(o, IODBTLDT, turret_pos, w[7]);
                put_member!(o, IODBTLDT, chg_tl_no, w[9]);
                put_member!(o, IODBTLDT, punch_count, w[11]);
                put_member!(o, IODBTLDT, tool_life, w[13]);
                put_member!(o, IODBTLDT, m_tl_radius, w[15]);
                put_member!(o, IODBTLDT, m_tl_angle, w[17]);
                put_member!(o, IODBTLDT, tl_shape, w[19] as c_char);
                put_member!(o, IODBTLDT, tl_size_i, w[21]);
                put_member!(o, IODBTLDT, tl_size_j, w[23]);
                put_member!(o, IODBTLDT, tl_angle, w[25]);
                if decimals {
                    put_member!(o, IODBTLDT, x_axis_dec, w[27] as c_char);
                    put_member!(o, IODBTLDT, y_axis_dec, w[29] as c_char);
                    put_member!(o, IODBTLDT, turret_dec, w[31] as c_char);
                    put_member!(o, IODBTLDT, m_radius_dec, w[33] as c_char);
                    put_member!(o, IODBTLDT, m_angle_dec, w[35] as c_char);
                    put_member!(o, IODBTLDT, tl_size_i_dec, w[37] as c_char);
                    put_member!(o, IODBTLDT, tl_size_j_dec, w[39] as c_char);
                    put_member!(o, IODBTLDT, tl_angle_dec, w[41] as c_char);
                }
            }
            put(np, recs.len() as c_short);
        }
        Ok(())
    })
}

/// Reads the tool data sizes of a punch press (tool data and multi-tool
/// maxima and sizes). Other machines get EW_FUNC without traffic, as from
/// FANUC's library; the 16i class writes the places FANUC's library writes
/// there (src/proto/tool.rs).
///
/// # Safety
/// `info` must point to a writable ODBPTLINF.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cnc_rdtoolinfo(FlibHndl: c_ushort, info: *mut ODBPTLINF) -> c_short {
    ffi_boundary!("cnc_rdtoolinfo", {
        let h = handles::get(FlibHndl)?;
        let out = nonnull(info)?.cast::<u8>();
        punch(&h)?;
        let v = h.call(&PunchInfo)?;
        unsafe {
            for (o, x) in v {
                put_at(out, o, x);
            }
        }
        Ok(())
    })
}
