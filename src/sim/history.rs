//! The simulated alarm history: a ring of the newest `capacity` alarms with
//! the CNC's own time stamps (history number 1 = newest), from the profile's
//! `[alarm_history]` and every alarm the running machine raises
//! ([`Machine::record_alarm`]).

use super::Machine;
use super::profile::history::{HIS_SIGNALS, HisSignal};
pub use super::profile::history::{
    History, HistoryEntry, Message, MessageHistory, Operation, OperationHistory, parse_time,
};
use super::route::{Route, enc};
use super::service::{CncError, Reply};
use crate::ew;
use crate::proto::alarm::{AlmHisRecord, AlmHistory, HIS_MSG_LEN, RDALMHISNO, RDALMHISTRY};
use crate::proto::cmd::RDPITCHINFO;
use crate::proto::cmd::{
    CLEAROMHIS, CLEAROPHIS, RDALMHISNO3, RDHISSGNL, RDHISSGNL3, RDOMHISINFO, RDOMHISNO, RDOPHISNO,
    RDOPHISNO3, STARTOMHIS, STARTOPHIS, STOPOMHIS, STOPOPHIS,
};
use crate::proto::history::{
    RDALMHISTRY5, RDOMHISTRY, RDOMHISTRY2, RDOPHISTRY, RDOPHISTRY4, RDPITCHR, WRHISSGNL3,
};
use crate::proto::offset::Count;
use crate::proto::packet::ReqSub;
use std::time::SystemTime;

/// The signals cnc_rdhissgnl reads (IODBSIG's entries).
const HIS_SIGNALS_16: usize = 20;

/// A count as the history functions answer it (at most 65535).
fn count(n: usize) -> Vec<i64> {
    vec![n.min(usize::from(u16::MAX)) as i64]
}

pub(super) const ROUTES: &[Route] = &[
    // [s, e, 1]: alarm history entries s..=e (1 = newest).
    Route::cnc(
        RDALMHISTRY,
        |m, q| enc(m.history_read(q.args[0], q.args[1])),
    ),
    Route::table(RDALMHISNO, |m, _| {
        m.history_count().map(|c| vec![i64::from(c.value)])
    }),
    // The range reads of src/proto/history.rs: the answer's bytes for the
    // request's arguments.
    Route::cnc(RDOPHISTRY, |m, q| m.history_bytes(q.path, q.cmd, q.args)),
    Route::cnc(RDOPHISTRY4, |m, q| m.history_bytes(q.path, q.cmd, q.args)),
    Route::cnc(RDOMHISTRY, |m, q| m.history_bytes(q.path, q.cmd, q.args)),
    Route::cnc(RDOMHISTRY2, |m, q| m.history_bytes(q.path, q.cmd, q.args)),
    Route::cnc(RDALMHISTRY5, |m, q| m.history_bytes(q.path, q.cmd, q.args)),
    Route::cnc(RDPITCHR, |m, q| m.history_bytes(q.path, q.cmd, q.args)),
    Route::cnc(WRHISSGNL3, |m, q| m.write_signals(q)),
    // The 30i's counts: all 32 bits.
    Route::table(RDALMHISNO3, |m, _| {
        Ok(vec![m.profile.alarm_history.entries.len() as i64])
    }),
    Route::table(RDOPHISNO3, |m, _| {
        Ok(vec![m.profile.operation_history.entries.len() as i64])
    }),
    Route::table(RDOPHISNO, |m, _| {
        Ok(count(m.profile.operation_history.entries.len()))
    }),
    Route::table(STARTOPHIS, |m, _| {
        m.profile.operation_history.recording = true;
        Ok(Vec::new())
    }),
    Route::table(STOPOPHIS, |m, _| {
        m.profile.operation_history.recording = false;
        Ok(Vec::new())
    }),
    Route::table(CLEAROPHIS, |m, _| {
        m.profile.operation_history.entries.clear();
        Ok(Vec::new())
    }),
    Route::table(RDHISSGNL3, |m, _| Ok(m.signal_table())),
    // The 16i's form: the first 20 entries, without the PMC number.
    Route::table(RDHISSGNL, |m, _| {
        let t = m.signal_table();
        let recs = t.chunks(7).take(HIS_SIGNALS_16);
        Ok(recs.flat_map(|r| [r[0], r[2], 0, r[4], r[5], 0]).collect())
    }),
    Route::table(RDOMHISNO, |m, _| {
        Ok(count(m.profile.operator_message_history.entries.len()))
    }),
    Route::table(RDOMHISINFO, |m, _| {
        let oms = &m.profile.operator_message_history;
        Ok([oms.capacity, oms.entries.len(), oms.chars]
            .map(|n| n.min(usize::from(u16::MAX)) as i64)
            .to_vec())
    }),
    Route::table(STARTOMHIS, |m, _| {
        m.profile.operator_message_history.recording = true;
        Ok(Vec::new())
    }),
    Route::table(STOPOMHIS, |m, _| {
        m.profile.operator_message_history.recording = false;
        Ok(Vec::new())
    }),
    Route::table(CLEAROMHIS, |m, _| {
        m.profile.operator_message_history.entries.clear();
        Ok(Vec::new())
    }),
    Route::table(RDPITCHINFO, |m, _| {
        Ok(vec![i64::from(m.profile.pitch.size)])
    }),
];

/// UTC calendar time of `t` as "YYYY-MM-DD hh:mm:ss" (before 1970: 1970).
pub fn format_time(t: SystemTime) -> String {
    jiff::Timestamp::try_from(t.max(SystemTime::UNIX_EPOCH))
        .unwrap_or(jiff::Timestamp::UNIX_EPOCH)
        .strftime("%Y-%m-%d %H:%M:%S")
        .to_string()
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
    /// recording (cnc_startophis / cnc_stopophis): a `"date"` record first
    /// on a new day, a `"time"` record on a new second, then the operation.
    pub fn record_operation(&mut self, op: Operation, at: SystemTime) {
        let h = &mut self.profile.operation_history;
        if !h.recording {
            return;
        }
        let time = format_time(at);
        let last = |kind: &str| {
            h.entries
                .iter()
                .find(|e| e.kind == kind)
                .map(|e| e.time.clone())
        };
        let stamps = [
            ("date", last("date").is_none_or(|t| t[..10] != time[..10])),
            ("time", last("time").as_deref() != Some(&time)),
        ];
        for (kind, new) in stamps {
            if new {
                let e = Operation {
                    kind: kind.into(),
                    time: time.clone(),
                    ..Operation::default()
                };
                push_newest(&mut h.entries, h.capacity, e);
            }
        }
        push_newest(&mut h.entries, h.capacity, Operation { time, ..op });
    }

    /// A signal the machine changed itself, now: one `"signal"` record of
    /// PMC byte `byte` of address type `adr_type` (0 G, 1 F, 2 Y, 3 X) of
    /// PMC 1, when the history's signal table selects it.
    pub(crate) fn record_signal(&mut self, adr_type: i16, byte: i32, old: u8, new: u8) {
        self.record_pmc_signal(1, adr_type, byte, old, new);
    }

    /// [`Machine::record_signal`] of PMC `unit`: recorded when the signal
    /// table (cnc_rdhissgnl3) lists the byte and its mask selects a bit
    /// that changed (a press of a bit already set, old = new, counts).
    pub(crate) fn record_pmc_signal(
        &mut self,
        unit: u16,
        adr_type: i16,
        byte: i32,
        old: u8,
        new: u8,
    ) {
        let listed = self.profile.operation_history.signals.iter().any(|s| {
            i32::from(s.pmc) == i32::from(unit)
                && s.group == adr_type
                && i32::from(s.number) == byte
                && (old == new || (old ^ new) & s.mask != 0)
        });
        if !listed {
            return;
        }
        let op = Operation {
            kind: "signal".into(),
            number: byte,
            group: adr_type,
            old,
            new,
            ..Default::default()
        };
        self.record_operation(op, SystemTime::now());
    }

    /// The range reads (src/proto/history.rs): 0x006a [s, e] operation
    /// records, 0x0073 [s, e] and 0x01b5 [s, e, n] operator messages,
    /// 0x01d1 [s, e, n] alarm history 5 (entries s..=e, 1 = newest, that
    /// exist); 0x0012 [s, e] pitch error points.
    pub fn history_bytes(&mut self, path: u16, cmd: u16, a: [i32; 5]) -> Reply<Vec<u8>> {
        use crate::proto::history as ph;
        let (s, e) = (a[0], a[1]);
        if cmd == ph::RDPITCHR {
            // Pitch points s..=e of the table, 0 where the profile has none.
            let p = &self.profile.pitch;
            if s < 0 || e < s || e >= p.size {
                return Err(CncError::NUMBER);
            }
            let v = |n: i32| p.values.get(n as usize).copied().unwrap_or(0);
            return Ok((s..=e)
                .flat_map(|n| i16::from(v(n)).to_be_bytes())
                .collect());
        }
        if cmd == ph::RDOPHISTRY4 {
            return self.ophistry4(s, e);
        }
        if s < 0 || e < s {
            return Err(CncError::NUMBER);
        }
        let range = |n: usize| (s.max(1) as usize - 1).min(n)..(e as usize).min(n);
        let stamp = |t: &str| parse_time(t).unwrap_or([0; 6]);
        let mut out = Vec::new();
        match cmd {
            ph::RDOPHISTRY => {
                let ops = &self.profile.operation_history.entries;
                for o in &ops[range(ops.len())] {
                    let [y, mo, d, h, mi, se] = stamp(&o.time).map(i32::from);
                    let (t, w) = match o.kind.as_str() {
                        "mdi" => (0, [o.number, 0, 0, 0]),
                        "signal" => (1, [o.number, o.group.into(), o.old.into(), o.new.into()]),
                        "alarm" => (2, [o.number, o.group.into(), o.axis.into(), 0]),
                        "date" => (3, [y, mo, d, 0]),
                        _ => (4, [h, mi, se, 0]),
                    };
                    out.extend(ph::op_record(t, w));
                }
            }
            ph::RDOMHISTRY | ph::RDOMHISTRY2 => {
                let oms = &self.profile.operator_message_history.entries;
                let shown: Vec<i32> = self
                    .profile
                    .paths
                    .iter()
                    .flat_map(|p| p.opmsgs.iter().map(|m| m.number))
                    .collect();
                let r = range(oms.len());
                if cmd == ph::RDOMHISTRY2 {
                    out.extend((r.len() as i32).to_be_bytes());
                }
                for m in &oms[r] {
                    let t = stamp(&m.time);
                    out.extend(if cmd == ph::RDOMHISTRY {
                        ph::om_record(m.number as i16, &t, &m.text)
                    } else {
                        ph::om2_record(shown.contains(&m.number), m.number as i16, &t, &m.text)
                    });
                }
            }
            _ => {
                let axes = self.path(path)?.axes.len() as i16;
                let alms = &self.profile.alarm_history.entries;
                for x in &alms[range(alms.len())] {
                    out.extend(ph::alm5_record(&ph::Alm5 {
                        number: x.number,
                        group: x.kind.into(),
                        axis: x.axis.into(),
                        time: stamp(&x.time),
                        path: path as i16,
                        axes,
                        message: x.message.clone(),
                    }));
                }
            }
        }
        Ok(out)
    }

    /// 0x01b0 [s, e]: the operation history records s..=e (1 = newest)
    /// in the 30i's form: every entry but the "time" stamps (each record
    /// carries its time), as many as one answer holds; the more flag says
    /// the range goes on. A start past the history: no records.
    fn ophistry4(&mut self, s: i32, e: i32) -> Reply<Vec<u8>> {
        use crate::proto::history as ph;
        let ops: Vec<&Operation> = self
            .profile
            .operation_history
            .entries
            .iter()
            .filter(|o| o.kind != "time")
            .collect();
        if s < 1 || e < s {
            return Err(CncError::NUMBER);
        }
        let room = crate::proto::packet::MAX_ANSWER - 8;
        let (mut body, mut n) = (Vec::new(), 0);
        let last = (e as usize).min(ops.len());
        let first = (s as usize - 1).min(last);
        for o in &ops[first..last] {
            let [y, mo, d, h, mi, se] = parse_time(&o.time).unwrap_or([0; 6]).map(i32::from);
            let r = match o.kind.as_str() {
                "mdi" => ph::op4_record(0, |b| {
                    ph::put16(b, 4, o.number);
                    ph::put16(b, 8, 1);
                    for (k, v) in [h, mi, se].into_iter().enumerate() {
                        ph::put16(b, 0xc + 2 * k, v);
                    }
                }),
                "signal" => ph::op4_record(1, |b| {
                    ph::put32(b, 4, o.number);
                    ph::put16(b, 8, o.group.into());
                    ph::put16(b, 0xa, 1);
                    b[0xc] = o.old;
                    b[0xd] = o.new;
                    for (k, v) in [h, mi, se].into_iter().enumerate() {
                        ph::put16(b, 0xe + 2 * k, v);
                    }
                }),
                "alarm" => ph::op4_record(2, |b| {
                    ph::put32(b, 4, o.number);
                    ph::put16(b, 8, o.group.into());
                    ph::put16(b, 0xa, o.axis.into());
                    for (k, v) in [y, mo, d, h, mi, se, 1].into_iter().enumerate() {
                        ph::put16(b, 0xc + 2 * k, v);
                    }
                }),
                _ => ph::op4_record(3, |b| {
                    for (k, v) in [0, y, mo, d, h, mi, se].into_iter().enumerate() {
                        ph::put16(b, 4 + 2 * k, v);
                    }
                }),
            };
            if body.len() + r.len() > room {
                break;
            }
            body.extend(r);
            n += 1;
        }
        let more = i32::from(first + n < last);
        let mut out = more.to_be_bytes().to_vec();
        out.extend((n as i32).to_be_bytes());
        out.extend(body);
        Ok(out)
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

    /// 0x01b3 (cnc_wrhissgnl3) [n] and n 16-byte entries: each entry
    /// number 1..=60, PMC 0 (clears the entry) ..= the PMCs, address type
    /// 0..=3, byte 0..=9999, else EW_DATA and nothing changes; the payload
    /// must hold n entries (n 0..=60), else EW_LENGTH.
    fn write_signals(&mut self, sub: &ReqSub) -> Reply<Vec<u8>> {
        use crate::proto::history::{SIG3_REC, Sig3};
        let n = sub.args[0];
        let p = &sub.payload;
        if !(0..=HIS_SIGNALS as i32).contains(&n) || p.len() != n as usize * SIG3_REC {
            return Err(CncError::new(ew::EW_LENGTH));
        }
        let units = self.profile.pmc.units() as i32;
        let mut new = Vec::new();
        for e in p.chunks_exact(SIG3_REC) {
            let (ent, pmc, number, group, mask) = Sig3::from_wire(e);
            let ok = (1..=HIS_SIGNALS as i32).contains(&ent)
                && (0..=units).contains(&pmc)
                && (0..=3).contains(&group)
                && (0..=9999).contains(&number);
            if !ok {
                return Err(CncError::new(ew::EW_DATA));
            }
            let s = if pmc == 0 {
                HisSignal {
                    pmc: 0,
                    group: 0,
                    number: 0,
                    mask: 0,
                }
            } else {
                HisSignal {
                    pmc: pmc as i16,
                    group: i16::from(group),
                    number: number as i16,
                    mask,
                }
            };
            new.push((ent as usize - 1, s));
        }
        let table = &mut self.profile.operation_history.signals;
        for (k, s) in new {
            if table.len() <= k {
                table.resize(
                    k + 1,
                    HisSignal {
                        pmc: 0,
                        group: 0,
                        number: 0,
                        mask: 0,
                    },
                );
            }
            table[k] = s;
        }
        Ok(Vec::new())
    }

    /// cnc_rdhissgnl3: the 60 entries of the signal table, numbered 1..,
    /// those the profile does not set zeros.
    fn signal_table(&self) -> Vec<i64> {
        let ops = &self.profile.operation_history;
        (0..HIS_SIGNALS)
            .flat_map(|k| {
                let s = ops.signals.get(k);
                let v = |f: fn(&HisSignal) -> i64| s.map_or(0, f);
                [
                    k as i64 + 1,
                    v(|s| s.pmc.into()),
                    v(|s| s.number.into()),
                    0,
                    v(|s| s.group.into()),
                    v(|s| s.mask.into()),
                    0,
                ]
            })
            .collect()
    }
}
