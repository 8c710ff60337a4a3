//! The simulator's parameter and diagnosis tables (profile section `[param]`)
//! and how a CNC answers reads and writes of them.
//!
//! Writes are checked as a real CNC checks them, in this order: payload size
//! (EW_LENGTH), number (EW_NUMBER), type and axis (EW_ATTRIB), read-only
//! (EW_PROT), then parameter write enable and MDI mode (EW_PASSWD). A refused
//! write changes nothing.

use super::machine::Machine;
use super::profile::Class;
pub use super::profile::param::{Entry, Kind, Params};
use super::route::{Asked, Route, enc};
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::cmd::RDSETNUM;
use crate::proto::described::block;
use crate::proto::param::{
    DIAGNOSS, DIAGNOSS16, DIAGTYPE, INFO3_FLAG, InfoEntry, InfoList, NumRange, PARAMTYPE, Param16,
    Param30, ParamType30, RDDIAGINFO, RDDIAGNUM, RDPARAINFO, RDPARAM, RDPARAM16, RDPARANUM, Table,
    WRITE_RECORDS_30, WRPARAM, WRPARAM16,
};
use crate::proto::value::{BASE_10, Value};
use crate::proto::wire::Wire;
use crate::proto::{OPTION_PARAM_15, OPTION_PARAM_16};

/// Items per answer of a 30i range read (cnc_rdparar); our choice, the
/// limit of a real CNC is not known.
pub const RANGE_PER_ANSWER: usize = 5;

/// cnc_rdsetnum: the smallest and largest setting data numbers (the
/// parameters up to `[param] setting_max`) and their count, each the low
/// half of a 32-bit word.
fn setting_num(m: &mut Machine, _: &Asked<'_>) -> Reply<Vec<i64>> {
    let p = &m.profile.param;
    let set: Vec<i32> = (p.parameters.iter())
        .map(|e| e.number)
        .filter(|n| *n <= p.setting_max)
        .collect();
    let (min, max) = (set.first().copied(), set.last().copied());
    Ok(vec![
        0,
        i64::from(min.unwrap_or(0)),
        0,
        i64::from(max.unwrap_or(0)),
        0,
        set.len() as i64,
    ])
}

const fn err(code: i16) -> CncError {
    CncError::new(code)
}

pub(super) const ROUTES: &[Route] = &[
    // [s, e, axis]: the 16i-class reads, one item (s == e) or a range
    // (cnc_rdparam, cnc_rdparar ...), through the block layout
    // (src/proto/described/block.rs) the client decodes with.
    Route::table(RDPARAM16, |m, q| {
        let r = m.param16(q.path, q.words[0], q.words[1], q.words[2] as i16);
        m.block_values(r)
    }),
    Route::table(DIAGNOSS16, |m, q| {
        m.class16()?;
        let [s, e, axis, ..] = q.words;
        let r = m.table_read16_range(q.path, Table::Diag, s, e, axis as i16);
        m.block_values(r)
    }),
    // [s, e, axis]: the 30i-class reads (a Series 15's too).
    Route::table(RDPARAM, |m, q| {
        let [s, e, axis, ..] = q.words;
        let r = m.param_read30(q.path, Table::Param, s, e, axis as i16);
        m.block_values(r)
    }),
    Route::table(DIAGNOSS, |m, q| {
        let [s, e, axis, ..] = q.words;
        let r = m.param_read30(q.path, Table::Diag, s, e, axis as i16);
        m.block_values(r)
    }),
    // With the list flag (args[4]): cnc_rdparainfo3, parameters from s on;
    // else the attribute record of one parameter.
    Route::cnc(PARAMTYPE, |m, q| match q.args[4] {
        INFO3_FLAG => m.table_info3(q.args[0], q.args[1]),
        _ => {
            m.class30()?;
            enc(m.table_type30(Table::Param, q.args[0]))
        }
    }),
    Route::cnc(DIAGTYPE, |m, q| {
        m.class30()?;
        enc(m.table_type30(Table::Diag, q.args[0]))
    }),
    Route::table(RDPARANUM, |m, _| Ok(num_values(m.table_num(Table::Param)))),
    Route::table(RDSETNUM, setting_num),
    Route::table(RDDIAGNUM, |m, _| Ok(num_values(m.table_num(Table::Diag)))),
    Route::cnc(RDPARAINFO, |m, q| {
        enc(m.table_info(Table::Param, q.args[0], q.args[1]))
    }),
    Route::cnc(RDDIAGINFO, |m, q| {
        enc(m.table_info(Table::Diag, q.args[0], q.args[1]))
    }),
    // cnc_wrparam's block (cnc_wrparas' blocks too), as sent.
    Route::table(WRPARAM, |m, q| {
        m.class30()?;
        m.table_write(q.path, false, q.bytes).map(|_| Vec::new())
    }),
    Route::table(WRPARAM16, |m, q| {
        m.class16()?;
        m.table_write(q.path, true, q.bytes).map(|_| Vec::new())
    }),
];

/// A number range's answer as its layout's integers: each 32-bit word as
/// its high and low halves.
fn num_values(r: NumRange) -> Vec<i64> {
    [r.min, r.max, r.total]
        .iter()
        .flat_map(|w| [i64::from(*w >> 16), i64::from(*w & 0xffff)])
        .collect()
}

impl Machine {
    /// A parameter block answer's bytes as the integers of its layout
    /// ([`block::wire_values`], which the dispatch encodes back).
    fn block_values(&self, r: Reply<Vec<u8>>) -> Reply<Vec<i64>> {
        let bytes = r?;
        if bytes.is_empty() {
            return Ok(Vec::new());
        }
        block::wire_values(self.set_class(), false, &bytes).map_err(|_| CncError::FUNC)
    }

    /// EW_FUNC unless the CNC is of the 16i class.
    fn class16(&self) -> Reply<()> {
        match self.profile.cnc.class {
            Class::Series16 => Ok(()),
            Class::Series30 => Err(CncError::FUNC),
        }
    }

    /// EW_FUNC unless the CNC is of the 30i class.
    fn class30(&self) -> Reply<()> {
        match self.profile.cnc.class {
            Class::Series30 => Ok(()),
            Class::Series16 => Err(CncError::FUNC),
        }
    }

    /// The FOCAS option probe's answer, in the 16i value form (SPEC.md §3.4).
    fn option_probe(&self, number: i32, axis: i16) -> Vec<u8> {
        Param16 {
            number,
            axis,
            ptype: 0,
            values: vec![i32::from(self.profile.cnc.option), 0, 0, 0, 0, 0, 0, 0],
        }
        .to_bytes()
    }

    /// 16i read of parameters (0x000e) [s, e, axis]: one item (`s == e`)
    /// or a range (cnc_rdparar), as answer blocks.
    fn param16(&mut self, path: u16, number: i32, e: i32, axis: i16) -> Reply<Vec<u8>> {
        self.class16()?;
        // The 16i-class FOCAS option probe (SPEC.md §3.4).
        if number == OPTION_PARAM_16 && e == number {
            return Ok(self.option_probe(number, axis));
        }
        self.table_read16_range(path, Table::Param, number, e, axis)
    }

    /// 30i read of parameters (0x008d) or diagnosis data (0x0093) [s, e, axis].
    fn param_read30(
        &mut self,
        path: u16,
        table: Table,
        s: i32,
        e: i32,
        axis: i16,
    ) -> Reply<Vec<u8>> {
        let c = &self.profile.cnc;
        let series15 = c.class == Class::Series16 && c.kind == 2;
        if series15 && table == Table::Param && s == OPTION_PARAM_15 {
            // The Series-15 FOCAS option probe (SPEC.md §3.4), in the 16i
            // value form the library reads it in.
            return Ok(self.option_probe(s, axis));
        }
        if series15 && s == e {
            // A Series 15 reads parameters and diagnosis data with the 30i
            // commands, answered in the 16i value form (as FANUC's library
            // reads them).
            return self
                .table_read16(path, table, s, axis)
                .map(|p| p.to_bytes());
        }
        self.class30()?;
        self.table_read30(path, table, s, e, axis)
    }
}

impl Machine {
    /// The items `s..=e` of a range read's answer (at most
    /// RANGE_PER_ANSWER); none is EW_NUMBER.
    fn range_items(&self, t: Table, s: i32, e: i32) -> Reply<Vec<&Entry>> {
        let items: Vec<&Entry> = self
            .table(t)
            .iter()
            .filter(|x| (s..=e).contains(&x.number))
            .take(RANGE_PER_ANSWER)
            .collect();
        if items.is_empty() {
            return Err(CncError::NUMBER);
        }
        Ok(items)
    }

    fn table(&self, t: Table) -> &[Entry] {
        match t {
            Table::Param => &self.profile.param.parameters,
            Table::Diag => &self.profile.param.diagnostics,
        }
    }

    fn entry(&self, t: Table, number: i32) -> Reply<&Entry> {
        self.table(t)
            .iter()
            .find(|e| e.number == number)
            .ok_or(CncError::NUMBER)
    }

    fn axes(&self, path: u16) -> Reply<usize> {
        self.profile
            .paths
            .get(path as usize - 1)
            .map(|p| p.axes.len())
            .ok_or(CncError::PATH)
    }

    /// The values answered for `axis`: one (no axis, or axis n) or max-axes
    /// (-1). A non-axis item asked for all axes answers its one value, with
    /// axis word 0 ([`answer_axis`]): the axis does not apply to it.
    fn read_values(&self, path: u16, e: &Entry, axis: i16) -> Reply<Vec<i32>> {
        let n = self.axes(path)?;
        match (e.axis, axis) {
            (false, 0 | -1) => Ok(vec![e.value(0)]),
            (true, -1) => Ok((0..self.profile.cnc.max_axes as usize)
                .map(|i| e.value(i))
                .collect()),
            (true, a) if a >= 1 && (a as usize) <= n => Ok(vec![e.value(a as usize - 1)]),
            _ => Err(err(ew::EW_ATTRIB)),
        }
    }

    /// 30i read (0x008d / 0x0093) [s, e, axis]. Every answer block has
    /// max-axes value records (8 + 8 · max_axes bytes, unused records zero):
    /// FANUC's cnc_rdparar sends the same [s, e, axis] as cnc_rdparam and
    /// needs whole blocks, so a CNC cannot answer the two differently.
    ///
    /// `s == e`: that item, as `Machine::read_values` allows. A range
    /// (`s < e`, cnc_rdparar): the existing items from `s` on, at most
    /// [`RANGE_PER_ANSWER`] per answer (the library asks again from the
    /// last number + 1); EW_NUMBER if there is none. In a range every item
    /// answers in its own form (our choice; what a real CNC does is not
    /// known): axis -1 all axes; axis 0 a non-axis item its value and an
    /// axis item all axes (axis word -1); axis n an axis item its n-th value
    /// and a non-axis item its value (axis word 0).
    pub fn table_read30(&self, path: u16, t: Table, s: i32, e: i32, axis: i16) -> Reply<Vec<u8>> {
        let max = self.profile.cnc.max_axes as usize;
        let block = |x: &Entry, axis: i16, vals: Vec<i32>| {
            let mut values: Vec<Value> = vals
                .into_iter()
                .map(|v| Value {
                    value: v,
                    base: BASE_10,
                    exp: if x.kind == Kind::Real { x.decimals } else { 0 },
                })
                .collect();
            values.resize(max.max(values.len()), Value::default());
            Param30 {
                number: x.number,
                axis,
                ptype: x.kind.code(t),
                values,
            }
            .to_bytes()
        };
        if s == e {
            let x = self.entry(t, s)?;
            return Ok(block(
                x,
                answer_axis(x, axis),
                self.read_values(path, x, axis)?,
            ));
        }
        let n_axes = self.axes(path)?;
        if axis < -1 || axis as i32 > n_axes as i32 {
            return Err(err(ew::EW_ATTRIB));
        }
        let items = self.range_items(t, s, e)?;
        let mut out = Vec::new();
        for x in items {
            let a = range_axis(x, axis);
            out.extend(block(x, a, self.read_values(path, x, a)?));
        }
        Ok(out)
    }

    /// 16i read (0x000e / 0x0030): number, axis, type, max-axes 4-byte values
    /// (a 16i CNC always sends the whole array; a real takes two words).
    pub fn table_read16(&self, path: u16, t: Table, number: i32, axis: i16) -> Reply<Param16> {
        let x = self.entry(t, number)?;
        let vals = self.read_values(path, x, axis)?;
        let mut values: Vec<i32> = if x.kind == Kind::Real {
            vals.iter()
                .flat_map(|v| [*v, x.decimals as i32 & 0xffff])
                .collect()
        } else {
            vals
        };
        values.resize((self.profile.cnc.max_axes as usize).max(values.len()), 0);
        Ok(Param16 {
            number,
            axis: answer_axis(x, axis),
            ptype: x.kind.code(t),
            values,
        })
    }

    /// 16i read (0x000e / 0x0030) [s, e, axis] as answer bytes. `s == e`:
    /// that item ([`Machine::table_read16`]). A range (cnc_rdparar): the
    /// existing items from `s` on, at most [`RANGE_PER_ANSWER`] per answer,
    /// each in its own form as in [`Machine::table_read30`], every block
    /// 8 + 4 · max_axes bytes (FANUC's library steps through the answer by
    /// that size). A real item for all axes takes two words a value, longer
    /// than a block: the library reads its values on past the block, so it
    /// ends its answer. EW_NUMBER if there is no item.
    pub fn table_read16_range(
        &self,
        path: u16,
        t: Table,
        s: i32,
        e: i32,
        axis: i16,
    ) -> Reply<Vec<u8>> {
        if s == e {
            return self.table_read16(path, t, s, axis).map(|p| p.to_bytes());
        }
        let n_axes = self.axes(path)?;
        if axis < -1 || axis as i32 > n_axes as i32 {
            return Err(err(ew::EW_ATTRIB));
        }
        let block = 8 + 4 * self.profile.cnc.max_axes as usize;
        let items = self.range_items(t, s, e)?;
        let mut out = Vec::new();
        for x in items {
            let a = range_axis(x, axis);
            // The axis word is the axis answered for, as in a 30i range.
            let mut p = self.table_read16(path, t, x.number, a)?;
            p.axis = a;
            let bytes = p.to_bytes();
            let long = bytes.len() > block;
            out.extend(bytes);
            if long {
                break;
            }
        }
        Ok(out)
    }

    /// 0x00a0 / 0x00a2: the 28-byte attribute record of one item (number
    /// at offset 8, type, axis attribute 2 for axis items; other words 0).
    pub fn table_type30(&self, t: Table, number: i32) -> Reply<ParamType30> {
        let x = self.entry(t, number)?;
        Ok(ParamType30 {
            number,
            ptype: x.kind.code(t),
            axis: if x.axis { 2 } else { 0 },
            ..ParamType30::default()
        })
    }

    /// 0x00a0 with the list flag (cnc_rdparainfo3): the previous and next
    /// numbers, then up to `n` parameters from `s` on, each its attribute
    /// record from `number` on (as 0x00a0 answers one).
    pub fn table_info3(&self, s: i32, n: i32) -> Reply<Vec<u8>> {
        let list = self.table_info(Table::Param, s, n)?;
        let mut out = [list.prev, list.next].map(i32::to_be_bytes).concat();
        for e in &list.entries {
            out.extend(&self.table_type30(Table::Param, e.number)?.to_bytes()[8..]);
        }
        Ok(out)
    }

    /// 0x0011 / 0x0032: smallest and largest number, count.
    pub fn table_num(&self, t: Table) -> NumRange {
        let all = self.table(t);
        NumRange {
            min: all.first().map_or(0, |e| e.number),
            max: all.last().map_or(0, |e| e.number),
            total: all.len() as i32,
        }
    }

    /// 0x0010 / 0x0031: up to `n` items from `s` on, with the previous and
    /// next existing numbers (0 where there is none).
    pub fn table_info(&self, t: Table, s: i32, n: i32) -> Reply<InfoList> {
        let all = self.table(t);
        let first = all
            .iter()
            .position(|e| e.number >= s)
            .ok_or(CncError::NUMBER)?;
        let take = (n.max(0) as usize).min(all.len() - first);
        let entries: Vec<InfoEntry> = all[first..first + take]
            .iter()
            .map(|e| InfoEntry {
                number: e.number,
                ptype: e.kind.info(e.axis),
            })
            .collect();
        let prev = if first > 0 { all[first - 1].number } else { 0 };
        let next = all.get(first + take).map_or(0, |e| e.number);
        Ok(InfoList {
            prev,
            next,
            entries,
        })
    }

    /// 0x008e (30i) / 0x000f (16i): write parameters. A payload is one
    /// block (cnc_wrparam: 264 bytes on the 30i class, 8 + 4 · max_axes on
    /// the 16i class) or several of 8 + 8 · max_axes / 8 + 4 · max_axes
    /// bytes (cnc_wrparas). Every block is checked before any is applied, so a
    /// refused subpacket changes nothing and answers the first refusal (a
    /// real CNC is said to stop at the failing parameter, keeping the
    /// ones before it in the same subpacket).
    pub fn table_write(&mut self, path: u16, class16: bool, payload: &[u8]) -> Reply<Vec<u8>> {
        let max = self.profile.cnc.max_axes as usize;
        // cnc_wrparam's 30i block has 32 records whatever the CNC's axes;
        // cnc_wrparas's blocks have max-axes records (8-byte records on the
        // 30i class, 4-byte words on the 16i class), several per subpacket.
        let size = if class16 { 8 + 4 * max } else { 8 + 8 * max };
        let blocks: Vec<&[u8]> = if !class16 && payload.len() == 8 + 8 * WRITE_RECORDS_30 {
            vec![payload]
        } else {
            if payload.is_empty() || !payload.len().is_multiple_of(size) {
                return Err(err(ew::EW_LENGTH));
            }
            payload.chunks_exact(size).collect()
        };
        let mut all = Vec::with_capacity(blocks.len());
        for b in blocks {
            all.push(self.check_write(path, class16, b)?);
        }
        for (number, new) in all {
            let x = self.param_entry_mut(number).ok_or(CncError::NUMBER)?;
            for (slot, v) in new {
                if x.values.len() <= slot {
                    x.values.resize(slot + 1, 0);
                }
                x.values[slot] = v;
            }
        }
        Ok(Vec::new())
    }

    /// Checks one write block and returns the parameter's number and the
    /// (slot, stored value) pairs it sets.
    fn check_write(
        &self,
        path: u16,
        class16: bool,
        payload: &[u8],
    ) -> Reply<(i32, Vec<(usize, i32)>)> {
        let (number, axis, ptype, raw): (i32, i16, u16, Vec<(i32, i16)>) = if class16 {
            let p = Param16::from_bytes(payload).map_err(|_| err(ew::EW_LENGTH))?;
            // A 16i real takes two words: the value, the decimals in the
            // low half of the second.
            let v = if p.ptype == Kind::Real.code(Table::Param) {
                p.values
                    .chunks_exact(2)
                    .map(|c| (c[0], c[1] as i16))
                    .collect()
            } else {
                p.values.iter().map(|v| (*v, 0)).collect()
            };
            (p.number, p.axis, p.ptype, v)
        } else {
            let p = Param30::from_bytes(payload).map_err(|_| err(ew::EW_LENGTH))?;
            let v = p.values.iter().map(|r| (r.value, r.exp)).collect();
            (p.number, p.axis, p.ptype, v)
        };
        let n_axes = self.axes(path)?;
        let x = self.entry(Table::Param, number)?;
        if ptype != x.kind.code(Table::Param) {
            return Err(err(ew::EW_ATTRIB));
        }
        // Which stored slots the write fills, from which payload values.
        let slots: Vec<(usize, usize)> = match (x.axis, axis) {
            (false, 0) => vec![(0, 0)],
            (true, -1) => (0..n_axes).map(|i| (i, i)).collect(),
            (true, a) if a >= 1 && (a as usize) <= n_axes => vec![(a as usize - 1, 0)],
            _ => return Err(err(ew::EW_ATTRIB)),
        };
        if x.read_only {
            return Err(err(ew::EW_PROT));
        }
        let mdi = self.profile.paths[path as usize - 1].status.aut == 0;
        if !self.profile.param.param_write_enable || !mdi {
            return Err(err(ew::EW_PASSWD));
        }
        // Convert everything first, so a bad value changes nothing.
        let mut new = Vec::with_capacity(slots.len());
        for (slot, src) in slots {
            let (v, dec) = raw.get(src).copied().unwrap_or((0, 0));
            let v = if x.kind == Kind::Real {
                rescale(v, dec, x.decimals).ok_or(err(ew::EW_DATA))?
            } else {
                x.kind.normalize(v)
            };
            new.push((slot, v));
        }
        Ok((number, new))
    }

    fn param_entry_mut(&mut self, number: i32) -> Option<&mut Entry> {
        self.profile
            .param
            .parameters
            .iter_mut()
            .find(|e| e.number == number)
    }

    /// Sets a parameter's value from inside the machine (e.g. the part
    /// counter 6711 when a program ends), without the write protection a
    /// FOCAS write meets. `axis` 0 for a non-axis parameter, else 1-based.
    /// Returns false if the parameter does not exist. Reals are in units of
    /// their decimals.
    pub fn set_param_value(&mut self, number: i32, axis: i16, value: i32) -> bool {
        let Some(x) = self.param_entry_mut(number) else {
            return false;
        };
        let slot = if axis >= 1 { axis as usize - 1 } else { 0 };
        if x.values.len() <= slot {
            x.values.resize(slot + 1, 0);
        }
        x.values[slot] = x.kind.normalize(value);
        true
    }

    /// A parameter's value (0 for axes without one); None if it does not exist.
    pub fn param_value(&self, number: i32, axis: i16) -> Option<i32> {
        let x = self.entry(Table::Param, number).ok()?;
        Some(x.value(if axis >= 1 { axis as usize - 1 } else { 0 }))
    }

    /// Turns parameter write enable (PWE) on or off.
    pub fn set_param_write_enable(&mut self, on: bool) {
        self.profile.param.param_write_enable = on;
    }
}

/// `v · 10^-from` in units of `10^-to`, if exact and in range.
fn rescale(v: i32, from: i16, to: i16) -> Option<i32> {
    let d = to as i32 - from as i32;
    let p = 10i64.checked_pow(d.unsigned_abs())?;
    let x = if d >= 0 {
        (v as i64).checked_mul(p)?
    } else if (v as i64) % p == 0 {
        v as i64 / p
    } else {
        return None;
    };
    i32::try_from(x).ok()
}

/// The axis an item of a range read answers for when the range is asked
/// with `axis`: -1 all axes; 0 a non-axis item its value and an axis item
/// all axes; n an axis item its n-th value, a non-axis item its value.
fn range_axis(x: &Entry, axis: i16) -> i16 {
    match (x.axis, axis) {
        (_, -1) | (true, 0) => -1,
        (false, _) => 0,
        (true, a) => a,
    }
}

/// The axis word of the answer for an item asked with `axis`: a non-axis
/// item asked for all axes (-1) answers as a non-axis item (0), which
/// FANUC's library reads as one value; otherwise the axis asked.
fn answer_axis(e: &Entry, axis: i16) -> i16 {
    if !e.axis && axis == -1 { 0 } else { axis }
}
