//! Simulated PMC memory: the address areas of a 31i-B's first PMC, their
//! valid address ranges, which ones FOCAS may write, and their bytes.

use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::pmc::{PMCINFO_MAX, PmcAreaInfo, PmcInfo, PmcRange, TITLE, elem_size};
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
    /// pmc_rdpmctitle's texts in ODBPMCTITLE's order (`[pmc] title`).
    pub title: Vec<String>,
}

fn standard_areas() -> Vec<PmcArea> {
    STANDARD
        .iter()
        .map(|(l, r, w)| PmcArea::new(l, r.to_vec(), *w))
        .collect()
}

impl Pmc {
    /// 0x800b's answer: the title texts, each cut or zero-padded to its
    /// size on the wire.
    pub fn title_bytes(&self) -> Vec<u8> {
        let mut out = Vec::new();
        for (i, (n, _)) in TITLE.iter().enumerate() {
            let t = self.title.get(i).map_or(&[][..], |t| t.as_bytes());
            let at = out.len();
            out.extend(&t[..t.len().min(*n)]);
            out.resize(at + n, 0);
        }
        out
    }
}

impl Default for Pmc {
    fn default() -> Self {
        Pmc {
            areas: standard_areas(),
            extra: Vec::new(),
            title: Vec::new(),
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PmcToml {
    /// How many PMC units the CNC has (pmc_get_number_of_pmc), 1 to 8.
    units: Option<usize>,
    #[serde(default)]
    title: Vec<String>,
    #[serde(default)]
    area: BTreeMap<String, AreaToml>,
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
    fn try_from(t: PmcToml) -> Result<Pmc, String> {
        let mut pmc = Pmc::default();
        if t.title.len() > TITLE.len() {
            return Err("[pmc] title: at most 10 texts".to_string());
        }
        pmc.title = t.title;
        match t.units {
            Some(n @ 1..=8) => {
                // Zeroed memory, shared by the units until one is written.
                let blank = standard_areas();
                pmc.extra = (1..n).map(|_| blank.clone()).collect();
            }
            Some(n) => return Err(format!("[pmc] units = {n}: 1 to 8")),
            None => {}
        }
        for (letter, a) in t.area {
            if !AREA_TYPES.iter().any(|x| x.0 == letter) {
                return Err(format!(
                    "unknown PMC area {letter:?} (known: G F Y X A R T K C D E)"
                ));
            }
            let std = pmc.area_by_letter(&letter).cloned().expect("standard area");
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
            let i = pmc
                .areas
                .iter()
                .position(|x| x.letter == letter)
                .expect("standard area");
            pmc.areas[i] = area;
        }
        Ok(pmc)
    }
}

impl Pmc {
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

    /// Command 0x800f[most]: the unit types (1, 2 ...), at most `most`.
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
        if n == 0 || n % size != 0 || !area.covers(r.s, r.e) {
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
}

impl Pmc {
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
