//! Simulated custom macro variables: which numbers exist, which are
//! write-protected, and their values (digits and decimal places, or vacant).

use super::Machine;
use super::profile::Class;
pub use super::profile::macros::{MAX_DEC, Macros, PCodeMacros, parse_decimal};
use super::route::{Route, enc};
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::cmd::{
    GETRTMRVAR, GETRTMRVARS, RDMACROINFO, RDMACRONUM, RDMACROR2, RDPMACRO, RDPMACROINFO,
    RDPMACROINFO2, RDPMACROR2, WRMACROR2, WRPMACRO, WRPMACROR2,
};
use crate::proto::macros::{MacroInfo, RDMACRO, VACANT_DEC, WRMACRO};
use crate::proto::value::Value;
use crate::proto::wire::Wire;

pub(super) const ROUTES: &[Route] = &[
    // [s, e]
    Route::cnc(RDMACRO, |m, q| {
        enc(m.read_macros(q.path, q.args[0], q.args[1]))
    }),
    // [s, e] + records
    Route::cnc(WRMACRO, |m, q| match Vec::<Value>::from_bytes(&q.payload) {
        Ok(v) => m
            .write_macros(q.path, q.args[0], q.args[1], &v)
            .map(|()| Vec::new()),
        Err(_) => Err(CncError::new(ew::EW_LENGTH)),
    }),
    // cnc_rdmacror2 [s, n], cnc_rdpmacror2 [s, n, type]: the doubles
    // (their bits) of the custom or the P-code store.
    Route::table(RDMACROR2, read_doubles),
    Route::table(RDPMACROR2, read_doubles),
    // cnc_wrmacror2 [s], cnc_wrpmacror2 [s, 0, type] + doubles: the count.
    Route::table(WRMACROR2, write_doubles),
    Route::table(WRPMACROR2, write_doubles),
    Route::table(RDMACROINFO, |m, q| {
        m.macro_info(q.path)
            .map(|i| vec![i64::from(i.use_no1), i64::from(i.use_no2)])
    }),
    // The real-time custom macro variables' counts.
    Route::table(GETRTMRVAR, |m, q| {
        Ok(vec![i64::from(m.path(q.path)?.rt_macros.volatile)])
    }),
    Route::table(GETRTMRVARS, |m, q| {
        Ok(vec![i64::from(m.path(q.path)?.rt_macros.nonvolatile)])
    }),
    Route::table(RDPMACROINFO, pcode_info),
    Route::table(RDPMACRO, pcode_read),
    Route::table(RDPMACROINFO2, pcode_info2),
    Route::table(WRPMACRO, pcode_write),
    Route::table(RDMACRONUM, macro_number),
];

/// The store an IEEE-double command reads or writes: the P-code variables
/// (`[path.pmacros]`) for cnc_rdpmacror2 / cnc_wrpmacror2's commands, the
/// custom ones (`[path.macros]`) for cnc_rdmacror2 / cnc_wrmacror2's.
/// Their `type` word (0..=2) is not read: what it selects on a CNC is not
/// known.
fn doubles_store<'a>(m: &'a mut Machine, q: &super::route::Asked<'_>) -> Reply<&'a mut Macros> {
    let pcode = matches!(q.f.forms.first(), Some(f) if f.cmd == RDPMACROR2 || f.cmd == WRPMACROR2);
    let p = m
        .profile
        .paths
        .get_mut(usize::from(q.path).wrapping_sub(1))
        .ok_or(CncError::PATH)?;
    Ok(if pcode {
        &mut p.pmacros.vars
    } else {
        &mut p.macros
    })
}

/// cnc_rdmacror2, cnc_rdpmacror2: up to `n` (the second word: 1..= the
/// records a request carries, the function's `Records::max`) variables
/// from `s` (the first) as doubles (their bits), stopping at the first
/// number that does not exist (EW_NUMBER if that is `s`). A vacant
/// variable reads as 0.0: how a real CNC marks vacancy in this form is not
/// known.
fn read_doubles(m: &mut Machine, q: &super::route::Asked<'_>) -> Reply<Vec<i64>> {
    let most = q.f.records.map_or(0, |r| i32::from(r.max));
    let (s, n) = (q.words[0], q.words[1]);
    let v = doubles_store(m, q)?;
    if n <= 0 || n > most || !v.exists(s) {
        return Err(CncError::NUMBER);
    }
    Ok((s..s.saturating_add(n))
        .take_while(|k| v.exists(*k))
        .map(|k| {
            let (x, d) = v.values.get(&k).copied().unwrap_or((0, 0));
            (f64::from(x) / 10f64.powi(i32::from(d))).to_bits() as i64
        })
        .collect())
}

/// cnc_wrmacror2, cnc_wrpmacror2: the payload's doubles (their bits) to
/// the variables from `s` (the first word), which later reads give back;
/// all must exist and be writable (else EW_NUMBER / EW_PROT, nothing
/// written), none EW_LENGTH. Each double is kept with the fewest decimal
/// places (up to 9) that reproduce it; NaN and infinities are EW_DATA.
/// Answers the count written.
fn write_doubles(m: &mut Machine, q: &super::route::Asked<'_>) -> Reply<Vec<i64>> {
    let s = q.words[0];
    let v = doubles_store(m, q)?;
    let n = i32::try_from(q.payload.len()).unwrap_or(i32::MAX);
    if n == 0 {
        return Err(CncError::new(ew::EW_LENGTH));
    }
    let e = s.checked_add(n - 1).ok_or(CncError::NUMBER)?;
    if !(s..=e).all(|k| v.exists(k)) {
        return Err(CncError::NUMBER);
    }
    if (s..=e).any(|k| v.protected(k)) {
        return Err(CncError::new(ew::EW_PROT));
    }
    let new = q
        .payload
        .iter()
        .map(|b| double_to_decimal(f64::from_bits(*b as u64)).ok_or(CncError::new(ew::EW_DATA)))
        .collect::<Reply<Vec<_>>>()?;
    for (k, x) in (s..=e).zip(new) {
        v.values.insert(k, x);
    }
    Ok(vec![i64::from(n)])
}

/// cnc_rdmacronum: the number and attribute of the custom macro variable
/// whose name is the payload's bytes (up to a NUL), from the path's
/// `[path.macros.names]`; a name the path does not have is EW_DATA.
fn macro_number(m: &mut Machine, q: &super::route::Asked<'_>) -> Reply<Vec<i64>> {
    let name: Vec<u8> = q
        .payload
        .iter()
        .map(|&b| b as u8)
        .take_while(|&b| b != 0)
        .collect();
    let names = &m.macros(q.path)?.names;
    let (n, attr) = std::str::from_utf8(&name)
        .ok()
        .and_then(|k| names.get(k))
        .ok_or(CncError::new(ew::EW_DATA))?;
    Ok(vec![i64::from(*n), i64::from(*attr)])
}

/// cnc_wrpmacro, cnc_wrpmacror: P-code variables `s..=e` (the request's
/// first two words) from the payload's records (digits, places), which
/// later reads of the store give back. All or nothing per request: a
/// number the path does not have (or more than [`PCODE_RECORDS`]) is
/// EW_NUMBER, a protected one EW_PROT, a value that is neither vacant
/// (0 with -1 places) nor of 0..=9 places EW_DATA, too few records
/// EW_LENGTH; then nothing of the request is written (cnc_wrpmacror's
/// earlier requests stay written).
fn pcode_write(m: &mut Machine, q: &super::route::Asked<'_>) -> Reply<Vec<i64>> {
    let (s, e) = (q.words[0], q.words[1]);
    // A 16i (not Series 15) gets binary records, which read back with 9
    // significant digits: kept in their shortest decimal form, as
    // cnc_wrmacro's are.
    let binary = m.profile.cnc.class == Class::Series16 && m.profile.cnc.kind != 2;
    let p = m
        .profile
        .paths
        .get_mut(usize::from(q.path).wrapping_sub(1))
        .map(|p| &mut p.pmacros.vars)
        .ok_or(CncError::PATH)?;
    p.check_range_of(s, e, PCODE_RECORDS)?;
    let n = usize::try_from(i64::from(e) - i64::from(s) + 1).unwrap_or(0);
    if q.payload.len() < 2 * n {
        return Err(CncError::new(ew::EW_LENGTH));
    }
    if (s..=e).any(|k| p.protected(k)) {
        return Err(CncError::new(ew::EW_PROT));
    }
    let new = q.payload[..2 * n]
        .chunks(2)
        .map(|r| {
            let (mut v, mut d) = (r[0] as i32, r[1] as i16);
            while binary && d > 0 && v % 10 == 0 {
                v /= 10;
                d -= 1;
            }
            check_value(v, d)
        })
        .collect::<Reply<Vec<_>>>()?;
    for (k, v) in (s..=e).zip(new) {
        match v {
            Some(v) => p.values.insert(k, v),
            None => p.values.remove(&k),
        };
    }
    Ok(Vec::new())
}

/// Variables of `p` within `a..=b`.
fn pcode_count(p: &PCodeMacros, a: i32, b: i32) -> i64 {
    p.vars
        .ranges
        .iter()
        .map(|&(s, e)| {
            let (s, e) = (s.max(a), e.min(b));
            if s > e {
                0
            } else {
                i64::from(e) - i64::from(s) + 1
            }
        })
        .sum::<i64>()
}

/// cnc_rdpmacroinfo2: how many P-code variables the path has, #10000..
/// #19999, #20000..#199999 and #200000.., and each range's type (the
/// profile's `[path.pmacros]`), in words 3..8 where FANUC's library reads
/// them; words 0..2, which it never reads, sent as 0.
fn pcode_info2(m: &mut Machine, q: &super::route::Asked<'_>) -> Reply<Vec<i64>> {
    let p = m.pcode(q.path)?;
    Ok(vec![
        0,
        0,
        0,
        pcode_count(p, 10000, 19999),
        pcode_count(p, 20000, 199_999),
        pcode_count(p, 200_000, i32::MAX),
        i64::from(p.v1_type),
        i64::from(p.v2_type),
        i64::from(p.v20_type),
    ])
}

/// cnc_rdpmacro, cnc_rdpmacror: P-code variables `s..=e` (the request's first two words)
/// of the path's store (`[path.pmacros]`, or what writes left there), one
/// value record each (vacant: 0 with -1 places); a number the path does
/// not have is EW_NUMBER.
fn pcode_read(m: &mut Machine, q: &super::route::Asked<'_>) -> Reply<Vec<i64>> {
    let p = &m.pcode(q.path)?.vars;
    let (s, e) = (q.words[0], q.words[1]);
    p.check_range_of(s, e, PCODE_RECORDS)?;
    // The fields FANUC's library fills without the wire (the numbers it
    // writes back) come first in the layout the dispatch encodes.
    let skipped = q.f.reply.iter().filter(|x| x.arg.is_some()).count();
    let mut v = vec![i64::from(s); skipped];
    for n in s..=e {
        let r = p.record(n);
        v.extend([i64::from(r.value), i64::from(r.exp)]);
    }
    Ok(v)
}

/// cnc_rdpmacroinfo: how many P-code variables the path has, #10000..#19999
/// and the extended #20000.., and the extended ones' type (the profile's
/// `[path.pmacros]`), in words 3, 4 and 5 where FANUC's library reads
/// them. Words 0..2 FANUC's library never reads (what a CNC sends there is
/// not known): sent as 0.
fn pcode_info(m: &mut Machine, q: &super::route::Asked<'_>) -> Reply<Vec<i64>> {
    let p = m.pcode(q.path)?;
    let count = |a: i32, b: i32| {
        let n = (a..=b).filter(|n| p.vars.exists(*n)).count();
        i64::try_from(n).unwrap_or(i64::MAX)
    };
    Ok(vec![
        0,
        0,
        0,
        count(10000, 19999),
        count(20000, 29999),
        i64::from(p.v2_type),
    ])
}

/// Most records one read or write may carry (the reply must fit in the
/// smallest frame a CNC sends, 1450 bytes).
pub const MAX_RECORDS: usize = 100;

/// Most P-code records one read or write may carry: FANUC's library asks
/// for up to 179 (cnc_rdpmacror) and writes up to 177 (cnc_wrpmacror) a
/// request.
pub const PCODE_RECORDS: usize = 179;

impl Macros {
    /// The record a read answers for `n` (vacant: value 0, decimals -1).
    pub fn record(&self, n: i32) -> Value {
        match self.values.get(&n) {
            Some(&(v, d)) => Value::decimal(v, d),
            None => Value::decimal(0, VACANT_DEC),
        }
    }

    /// Variables `s..=e` that all exist, else EW_NUMBER.
    fn check_range(&self, s: i32, e: i32) -> Reply<()> {
        self.check_range_of(s, e, MAX_RECORDS)
    }

    /// [`Macros::check_range`], at most `max` records.
    fn check_range_of(&self, s: i32, e: i32, max: usize) -> Reply<()> {
        // abs_diff: the numbers come from the client, any i32 (fuzzing
        // found `e - s` overflowing).
        if e < s || e.abs_diff(s) as usize >= max {
            return Err(CncError::NUMBER);
        }
        if (s..=e).all(|n| self.exists(n)) {
            Ok(())
        } else {
            Err(CncError::NUMBER)
        }
    }
}

/// Checks a value a client writes: decimals -1 (vacant, with digits 0) or
/// 0..=[`MAX_DEC`].
fn check_value(v: i32, d: i16) -> Reply<Option<(i32, i16)>> {
    match d {
        VACANT_DEC if v == 0 => Ok(None),
        0..=MAX_DEC => Ok(Some((v, d))),
        _ => Err(CncError::new(ew::EW_DATA)),
    }
}

impl Machine {
    fn macros(&self, path: u16) -> Reply<&Macros> {
        self.profile
            .paths
            .get(usize::from(path).wrapping_sub(1))
            .map(|p| &p.macros)
            .ok_or(CncError::PATH)
    }

    /// The path's P-code macro variables.
    pub(crate) fn pcode(&self, path: u16) -> Reply<&PCodeMacros> {
        self.profile
            .paths
            .get(usize::from(path).wrapping_sub(1))
            .map(|p| &p.pmacros)
            .ok_or(CncError::PATH)
    }

    fn macros_mut(&mut self, path: u16) -> Reply<&mut Macros> {
        self.profile
            .paths
            .get_mut(usize::from(path).wrapping_sub(1))
            .map(|p| &mut p.macros)
            .ok_or(CncError::PATH)
    }

    /// Command 0x0015: variables `s..=e`.
    pub(crate) fn read_macros(&mut self, path: u16, s: i32, e: i32) -> Reply<Vec<Value>> {
        let m = self.macros(path)?;
        m.check_range(s, e)?;
        Ok((s..=e).map(|n| m.record(n)).collect())
    }

    /// Command 0x0016: variables `s..=e` from records. All or nothing: a
    /// rejected write changes no variable.
    pub(crate) fn write_macros(
        &mut self,
        path: u16,
        s: i32,
        e: i32,
        records: &[Value],
    ) -> Reply<()> {
        let series16 = self.profile.cnc.class == Class::Series16;
        let m = self.macros_mut(path)?;
        m.check_range(s, e)?;
        if records.len() != (e - s + 1) as usize {
            return Err(CncError::new(ew::EW_LENGTH));
        }
        if (s..=e).any(|n| m.protected(n)) {
            return Err(CncError::new(ew::EW_PROT));
        }
        let mut new = Vec::with_capacity(records.len());
        for r in records {
            // A record is value · base^-exp. FANUC's library sends the 16i
            // class a normalised binary record (m · 2^-e, see
            // proto::macros::to_base2); kept as the shortest decimal form.
            let (v, d) = if r.base == 10 {
                (r.value, r.exp)
            } else if r.base == 2 {
                let (mut v, mut d) = r.to_decimal();
                if series16 {
                    while d > 0 && v % 10 == 0 {
                        v /= 10;
                        d -= 1;
                    }
                }
                (v, d)
            } else {
                return Err(CncError::new(ew::EW_DATA));
            };
            new.push(check_value(v, d)?);
        }
        for (n, v) in (s..=e).zip(new) {
            match v {
                Some(v) => m.values.insert(n, v),
                None => m.values.remove(&n),
            };
        }
        Ok(())
    }

    /// Command 0x0017: how many common variables exist from #100 (below
    /// #500) and from #500 (below #1000).
    pub(crate) fn macro_info(&mut self, path: u16) -> Reply<MacroInfo> {
        let m = self.macros(path)?;
        let count = |a: i32, b: i32| (a..=b).filter(|n| m.exists(*n)).count() as i32;
        Ok(MacroInfo {
            use_no1: count(100, 499),
            use_no2: count(500, 999),
        })
    }

    /// Sets a macro variable as a running program would (`None`: vacant),
    /// ignoring write protection. EW_NUMBER for a number that does not exist.
    pub fn set_macro(&mut self, path: u16, number: i32, value: Option<(i32, i16)>) -> Reply<()> {
        let m = self.macros_mut(path)?;
        if !m.exists(number) {
            return Err(CncError::NUMBER);
        }
        match value {
            Some(v) => m.values.insert(number, v),
            None => m.values.remove(&number),
        };
        Ok(())
    }

    /// A macro variable's value (`None`: vacant).
    pub fn macro_value(&self, path: u16, number: i32) -> Reply<Option<(i32, i16)>> {
        let m = self.macros(path)?;
        if !m.exists(number) {
            return Err(CncError::NUMBER);
        }
        Ok(m.values.get(&number).copied())
    }
}

/// The fewest decimal places (0..=9) whose digits fit in 32 bits and give
/// back `x` exactly, else the most places that fit; None for NaN/inf or
/// magnitudes beyond 32-bit digits.
pub fn double_to_decimal(x: f64) -> Option<(i32, i16)> {
    if !x.is_finite() {
        return None;
    }
    let mut best = None;
    for d in 0..=MAX_DEC {
        let m = (x * 10f64.powi(i32::from(d))).round();
        if m.abs() > f64::from(i32::MAX) {
            break;
        }
        best = Some((m as i32, d));
        if m / 10f64.powi(i32::from(d)) == x {
            break;
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_parse_exactly() {
        assert_eq!(parse_decimal("12.500"), Some((12500, 3)));
        assert_eq!(parse_decimal("-0.5"), Some((-5, 1)));
        assert_eq!(parse_decimal("7"), Some((7, 0)));
        assert_eq!(parse_decimal("+.25"), Some((25, 2)));
        assert_eq!(parse_decimal("1e3"), None);
        assert_eq!(parse_decimal("99999999999"), None);
        assert_eq!(parse_decimal("."), None);
    }

    #[test]
    fn ranges_from_any_numbers_are_checked_without_overflow() {
        // Found by fuzzing (fuzz/regressions/request/macro-range-overflow).
        let mut m = Machine::new(crate::sim::Profile::default());
        for (s, e) in [(-1, i32::MAX), (i32::MIN, i32::MAX), (i32::MIN, -1)] {
            assert_eq!(m.read_macros(1, s, e).err(), Some(CncError::NUMBER));
            let w = m.write_macros(1, s, e, &[]).err();
            assert_eq!(w, Some(CncError::NUMBER));
        }
    }

    #[test]
    fn doubles_keep_their_places() {
        assert_eq!(double_to_decimal(1.5), Some((15, 1)));
        assert_eq!(double_to_decimal(-2.25), Some((-225, 2)));
        assert_eq!(double_to_decimal(7.0), Some((7, 0)));
        assert_eq!(double_to_decimal(f64::NAN), None);
        assert_eq!(double_to_decimal(1e12), None);
    }
}
