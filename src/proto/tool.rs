//! Tool numbers, tool life and counters.
//!
//! Recorded from FANUC's library against a fake CNC (not from a real CNC):
//! cnc_rdntool, cnc_rdlife and cnc_rdcount all read the group record of
//! 0x008b [grp, grp]; cnc_rdtoolgrp reads it and then the group's tools
//! with 0x004d [grp, 1, ntool] (cnc_toolnum's command).

use super::call::{Call, Ctx, Single, payload_padded, sub};
pub use super::cmd::{
    PTLDATA, PTLINFO, TLCTL, TLGROUP, TLINSERT, TLMNG, TLOPTGRP, TLTOOLS, TLUSEGRP, WRGRPINFO,
};
use super::open::CncClass;
use super::packet::ReqSub;
use super::packet::RespSub;
use super::value::Value;
use super::wire::{DecodeError, Reader, Wire, Writer};
use crate::error::Result;
use crate::wire_struct;

wire_struct! {
    /// Payload of 0x008b: group number, then the number of tools, tool life
    /// and life counter as value records. FANUC's library reads the value
    /// words at payload offsets 4 (ntool), 12 (life) and 20 (count).
    pub struct ToolGroup {
        pub grp: i32,
        pub ntool: Value,
        pub life: Value,
        pub count: Value,
    }
}

/// cnc_instlifedt: an empty answer.
pub fn tlinsert(grp: i16, tuse: i16, tool: i32) -> Single<super::offset::Ack> {
    let args = [i32::from(grp), i32::from(tuse), tool];
    Single::new(ReqSub::cnc(TLINSERT, &args))
}

/// cnc_rdtoolgrp's first frame, 0x008b [grp, grp]: None for an answer
/// under 4 bytes or whose group number is 0 (FANUC's library then writes
/// grp_num 0 only [fuzz, rdtoolgrp `s0L`: an 8-byte answer of group 0 and
/// 2 tools]); a longer one short of the record reads its missing words as
/// zeros.
pub fn tlgroup(grp: i16) -> TlGroup {
    TlGroup(i32::from(grp))
}

#[derive(Debug, Clone, Copy)]
pub struct TlGroup(pub i32);

impl Call for TlGroup {
    type Output = Option<ToolGroup>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(TLGROUP, &[self.0, self.0])]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Option<ToolGroup>> {
        if sub(resp, 0)?.payload.len() < 4 {
            return Ok(None);
        }
        let full = ToolGroup::default().to_bytes().len();
        let g: ToolGroup = payload_padded(resp, 0, full)?;
        // Group 0 is the answer's low 16 bits, as FANUC's library reads
        // it [fuzz, seed 0x202a1129 `s0L`: 0x80000000 is no group].
        Ok((g.grp as i16 != 0).then_some(g))
    }
}

wire_struct! {
    /// One tool of a group in a 0x004d answer (16 bytes).
    pub struct ToolEntry {
        pub tool_num: i32,
        pub length_num: i32,
        pub radius_num: i32,
        pub tinfo: i32,
    }
}

/// Payload of 0x004d: i32 group, i32 first tool-use number, then 16-byte
/// tool records (FANUC's library numbers them tuse 1, 2, ... in order). A
/// ragged tail is ignored, as FANUC's library ignores it.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ToolList {
    pub grp: i32,
    pub first: i32,
    pub tools: Vec<ToolEntry>,
}

impl Wire for ToolList {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.grp);
        w.i32(self.first);
        self.tools.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let grp = r.i32()?;
        let first = r.i32()?;
        let mut tools = Vec::new();
        while r.remaining() >= 16 {
            tools.push(ToolEntry::decode(r)?);
        }
        Ok(ToolList { grp, first, tools })
    }
}

/// Most tools one 0x004d request asks for, as FANUC's library does.
pub const TOOLS_PER_REQUEST: i32 = 89;

/// Tools 1.. of group `grp` (the group number the 0x008b answer gave), at
/// most [`TOOLS_PER_REQUEST`], as FANUC's cnc_rdtoolgrp asks.
pub fn tltools(grp: i32, ntool: i32) -> Single<ToolList> {
    Single::new(ReqSub::cnc(
        TLTOOLS,
        &[grp, 1, ntool.min(TOOLS_PER_REQUEST)],
    ))
}

wire_struct! {
    /// Payload of 0x009a (cnc_rdtlctldata), read from FANUC's library code
    /// (it only sends it to a punch press or laser, mt_type " P" / " L"):
    /// 32-bit words, of which the short fields take the low 16 bits and
    /// t_axis_dec the low byte. Not exercised against any CNC.
    pub struct ToolCtl {
        pub slct: i32,
        pub used_tool: i32,
        pub turret_indx: i32,
        pub zero_tl_no: i32,
        pub total_punch0: i32,
        pub total_punch1: i32,
        pub t_axis_move: i32,
        pub reserved: i32,
        pub t_axis_dec: i32,
    }
}

pub fn tlctl() -> Single<ToolCtl> {
    Single::new(ReqSub::cnc(TLCTL, &[]))
}

/// Most groups one 0x008b range request asks for (e capped at s + 43), as
/// FANUC's cnc_rdgrpinfo asks: 44 records of 32 bytes fit one answer.
pub const GROUPS_PER_REQUEST: i32 = 44;

wire_struct! {
    /// One tool life group of a 0x008b answer (32 bytes). FANUC's library
    /// reads `ntool`, `life`, `count_type` and `count` (cnc_rdgrpinfo) and,
    /// on the 16i class, `opt_grp` (cnc_rdtlusegrp); the other words are
    /// not read by any function learnt so far.
    pub struct GroupRecord {
        pub ntool: i32,
        pub w1: i32,
        pub life: i32,
        pub count_type: i32,
        pub count: i32,
        pub w5: i32,
        pub opt_grp: i32,
        pub w7: i32,
    }
}

/// Payload of 0x008b [s, e]: an i32 (the first group's number; read by
/// cnc_rdlife / cnc_rdcount / cnc_rdntool as `datano`, not by
/// cnc_rdgrpinfo), then whole [`GroupRecord`]s: FANUC's library counts
/// (length - 4) / 32 of them and ignores a ragged tail; an answer shorter
/// than 4 bytes has none.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct GroupRange {
    pub first: i32,
    pub groups: Vec<GroupRecord>,
}

impl Wire for GroupRange {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.first);
        self.groups.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        if r.remaining() < 4 {
            return Ok(GroupRange::default());
        }
        let first = r.i32()?;
        let mut groups = Vec::new();
        while r.remaining() >= 32 {
            groups.push(GroupRecord::decode(r)?);
        }
        Ok(GroupRange { first, groups })
    }
}

/// cnc_rdgrpinfo: groups `s..=e`, e capped at s + 43 as FANUC's library
/// caps it.
pub fn grpinfo(s: i16, e: i16) -> Single<GroupRange> {
    let s = i32::from(s);
    let e = i32::from(e).min(s + GROUPS_PER_REQUEST - 1);
    Single::new(ReqSub::cnc(TLGROUP, &[s, e]))
}

wire_struct! {
    /// One group of a 0x004c write (20 bytes): the life, the counter type
    /// and the counter from IODBTGI (`n_tool` is not sent), then two words
    /// FANUC's library always sends as -1.
    pub struct GroupWrite {
        pub life: i32,
        pub count_type: i32,
        pub count: i32,
        pub w3: i32,
        pub w4: i32,
    }
}

/// Most groups one 0x004c write carries (e capped at s + 70), as FANUC's
/// cnc_wrgrpinfo sends: 71 records of 20 bytes fit one request.
pub const GROUPS_PER_WRITE: i32 = 71;

/// cnc_wrgrpinfo: groups `s..=e` written (`groups` from `s` on; e capped
/// at s + 70 as FANUC's library caps it); an empty answer.
pub fn wrgrpinfo(s: i16, e: i16, groups: &[GroupWrite]) -> Single<super::offset::Ack> {
    let (s, e) = (i32::from(s), i32::from(e));
    let e = e.min(s + GROUPS_PER_WRITE - 1);
    let n = (e - s + 1).max(0) as usize;
    let payload = groups[..n.min(groups.len())].to_vec().to_bytes();
    let args = [s, e];
    Single::new(ReqSub::cnc(WRGRPINFO, &args).with_payload(payload))
}

wire_struct! {
    /// Payload of 0x0048 (cnc_rdtlusegrp): the next, in-use and selected
    /// tool life groups. A shorter answer reads as zeros, as FANUC's
    /// library reads it.
    pub struct UseGroups {
        pub next: i32,
        pub used: i32,
        pub slct: i32,
    }
}

pub fn usegrp() -> Single<UseGroups> {
    Single::padded(ReqSub::cnc(TLUSEGRP, &[]))
}

/// cnc_rdtlusegrp's second frame: the optional group numbers of the
/// groups (next, use, slct). The 30i class asks (1,0x1bf)[g, g] for each
/// group above 0, but only when `next` is above 0 (the optional group
/// number is the answer's second i32); the 16i class asks the group record
/// (1,0x8b)[g, g] of all three, 0 included (the record's `opt_grp`);
/// Series 15 sends nothing. A group 0, one whose subpacket carries an
/// error and every group after that one read -1.
#[derive(Debug, Clone, Copy)]
pub struct OptGroups(pub [i32; 3]);

impl OptGroups {
    /// The groups asked on class `c`, by their index in (next, use, slct).
    fn asked(&self, c: CncClass) -> Vec<usize> {
        match c {
            CncClass::Series30 if self.0[0] > 0 => (0..3).filter(|&i| self.0[i] > 0).collect(),
            CncClass::Series30 | CncClass::Series16 { kind: 2 } => Vec::new(),
            CncClass::Series16 { .. } => vec![0, 1, 2],
        }
    }
    /// Whether there is a second frame at all.
    pub fn needed(&self, c: CncClass) -> bool {
        !self.asked(c).is_empty()
    }
}

impl Call for OptGroups {
    /// The three optional group numbers, and the first error a subpacket
    /// of a group that is not 0 carried (FANUC's library writes the
    /// numbers and returns that error).
    type Output = ([i32; 3], Option<crate::error::Error>);
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let cmd = if cx.class.is_16i() { TLGROUP } else { TLOPTGRP };
        (self.asked(cx.class).iter())
            .map(|&i| ReqSub::cnc(cmd, &[self.0[i], self.0[i]]))
            .collect()
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Self::Output> {
        let (mut out, mut err) = ([-1; 3], None);
        // The optional group number: 30i the second i32, 16i the record's
        // opt_grp (bytes 28..32 after the 4-byte head).
        let at = if cx.class.is_16i() { 28 } else { 4 };
        for (k, i) in self.asked(cx.class).into_iter().enumerate() {
            if resp.len() <= k {
                sub(resp, k)?;
            }
            // After an error FANUC's library looks at no later group.
            if self.0[i] == 0 || err.is_some() {
                continue;
            }
            let p = match sub(resp, k) {
                Ok(s) => &s.payload,
                Err(e) => {
                    err.get_or_insert(e);
                    continue;
                }
            };
            let b = p.get(at..at + 4).ok_or(DecodeError::Short {
                need: at + 4,
                have: p.len(),
            })?;
            out[i] = i32::from_be_bytes([b[0], b[1], b[2], b[3]]);
        }
        Ok((out, err))
    }
}

/// Most records one 0x014b request asks for, as FANUC's library asks (9
/// records of 156 bytes and the count fit one answer).
pub const TOOLS_PER_MNG: i32 = 9;
/// The i32 words of one 0x014b record.
pub const MNG_WORDS: usize = 39;

/// One record of a 0x014b answer: 39 i32 words. FANUC's library writes
/// IODBTLMNG from them: T_code w0, life_count w1, max_life w2, rest_life
/// w3 (longs); life_stat and cust_bits the low bytes of w4 and w5;
/// tool_info, H_code, D_code the low 16 bits of w6..w8; spindle_speed w9,
/// feedrate w10; magazine, pot, G_code, W_code, gno the low 16 bits of
/// w11..w15; grp the high and edge the low 16 bits of w16; org_magazine,
/// org_pot the low 16 bits of w17, w18; custom1..20 w19..w38. edge_num is
/// written 0, reserve_c and reserved are not written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MngRecord(pub [i32; MNG_WORDS]);

impl Default for MngRecord {
    fn default() -> Self {
        MngRecord([0; MNG_WORDS])
    }
}

impl Wire for MngRecord {
    fn encode(&self, w: &mut Writer) {
        for x in self.0 {
            w.i32(x);
        }
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let mut v = [0; MNG_WORDS];
        for x in &mut v {
            *x = r.i32()?;
        }
        Ok(MngRecord(v))
    }
}

/// Payload of 0x014b: an i32 count, then that many records.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct MngList {
    pub count: i32,
    pub tools: Vec<MngRecord>,
}

impl Wire for MngList {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.count);
        self.tools.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let count = r.i32()?;
        let mut tools = Vec::new();
        while r.remaining() >= 4 * MNG_WORDS {
            tools.push(MngRecord::decode(r)?);
        }
        Ok(MngList { count, tools })
    }
}

/// One 0x014b exchange: records `top..top + n` (n capped at 9). The
/// answer's count says how many records it holds; FANUC's library takes
/// that many, reading the bytes a short answer lacks as zeros (a missing
/// count is 0). Ours takes at most `n` of them.
#[derive(Debug, Clone, Copy)]
pub struct RdTool {
    pub top: i32,
    pub n: i32,
}

impl RdTool {
    pub fn new(top: i32, want: i32) -> Self {
        RdTool {
            top,
            n: want.clamp(0, TOOLS_PER_MNG),
        }
    }
}

impl Call for RdTool {
    type Output = Vec<MngRecord>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(TLMNG, &[self.top, self.n])]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Vec<MngRecord>> {
        let mut p = sub(resp, 0)?.payload.clone();
        p.resize(p.len().max(4), 0);
        let count = i32::from_be_bytes([p[0], p[1], p[2], p[3]]).clamp(0, self.n) as usize;
        p.resize(p.len().max(4 + 4 * MNG_WORDS * count), 0);
        let l = MngList::from_bytes(&p)?;
        Ok(l.tools.into_iter().take(count).collect())
    }
}

/// The 30i-class 0x0099 answer as FANUC's library reads it (108 bytes):
/// tld_max, mlt_max and reserve the low 16 bits of three i32, then the 48
/// shorts of tld_size, mlt_size and reserves. A shorter answer reads as
/// zeros.
pub const PTLINFO_LEN_30: usize = 108;
/// The 16i class reads other places of the answer, as (ODBPTLINF byte
/// offset, i16 index in the payload); the rest of ODBPTLINF is not
/// written (learnt with distinct words, never seen from a real CNC).
pub const PTLINFO_16: [(usize, usize); 30] = [
    (0, 1),
    (2, 3),
    (4, 5),
    (6, 6),
    (8, 7),
    (10, 8),
    (12, 9),
    (14, 10),
    (16, 11),
    (18, 12),
    (20, 13),
    (22, 14),
    (24, 15),
    (26, 16),
    (28, 17),
    (30, 18),
    (38, 22),
    (40, 29),
    (42, 30),
    (44, 23),
    (46, 24),
    (48, 31),
    (50, 32),
    (52, 33),
    (54, 34),
    (70, 38),
    (72, 39),
    (74, 40),
    (76, 43),
    (78, 44),
];

/// cnc_rdtoolinfo's answer, zero-extended to what the class reads: the
/// ODBPTLINF bytes to write, as (offset, value).
#[derive(Debug, Clone, Copy)]
pub struct PunchInfo;

impl Call for PunchInfo {
    type Output = Vec<(usize, i16)>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(PTLINFO, &[])]
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Self::Output> {
        let mut p = sub(resp, 0)?.payload.clone();
        p.resize(p.len().max(PTLINFO_LEN_30), 0);
        let hw = |k: usize| i16::from_be_bytes([p[2 * k], p[2 * k + 1]]);
        Ok(if cx.class.is_16i() {
            PTLINFO_16.iter().map(|&(o, k)| (o, hw(k))).collect()
        } else {
            let head = [(0, hw(1)), (2, hw(3)), (4, hw(5))];
            head.into_iter()
                .chain((0..48).map(|i| (6 + 2 * i, hw(6 + i))))
                .collect()
        })
    }
}

/// Most tool data one 0x009c request asks for: 7 records of 204 bytes
/// (30i class), 10 of 132 (16i class).
pub fn ptl_per_request(c: CncClass) -> i32 {
    if c.is_16i() { 10 } else { 7 }
}

/// The i32 words of one 0x009c record: 51 (30i class), 33 (16i class).
pub fn ptl_words(c: CncClass) -> usize {
    if c.is_16i() { 33 } else { 51 }
}

/// cnc_rdtooldata: tool data `tool_no..` of a punch press, at most `n`;
/// whole records of [`ptl_words`] i32, as many as the answer holds (FANUC's
/// library writes them all; ours at most `n`). FANUC's library reads from a
/// record: slct the low 16 bits of w0, tool_no w1, x_axis_ofs w3,
/// y_axis_ofs w5, turret_pos w7, chg_tl_no w9, punch_count w11, tool_life
/// w13, m_tl_radius w15, m_tl_angle w17, tl_shape the low byte of w19,
/// tl_size_i w21, tl_size_j w23, tl_angle w25 and, on the 30i class only,
/// the eight decimals the low bytes of w27, w29 .. w41.
#[derive(Debug, Clone, Copy)]
pub struct PunchData {
    pub tool_no: i16,
    pub n: i16,
}

impl Call for PunchData {
    type Output = Vec<Vec<i32>>;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let n = i32::from(self.n).min(ptl_per_request(cx.class));
        vec![ReqSub::cnc(PTLDATA, &[0, i32::from(self.tool_no), n])]
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Self::Output> {
        let p = &sub(resp, 0)?.payload;
        let size = 4 * ptl_words(cx.class);
        Ok(p.chunks_exact(size)
            .take(self.n.max(0) as usize)
            .map(|r| {
                r.chunks_exact(4)
                    .map(|b| i32::from_be_bytes([b[0], b[1], b[2], b[3]]))
                    .collect()
            })
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tool_list_request_asks_the_answered_group_for_at_most_89_tools() {
        let r = tltools(7, 100).request(&Ctx::default());
        assert_eq!((r[0].cmd, &r[0].args[..3]), (TLTOOLS, &[7, 1, 89][..]));
        let r = tltools(7, 3).request(&Ctx::default());
        assert_eq!(&r[0].args[..3], &[7, 1, 3]);
    }
}
