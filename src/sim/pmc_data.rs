//! What a PMC unit's program holds besides the PMC memory (src/sim/pmc.rs
//! keeps them per unit): the title texts' answers (pmc_rdpmctitle,
//! pmc_rdpmctitle2), the program's and memory's type
//! (pmc_read_seq_program_and_memory_type) and the alarm messages' answer
//! (pmc_rdalmmsg).

use super::service::{CncError, Reply};
use crate::spec::Func;
use serde::Deserialize;

/// The title texts' members, in the profile's order (ODBPMCTITLE's).
const TITLE_MEMBERS: [&str; 10] = [
    "mtb", "machine", "type", "prgno", "prgvers", "prgdraw", "date", "design", "written", "remarks",
];

/// A title answer (reply layout `f`): each wire field the characters of
/// the text its member names from the element its `to` names on (`prgno`,
/// `prgno[4]`), cut or zero-padded to the field; zeros for the fields not
/// on the wire.
pub fn title(texts: &[String], f: &Func) -> Vec<i64> {
    let mut out = Vec::new();
    for field in f.reply {
        let text = match (field.arg, field.to) {
            (None, Some(to)) => {
                let (name, at) = match to.split_once('[') {
                    Some((m, i)) => (m, i.trim_end_matches(']').parse().unwrap_or(0)),
                    None => (to, 0),
                };
                (TITLE_MEMBERS.iter().position(|m| *m == name))
                    .and_then(|k| texts.get(k))
                    .map_or(&[][..], |t| t.as_bytes().get(at..).unwrap_or_default())
            }
            _ => &[][..],
        };
        let n = usize::from(field.n);
        out.extend((0..n).map(|k| i64::from(text.get(k).copied().unwrap_or(0))));
    }
    out
}

/// Most alarm messages one 0x8010 answer carries (FANUC's library asks
/// for no more: 11 × 128 bytes fit one answer).
pub const ALMMSG_MAX: usize = 11;
/// Bytes of one alarm message on the wire (ODBPMCALM).
pub const ALMMSG_LEN: usize = 128;

/// Command 0x8010[s, n] over the alarms `on` (in bit order): i32 count,
/// i32 exist (-1 no alarm, 0 all read, 1 more after these), then `count`
/// messages of 128 bytes (alarms s.., at most n and 11).
pub fn alarm_messages(on: &[&str], s: i32, n: i32) -> Reply<Vec<u8>> {
    if s < 1 || n < 1 {
        return Err(CncError::NUMBER);
    }
    let first = (s - 1) as usize;
    let take = (n as usize).min(ALMMSG_MAX);
    let list: Vec<&str> = on.iter().skip(first).take(take).copied().collect();
    let exist: i32 = if on.is_empty() {
        -1
    } else if first + list.len() < on.len() {
        1
    } else {
        0
    };
    let mut out = Vec::with_capacity(8 + list.len() * ALMMSG_LEN);
    out.extend((list.len() as i32).to_be_bytes());
    out.extend(exist.to_be_bytes());
    for m in list {
        let at = out.len();
        out.extend(&m.as_bytes()[..m.len().min(ALMMSG_LEN)]);
        out.resize(at + ALMMSG_LEN, 0);
    }
    Ok(out)
}

/// The sequence program's and the PMC memory's type (profile `[pmc]
/// program_type`, pmc_read_seq_program_and_memory_type): codes and names
/// \[ours: a real PMC's codes are not known\].
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProgramType {
    #[serde(default)]
    pub system: u32,
    #[serde(default)]
    pub system_attribute: u32,
    #[serde(default)]
    pub target: u32,
    #[serde(default)]
    pub target_attribute: u32,
    /// At most 32 characters each.
    #[serde(default)]
    pub system_name: String,
    #[serde(default)]
    pub target_name: String,
}

/// Characters of each of [`ProgramType`]'s names on the wire.
const TYPE_NAME: usize = 32;

impl ProgramType {
    /// Refuses names past their 32 bytes.
    pub fn check(&self) -> Result<(), String> {
        if self.system_name.len() > TYPE_NAME || self.target_name.len() > TYPE_NAME {
            return Err(format!(
                "[pmc] program_type: names of at most {TYPE_NAME} bytes"
            ));
        }
        Ok(())
    }

    /// Command 0x804c's answer: the four codes, then the two names
    /// zero-padded to 32 bytes.
    pub fn values(&self) -> Vec<i64> {
        let mut out: Vec<i64> = [
            self.system,
            self.system_attribute,
            self.target,
            self.target_attribute,
        ]
        .map(i64::from)
        .to_vec();
        for s in [&self.system_name, &self.target_name] {
            out.extend(
                (0..TYPE_NAME).map(|k| i64::from(s.as_bytes().get(k).copied().unwrap_or(0))),
            );
        }
        out
    }
}
