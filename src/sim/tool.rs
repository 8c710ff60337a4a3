//! Simulated tool life management: the profile's tool life groups, read,
//! written and deleted; the groups in use; the punch press tools.

use super::Machine;
use super::profile::offset::{ToolGroupProfile, ToolProfile};
use super::route::{Route, enc, none};
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::cmd::{DELTLIFEDT, DELTLIFEGRP, RDGRPID2};
use crate::proto::cmd::{RD1TLIFEDATA, RDEXCHGTGRP, RDNGRP, RDTLINFO, RDUSETLNO, WR1TLIFEDATA};
use crate::proto::packet::ReqSub;
use crate::proto::tool::{
    GroupRange, GroupRecord, GroupWrite, PTLDATA, PTLINFO, PTLINFO_16, TLGROUP, TLINSERT, TLOPTGRP,
    TLTOOLS, TLUSEGRP, UseGroups, WRGRPINFO,
};
use crate::proto::wire::Wire;

const NUMBER: CncError = CncError::NUMBER;
/// cnc_modal's code of the T code (AUX_ORDER position 8, src/sim/modal.rs).
const T_CODE: i32 = crate::proto::program::AUX_ORDER[8];
const LENGTH: CncError = CncError::new(ew::EW_LENGTH);

pub(super) const ROUTES: &[Route] = &[
    // [s, e]: tool life group records (s = e: one group), cnc_rdgrpinfo's
    // layout (`s_grp`, `e_grp` not sent; the first group's number, then
    // the records), of which cnc_rdlife, cnc_rdcount and cnc_rdntool read
    // the first group.
    Route::table(TLGROUP, |m, q| {
        let r = m.tl_groups(q.path, q.words[0], q.words[1])?;
        let mut v = vec![0, 0, i64::from(r.first)];
        for g in &r.groups {
            let w = [
                g.ntool,
                g.w1,
                g.life,
                g.count_type,
                g.count,
                g.w5,
                g.opt_grp,
                g.w7,
            ];
            v.extend(w.map(i64::from));
        }
        Ok(v)
    }),
    // [grp, s, e]: tools s..=e of a group.
    Route::cnc(TLTOOLS, |m, q| {
        enc(m.tl_list(q.path, q.args[0], q.args[1], q.args[2]))
    }),
    Route::cnc(TLINSERT, |m, q| {
        m.tl_insert(q.path, q.args).map(|_| Vec::new())
    }),
    Route::cnc(WRGRPINFO, |m, q| m.tl_write(q)),
    Route::cnc(PTLDATA, |m, q| m.punch_data(q.path, q.args[1], q.args[2])),
    Route::cnc(PTLINFO, |m, q| m.punch_info(q.path)),
    Route::cnc(TLUSEGRP, |m, q| m.tl_use(q.path)),
    Route::cnc(TLOPTGRP, |m, q| m.tl_optional(q.path, q.args[0])),
    Route::table(RDGRPID2, |m, q| {
        m.tl_group_of_tool(q.path, q.arg(0))
            .map(|g| vec![i64::from(q.arg(0)), i64::from(g)])
    }),
    Route::table(DELTLIFEGRP, |m, q| {
        none(m.tl_delete(q.path, q.arg(0), None))
    }),
    Route::table(DELTLIFEDT, |m, q| {
        none(m.tl_delete(q.path, q.arg(0), Some(q.arg(1))))
    }),
    // The number of groups; on the 16i class cnc_rdtlinfo's limits
    // follow it in the same answer (the layout asked for holds them).
    Route::table(RDNGRP, |m, q| {
        let n = m.tl_group_count(q.path)?;
        let mut v = vec![i64::from(n)];
        v.extend(m.tl_limits(q.path)?);
        v.truncate(q.f.reply.len());
        Ok(v)
    }),
    // cnc_rd1tlifedata [grp, n]: the group, tool n's number, its use
    // number (a word cnc_rd1tlifedata does not read; the simulator's
    // choice), its H and D codes and information; tool 0 is the one in use.
    Route::table(RD1TLIFEDATA, |m, q| {
        let l = m.tl_list(q.path, q.arg(0), q.arg(1), q.arg(1))?;
        let t = l.tools.first().ok_or(NUMBER)?;
        Ok([
            l.grp,
            t.tool_num,
            l.first,
            t.length_num,
            t.radius_num,
            t.tinfo,
        ]
        .map(i64::from)
        .to_vec())
    }),
    // cnc_rdtlinfo on the 30i class: a word cnc_rdtlinfo does not read (the
    // simulator's: the number of groups, as on the 16i class), the limits.
    Route::table(RDTLINFO, |m, q| {
        let mut v = vec![i64::from(m.tl_group_count(q.path)?)];
        v.extend(m.tl_limits(q.path)?);
        Ok(v)
    }),
    // cnc_rdusetlno [s, e]: the first group's number, then the use number
    // of each group's tool in use (`s_grp` and `e_grp` not sent).
    Route::table(RDUSETLNO, |m, q| {
        let using = m.tl_using(q.path, q.words[0], q.words[1])?;
        Ok([vec![0, 0, i64::from(q.words[0])], using].concat())
    }),
    // cnc_rdexchgtgrp [n]: the groups whose life is used up, at most n.
    Route::table(RDEXCHGTGRP, |m, q| m.tl_exchange(q.path, q.words[0])),
    // cnc_wr1tlifedata [grp, n] + the tool's number, H, D and information.
    Route::table(WR1TLIFEDATA, |m, q| {
        let [tno, h, d, inf] = match q.payload {
            [a, b, c, d, ..] => [*a, *b, *c, *d].map(|v| v as i32),
            _ => return Err(LENGTH),
        };
        let t = ToolProfile {
            number: tno,
            length: h,
            radius: d,
            info: inf,
        };
        none(m.tl_set_tool(q.path, q.arg(0), q.arg(1), t))
    }),
];

impl Machine {
    /// Group `grp`; 0 is the group in use (the simulator's choice: the
    /// first group; adapters ask cnc_toolnum(0, 0) for the tool in use).
    fn tool_group_of(&self, path: u16, grp: i32) -> Reply<&ToolGroupProfile> {
        let groups = &self
            .profile
            .paths
            .get(path as usize - 1)
            .ok_or(CncError::PATH)?
            .tool_groups;
        if grp == 0 {
            return groups.first().ok_or(NUMBER);
        }
        groups.iter().find(|g| g.number == grp).ok_or(NUMBER)
    }

    /// 0x0053 \[grp\] deletes tool life group `grp`; 0x0055 [grp, n] its
    /// `n`-th tool. An absent group or tool: EW_NUMBER, nothing changed.
    pub fn tl_delete(&mut self, path: u16, grp: i32, tool: Option<i32>) -> Reply<()> {
        let groups = &mut (self.profile.paths)
            .get_mut(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?
            .tool_groups;
        let i = groups.iter().position(|g| g.number == grp).ok_or(NUMBER)?;
        match tool {
            None => {
                groups.remove(i);
            }
            Some(n) if n >= 1 && n as usize <= groups[i].tools.len() => {
                groups[i].tools.remove(n as usize - 1);
            }
            Some(_) => return Err(NUMBER),
        }
        Ok(())
    }

    /// 0x0054 [grp, n, tno]: tool number `tno` inserted into group `grp` as
    /// its `n`-th tool (1..=tools + 1), no offsets; else EW_NUMBER (a tool
    /// number below 1: EW_DATA), nothing changed.
    pub fn tl_insert(&mut self, path: u16, a: [i32; 5]) -> Reply<()> {
        let groups = &mut (self.profile.paths)
            .get_mut(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?
            .tool_groups;
        let g = groups.iter_mut().find(|g| g.number == a[0]).ok_or(NUMBER)?;
        if a[1] < 1 || a[1] as usize > g.tools.len() + 1 {
            return Err(NUMBER);
        }
        if a[2] < 1 {
            return Err(CncError::new(ew::EW_DATA));
        }
        let t = ToolProfile {
            number: a[2],
            length: 0,
            radius: 0,
            info: 0,
        };
        g.tools.insert(a[1] as usize - 1, t);
        Ok(())
    }

    /// 0x0050 [grp, n] + a record: tool `n` (its use number) of group
    /// `grp` becomes `t`. An absent group or tool: EW_NUMBER; a tool number
    /// below 1: EW_DATA (as 0x0054's); nothing changed.
    pub fn tl_set_tool(&mut self, path: u16, grp: i32, n: i32, t: ToolProfile) -> Reply<()> {
        let groups = &mut (self.profile.paths)
            .get_mut(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?
            .tool_groups;
        let g = groups.iter_mut().find(|g| g.number == grp).ok_or(NUMBER)?;
        let slot = usize::try_from(n.wrapping_sub(1)).ok();
        let tool = slot.and_then(|k| g.tools.get_mut(k)).ok_or(NUMBER)?;
        if t.number < 1 {
            return Err(CncError::new(ew::EW_DATA));
        }
        *tool = t;
        Ok(())
    }

    /// 0x0047 \[tno\]: the first group holding tool number `tno` (none:
    /// EW_NUMBER).
    pub fn tl_group_of_tool(&self, path: u16, tno: i32) -> Reply<i32> {
        let p = (self.profile.paths)
            .get(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?;
        (p.tool_groups.iter())
            .find(|g| g.tools.iter().any(|t| t.number == tno))
            .map(|g| g.number)
            .ok_or(NUMBER)
    }

    /// 0x004a: how many tool life groups the path has.
    /// The tool life limits of the profile: groups, tools in a group,
    /// minutes, cycles.
    pub fn tl_limits(&self, path: u16) -> Reply<[i64; 4]> {
        let l = self.path(path)?.tool_life;
        Ok([l.max_group, l.max_tool, l.max_minute, l.max_cycle].map(i64::from))
    }

    pub fn tl_group_count(&self, path: u16) -> Reply<i32> {
        let p = (self.profile.paths)
            .get(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?;
        Ok(p.tool_groups.len() as i32)
    }

    /// 0x008b [s, e]: s = e, one group (0: the first; absent: EW_NUMBER);
    /// a range, every group number s..=e up to the highest the table
    /// holds (numbers it lacks answer as empty groups); s < 1, e < s or s
    /// past the highest: EW_NUMBER.
    pub fn tl_groups(&mut self, path: u16, s: i32, e: i32) -> Reply<GroupRange> {
        let rec = |g: &ToolGroupProfile| GroupRecord {
            ntool: g.tools.len() as i32,
            life: g.life,
            count_type: g.count_type,
            count: g.count,
            opt_grp: g.optional,
            ..GroupRecord::default()
        };
        if s == e {
            let g = self.tool_group_of(path, s)?;
            return Ok(GroupRange {
                first: g.number,
                groups: vec![rec(g)],
            });
        }
        let groups = &(self.profile.paths)
            .get(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?
            .tool_groups;
        let last = groups.iter().map(|g| g.number).max().unwrap_or(0);
        if s < 1 || e < s || s > last {
            return Err(NUMBER);
        }
        let groups = (s..=e.min(last))
            .map(|n| {
                groups
                    .iter()
                    .find(|g| g.number == n)
                    .map(rec)
                    .unwrap_or_default()
            })
            .collect();
        Ok(GroupRange { first: s, groups })
    }

    /// 0x004c [s, e, .., len] + 20-byte records (life, counter type,
    /// counter, two words not used): groups s..=e written. Every group must
    /// exist (else EW_NUMBER), the payload hold them (else EW_LENGTH), the
    /// values be a counter type 0 or 1 and a life and counter from 0 (else
    /// EW_DATA); a refused write changes nothing.
    fn tl_write(&mut self, sub: &ReqSub) -> Reply<Vec<u8>> {
        let (s, e) = (sub.args[0], sub.args[1]);
        let groups = &mut (self.profile.paths)
            .get_mut(usize::from(sub.path).wrapping_sub(1))
            .ok_or(CncError::PATH)?
            .tool_groups;
        if e < s {
            return Err(NUMBER);
        }
        let n = (i64::from(e) - i64::from(s) + 1) as usize;
        let recs = Vec::<GroupWrite>::from_bytes(&sub.payload).map_err(|_| LENGTH)?;
        if recs.len() < n {
            return Err(LENGTH);
        }
        let mut at = Vec::with_capacity(n);
        for (k, r) in recs.iter().take(n).enumerate() {
            let num = s + k as i32;
            let i = groups.iter().position(|g| g.number == num).ok_or(NUMBER)?;
            if !(0..=1).contains(&r.count_type) || r.life < 0 || r.count < 0 {
                return Err(CncError::new(ew::EW_DATA));
            }
            at.push((i, r));
        }
        for (i, r) in at {
            let g = &mut groups[i];
            (g.life, g.count_type, g.count) = (r.life, r.count_type, r.count);
        }
        Ok(Vec::new())
    }

    /// The tool life group of the T code in effect (the running program's,
    /// else the profile's modal T): the first group holding that tool
    /// number, 0 when none does.
    fn tl_group_in_use(&self, path: u16) -> Reply<i32> {
        let t = self
            .aux_modal(path, T_CODE)?
            .0
            .first()
            .map_or(0, |a| a.value);
        Ok(self.tl_group_of_tool(path, t).unwrap_or(0))
    }

    /// 0x0048: next, in-use and selected groups. The simulator changes
    /// tools at once and reads no block ahead: the group of the T code in
    /// effect is selected, in use and the next to be used.
    fn tl_use(&self, path: u16) -> Reply<Vec<u8>> {
        let g = self.tl_group_in_use(path)?;
        Ok(UseGroups {
            next: g,
            used: g,
            slct: g,
        }
        .to_bytes())
    }

    /// A punch press path's tool data; other machines: EW_FUNC.
    fn punch_tools(&self, path: u16) -> Reply<&[super::profile::offset::PunchTool]> {
        let p = (self.profile.paths)
            .get(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?;
        if p.machine != super::profile::MachineKind::Punch {
            return Err(CncError::FUNC);
        }
        Ok(&p.punch_tools)
    }

    fn is_16i(&self) -> bool {
        self.profile.cnc.class == super::profile::Class::Series16
    }

    /// 0x009c [0, s, n]: tool data s.. of a punch press, as many as the
    /// table holds, at most n (s past the table, s or n below 1:
    /// EW_NUMBER). Records of 51 words (30i class) or 33 (16i class, no
    /// decimals), the words FANUC's library reads (src/proto/tool.rs),
    /// the others 0.
    fn punch_data(&self, path: u16, s: i32, n: i32) -> Reply<Vec<u8>> {
        let tools = self.punch_tools(path)?;
        if s < 1 || n < 1 || s as usize > tools.len() {
            return Err(NUMBER);
        }
        let words = if self.is_16i() { 33 } else { 51 };
        let mut out = Vec::new();
        for t in tools.iter().skip(s as usize - 1).take(n as usize) {
            let mut w = vec![0i32; words];
            let vals = [
                t.number,
                t.x_offset,
                t.y_offset,
                t.turret,
                t.change,
                t.punch_count,
                t.life,
                t.radius,
                t.radius_angle,
                t.shape,
                t.size_i,
                t.size_j,
                t.angle,
            ];
            for (k, v) in vals.into_iter().enumerate() {
                w[1 + 2 * k] = v;
            }
            if words == 51 {
                let (d, a) = (t.decimals, t.angle_decimals);
                for (k, v) in [d, d, d, d, a, d, d, a].into_iter().enumerate() {
                    w[27 + 2 * k] = v;
                }
            }
            out.extend(w.iter().flat_map(|x| x.to_be_bytes()));
        }
        Ok(out)
    }

    /// 0x0099: the tool data sizes of a punch press: tld_max the number of
    /// tool data, tld_size[0] the same, the rest 0 (the simulator's
    /// choice), at the places each class's FANUC library reads.
    fn punch_info(&self, path: u16) -> Reply<Vec<u8>> {
        let n = self.punch_tools(path)?.len() as i16;
        let mut hw = [0i16; 54];
        if self.is_16i() {
            for &(o, k) in &PTLINFO_16 {
                if o == 0 || o == 6 {
                    hw[k] = n;
                }
            }
        } else {
            hw[1] = n;
            hw[6] = n;
        }
        Ok(hw.iter().flat_map(|x| x.to_be_bytes()).collect())
    }

    /// 0x01bf [g, g] (30i class): group `g` and its optional group number.
    fn tl_optional(&self, path: u16, g: i32) -> Reply<Vec<u8>> {
        let opt = self.tool_group_of(path, g)?.optional;
        Ok([g, opt].iter().flat_map(|x| x.to_be_bytes()).collect())
    }

    /// 0x0049 [s, e]: the use number of the tool in use of each group
    /// s..=e up to the highest the table holds (0 for a number it lacks);
    /// s < 1, e < s or s past the highest: EW_NUMBER (as 0x008b's range).
    fn tl_using(&self, path: u16, s: i32, e: i32) -> Reply<Vec<i64>> {
        let groups = &self.path(path)?.tool_groups;
        let last = groups.iter().map(|g| g.number).max().unwrap_or(0);
        if s < 1 || e < s || s > last {
            return Err(NUMBER);
        }
        let of = |n: i32| groups.iter().find(|g| g.number == n).map_or(0, |g| g.using);
        Ok((s..=e.min(last)).map(|n| i64::from(of(n))).collect())
    }

    /// 0x00d4 \[n\]: the groups to exchange, at most n: those whose counter
    /// reached their life (a life of 0: never), each with its optional
    /// group number.
    fn tl_exchange(&self, path: u16, n: i32) -> Reply<Vec<i64>> {
        let groups = &self.path(path)?.tool_groups;
        let spent = groups.iter().filter(|g| g.life > 0 && g.count >= g.life);
        let n = usize::try_from(n).unwrap_or(0);
        Ok(spent
            .take(n)
            .flat_map(|g| [g.number, g.optional].map(i64::from))
            .collect())
    }

    /// 0x004d [grp, s, e]: the tools with use numbers s..=e that exist.
    pub fn tl_list(
        &mut self,
        path: u16,
        grp: i32,
        s: i32,
        e: i32,
    ) -> Reply<crate::proto::tool::ToolList> {
        let g = self.tool_group_of(path, grp)?;
        // Use number 0: the tool in use (the group's first, in this simulator).
        let (s, e) = if s == 0 { (1, e.max(1)) } else { (s, e) };
        if s < 1 || e < s || s as usize > g.tools.len() {
            return Err(NUMBER);
        }
        Ok(crate::proto::tool::ToolList {
            grp: g.number,
            first: s,
            tools: g
                .tools
                .iter()
                .skip(s as usize - 1)
                .take((e - s + 1) as usize)
                .map(|t| crate::proto::tool::ToolEntry {
                    tool_num: t.number,
                    length_num: t.length,
                    radius_num: t.radius,
                    tinfo: t.info,
                })
                .collect(),
        })
    }
}
