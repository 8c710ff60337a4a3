//! Simulated tool and work offsets: the profile's `[path.offset]` tables,
//! read and written through 0x0008..0x000d, and the work coordinate shift.

use super::Machine;
pub use super::profile::offset::{Offsets, ToolGroupProfile, ToolProfile};
use super::route::{Asked, Route, enc, none};
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::cmd::RDTLMSINFO;
use crate::proto::cmd::RDWKCDSHFT;
use crate::proto::cmd::{CLRTOFS, RD3DTOFS, RDBTOFSINFO, RDRADOFS, RDTLDATA, RDTOFSENBL};
use crate::proto::cmd::{RDACTFIXOFS, RDTOFSINFO, RDVOLCCOMP, RDZOFSINFO};
use crate::proto::cmd::{TOFS_RNGE, WKSFT_RNGE, ZOFS_RNGE};
use crate::proto::offset::{
    Ack, Count, RDTOFS, RDZOFS, TOFS_SINGLE, TofsInfo, WRTOFS, WRWKCDSHFT, WRZOFS,
};
use crate::proto::packet::ReqSub;
use crate::proto::value::Value;
use crate::proto::wire::Wire;

const NUMBER: CncError = CncError::NUMBER;
/// cnc_modal's code of the D code (AUX_ORDER position 1, src/sim/modal.rs).
const D_CODE: i32 = crate::proto::program::AUX_ORDER[1];
const ATTRIB: CncError = CncError::new(ew::EW_ATTRIB);
const LENGTH: CncError = CncError::new(ew::EW_LENGTH);

pub(super) const ROUTES: &[Route] = &[
    // [s, e, type] (type >= 1000: cnc_rdtofs's single form)
    Route::cnc(RDTOFS, |m, q| {
        enc(m.tofs_read(q.path, q.args[0], q.args[1], q.args[2]))
    }),
    // [n, n, 1000 + type] + one record
    Route::cnc(WRTOFS, |m, q| {
        enc(m.tofs_write(q.path, q.args[0], q.args[2], &q.payload))
    }),
    // [s, e, axis]
    Route::cnc(RDZOFS, |m, q| {
        enc(m.zofs_read(q.path, q.args[0], q.args[1], q.args[2]))
    }),
    // [n, n, axis] + records
    Route::cnc(WRZOFS, |m, q| {
        enc(m.zofs_write(q.path, q.args[0], q.args[2], &q.payload))
    }),
    Route::cnc(WRWKCDSHFT, |m, q| m.shift_write(q)),
    Route::table(RDTOFSINFO, tofs_info),
    Route::table(RDZOFSINFO, |m, q| {
        m.zofs_info(q.path).map(|c| vec![i64::from(c.value)])
    }),
    // [MEASURE] can be used while tool offsets are (cnc_rdtofsinfo2's).
    Route::table(RDTOFSENBL, |m, q| {
        m.offsets(q.path).map(|o| vec![i64::from(o.enable)])
    }),
    Route::table(CLRTOFS, |m, q| none(m.tofs_clear(q.path, q.arg(0)))),
    Route::table(RDTLMSINFO, length_measurement),
    Route::table(RDTLDATA, |m, q| {
        let o = m.offsets(q.path)?;
        Ok(vec![o.tl.into(), o.decimals.into()])
    }),
    Route::table(RDBTOFSINFO, |m, q| {
        let o = m.offsets(q.path)?;
        Ok([o.b_axis, o.b_cancel, o.memory].map(i64::from).to_vec())
    }),
    Route::table(RDRADOFS, radius_offset),
    Route::table(RD3DTOFS, offset_3d),
    Route::table(RDWKCDSHFT, |m, q| {
        m.shift_read(q.path, q.arg(0))
            .map(|r| [vec![i64::from(q.arg(0))], r].concat())
    }),
    // [n, 0, 1000 + type]: tool offset n of one type.
    Route::table(TOFS_RNGE, |m, q| {
        let o = m.offsets(q.path)?;
        Machine::range(q.words[0], q.words[0], 1, o.tool.len())?;
        let types = o.tool.first().map_or(0, Vec::len) as i32;
        let t = q.words[2].wrapping_sub(TOFS_SINGLE);
        if !(0..types).contains(&t) {
            return Err(ATTRIB);
        }
        m.offset_limits(q.path)
    }),
    // [n, 0, axis]: work zero offset n (0 external) of one axis.
    Route::table(ZOFS_RNGE, |m, q| {
        m.one_axis(q.path, q.words[2])?;
        let o = m.offsets(q.path)?;
        Machine::range(q.words[0], q.words[0], 0, o.work.len())?;
        m.offset_limits(q.path)
    }),
    // [axis]: the work coordinate shift of one axis.
    Route::table(WKSFT_RNGE, |m, q| {
        m.one_axis(q.path, q.words[0])?;
        m.offset_limits(q.path)
    }),
    // The volumetric compensation amount of each of the path's axes.
    Route::table(RDVOLCCOMP, |m, q| {
        let n = m.offsets(q.path).map(|_| m.axes_of(q.path))?;
        let v = &m.offsets(q.path)?.volumetric;
        Ok((0..n)
            .map(|k| i64::from(v.get(k).copied().unwrap_or(0)))
            .collect())
    }),
    // [axis]: the fixture offset in effect, each selected axis's value
    // (the offsets' decimals).
    Route::table(RDACTFIXOFS, |m, q| {
        let cols = m.zofs_axes(q.path, q.words[0])?;
        let o = m.offsets(q.path)?;
        let n = o.fixture_active;
        let row = usize::try_from(n.wrapping_sub(1)).ok();
        let row = row
            .and_then(|k| o.fixture.get(k))
            .map_or(&[][..], Vec::as_slice);
        let mut v = vec![i64::from(q.words[0]), i64::from(n)];
        for c in cols {
            let x = row.get(c).copied().unwrap_or(0);
            v.extend([i64::from(x), base10(o.decimals)]);
        }
        Ok(v)
    }),
];

/// The base and exponent word of a value record of `decimals` places,
/// base 10.
fn base10(decimals: i16) -> i64 {
    (10 << 16) | i64::from(decimals as u16)
}

/// cnc_rdtofsinfo2's words (cnc_rdtofsinfo reads a prefix of them).
fn tofs_info(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    m.tofs_info(q.path).map(|t| {
        let w = [t.reserved, t.use_no, t.ofs_type, t.enable];
        w.map(i64::from).to_vec()
    })
}

/// The cutter compensation in effect: G group 07's code (0 G40, 1 G41, 2
/// G42), its plane's axes (group 02; the path's axes 1, 2, 3 as X, Y, Z),
/// the offset along the plane's second axis, and the offsets' decimals.
/// Compensating, the offset is the D code's radius (geometry + wear): the
/// simulator's tool moves along the plane's first axis, G41 offsets it to
/// the left (+), G42 to the right (−).
fn compensation(m: &mut Machine, path: u16) -> Reply<(u8, [i64; 2], i64, i64)> {
    let (mode, plane) = (m.modal_g(path, 6), m.modal_g(path, 1));
    let axes = [[1, 2], [3, 1], [2, 3]][usize::from(plane.min(2))];
    let d = m.aux_modal(path, D_CODE)?.0.first().map_or(0, |a| a.value);
    let o = m.offsets(path)?;
    let r = (o.tool.get(d.wrapping_sub(1) as usize))
        .map_or(0, |t| t.iter().take(2).map(|&v| i64::from(v)).sum());
    let v = match mode {
        1 => r,
        2 => -r,
        _ => 0,
    };
    Ok((mode, axes, v, o.decimals.into()))
}

/// cnc_rdradofs: mode, plane axes, then the vector as value records
/// (value, decimals; the last one's decimals not sent).
fn radius_offset(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let (mode, axes, v, dec) = compensation(m, q.path)?;
    Ok(vec![mode.into(), axes[0], axes[1], 0, dec, v])
}

/// cnc_rd3dtofs: the same compensation in X, Y, Z (the simulator follows
/// no other 3-D tool offset).
fn offset_3d(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let (mode, axes, v, dec) = compensation(m, q.path)?;
    let mut xyz = [0; 3];
    xyz[axes[1] as usize - 1] = v;
    Ok(vec![mode.into(), 1, 2, 3, xyz[0], dec, xyz[1], dec, xyz[2]])
}

/// cnc_rdtlmsinfo: the T and M codes in effect and the H code's length
/// (geometry, type 3; its decimals), the offset a measurement writes: the
/// simulator measures nothing, it shows the length the H code holds.
fn length_measurement(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let code = |m: &Machine, k: usize| {
        let c = crate::proto::program::AUX_ORDER[k];
        m.aux_modal(q.path, c)
            .map(|a| a.0.first().map_or(0, |a| a.value))
    };
    let (t, mc, h) = (code(m, 8)?, code(m, 6)?, code(m, 4)?);
    let o = m.offsets(q.path)?;
    let hm = (o.tool.get(h.wrapping_sub(1) as usize)).map_or(0, |r| r.get(3).copied().unwrap_or(0));
    Ok([t, mc, hm, o.decimals.into(), h].map(i64::from).to_vec())
}

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

    /// 0x01b7 \[type\]: every tool offset of `type` (a column; -1: all)
    /// set to 0; another type: EW_ATTRIB, nothing changed.
    pub fn tofs_clear(&mut self, path: u16, t: i32) -> Reply<()> {
        let o = self.offsets_mut(path)?;
        let types = o.tool.first().map_or(0, Vec::len) as i32;
        if !(-1..types).contains(&t) {
            return Err(ATTRIB);
        }
        for row in &mut o.tool {
            for (k, v) in row.iter_mut().enumerate() {
                if t == -1 || t == k as i32 {
                    *v = 0;
                }
            }
        }
        Ok(())
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

    /// The range offsets may be set in and the setting status (the
    /// cnc_*_rnge answers: two value records and a word).
    fn offset_limits(&self, path: u16) -> Reply<Vec<i64>> {
        let o = self.offsets(path)?;
        // Each limit a value record: base 10, the offsets' decimals.
        let [lo, hi] = o.limits.map(i64::from);
        let exp = base10(o.decimals);
        Ok(vec![lo, exp, hi, exp, i64::from(o.limit_status)])
    }

    /// One axis of the path, 1..=n (else EW_ATTRIB).
    fn one_axis(&self, path: u16, axis: i32) -> Reply<()> {
        let n = self.offsets(path).map(|_| self.axes_of(path))?;
        if axis < 1 || axis as usize > n {
            return Err(ATTRIB);
        }
        Ok(())
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
