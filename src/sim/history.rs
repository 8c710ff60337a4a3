//! The simulated alarm history: a ring of the newest `capacity` alarms with
//! the CNC's own time stamps (history number 1 = newest), from the profile's
//! `[alarm_history]` and every alarm the running machine raises
//! ([`Machine::record_alarm`]).

use super::Machine;
use super::service::{CncError, Reply};
use crate::proto::alarm::{AlmHisRecord, AlmHistory, HIS_MSG_LEN};
use crate::proto::offset::Count;
use serde::Deserialize;
use std::time::SystemTime;

/// `[alarm_history]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct History {
    /// Entries kept; the oldest is dropped when a new alarm arrives.
    pub capacity: usize,
    /// `[[alarm_history.entry]]`, newest first.
    #[serde(rename = "entry")]
    pub entries: Vec<HistoryEntry>,
}

impl Default for History {
    fn default() -> Self {
        History {
            capacity: 50,
            entries: Vec::new(),
        }
    }
}

/// One alarm in the history.
#[derive(Debug, Clone, Deserialize, Default, PartialEq, Eq)]
#[serde(deny_unknown_fields, default)]
pub struct HistoryEntry {
    pub number: i32,
    /// Alarm type (group) code, as cnc_rdalmmsg's `type` (4 OT, 19 PC ...).
    #[serde(rename = "type")]
    pub kind: i16,
    /// Axis number (0 = none).
    pub axis: i16,
    /// "YYYY-MM-DD hh:mm:ss", the CNC's clock.
    pub time: String,
    /// Up to 32 characters are reported.
    pub message: String,
}

/// Parses "YYYY-MM-DD hh:mm:ss" into [year, month, day, hour, minute, second].
pub fn parse_time(s: &str) -> Option<[u16; 6]> {
    let (d, t) = s.trim().split_once([' ', 'T'])?;
    let mut out = [0u16; 6];
    let parts: Vec<&str> = d.split('-').chain(t.split(':')).collect();
    if parts.len() != 6 {
        return None;
    }
    for (o, p) in out.iter_mut().zip(parts) {
        *o = p.parse().ok()?;
    }
    let [_, mo, da, h, mi, se] = out;
    ((1..=12).contains(&mo) && (1..=31).contains(&da) && h < 24 && mi < 60 && se < 60)
        .then_some(out)
}

/// UTC calendar time of `t` as "YYYY-MM-DD hh:mm:ss".
pub fn format_time(t: SystemTime) -> String {
    let secs = t
        .duration_since(SystemTime::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs()) as i64;
    let (days, rem) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    // Howard Hinnant's days-to-civil.
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!(
        "{y:04}-{m:02}-{d:02} {:02}:{:02}:{:02}",
        rem / 3600,
        rem / 60 % 60,
        rem % 60
    )
}

impl History {
    pub fn validate(&self) -> Result<(), String> {
        if self.capacity == 0 {
            return Err("alarm_history.capacity must be at least 1".into());
        }
        if self.entries.len() > self.capacity {
            return Err("alarm_history has more entries than its capacity".into());
        }
        for e in &self.entries {
            if parse_time(&e.time).is_none() {
                return Err(format!(
                    "alarm_history entry time {:?} is not \"YYYY-MM-DD hh:mm:ss\"",
                    e.time
                ));
            }
        }
        Ok(())
    }
}

fn record(e: &HistoryEntry) -> AlmHisRecord {
    let [year, month, day, hour, minute, second] = parse_time(&e.time).unwrap_or([0; 6]);
    let b = e.message.as_bytes();
    let n = b.len().min(HIS_MSG_LEN);
    let mut msg = [0u8; HIS_MSG_LEN];
    msg[..n].copy_from_slice(&b[..n]);
    AlmHisRecord {
        alm_no: e.number,
        reserved: 0,
        alm_grp: e.kind,
        axis: i32::from(e.axis),
        year,
        month,
        day,
        hour,
        minute,
        second,
        msg_len: n as i32,
        msg,
    }
}

impl Machine {
    /// Adds an alarm to the history as the newest entry (number 1), time
    /// stamped `at` (UTC), dropping the oldest entry when the ring is full.
    /// Called by the running machine whenever it raises an alarm.
    pub fn record_alarm(
        &mut self,
        number: i32,
        kind: i16,
        axis: i16,
        message: &str,
        at: SystemTime,
    ) {
        let h = &mut self.profile.alarm_history;
        h.entries.insert(
            0,
            HistoryEntry {
                number,
                kind,
                axis,
                time: format_time(at),
                message: message.to_owned(),
            },
        );
        h.entries.truncate(h.capacity.max(1));
    }

    /// 0x006c [s, e, 1]: entries s..=e (1 = newest) that exist.
    pub fn history_read(&mut self, s: i32, e: i32) -> Reply<AlmHistory> {
        if s < 1 || e < s {
            return Err(CncError::NUMBER);
        }
        let all = &self.profile.alarm_history.entries;
        Ok(AlmHistory(
            all.iter()
                .skip(s as usize - 1)
                .take((e - s + 1) as usize)
                .map(record)
                .collect(),
        ))
    }

    /// 0x006b: number of entries.
    pub fn history_count(&mut self) -> Reply<Count> {
        Ok(Count {
            value: self.profile.alarm_history.entries.len() as i32,
        })
    }
}
