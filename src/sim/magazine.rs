//! Simulated tool management data and magazines: the profile's
//! `[[path.managed_tool]]` table, read, written and registered
//! (cnc_rdtool, cnc_wrtool, cnc_regtool), and the pots that hold its tools
//! (cnc_rdmagazine, cnc_regmagazine, cnc_delmagazine, cnc_wrmagazine).

use super::Machine;
use super::route::{Route, none};
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::cmd::{DELMAGAZINE, RDMAGAZINE, REGMAGAZINE, REGTOOL, REGTOOL_F2};
use crate::proto::cmd::{WRMAGAZINE, WRTOOL};
use crate::proto::tool::{MNG_WORDS, MngList, MngRecord, TLMNG};
use crate::proto::wire::Wire;

const NUMBER: CncError = CncError::NUMBER;

pub(super) const ROUTES: &[Route] = &[
    Route::cnc(TLMNG, |m, q| m.tl_managed(q.path, q.args[0], q.args[1])),
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
];

impl Machine {
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
