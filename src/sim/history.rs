//! The simulated alarm history: a ring of the newest `capacity` alarms with
//! the CNC's own time stamps (history number 1 = newest), from the profile's
//! `[alarm_history]` and every alarm the running machine raises
//! ([`Machine::record_alarm`]).

use super::Machine;
pub use super::profile::history::{
    History, HistoryEntry, Message, MessageHistory, Operation, OperationHistory, parse_time,
};
use super::service::{CncError, Reply};
use crate::proto::alarm::{AlmHisRecord, AlmHistory, HIS_MSG_LEN};
use crate::proto::offset::Count;
use std::time::SystemTime;

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

/// Puts `e` first in a ring of `capacity` entries.
fn push_newest<T>(entries: &mut Vec<T>, capacity: usize, e: T) {
    entries.insert(0, e);
    entries.truncate(capacity);
}

impl Machine {
    /// Records an operation, newest first, when the operation history is
    /// recording (cnc_startophis / cnc_stopophis).
    pub fn record_operation(&mut self, kind: &str, number: i32, at: SystemTime) {
        let h = &mut self.profile.operation_history;
        if h.recording {
            let e = Operation {
                kind: kind.to_string(),
                number,
                time: format_time(at),
            };
            push_newest(&mut h.entries, h.capacity, e);
        }
    }

    /// The operator messages on display at power-on enter the operator
    /// message history once, at the first advance.
    pub(crate) fn seed_messages(&mut self, at: SystemTime) {
        if std::mem::replace(&mut self.profile.operator_message_history.seeded, true) {
            return;
        }
        let shown: Vec<(i32, String)> = self
            .profile
            .paths
            .iter()
            .flat_map(|p| p.opmsgs.iter().map(|m| (m.number, m.text.clone())))
            .collect();
        let h = &mut self.profile.operator_message_history;
        for (number, text) in shown {
            if h.recording {
                let text: String = text.chars().take(h.chars).collect();
                let e = Message {
                    number,
                    text,
                    time: format_time(at),
                };
                push_newest(&mut h.entries, h.capacity, e);
            }
        }
    }

    /// The answers of the history functions described as data
    /// (src/spec/table.rs): counts and sizes, and the record/clear commands.
    pub(crate) fn history_answer(&mut self, name: &str) -> Option<Vec<i64>> {
        let ops = &mut self.profile.operation_history;
        let oms = &mut self.profile.operator_message_history;
        let count = |n: usize| vec![n.min(usize::from(u16::MAX)) as i64];
        Some(match name {
            "cnc_rdophisno" => count(ops.entries.len()),
            "cnc_startophis" | "cnc_stopophis" => {
                ops.recording = name == "cnc_startophis";
                Vec::new()
            }
            "cnc_clearophis" => {
                ops.entries.clear();
                Vec::new()
            }
            "cnc_rdomhisno" => count(oms.entries.len()),
            "cnc_rdomhisinfo" => [oms.capacity, oms.entries.len(), oms.chars]
                .map(|n| n.min(usize::from(u16::MAX)) as i64)
                .to_vec(),
            "cnc_startomhis" | "cnc_stopomhis" => {
                oms.recording = name == "cnc_startomhis";
                Vec::new()
            }
            "cnc_clearomhis" => {
                oms.entries.clear();
                Vec::new()
            }
            _ => return None,
        })
    }
}
