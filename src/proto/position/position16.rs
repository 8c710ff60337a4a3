//! cnc_rdposition on the 16i class and the Series 15 (learnt from FANUC's
//! library with the oracle, docs/protocol/position.md).

use super::codes::{ALL, pos};
use super::read::{be16, expect_subs, need, whole_records, zext};
use crate::error::{Error, Result};
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::{POSITION, RDAXISNAME, UNITS};
use crate::proto::packet::{ReqSub, RespSub};

/// 16i class: the per-axis parameter whose bits hide positions on the
/// screen (bit 0: every position, bit 1: absolute, relative and distance to
/// go); cnc_rdposition's `disp` is their inverse.
pub const PARAM_POS_DISPLAY: i32 = 3115;

/// The mode words (first word of 0x19) with which FANUC's library takes
/// the distance to go from the CNC: MDI, MEM and RMT. In any other mode
/// (EDIT, JOG, HND ...) it writes data 0 with `dec` -1.
pub const DISTANCE_MODES: [u16; 3] = [0, 1, 10];

/// One ODBPOS element as FANUC's library fills it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct PosValue {
    pub data: i32,
    pub dec: i16,
    pub unit: i16,
    pub disp: i16,
    /// Name and suffix.
    pub name: [u8; 2],
}

/// cnc_rdposition's frame on a 16i-class CNC (`s15` false):
/// `0x19`, `0x26[k, -1]` for k = 0..3, `0x89[-1]`, `0x0e[3115, 3115, -1]`,
/// `0x88[2]`, `0x19`; on a Series 15: the four `0x26`, `0x89[-1]`,
/// `0x88[2]`, `0x8c`. Always all four positions, whatever type is asked.
#[derive(Debug, Clone, Copy)]
pub struct Position16 {
    pub s15: bool,
    /// The caller's `*data_num` (at least 1).
    pub limit: i16,
}

/// `axes[i][k]`: axis i, position k (absolute, machine, relative,
/// distance to go).
pub type Positions16 = Vec<[PosValue; 4]>;

impl Call for Position16 {
    type Output = Positions16;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        let mut v = Vec::with_capacity(9);
        if !self.s15 {
            v.push(ReqSub::cnc(crate::proto::cmd::STATINFO, &[]));
        }
        v.extend(DYNAMIC_POS_2.map(|k| ReqSub::cnc(POSITION, &[k, ALL])));
        v.push(ReqSub::cnc(RDAXISNAME, &[ALL]));
        if self.s15 {
            v.push(ReqSub::cnc(UNITS, &[2]));
            v.push(ReqSub::cnc(crate::proto::cmd::SYSINFO15, &[]));
        } else {
            let n = PARAM_POS_DISPLAY;
            v.push(ReqSub::cnc(crate::proto::cmd::RDPARAM16, &[n, n, ALL]));
            v.push(ReqSub::cnc(UNITS, &[2]));
            v.push(ReqSub::cnc(crate::proto::cmd::STATINFO, &[]));
        }
        v
    }

    /// The first CNC error in subpacket order is the result (nothing
    /// written). The count: 16i, min(`limit`, the path's maximum axes of
    /// the open response); Series 15, min(`limit`, word 0 of 0x8c). Every
    /// axis counted must have its record, name entry, unit pair and
    /// display word in the answer (FANUC's library reads past a shorter
    /// one; ours: EW_PROTOCOL); the last subpacket reads as zeros past its
    /// payload, as FANUC's buffer does past the frame.
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Positions16> {
        let n_subs = if self.s15 { 7 } else { 9 };
        expect_subs(resp, n_subs)?;
        for i in 0..n_subs {
            sub(resp, i)?;
        }
        let p = |i: usize| &resp[i].payload;
        let first = usize::from(!self.s15);
        let last = p(n_subs - 1);
        let limit = self.limit.max(0) as usize;
        let (count, auto, disp): (usize, bool, Vec<i16>) = if self.s15 {
            // 0x8c: u16 count, a word not used, then one display word per axis.
            let count = limit
                .min(usize::from(u16::from_be_bytes(zext(last))))
                .min(crate::types::MAX_AXIS);
            let disp = (0..count)
                .map(|i| i16::from_be_bytes(zext(last.get(4 + 2 * i..).unwrap_or(&[]))))
                .collect();
            (count, true, disp)
        } else {
            let count = limit.min(cx.axes());
            let st = p(0);
            need(st, 2, "status")?;
            let mode_ok = |w: u16| DISTANCE_MODES.contains(&w);
            let auto = mode_ok(be16(st, 0)) && mode_ok(u16::from_be_bytes(zext(last)));
            let par = p(6);
            need(par, 8 + 4 * count, "parameter 3115")?;
            let disp = (0..count)
                .map(|i| i32::from_be_bytes(zext(&par[8 + 4 * i..])) as i16)
                .collect();
            (count, auto, disp)
        };
        let mut recs = Vec::with_capacity(4);
        for k in 0..4 {
            let r = whole_records(resp, first + k)?;
            if r.len() < count {
                return Err(Error::short("fewer position records than the count"));
            }
            recs.push(r);
        }
        let names = p(first + 4);
        need(names, 4 + 16 * count, "axis names")?;
        let units = p(first + 5 + usize::from(!self.s15));
        need(units, 4 * count, "unit words")?;
        let mut out = Vec::with_capacity(count);
        for i in 0..count {
            let e = &names[4 + 16 * i..];
            let (u0, u1) = (be16(units, 4 * i) as i16, be16(units, 4 * i + 2) as i16);
            let mut axis = [PosValue::default(); 4];
            for (k, v) in axis.iter_mut().enumerate() {
                let r = recs[k][i];
                let at = [0, 4, 8, 0][k];
                *v = PosValue {
                    data: r.value,
                    dec: r.exp,
                    unit: if k == 1 { u1 } else { u0 },
                    disp: if self.s15 {
                        disp[i]
                    } else {
                        // Bit 0 hides every position, bit 1 all but the
                        // machine position.
                        let mask = if k == 1 { 1 } else { 3 };
                        i16::from(disp[i] & mask == 0)
                    },
                    name: [e[at], e[at + 1]],
                };
                if k == 3 && !auto {
                    v.data = 0;
                    v.dec = -1;
                }
            }
            out.push(axis);
        }
        Ok(out)
    }
}

/// The 0x26 codes of cnc_rdposition's types 0..3.
pub const DYNAMIC_POS_2: [i32; 4] = [pos::ABSOLUTE2, pos::MACHINE, pos::RELATIVE2, pos::DISTANCE2];
