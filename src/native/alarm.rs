//! Active alarms (cnc_rdalmmsg2) and the alarm history (cnc_rdalmhistry).

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::error::{Error, Ew, Result};
use super::part::{Part, via};
use crate::proto::alarm::{AlmHisRecord, HIS_MSG_LEN, rdalmhistry, rdalmmsg};
use crate::proto::packet::{MAX_ANSWER, answer_records};
use std::fmt;

/// An alarm type (FANUC's alarm group): 4 is OT (overtravel), 6 SV (servo) ...
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct AlarmKind(pub i16);

/// Prefixes of the 30i-class alarm types 0 to 15, as the CNC shows them.
const PREFIXES: [&str; 16] = [
    "SW", "PW", "IO", "PS", "OT", "OH", "SV", "SR", "MC", "SP", "DS", "IE", "BG", "SN", "", "EX",
];

impl AlarmKind {
    /// The two-letter prefix the CNC shows ("OT"), if the type has one.
    pub fn prefix(self) -> Option<&'static str> {
        match self.0 {
            19 => Some("PC"),
            t => usize::try_from(t)
                .ok()
                .and_then(|t| PREFIXES.get(t))
                .copied()
                .filter(|p| !p.is_empty()),
        }
    }
}

/// An alarm number as the CNC shows it: "OT0500", or "500 (type 21)".
pub(crate) fn shown(kind: AlarmKind, number: i32) -> String {
    match kind.prefix() {
        Some(p) => format!("{p}{number:04}"),
        None => format!("{number} (type {})", kind.0),
    }
}

/// An active alarm.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Alarm {
    pub number: i32,
    pub kind: AlarmKind,
    /// The axis it concerns (1..), 0 for none.
    pub axis: i16,
    pub message: String,
}

impl Alarm {
    /// The number as the CNC shows it: "OT0500" (or "500 (type 21)").
    pub fn code(&self) -> String {
        shown(self.kind, self.number)
    }
}

impl fmt::Display for Alarm {
    /// `OT0500 OVER TRAVEL ( SOFT 1 ) +X`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", shown(self.kind, self.number), self.message)
    }
}

/// A CNC clock reading.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Timestamp {
    pub year: u16,
    pub month: u8,
    pub day: u8,
    pub hour: u8,
    pub minute: u8,
    pub second: u8,
}

impl Timestamp {
    /// RFC 3339 with the UTC offset this computer's time zone has at that
    /// time ("2024-05-17T13:45:30+02:00"): the CNC's clock keeps no zone,
    /// it is taken to be this computer's (`TZ`). `None` when the reading
    /// is no date (month 13, February 30).
    ///
    /// ```
    /// use fwlib32::native::Timestamp;
    ///
    /// let t = Timestamp { year: 2024, month: 5, day: 17, hour: 13, minute: 45, second: 30 };
    /// let s = t.rfc3339().unwrap();
    /// assert!(s.starts_with("2024-05-17T13:45:30"), "{s}");
    /// assert!(s.ends_with("Z") || s[19..].len() == 6, "an offset: {s}");
    /// assert_eq!(Timestamp { month: 13, ..t }.rfc3339(), None);
    /// ```
    pub fn rfc3339(&self) -> Option<String> {
        let n = |v: u8| i8::try_from(v).ok();
        let dt = jiff::civil::DateTime::new(
            i16::try_from(self.year).ok()?,
            n(self.month)?,
            n(self.day)?,
            n(self.hour)?,
            n(self.minute)?,
            n(self.second)?,
            0,
        )
        .ok()?;
        let z = dt.to_zoned(jiff::tz::TimeZone::system()).ok()?;
        Some(z.strftime("%Y-%m-%dT%H:%M:%S%:z").to_string())
    }
}

impl fmt::Display for Timestamp {
    /// `2024-05-17 13:45:30`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:04}-{:02}-{:02} {:02}:{:02}:{:02}",
            self.year, self.month, self.day, self.hour, self.minute, self.second
        )
    }
}

/// An entry of the alarm history.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct HistoryEntry {
    pub number: i32,
    pub kind: AlarmKind,
    /// The axis it concerns (1..), 0 for none.
    pub axis: i16,
    /// When the alarm was raised, by the CNC's clock.
    pub time: Timestamp,
    pub message: String,
}

impl HistoryEntry {
    /// The number as the CNC shows it: "OT0500" (or "500 (type 21)").
    pub fn code(&self) -> String {
        shown(self.kind, self.number)
    }
}

impl fmt::Display for HistoryEntry {
    /// `2024-05-16 09:12:05 OT0500 OVER TRAVEL ( +Z )`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = shown(self.kind, self.number);
        write!(f, "{} {n} {}", self.time, self.message)
    }
}

/// The first `len` bytes of a message field, as text.
fn message(b: &[u8], len: i32) -> String {
    let n = usize::try_from(len).unwrap_or(0).min(b.len());
    super::position::name(&b[..n])
}

/// Alarms one cnc_rdalmmsg2 answer holds (80-byte records).
const ALMMSG_RECORDS: i16 = 17;

fn alarms_part() -> impl Part<Out = Vec<Alarm>> + Send + 'static {
    const CALL: &str = "cnc_rdalmmsg2";
    let n = answer_records(i32::from(ALMMSG_RECORDS), 80) as usize;
    NoAlarmIsEmpty(via(CALL, rdalmmsg::<64>(-1, ALMMSG_RECORDS), 80 * n, |r| {
        Ok(r.0
            .iter()
            .map(|a| Alarm {
                number: a.alm_no,
                kind: AlarmKind(a.kind as i16),
                axis: a.axis as i16,
                message: message(&a.msg, a.msg_len),
            })
            .collect())
    }))
}

fn entry(r: &AlmHisRecord) -> HistoryEntry {
    HistoryEntry {
        number: r.alm_no,
        kind: AlarmKind(r.alm_grp),
        axis: r.axis as i16,
        time: Timestamp {
            year: r.year,
            month: r.month as u8,
            day: r.day as u8,
            hour: r.hour as u8,
            minute: r.minute as u8,
            second: r.second as u8,
        },
        message: message(&r.msg, r.msg_len.min(HIS_MSG_LEN as i32)),
    }
}

impl Cnc {
    /// The alarms active on the current path, with their messages (at most
    /// 17, what one answer holds). No alarm: an empty list.
    ///
    /// ```
    /// use fwlib32::native::Cnc;
    /// use fwlib32::sim::{Profile, Simulator};
    /// use std::time::Duration;
    ///
    /// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// sim.set_elapsed(Duration::from_secs(35)); // the profile's alarm is raised at 30 s
    /// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
    /// let alarms = cnc.alarms()?;
    /// assert_eq!(alarms[0].to_string(), "OT0500 OVER TRAVEL ( SOFT 1 ) +X");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn alarms(&self) -> Result<Vec<Alarm>> {
        self.run(alarms_part())
    }

    /// The alarm history, newest first (cnc_rdalmhisno, then
    /// cnc_rdalmhistry as many times as needed). Entries with an impossible
    /// time are left out.
    ///
    /// ```
    /// # use fwlib32::native::Cnc;
    /// # use fwlib32::sim::{Profile, Simulator};
    /// # let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// # sim.set_elapsed(std::time::Duration::ZERO);
    /// # let cnc = Cnc::connect(&sim.addr().to_string(), std::time::Duration::from_secs(5))?;
    /// let history = cnc.alarm_history()?;
    /// assert_eq!(history[1].to_string(), "2024-05-16 09:12:05 OT0500 OVER TRAVEL ( +Z )");
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn alarm_history(&self) -> Result<Vec<HistoryEntry>> {
        let count = self.run(super::status::described("cnc_rdalmhisno"))?;
        let count = count.first().copied().unwrap_or(0);
        let total = u16::try_from(count.max(0)).unwrap_or(u16::MAX);
        let per = answer_records(i32::MAX, 60) as u16;
        let mut out = Vec::new();
        let mut s = 1u16;
        while s <= total && s > 0 {
            let e = s.saturating_add(per - 1).min(total);
            let recs = self.run(via("cnc_rdalmhistry", rdalmhistry(s, e), MAX_ANSWER, |h| {
                Ok(h.valid())
            }))?;
            out.extend(recs.iter().map(entry));
            s = e.wrapping_add(1);
        }
        Ok(out)
    }
}

impl Batch<'_> {
    /// [`Cnc::alarms`] in the batch.
    pub fn alarms(&mut self) -> Ticket<Vec<Alarm>> {
        self.push(alarms_part())
    }
}

/// The CNC's EW_LENGTH to a request for alarms: none (as FANUC's library reads it).
struct NoAlarmIsEmpty<P>(P);

impl<P: Part<Out = Vec<Alarm>>> Part for NoAlarmIsEmpty<P> {
    type Out = Vec<Alarm>;
    fn call(&self) -> &'static str {
        self.0.call()
    }
    fn subs(&self, cx: &crate::proto::call::Ctx) -> Vec<crate::proto::packet::ReqSub> {
        self.0.subs(cx)
    }
    fn answer_max(&self, cx: &crate::proto::call::Ctx) -> usize {
        self.0.answer_max(cx)
    }
    fn decode(
        &self,
        cx: &crate::proto::call::Ctx,
        resp: &[crate::proto::packet::RespSub],
    ) -> Result<Vec<Alarm>> {
        match self.0.decode(cx, resp) {
            Err(Error::Cnc {
                code: Ew::LENGTH, ..
            }) => Ok(Vec::new()),
            r => r,
        }
    }
}
