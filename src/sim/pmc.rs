//! Simulated PMC memory: the address areas of a 31i-B's first PMC, their
//! valid address ranges, which ones FOCAS may write, and their bytes.

use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::pmc::{PMCINFO_MAX, PmcAreaInfo, PmcInfo, PmcRange, elem_size};
use crate::spec::Func;
use serde::Deserialize;
use std::collections::BTreeMap;

/// Most bytes one read or write may carry (fits the smallest frame).
pub const MAX_BYTES: usize = 1400;

/// Address letters and their `adr_type` numbers (IODBPMC `type_a`).
pub const AREA_TYPES: &[(&str, i16)] = &[
    ("G", 0),
    ("F", 1),
    ("Y", 2),
    ("X", 3),
    ("A", 4),
    ("R", 5),
    ("T", 6),
    ("K", 7),
    ("C", 8),
    ("D", 9),
    ("E", 12),
];

/// A 31i-B first PMC (memory C): letter, address ranges, FOCAS-writable.
/// X (inputs from the machine), F (CNC → PMC) and Y (ladder outputs) are
/// written by the machine every scan, not by FOCAS: writes get EW_PROT.
/// (letter, inclusive address ranges, FOCAS-writable)
type AreaSpec = (&'static str, &'static [(u16, u16)], bool);

const STANDARD: &[AreaSpec] = &[
    ("G", &[(0, 767)], true),
    ("F", &[(0, 767)], false),
    ("Y", &[(0, 127)], false),
    ("X", &[(0, 127)], false),
    ("A", &[(0, 249)], true),
    ("R", &[(0, 7999)], true),
    ("T", &[(0, 499)], true),
    ("K", &[(0, 99), (900, 999)], true),
    ("C", &[(0, 399)], true),
    ("D", &[(0, 9999)], true),
    ("E", &[(0, 9999)], true),
];

/// One PMC address area.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PmcArea {
    pub letter: String,
    pub adr_type: i16,
    /// Inclusive byte-address ranges that exist.
    pub ranges: Vec<(u16, u16)>,
    /// Whether pmc_wrpmcrng may write it (else EW_PROT).
    pub writable: bool,
    /// The bytes, indexed by address (addresses outside `ranges` unused);
    /// shared by clones until one writes (a fleet's machines share their
    /// profile's until then).
    pub mem: std::sync::Arc<Vec<u8>>,
}

impl PmcArea {
    fn new(letter: &str, ranges: Vec<(u16, u16)>, writable: bool) -> PmcArea {
        let adr_type = AREA_TYPES
            .iter()
            .find(|a| a.0 == letter)
            .map_or(-1, |a| a.1);
        let size = ranges
            .iter()
            .map(|r| usize::from(r.1) + 1)
            .max()
            .unwrap_or(0);
        PmcArea {
            letter: letter.to_owned(),
            adr_type,
            ranges,
            writable,
            mem: std::sync::Arc::new(vec![0; size]),
        }
    }

    /// Whether every address `s..=e` exists.
    pub fn covers(&self, s: u16, e: u16) -> bool {
        self.ranges.iter().any(|&(a, b)| a <= s && e <= b)
    }

    /// Bytes `addr..addr+n` (None when outside the area).
    pub fn bytes(&self, addr: u16, n: usize) -> Option<&[u8]> {
        let e = u16::try_from(usize::from(addr) + n.max(1) - 1).ok()?;
        self.covers(addr, e)
            .then(|| &self.mem[usize::from(addr)..usize::from(addr) + n])
    }

    /// Mutable bytes `addr..addr+n` (None when outside the area).
    pub fn bytes_mut(&mut self, addr: u16, n: usize) -> Option<&mut [u8]> {
        let e = u16::try_from(usize::from(addr) + n.max(1) - 1).ok()?;
        self.covers(addr, e).then(|| {
            &mut std::sync::Arc::make_mut(&mut self.mem)[usize::from(addr)..usize::from(addr) + n]
        })
    }
}

/// The PMC (profile `[pmc]`).
#[derive(Debug, Clone, Deserialize)]
#[serde(try_from = "PmcToml")]
pub struct Pmc {
    /// The areas of PMC unit 1 (the profile's `[pmc.area.*]`).
    pub areas: Vec<PmcArea>,
    /// Units 2.. (`[pmc] units = n`): the standard areas, zeroed.
    pub extra: Vec<Vec<PmcArea>>,
    /// Per unit (index unit - 1): its title, alarm messages and timer
    /// types (`[pmc] title, messages, timer_types` for unit 1,
    /// `[pmc.unit.N]` for the others).
    pub info: Vec<UnitInfo>,
}

/// Variable timers of a unit (T0-T499: 250 timers of 2 bytes).
pub const TIMERS: usize = 250;
pub use super::pmc_data::{ALMMSG_LEN, ALMMSG_MAX, ProgramType};
/// The highest timer type (accuracy code) a unit accepts \[ours\].
pub const TIMER_TYPE_MAX: i16 = 5;

/// What a PMC unit holds besides its memory.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnitInfo {
    /// pmc_rdpmctitle's texts in ODBPMCTITLE's order.
    pub title: Vec<String>,
    /// The ladder's message texts by A-area bit (A0.0, A0.1 … A1.0 … are
    /// messages 0, 1 … 8 …): a message is an alarm while its bit is 1.
    pub messages: Vec<String>,
    /// The variable timers' types (pmc_get_timer_type), timer 1 first.
    pub timer_types: Vec<i16>,
    /// The group number of the data table's control data (pmc_rdcntlgrp,
    /// set by pmc_wrcntlgrp).
    pub control_group: i16,
    /// The group number of the extended relay's control data
    /// (pmc_rdcntl_exrelay_grp, set by pmc_wrcntl_exrelay_grp).
    pub exrelay_group: i16,
    /// The extended backup memory's maximum size (pmc_kpmsiz).
    pub kpm_size: u32,
    /// How many divided ladders the sequence program has
    /// (pmc_get_number_of_ladder).
    pub ladders: i32,
    pub program_type: ProgramType,
}

/// The highest control data group number a unit accepts \[ours\].
pub const GROUP_MAX: i16 = 2000;
/// The most divided ladders a profile may give a unit \[ours\].
pub const LADDERS_MAX: i32 = 255;

impl Default for UnitInfo {
    fn default() -> Self {
        UnitInfo {
            title: Vec::new(),
            messages: Vec::new(),
            timer_types: vec![0; TIMERS],
            control_group: 0,
            exrelay_group: 0,
            kpm_size: 0,
            ladders: 1,
            program_type: ProgramType::default(),
        }
    }
}

fn standard_areas() -> Vec<PmcArea> {
    STANDARD
        .iter()
        .map(|(l, r, w)| PmcArea::new(l, r.to_vec(), *w))
        .collect()
}

impl Pmc {
    /// Unit `unit`'s title, messages and timers: EW_NOPMC for a unit the
    /// CNC lacks.
    pub fn unit_info(&self, unit: u16) -> Reply<&UnitInfo> {
        (self.info.get(usize::from(unit).wrapping_sub(1))).ok_or(CncError::new(ew::EW_NOPMC))
    }

    /// A title answer (pmc_rdpmctitle, pmc_rdpmctitle2: reply layout `f`)
    /// on unit `unit` from its title texts (`pmc_data::title`).
    pub fn title(&self, unit: u16, f: &Func) -> Reply<Vec<i64>> {
        Ok(super::pmc_data::title(&self.unit_info(unit)?.title, f))
    }

    /// The alarm messages of unit `unit` now: the texts whose A bit is 1,
    /// in bit order.
    pub fn alarms(&self, unit: u16) -> Reply<Vec<&str>> {
        let info = self.unit_info(unit)?;
        let a = self.unit(unit)?.iter().find(|a| a.letter == "A");
        let on = |i: usize| {
            let byte = a.and_then(|a| a.bytes(u16::try_from(i / 8).ok()?, 1));
            byte.is_some_and(|b| b[0] >> (i % 8) & 1 == 1)
        };
        Ok((info.messages.iter().enumerate())
            .filter(|(i, m)| !m.is_empty() && on(*i))
            .map(|(_, m)| m.as_str())
            .collect())
    }

    /// Command 0x8010[s, n] on unit `unit`: its alarms s.. (at most n
    /// and 11, `pmc_data::alarm_messages`).
    pub fn alarm_messages(&self, unit: u16, s: i32, n: i32) -> Reply<Vec<u8>> {
        super::pmc_data::alarm_messages(&self.alarms(unit)?, s, n)
    }

    /// Timers `s..=e` of unit `unit` (1-based): EW_NUMBER outside 1..=250.
    fn timer_range(s: i32, e: i32) -> Reply<std::ops::RangeInclusive<usize>> {
        if s < 1 || e < s || e as usize > TIMERS {
            return Err(CncError::NUMBER);
        }
        Ok(s as usize - 1..=e as usize - 1)
    }

    /// Command 0x804a[s, e] on unit `unit`: the timers' types, one record
    /// each (pmc_get_timer_type's layout).
    pub fn timer_types(&self, unit: u16, s: i32, e: i32) -> Reply<Vec<i64>> {
        let r = Self::timer_range(s, e)?;
        let t = &self.unit_info(unit)?.timer_types;
        Ok(t[r].iter().map(|v| i64::from(*v)).collect())
    }

    /// Command 0x804b[s, e] on unit `unit`: sets the timers' types from
    /// the payload's records (pmc_set_timer_type's layout, one i16 each);
    /// all or nothing: another number of them is EW_LENGTH, a type outside
    /// 0..=5 EW_DATA with the timer's number as detail.
    pub fn set_timer_types(&mut self, unit: u16, s: i32, e: i32, data: &[i64]) -> Reply<()> {
        let r = Self::timer_range(s, e)?;
        self.unit_info(unit)?;
        if data.len() != r.clone().count() {
            return Err(CncError::new(ew::EW_LENGTH));
        }
        let v: Vec<i16> = data.iter().map(|t| *t as i16).collect();
        if let Some(k) = v.iter().position(|t| !(0..=TIMER_TYPE_MAX).contains(t)) {
            return Err(CncError {
                code: ew::EW_DATA,
                detail: (0, (s as usize + k) as u16),
            });
        }
        let i = usize::from(unit) - 1;
        self.info[i].timer_types[r].copy_from_slice(&v);
        Ok(())
    }

    /// Unit `unit`'s control data group numbers: [data table, extended
    /// relay]; EW_NOPMC for a unit the CNC lacks.
    pub fn groups(&self, unit: u16) -> Reply<[i16; 2]> {
        let i = self.unit_info(unit)?;
        Ok([i.control_group, i.exrelay_group])
    }

    /// pmc_wrcntlgrp (`extended` false) / pmc_wrcntl_exrelay_grp: sets a
    /// group number of unit `unit`; outside 0..=GROUP_MAX EW_DATA, nothing
    /// changed \[ours\].
    pub fn set_group(&mut self, unit: u16, extended: bool, g: i32) -> Reply<()> {
        self.unit_info(unit)?;
        let g = (i16::try_from(g).ok())
            .filter(|g| (0..=GROUP_MAX).contains(g))
            .ok_or(CncError::new(ew::EW_DATA))?;
        let info = &mut self.info[usize::from(unit) - 1];
        *if extended {
            &mut info.exrelay_group
        } else {
            &mut info.control_group
        } = g;
        Ok(())
    }

    /// Unit `unit`'s extended backup memory size and how many divided
    /// ladders it has; EW_NOPMC for a unit the CNC lacks.
    pub fn ladders(&self, unit: u16) -> Reply<(u32, i32)> {
        let i = self.unit_info(unit)?;
        Ok((i.kpm_size, i.ladders))
    }

    pub fn area(&self, adr_type: i16) -> Option<&PmcArea> {
        self.areas.iter().find(|a| a.adr_type == adr_type)
    }

    pub fn area_mut(&mut self, adr_type: i16) -> Option<&mut PmcArea> {
        self.areas.iter_mut().find(|a| a.adr_type == adr_type)
    }

    pub fn area_by_letter(&self, letter: &str) -> Option<&PmcArea> {
        self.areas.iter().find(|a| a.letter == letter)
    }

    pub fn area_by_letter_mut(&mut self, letter: &str) -> Option<&mut PmcArea> {
        self.areas.iter_mut().find(|a| a.letter == letter)
    }

    /// How many PMC units the CNC has.
    pub fn units(&self) -> usize {
        1 + self.extra.len()
    }

    /// The areas of unit `unit` (1..): EW_NOPMC for a unit the CNC lacks.
    fn unit(&self, unit: u16) -> Reply<&Vec<PmcArea>> {
        match unit {
            1 => Ok(&self.areas),
            n => (self.extra)
                .get(usize::from(n).wrapping_sub(2))
                .ok_or(CncError::new(ew::EW_NOPMC)),
        }
    }

    fn unit_mut(&mut self, unit: u16) -> Reply<&mut Vec<PmcArea>> {
        match unit {
            1 => Ok(&mut self.areas),
            n => (self.extra)
                .get_mut(usize::from(n).wrapping_sub(2))
                .ok_or(CncError::new(ew::EW_NOPMC)),
        }
    }

    /// Command 0x800f\[most\]: the unit types (1, 2 ...), at most `most`.
    pub fn unit_types(&self, most: i32) -> Vec<i32> {
        (1..=self.units() as i32)
            .take(most.max(0) as usize)
            .collect()
    }

    /// Command 0x800c[unit]: whether the CNC has that unit.
    pub fn select(&self, unit: i32) -> Reply<()> {
        let unit = u16::try_from(unit).map_err(|_| CncError::new(ew::EW_NOPMC))?;
        self.unit(unit).map(|_| ())
    }

    /// The area and checked address range of a request: EW_TYPE for an
    /// unknown area or data type, EW_RANGE for addresses outside the area
    /// or a range that is not whole elements, EW_LENGTH when too long.
    fn check<'a>(areas: &'a [PmcArea], r: &PmcRange) -> Reply<&'a PmcArea> {
        let area = (areas.iter())
            .find(|a| a.adr_type == r.adr_type)
            .ok_or(CncError::new(ew::EW_TYPE))?;
        let size = elem_size(r.data_type).ok_or(CncError::new(ew::EW_TYPE))?;
        let n = r.span();
        if n == 0 || !n.is_multiple_of(size) || !area.covers(r.s, r.e) {
            return Err(CncError::new(ew::EW_RANGE));
        }
        if n > MAX_BYTES {
            return Err(CncError::new(ew::EW_LENGTH));
        }
        Ok(area)
    }

    /// Command 0x8001 on unit `unit`: the range's bytes (big-endian
    /// elements, as stored).
    pub fn read(&self, unit: u16, r: &PmcRange) -> Reply<Vec<u8>> {
        let area = Self::check(self.unit(unit)?, r)?;
        Ok(area.mem[usize::from(r.s)..=usize::from(r.e)].to_vec())
    }

    /// Command 0x8002 on unit `unit`: all or nothing; read-only areas EW_PROT.
    pub fn write(&mut self, unit: u16, r: &PmcRange, data: &[u8]) -> Reply<()> {
        let area = Self::check(self.unit(unit)?, r)?;
        if data.len() != r.span() {
            return Err(CncError::new(ew::EW_LENGTH));
        }
        if !area.writable {
            return Err(CncError::new(ew::EW_PROT));
        }
        let areas = self.unit_mut(unit)?;
        let area = areas
            .iter_mut()
            .find(|a| a.adr_type == r.adr_type)
            .expect("checked");
        std::sync::Arc::make_mut(&mut area.mem)[usize::from(r.s)..=usize::from(r.e)]
            .copy_from_slice(data);
        Ok(())
    }

    /// The 0x8003 answer: one record per address range (K has two), the
    /// letter's character code, attribute 0, first and last address. What a
    /// real PMC puts in the attribute word and does with `adr_type` is not
    /// known; the simulator answers every area whatever `adr_type`.
    pub fn info(&self, unit: u16, _adr_type: i16) -> Reply<PmcInfo> {
        let areas: Vec<PmcAreaInfo> = self
            .unit(unit)?
            .iter()
            .flat_map(|a| {
                a.ranges.iter().map(|&(s, e)| PmcAreaInfo {
                    adr: u16::from(a.letter.as_bytes()[0]),
                    attr: 0,
                    top: i32::from(s),
                    last: i32::from(e),
                })
            })
            .take(PMCINFO_MAX)
            .collect();
        Ok(PmcInfo {
            count: areas.len() as i32,
            areas,
        })
    }
}

impl Default for Pmc {
    fn default() -> Self {
        Pmc {
            areas: standard_areas(),
            extra: Vec::new(),
            info: vec![UnitInfo::default()],
        }
    }
}

/// `[pmc]` (unit 1, and how many units) and each `[pmc.unit.N]`: one
/// struct, as `#[serde(flatten)]` cannot be combined with
/// `deny_unknown_fields`; a unit's `units` and `unit` are refused by hand.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PmcToml {
    /// How many PMC units the CNC has (pmc_get_number_of_pmc), 1 to 8.
    units: Option<usize>,
    #[serde(default)]
    title: Vec<String>,
    /// The ladder's message texts by A bit.
    #[serde(default)]
    messages: Vec<String>,
    /// Timer types from timer 1 on; the rest 0.
    #[serde(default)]
    timer_types: Vec<i16>,
    /// pmc_rdcntlgrp's group number, 0 to GROUP_MAX.
    #[serde(default)]
    control_group: i16,
    /// pmc_rdcntl_exrelay_grp's group number, 0 to GROUP_MAX.
    #[serde(default)]
    exrelay_group: i16,
    /// pmc_kpmsiz's size.
    #[serde(default)]
    kpm_size: u32,
    /// pmc_get_number_of_ladder's count, 1 to 255 (default 1).
    ladders: Option<i32>,
    #[serde(default)]
    program_type: ProgramType,
    #[serde(default)]
    area: BTreeMap<String, AreaToml>,
    /// Units 2..: `[pmc.unit.2]` ... (an Option: a unit's empty `unit`
    /// table is refused too).
    unit: Option<BTreeMap<String, PmcToml>>,
}

/// The texts of pmc_rdpmctitle's answer.
const TITLE_TEXTS: usize = 10;

/// A unit's title, messages and timer types from the profile.
fn unit_info(t: &mut PmcToml) -> Result<UnitInfo, String> {
    let (title, messages) = (
        std::mem::take(&mut t.title),
        std::mem::take(&mut t.messages),
    );
    let types = std::mem::take(&mut t.timer_types);
    for (name, g) in [
        ("control_group", t.control_group),
        ("exrelay_group", t.exrelay_group),
    ] {
        if !(0..=GROUP_MAX).contains(&g) {
            return Err(format!("[pmc] {name}: 0 to {GROUP_MAX}"));
        }
    }
    let ladders = t.ladders.unwrap_or(1);
    if !(1..=LADDERS_MAX).contains(&ladders) {
        return Err(format!("[pmc] ladders: 1 to {LADDERS_MAX}"));
    }

    if title.len() > TITLE_TEXTS {
        return Err("[pmc] title: at most 10 texts".to_string());
    }
    if types.len() > TIMERS {
        return Err(format!("[pmc] timer_types: at most {TIMERS}"));
    }
    if types.iter().any(|t| !(0..=TIMER_TYPE_MAX).contains(t)) {
        return Err(format!("[pmc] timer_types: 0 to {TIMER_TYPE_MAX}"));
    }
    t.program_type.check()?;
    let mut info = UnitInfo {
        program_type: std::mem::take(&mut t.program_type),
        title,
        messages,
        control_group: t.control_group,
        exrelay_group: t.exrelay_group,
        kpm_size: t.kpm_size,
        ladders,
        ..UnitInfo::default()
    };
    info.timer_types[..types.len()].copy_from_slice(&types);
    Ok(info)
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct AreaToml {
    ranges: Option<Vec<[u16; 2]>>,
    writable: Option<bool>,
    /// address = [bytes from that address on]
    #[serde(default)]
    data: BTreeMap<String, Vec<u8>>,
}

impl TryFrom<PmcToml> for Pmc {
    type Error = String;
    fn try_from(mut t: PmcToml) -> Result<Pmc, String> {
        let mut pmc = Pmc {
            info: vec![unit_info(&mut t)?],
            ..Pmc::default()
        };
        match t.units {
            Some(n @ 1..=8) => {
                // Zeroed memory, shared by the units until one is written.
                let blank = standard_areas();
                pmc.extra = (1..n).map(|_| blank.clone()).collect();
                pmc.info.resize(n, UnitInfo::default());
            }
            Some(n) => return Err(format!("[pmc] units = {n}: 1 to 8")),
            None => {}
        }
        for (k, mut u) in t.unit.unwrap_or_default() {
            let n: usize = (k.trim().parse().ok())
                .filter(|n| (2..=pmc.info.len()).contains(n))
                .ok_or_else(|| format!("[pmc.unit.{k}]: units 2 to {}", pmc.info.len()))?;
            if u.units.is_some() || u.unit.is_some() {
                return Err(format!("[pmc.unit.{k}]: units and unit belong in [pmc]"));
            }
            pmc.info[n - 1] = unit_info(&mut u)?;
            apply_areas(&mut pmc.extra[n - 2], u.area)?;
        }
        apply_areas(&mut pmc.areas, t.area)?;
        Ok(pmc)
    }
}

/// The profile's `[...area.*]` tables over a unit's standard areas.
fn apply_areas(areas: &mut [PmcArea], t: BTreeMap<String, AreaToml>) -> Result<(), String> {
    for (letter, a) in t {
        let i = (areas.iter().position(|x| x.letter == letter))
            .ok_or_else(|| format!("unknown PMC area {letter:?} (known: G F Y X A R T K C D E)"))?;
        let std = &areas[i];
        let ranges = match a.ranges {
            Some(r) => r
                .into_iter()
                .map(|[s, e]| {
                    if s > e {
                        Err(format!("PMC area {letter}: range [{s}, {e}] is reversed"))
                    } else {
                        Ok((s, e))
                    }
                })
                .collect::<Result<Vec<_>, _>>()?,
            None => std.ranges.clone(),
        };
        let mut area = PmcArea::new(&letter, ranges, a.writable.unwrap_or(std.writable));
        for (k, bytes) in a.data {
            let addr: u16 = k
                .trim()
                .parse()
                .map_err(|_| format!("PMC address {letter}{k:?} is not a number"))?;
            area.bytes_mut(addr, bytes.len())
                .ok_or_else(|| format!("PMC data {letter}{addr} lies outside the area"))?
                .copy_from_slice(&bytes);
        }
        areas[i] = area;
    }
    Ok(())
}
