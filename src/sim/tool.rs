//! Simulated tool life management: the profile's tool life groups, read,
//! written and deleted; the groups in use; the punch press tools.

use super::Machine;
use super::profile::offset::{ToolGroupProfile, ToolProfile};
use super::route::{Route, enc, none};
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::cmd::{DELMAGAZINE, RDMAGAZINE, REGMAGAZINE, REGTOOL, REGTOOL_F2};
use crate::proto::cmd::{DELTLIFEDT, DELTLIFEGRP, RDGRPID2};
use crate::proto::cmd::{RD1TLIFEDATA, RDNGRP, RDTLINFO, WRMAGAZINE, WRTOOL};
use crate::proto::packet::ReqSub;
use crate::proto::tool::{
    GroupRange, GroupRecord, GroupWrite, MNG_WORDS, MngList, MngRecord, PTLDATA, PTLINFO,
    PTLINFO_16, TLGROUP, TLINSERT, TLMNG, TLOPTGRP, TLTOOLS, TLUSEGRP, UseGroups, WRGRPINFO,
};
use crate::proto::wire::Wire;

const NUMBER: CncError = CncError::NUMBER;
/// cnc_modal's code of the T code (AUX_ORDER position 8, src/sim/modal.rs).
const T_CODE: i32 = crate::proto::program::AUX_ORDER[8];
const LENGTH: CncError = CncError::new(ew::EW_LENGTH);

pub(super) const ROUTES: &[Route] = &[
    // [s, e]: tool life group records (s = e: one group).
    Route::cnc(TLGROUP, |m, q| {
        enc(m.tl_groups(q.path, q.args[0], q.args[1]))
    }),
    // [grp, s, e]: tools s..=e of a group.
    Route::cnc(TLTOOLS, |m, q| {
        enc(m.tl_list(q.path, q.args[0], q.args[1], q.args[2]))
    }),
    Route::cnc(TLINSERT, |m, q| {
        m.tl_insert(q.path, q.args).map(|_| Vec::new())
    }),
    Route::cnc(WRGRPINFO, |m, q| m.tl_write(q)),
    Route::cnc(TLMNG, |m, q| m.tl_managed(q.path, q.args[0], q.args[1])),
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
    // cnc_wrmagazine [magazine, pot, tool_index]: the magazine is where
    // the tool management data say their tools are.
    Route::table(WRMAGAZINE, |m, q| {
        none(m.put_in_pot(q.path, q.arg(0), q.arg(1), q.arg(2)))
    }),
    // cnc_rdmagazine + pots (magazine, pot, 0): the pots answered, each
    // with the data number of the tool the magazine holds there.
    Route::table(RDMAGAZINE, |m, q| m.read_pots(q.path, q.payload)),
    // cnc_regmagazine + pots (magazine, pot, tool_index): each tool put in
    // its pot; the pots registered.
    Route::table(REGMAGAZINE, |m, q| {
        m.register_pots(q.path, q.payload).map(|n| vec![n])
    }),
    // cnc_delmagazine + pots (magazine, pot): each pot emptied.
    Route::table(DELMAGAZINE, |m, q| {
        m.delete_pots(q.path, q.payload).map(|n| vec![n])
    }),
    // cnc_regtool [top] + records as cnc_wrtool's: data numbers top, top + 1 ...
    Route::table(REGTOOL, |m, q| m.register_tools(q)),
    // cnc_regtool_f2: the same with 40 custom data a record.
    Route::table(REGTOOL_F2, |m, q| m.register_tools(q)),
    // cnc_wrtool [tool_no] + the record cnc_rdtool reads.
    Route::table(WRTOOL, |m, q| {
        none(m.write_managed(q.path, q.arg(0), q.payload))
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

    /// 0x0151 [magazine, pot, tool_index]: tool management data number
    /// `tool_index` (`[[path.managed_tool]]`, 1, 2, ...) moves to the pot,
    /// whose tool (if another) leaves the magazine (magazine and pot 0);
    /// `tool_index` 0 empties the pot. A magazine or pot below 1, or a
    /// data number the table lacks: EW_NUMBER, nothing changed.
    pub fn put_in_pot(&mut self, path: u16, magazine: i32, pot: i32, index: i32) -> Reply<()> {
        let tools = &mut (self.profile.paths)
            .get_mut(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?
            .managed_tools;
        if magazine < 1 || pot < 1 || index < 0 || index as usize > tools.len() {
            return Err(NUMBER);
        }
        for t in tools.iter_mut() {
            if (t.magazine, t.pot) == (magazine, pot) {
                (t.magazine, t.pot) = (0, 0);
            }
        }
        if let Some(t) = tools.get_mut((index as usize).wrapping_sub(1)) {
            (t.magazine, t.pot) = (magazine, pot);
        }
        Ok(())
    }

    /// 0x0150 + pots (i32 magazine, pot, 0 each): `[n, (magazine, pot,
    /// tool_index) * n]`, every pot asked, `tool_index` the data number of
    /// the `[[path.managed_tool]]` in it (0: an empty pot). A magazine or
    /// pot below 1: EW_NUMBER.
    pub fn read_pots(&self, path: u16, pots: &[i64]) -> Reply<Vec<i64>> {
        let tools = &self.path(path)?.managed_tools;
        let mut v = vec![(pots.len() / 3) as i64];
        for p in pots.chunks_exact(3) {
            let (mg, pot) = (p[0] as i32, p[1] as i32);
            if mg < 1 || pot < 1 {
                return Err(NUMBER);
            }
            let at = tools.iter().position(|t| (t.magazine, t.pot) == (mg, pot));
            v.extend([
                i64::from(mg),
                i64::from(pot),
                at.map_or(0, |i| i as i64 + 1),
            ]);
        }
        Ok(v)
    }

    /// 0x014e + pots (i32 magazine, pot, tool_index each): each tool
    /// management data number goes to its pot (as cnc_wrmagazine puts it);
    /// the answer is the pots registered. A magazine or pot below 1, a data
    /// number below 1 or that the table lacks: EW_NUMBER; a pot already
    /// holding a tool, or one pot twice: EW_DATA; nothing changed.
    pub fn register_pots(&mut self, path: u16, pots: &[i64]) -> Reply<i64> {
        let tools = &self.path(path)?.managed_tools;
        let recs: Vec<(i32, i32, i32)> = pots
            .chunks_exact(3)
            .map(|p| (p[0] as i32, p[1] as i32, p[2] as i32))
            .collect();
        for (k, &(mg, pot, index)) in recs.iter().enumerate() {
            if mg < 1 || pot < 1 || index < 1 || index as usize > tools.len() {
                return Err(NUMBER);
            }
            let taken = tools.iter().any(|t| (t.magazine, t.pot) == (mg, pot));
            if taken || recs[..k].iter().any(|r| (r.0, r.1) == (mg, pot)) {
                return Err(CncError::new(ew::EW_DATA));
            }
        }
        for &(mg, pot, index) in &recs {
            self.put_in_pot(path, mg, pot, index)?;
        }
        Ok(recs.len() as i64)
    }

    /// 0x014f + pots (i32 magazine, pot each): the tool in each pot leaves
    /// the magazine (an empty pot stays empty); the answer is the pots
    /// deleted. A magazine or pot below 1: EW_NUMBER, nothing changed.
    pub fn delete_pots(&mut self, path: u16, pots: &[i64]) -> Reply<i64> {
        self.path(path)?;
        let recs: Vec<(i32, i32)> = pots
            .chunks_exact(2)
            .map(|p| (p[0] as i32, p[1] as i32))
            .collect();
        if recs.iter().any(|&(mg, pot)| mg < 1 || pot < 1) {
            return Err(NUMBER);
        }
        for &(mg, pot) in &recs {
            self.put_in_pot(path, mg, pot, 0)?;
        }
        Ok(recs.len() as i64)
    }

    /// 0x0149 `[top]` + records as cnc_wrtool sends them (`per` integers
    /// each: 40, or 60 with cnc_regtool_f2's 40 custom data): tool management data numbers `top`, `top + 1` ... take them
    /// as [`Machine::write_managed`] writes one, a number one past the
    /// table's end adding an entry; the answer is the tools registered. A
    /// number below 1 or further past the end: EW_NUMBER; a record
    /// cnc_wrtool's checks refuse: EW_DATA; nothing changed.
    pub fn register_managed(&mut self, path: u16, top: i32, v: &[i64], per: usize) -> Reply<i64> {
        let tools = &self.path(path)?.managed_tools;
        let n = v.len() / per;
        if top < 1 || top as usize - 1 > tools.len() {
            return Err(NUMBER);
        }
        // Every record is checked first: a refused record changes nothing.
        v.chunks_exact(per).try_for_each(managed_record_ok)?;
        let end = (top as usize - 1 + n).max(tools.len());
        self.managed_mut(path)?.resize(end, Default::default());
        for (k, rec) in v.chunks_exact(per).enumerate() {
            self.write_managed(path, top + k as i32, rec)?;
        }
        Ok(n as i64)
    }

    /// cnc_regtool's and cnc_regtool_f2's answer: [`Machine::register_managed`]
    /// with records of the function's payload (40 or 60 integers).
    fn register_tools(&mut self, q: &super::route::Asked<'_>) -> Reply<Vec<i64>> {
        let per = q.f.payload.map_or(40, |p| p.fields.len());
        let n = self.register_managed(q.path, q.arg(0), q.payload, per)?;
        Ok(vec![n])
    }

    fn managed_mut(&mut self, path: u16) -> Reply<&mut Vec<super::profile::offset::ManagedTool>> {
        Ok(&mut (self.profile.paths)
            .get_mut(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?
            .managed_tools)
    }

    /// `0x014c [tool_no]` + a record (cnc_wrtool's payload fields: T code,
    /// life counter, life, rest (not kept), life status, custom bits,
    /// tool information, H, D, spindle speed, feedrate, magazine, pot, G,
    /// W, gno, grp, edge, original magazine and pot, custom 1..20):
    /// tool management data number `tool_no` takes them (what the
    /// simulator keeps: T code, life and counter, life status, H, D,
    /// speed, feedrate, magazine, pot, group, custom data). A data number
    /// the table lacks: EW_NUMBER; a life status past 3, a negative life
    /// or counter, or a payload short of a record: EW_DATA; nothing
    /// changed.
    pub fn write_managed(&mut self, path: u16, tool_no: i32, v: &[i64]) -> Reply<()> {
        let tools = &mut (self.profile.paths)
            .get_mut(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?
            .managed_tools;
        let t = (tool_no as usize)
            .checked_sub(1)
            .and_then(|i| tools.get_mut(i))
            .ok_or(NUMBER)?;
        managed_record_ok(v)?;
        let w = |i: usize| v.get(i).map_or(0, |x| *x as i32);
        t.number = w(0);
        (t.life_count, t.max_life, t.life_stat) = (w(1), w(2), w(4) as u8);
        (t.length, t.radius) = (w(7) as i16 as i32, w(8) as i16 as i32);
        (t.spindle_speed, t.feedrate) = (w(9), w(10));
        (t.magazine, t.pot) = (w(11) as i16 as i32, w(12) as i16 as i32);
        t.group = w(16);
        // Custom 1..20 (cnc_wrtool), or 1..40 (cnc_regtool_f2).
        t.custom = (20..v.len()).map(w).collect();
        Ok(())
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

    /// 0x014b [top, n]: tool management data top..top + n - 1, as many as
    /// the table holds from `top` (top < 1, n < 1 or top past the table:
    /// EW_NUMBER). A tool in a tool life group has its group's life and
    /// counter.
    fn tl_managed(&self, path: u16, top: i32, n: i32) -> Reply<Vec<u8>> {
        let p = (self.profile.paths)
            .get(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)?;
        let tools = &p.managed_tools;
        if top < 1 || n < 1 || top as usize > tools.len() {
            return Err(NUMBER);
        }
        let rec = |t: &super::profile::offset::ManagedTool| {
            let g = p
                .tool_groups
                .iter()
                .find(|g| t.group != 0 && g.number == t.group);
            let (count, life) = g.map_or((t.life_count, t.max_life), |g| (g.count, g.life));
            let mut w = [0; MNG_WORDS];
            w[..19].copy_from_slice(&[
                t.number,
                count,
                life,
                life - count,
                i32::from(t.life_stat),
                0,
                0,
                t.length,
                t.radius,
                t.spindle_speed,
                t.feedrate,
                t.magazine,
                t.pot,
                0,
                0,
                0,
                t.group << 16,
                t.magazine,
                t.pot,
            ]);
            for (d, c) in w[19..].iter_mut().zip(&t.custom) {
                *d = *c;
            }
            MngRecord(w)
        };
        let list: Vec<MngRecord> = tools
            .iter()
            .skip(top as usize - 1)
            .take(n as usize)
            .map(rec)
            .collect();
        Ok(MngList {
            count: list.len() as i32,
            tools: list,
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

/// cnc_wrtool's checks on a record: a payload short of a record, a life
/// status past 3, a negative life or counter: EW_DATA.
fn managed_record_ok(v: &[i64]) -> Reply<()> {
    let w = |i: usize| v.get(i).map_or(0, |x| *x as i32);
    if v.len() < 40 || !(0..=3).contains(&w(4)) || w(1) < 0 || w(2) < 0 {
        return Err(CncError::new(ew::EW_DATA));
    }
    Ok(())
}
