//! Profile section `[path.macros]`: the custom macro variables of a path
//! (served by src/sim/macros.rs).

use serde::Deserialize;
use std::collections::BTreeMap;

/// Decimal places a written value may have (a CNC keeps macro variables
/// as doubles; more places than this are refused with EW_DATA).
pub const MAX_DEC: i16 = 9;

/// The custom macro variables of a path (profile `[path.macros]`).
#[derive(Debug, Clone, Deserialize)]
#[serde(try_from = "MacrosToml")]
pub struct Macros {
    /// Inclusive number ranges that exist; others answer EW_NUMBER.
    pub ranges: Vec<(i32, i32)>,
    /// Inclusive ranges that cannot be written (EW_PROT), e.g. #500.. locked
    /// by parameters 6031/6032.
    pub protected: Vec<(i32, i32)>,
    /// Values (digits, decimal places); a missing number is vacant.
    pub values: BTreeMap<i32, (i32, i16)>,
    /// Variable names (`NAME = [number, attr]`): cnc_rdmacronum answers a
    /// name's number and the attribute word it reads after it.
    pub names: BTreeMap<String, (i32, i16)>,
}

impl Default for Macros {
    /// A 31i's standard set: #100-#199 and #500-#999, all vacant.
    fn default() -> Self {
        Macros {
            ranges: vec![(100, 199), (500, 999)],
            protected: Vec::new(),
            values: BTreeMap::new(),
            names: BTreeMap::new(),
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MacrosToml {
    #[serde(default)]
    ranges: Option<Vec<[i32; 2]>>,
    #[serde(default)]
    protected: Vec<[i32; 2]>,
    /// number = "decimal text" ("12.500" keeps three places).
    #[serde(default)]
    values: BTreeMap<String, String>,
    /// NAME = [number, attr] (cnc_rdmacronum).
    #[serde(default)]
    names: BTreeMap<String, (i32, i16)>,
}

impl TryFrom<MacrosToml> for Macros {
    type Error = String;
    fn try_from(t: MacrosToml) -> Result<Macros, String> {
        Macros::from_toml(t, Macros::default().ranges)
    }
}

impl Macros {
    /// The variables of a section; `ranges` when it gives none.
    fn from_toml(t: MacrosToml, ranges: Vec<(i32, i32)>) -> Result<Macros, String> {
        let pairs = |v: Vec<[i32; 2]>| -> Result<Vec<(i32, i32)>, String> {
            v.into_iter()
                .map(|[a, b]| {
                    if a > b {
                        Err(format!("macro range [{a}, {b}] is reversed"))
                    } else {
                        Ok((a, b))
                    }
                })
                .collect()
        };
        let mut m = Macros {
            ranges: match t.ranges {
                Some(r) => pairs(r)?,
                None => ranges,
            },
            protected: pairs(t.protected)?,
            values: BTreeMap::new(),
            names: t.names,
        };
        for (k, v) in t.values {
            let n: i32 = k
                .trim()
                .parse()
                .map_err(|_| format!("macro number {k:?} is not a number"))?;
            if !m.exists(n) {
                return Err(format!("macro #{n} is outside path.macros.ranges"));
            }
            let d = parse_decimal(&v).ok_or_else(|| {
                format!("macro #{n}: {v:?} is not a decimal number that fits in 32-bit digits")
            })?;
            m.values.insert(n, d);
        }
        Ok(m)
    }
}

/// The P-code macro variables of a path (profile `[path.pmacros]`, served
/// by src/sim/macros.rs: cnc_rdpmacroinfo, cnc_rdpmacro, cnc_wrpmacro ...):
/// the same numbers, protection and values as [`Macros`], with the
/// extended variables' type cnc_rdpmacroinfo reports.
#[derive(Debug, Clone, Deserialize)]
#[serde(try_from = "PCodeToml")]
pub struct PCodeMacros {
    pub vars: Macros,
    /// `v2_type` of cnc_rdpmacroinfo: the type of the extended variables
    /// #20000.. (a CNC setting, reported as it is).
    pub v2_type: i16,
    /// `v1_type` of cnc_rdpmacroinfo2: the type of the variables #10000..
    pub v1_type: i16,
    /// `v20_type` of cnc_rdpmacroinfo2: the type of the extended variables
    /// #200000..
    pub v20_type: i16,
}

/// The P-code variables a path has when its profile names none: #10000-#10099.
pub const PCODE_RANGES: [(i32, i32); 1] = [(10000, 10099)];

impl Default for PCodeMacros {
    fn default() -> Self {
        PCodeMacros {
            vars: Macros {
                ranges: PCODE_RANGES.to_vec(),
                protected: Vec::new(),
                values: BTreeMap::new(),
                names: BTreeMap::new(),
            },
            v2_type: 0,
            v1_type: 0,
            v20_type: 0,
        }
    }
}

#[derive(Deserialize)]
struct PCodeToml {
    #[serde(default)]
    v2_type: i16,
    #[serde(default)]
    v1_type: i16,
    #[serde(default)]
    v20_type: i16,
    #[serde(flatten)]
    vars: MacrosToml,
}

impl TryFrom<PCodeToml> for PCodeMacros {
    type Error = String;
    fn try_from(t: PCodeToml) -> Result<PCodeMacros, String> {
        Ok(PCodeMacros {
            vars: Macros::from_toml(t.vars, PCODE_RANGES.to_vec())?,
            v2_type: t.v2_type,
            v1_type: t.v1_type,
            v20_type: t.v20_type,
        })
    }
}

/// "-12.500" → (-12500, 3). At most [`MAX_DEC`] places, digits within i32.
pub fn parse_decimal(s: &str) -> Option<(i32, i16)> {
    let s = s.trim();
    let (neg, body) = match s.strip_prefix('-') {
        Some(b) => (true, b),
        None => (false, s.strip_prefix('+').unwrap_or(s)),
    };
    let (int, frac) = body.split_once('.').unwrap_or((body, ""));
    if int.is_empty() && frac.is_empty()
        || !int.bytes().chain(frac.bytes()).all(|c| c.is_ascii_digit())
        || frac.len() > MAX_DEC as usize
    {
        return None;
    }
    let digits: i64 = format!("{int}{frac}").parse().ok()?;
    let v = i32::try_from(if neg { -digits } else { digits }).ok()?;
    Some((v, frac.len() as i16))
}

impl Macros {
    pub fn exists(&self, n: i32) -> bool {
        self.ranges.iter().any(|&(a, b)| (a..=b).contains(&n))
    }

    pub fn protected(&self, n: i32) -> bool {
        self.protected.iter().any(|&(a, b)| (a..=b).contains(&n))
    }
}

/// `[path.rt_macros]`: the real-time custom macro variables a path has
/// (cnc_getrtmrvar counts the volatile ones, cnc_getrtmrvars the
/// non-volatile ones).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RtMacros {
    pub volatile: i32,
    pub nonvolatile: i32,
}
