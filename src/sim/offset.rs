//! Simulated tool and work offsets: the profile's `[path.offset]` tables,
//! read and written through 0x0008..0x000d.

use super::Machine;
pub use super::profile::offset::{Offsets, ToolGroupProfile, ToolProfile};
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::offset::{Ack, Count, TOFS_SINGLE, TofsInfo, WRWKCDSHFT};
use crate::proto::packet::{CLASS_CNC, ReqSub};
use crate::proto::tool::{
    GroupRange, GroupRecord, GroupWrite, MNG_WORDS, MngList, MngRecord, PTLDATA, PTLINFO,
    PTLINFO_16, TLINSERT, TLMNG, TLOPTGRP, TLUSEGRP, UseGroups, WRGRPINFO,
};
use crate::proto::value::Value;
use crate::proto::wire::Wire;

const NUMBER: CncError = CncError::NUMBER;
/// cnc_modal's code of the T code (AUX_ORDER position 8, src/sim/modal.rs).
const T_CODE: i32 = crate::proto::program::AUX_ORDER[8];
const ATTRIB: CncError = CncError::new(ew::EW_ATTRIB);
const LENGTH: CncError = CncError::new(ew::EW_LENGTH);

/// Write payload: exactly `n` whole records.
fn records(payload: &[u8], n: usize) -> Reply<Vec<i32>> {
    if payload.len() != 8 * n {
        return Err(LENGTH);
    }
    let v = Vec::<Value>::from_bytes(payload).map_err(|_| LENGTH)?;
    Ok(v.iter().map(|r| r.value).collect())
}

impl Machine {
    fn offsets(&self, path: u16) -> Reply<&Offsets> {
        self.profile
            .paths
            .get(path as usize - 1)
            .map(|p| &p.offset)
            .ok_or(CncError::PATH)
    }

    fn offsets_mut(&mut self, path: u16) -> Reply<&mut Offsets> {
        self.profile
            .paths
            .get_mut(path as usize - 1)
            .map(|p| &mut p.offset)
            .ok_or(CncError::PATH)
    }

    fn axes_of(&self, path: u16) -> usize {
        self.profile.paths[path as usize - 1].axes.len()
    }

    /// Offset number range check: `lo..=hi` within `first..first+rows`.
    fn range(s: i32, e: i32, first: i32, rows: usize) -> Reply<(usize, usize)> {
        if s < first || e < s || e >= first + rows as i32 {
            return Err(NUMBER);
        }
        Ok(((s - first) as usize, (e - first) as usize))
    }

    /// 0x0008 [s, e, type]: type ≥ 1000 is cnc_rdtofs's single form.
    pub fn tofs_read(&mut self, path: u16, s: i32, e: i32, t: i32) -> Reply<Vec<Value>> {
        let o = self.offsets(path)?;
        let kind = if t >= TOFS_SINGLE - 1 {
            t - TOFS_SINGLE
        } else {
            t
        };
        let (a, b) = Self::range(s, e, 1, o.tool.len())?;
        let types = o.tool.first().map_or(0, Vec::len);
        let rows = &o.tool[a..=b];
        let v: Vec<i32> = match kind {
            -1 => rows.iter().flatten().copied().collect(),
            k if k >= 0 && (k as usize) < types => rows.iter().map(|r| r[k as usize]).collect(),
            _ => return Err(ATTRIB),
        };
        Ok(v.into_iter()
            .map(|x| Value::decimal(x, o.decimals))
            .collect())
    }

    /// 0x0009 [n, n, 1000 + type] + one record.
    pub fn tofs_write(&mut self, path: u16, n: i32, t: i32, payload: &[u8]) -> Reply<Ack> {
        let o = self.offsets_mut(path)?;
        let (a, _) = Self::range(n, n, 1, o.tool.len())?;
        // Any i32 from the client (fuzzing found `t - 1000` overflowing).
        let kind = t.checked_sub(TOFS_SINGLE).ok_or(ATTRIB)?;
        let types = o.tool.first().map_or(0, Vec::len);
        if kind < 0 || kind as usize >= types {
            return Err(ATTRIB);
        }
        let v = records(payload, 1)?;
        o.tool[a][kind as usize] = v[0];
        Ok(Ack)
    }

    pub fn tofs_info(&mut self, path: u16) -> Reply<TofsInfo> {
        let o = self.offsets(path)?;
        Ok(TofsInfo {
            reserved: 0,
            use_no: o.tool.len() as i16,
            ofs_type: o.memory,
            enable: o.enable,
        })
    }

    /// Which axes an axis word selects: -1 all (max_axes records), 1..=n one.
    fn zofs_axes(&self, path: u16, axis: i32) -> Reply<std::ops::Range<usize>> {
        let n = self.axes_of(path);
        match axis {
            -1 => Ok(0..self.profile.cnc.max_axes as usize),
            a if a >= 1 && a as usize <= n => Ok(a as usize - 1..a as usize),
            _ => Err(ATTRIB),
        }
    }

    /// 0x000b [s, e, axis].
    pub fn zofs_read(&mut self, path: u16, s: i32, e: i32, axis: i32) -> Reply<Vec<Value>> {
        let cols = self.zofs_axes(path, axis)?;
        let o = self.offsets(path)?;
        let (a, b) = Self::range(s, e, 0, o.work.len())?;
        let mut out = Vec::new();
        for row in &o.work[a..=b] {
            for c in cols.clone() {
                let v = row.get(c).copied().unwrap_or(0);
                out.push(Value::decimal(v, o.decimals));
            }
        }
        Ok(out)
    }

    /// 0x000c [n, n, axis] + one record per selected axis.
    pub fn zofs_write(&mut self, path: u16, n: i32, axis: i32, payload: &[u8]) -> Reply<Ack> {
        let cols = self.zofs_axes(path, axis)?;
        let axes = self.axes_of(path);
        let o = self.offsets_mut(path)?;
        let (a, _) = Self::range(n, n, 0, o.work.len())?;
        let v = records(payload, cols.len())?;
        let row = &mut o.work[a];
        for (c, x) in cols.zip(v) {
            if c < axes {
                if row.len() <= c {
                    row.resize(c + 1, 0);
                }
                row[c] = x;
            }
        }
        Ok(Ack)
    }

    /// 0x0063 \[axis\]: the work coordinate shift of one axis (1..=n) or all
    /// (-1: max_axes records).
    pub fn shift_read(&self, path: u16, axis: i32) -> Reply<Vec<i64>> {
        let cols = self.zofs_axes(path, axis)?;
        let o = self.offsets(path)?;
        Ok(cols
            .flat_map(|c| {
                let v = o.shift.get(c).copied().unwrap_or(0);
                [i64::from(v), i64::from(o.decimals)]
            })
            .collect())
    }

    /// The writes without a table entry: 0x0064 (work coordinate shift),
    /// 0x0054 (tool insert).
    pub(crate) fn offset_raw(&mut self, sub: &ReqSub) -> Option<Reply<Vec<u8>>> {
        match (sub.class, sub.cmd) {
            (CLASS_CNC, WRWKCDSHFT) => Some(self.shift_write(sub)),
            (CLASS_CNC, TLINSERT) => Some(self.tl_insert(sub.path, sub.args).map(|_| Vec::new())),
            (CLASS_CNC, WRGRPINFO) => Some(self.tl_write(sub)),
            (CLASS_CNC, TLMNG) => Some(self.tl_managed(sub.path, sub.args[0], sub.args[1])),
            (CLASS_CNC, PTLDATA) => Some(self.punch_data(sub.path, sub.args[1], sub.args[2])),
            (CLASS_CNC, PTLINFO) => Some(self.punch_info(sub.path)),
            (CLASS_CNC, TLUSEGRP) => Some(self.tl_use(sub.path)),
            (CLASS_CNC, TLOPTGRP) => Some(self.tl_optional(sub.path, sub.args[0])),
            _ => None,
        }
    }

    /// 0x0064 [axis] + one record per selected axis: the shift written.
    fn shift_write(&mut self, sub: &ReqSub) -> Reply<Vec<u8>> {
        self.zofs_axes(sub.path, sub.args[0]).and_then(|cols| {
            let axes = self.axes_of(sub.path);
            let v = records(&sub.payload, cols.len())?;
            let shift = &mut self.offsets_mut(sub.path)?.shift;
            for (c, x) in cols.zip(v).filter(|(c, _)| *c < axes) {
                if shift.len() <= c {
                    shift.resize(c + 1, 0);
                }
                shift[c] = x;
            }
            Ok(Vec::new())
        })
    }

    /// 0x000d: the workpiece coordinate systems (G54.. and G54.1 P..), not
    /// counting the external offset. Not checked against a real CNC.
    pub fn zofs_info(&mut self, path: u16) -> Reply<Count> {
        let o = self.offsets(path)?;
        Ok(Count {
            value: o.work.len().saturating_sub(1) as i32,
        })
    }
}

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

    /// 0x004a: how many tool life groups the path has.
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
            .sim_modal_aux(path, T_CODE)?
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_write_of_any_type_word_is_checked_without_overflow() {
        // Found by fuzzing (fuzz/regressions/request/tofs-type-overflow).
        let mut m = Machine::new(crate::sim::Profile::default());
        for t in [i32::MIN, i32::MIN + 999, -1, i32::MAX] {
            assert_eq!(m.tofs_write(1, 1, t, &[0; 8]).err(), Some(ATTRIB), "{t}");
        }
    }
}
