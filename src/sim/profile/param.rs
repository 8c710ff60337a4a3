//! Profile section `[param]`: the parameter and diagnosis tables
//! (served by src/sim/param.rs).

use crate::proto::param::{INFO_AXIS, Table};
use serde::Deserialize;

/// Data type of a parameter or diagnosis item.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum Kind {
    #[serde(rename = "bit")]
    Bit,
    #[serde(rename = "byte")]
    Byte,
    #[serde(rename = "word")]
    Word,
    #[serde(rename = "2word")]
    TwoWord,
    #[serde(rename = "real")]
    Real,
}

impl Kind {
    /// The type word of read answers and writes.
    pub fn code(self, table: Table) -> u16 {
        match (table, self) {
            (Table::Param, Kind::Bit) => 0,
            (Table::Param, Kind::Byte) => 1,
            (Table::Param, Kind::Word) => 2,
            (Table::Param, Kind::TwoWord) => 3,
            (Table::Param, Kind::Real) => 4,
            (Table::Diag, Kind::Byte) => 0,
            (Table::Diag, Kind::Word) => 1,
            (Table::Diag, Kind::TwoWord) => 2,
            (Table::Diag, Kind::Bit) => 3,
            (Table::Diag, Kind::Real) => 5,
        }
    }
    /// The attribute word of cnc_rdparainfo / cnc_rddiaginfo: bits 0-1 data
    /// type (bit, byte, word, 2-word), bit 8 axis. Real items: 2-word with
    /// bit 12 set (our choice; what a real CNC sends for reals is not known).
    pub fn info(self, axis: bool) -> i32 {
        let t = match self {
            Kind::Bit => 0,
            Kind::Byte => 1,
            Kind::Word => 2,
            Kind::TwoWord => 3,
            Kind::Real => 3 | 0x1000,
        };
        t | if axis { INFO_AXIS } else { 0 }
    }
    /// The value as the CNC stores it (bit: 0..255, byte and word signed).
    pub(crate) fn normalize(self, v: i32) -> i32 {
        match self {
            Kind::Bit => v as u8 as i32,
            Kind::Byte => v as i8 as i32,
            Kind::Word => v as i16 as i32,
            Kind::TwoWord | Kind::Real => v,
        }
    }
}

/// One parameter or diagnosis item of the profile.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    pub number: i32,
    pub kind: Kind,
    /// An axis item: one value per axis of the path.
    #[serde(default)]
    pub axis: bool,
    /// The value (one), or the values by axis (missing axes read 0).
    #[serde(default)]
    pub values: Vec<i32>,
    /// Real items: decimals of every value.
    #[serde(default)]
    pub decimals: i16,
    /// Writes are refused with EW_PROT.
    #[serde(default)]
    pub read_only: bool,
}

impl Entry {
    pub(crate) fn value(&self, i: usize) -> i32 {
        self.values.get(i).copied().unwrap_or(0)
    }
}

/// The last setting parameter of a 30i / 16i (the SETTING screen's
/// parameters 0 .. 99; TVC, ISO, I/O channel ...).
pub const SETTING_MAX: i32 = 99;

/// Profile section `[param]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(try_from = "RawParams")]
pub struct Params {
    /// Parameter write enable (PWE, on the CNC's SETTING screen). Writes
    /// also need MDI mode (status `aut` = 0).
    pub param_write_enable: bool,
    /// The setting data (cnc_rdsetnum): the parameters numbered up to
    /// this one, those of the CNC's SETTING screen.
    pub setting_max: i32,
    pub parameters: Vec<Entry>,
    pub diagnostics: Vec<Entry>,
}

impl Default for Params {
    fn default() -> Self {
        Params {
            param_write_enable: false,
            setting_max: SETTING_MAX,
            parameters: Vec::new(),
            diagnostics: Vec::new(),
        }
    }
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
struct RawParams {
    param_write_enable: bool,
    setting_max: Option<i32>,
    #[serde(rename = "parameter")]
    parameters: Vec<Entry>,
    #[serde(rename = "diagnosis")]
    diagnostics: Vec<Entry>,
}

impl TryFrom<RawParams> for Params {
    type Error = String;
    fn try_from(r: RawParams) -> Result<Params, String> {
        for (what, list) in [("parameter", &r.parameters), ("diagnosis", &r.diagnostics)] {
            let mut seen = std::collections::BTreeSet::new();
            for e in list {
                if !(0..=65535).contains(&e.number) || !seen.insert(e.number) {
                    return Err(format!("{what} {}: number out of range or twice", e.number));
                }
                let most = if e.axis { crate::types::MAX_AXIS } else { 1 };
                if e.values.len() > most {
                    return Err(format!("{what} {}: more values than axes", e.number));
                }
                if e.values.iter().any(|v| e.kind.normalize(*v) != *v) {
                    return Err(format!(
                        "{what} {}: value out of its type's range",
                        e.number
                    ));
                }
            }
        }
        let mut p = Params {
            param_write_enable: r.param_write_enable,
            setting_max: r.setting_max.unwrap_or(SETTING_MAX),
            parameters: r.parameters,
            diagnostics: r.diagnostics,
        };
        p.parameters.sort_by_key(|e| e.number);
        p.diagnostics.sort_by_key(|e| e.number);
        Ok(p)
    }
}
