//! Profile section `[alarm_history]`: the alarm history at start
//! (kept and served by src/sim/history.rs).

use serde::Deserialize;

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

/// `[operation_history]`: what was done at the machine, newest first
/// (cnc_rdophisno, cnc_startophis / cnc_stopophis / cnc_clearophis). The
/// simulator records the alarms the running machine raises.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OperationHistory {
    /// Entries kept; the oldest is dropped when a new one arrives.
    pub capacity: usize,
    /// Whether new operations are recorded (cnc_startophis / cnc_stopophis).
    pub recording: bool,
    /// `[[operation_history.entry]]`, newest first.
    #[serde(rename = "entry")]
    pub entries: Vec<Operation>,
    /// `[[operation_history.signal]]`: the signals the history records
    /// (cnc_rdhissgnl3 / cnc_wrhissgnl3), at most [`HIS_SIGNALS`].
    #[serde(rename = "signal")]
    pub signals: Vec<HisSignal>,
}

/// The most signals the operation history records (IODBSIG3's entries).
pub const HIS_SIGNALS: usize = 60;

impl Default for OperationHistory {
    fn default() -> Self {
        // The panel signals the running machine records (FANUC's PMC
        // addresses): the mode select byte G43, ST (G7.2), RST (F1.1),
        // the manual feed override *JV (G10) and the feedrate override
        // *FV (G12).
        let sig = |group, number, mask| HisSignal {
            pmc: 1,
            group,
            number,
            mask,
        };
        OperationHistory {
            capacity: 100,
            recording: true,
            entries: Vec::new(),
            signals: vec![
                sig(0, 43, 0xff),
                sig(0, 7, 0x04),
                sig(1, 1, 0x02),
                sig(0, 10, 0xff),
                sig(0, 12, 0xff),
            ],
        }
    }
}

impl OperationHistory {
    pub fn validate(&self) -> Result<(), String> {
        if self.signals.len() > HIS_SIGNALS {
            return Err(format!(
                "operation_history has more than {HIS_SIGNALS} signals"
            ));
        }
        for s in &self.signals {
            s.validate()?;
        }
        Ok(())
    }
}

/// One signal byte the operation history records: PMC `pmc` (1..; 0 an
/// empty entry), its
/// address type `group` (0 G, 1 F, 2 Y, 3 X, as the signal records' sig_name),
/// byte `number`, and the bits `mask` selects.
#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq)]
#[serde(deny_unknown_fields, default)]
pub struct HisSignal {
    pub pmc: i16,
    pub group: i16,
    pub number: i16,
    pub mask: u8,
}

impl Default for HisSignal {
    fn default() -> Self {
        HisSignal {
            pmc: 1,
            group: 0,
            number: 0,
            mask: 0xff,
        }
    }
}

impl HisSignal {
    pub fn validate(&self) -> Result<(), String> {
        if self.pmc < 0 || !(0..=3).contains(&self.group) || self.number < 0 {
            return Err(format!(
                "operation_history signal {self:?}: pmc must be 0 (an empty entry) or 1.., group 0..=3 (G, F, Y, X), number 0.."
            ));
        }
        Ok(())
    }
}

/// One operation record, when ("YYYY-MM-DD hh:mm:ss") and what: `"mdi"`
/// (an MDI key, `number` its code), `"signal"` (a signal change: `number`
/// the byte, `group` the PMC address type, `old` and `new` its bits),
/// `"alarm"` (`number`, `group` the alarm type, `axis`), or the `"date"` /
/// `"time"` stamps the CNC puts before the records of a new day / second.
#[derive(Debug, Clone, Deserialize, Default, PartialEq, Eq)]
#[serde(deny_unknown_fields, default)]
pub struct Operation {
    pub kind: String,
    pub number: i32,
    pub group: i16,
    pub axis: i16,
    pub old: u8,
    pub new: u8,
    pub time: String,
}

/// `[operator_message_history]`: the operator messages that appeared,
/// newest first (cnc_rdomhisno, cnc_rdomhisinfo, cnc_startomhis ...): the
/// profile's messages on display at power-on are its first entries.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct MessageHistory {
    /// Entries kept; the oldest is dropped when a new one arrives.
    pub capacity: usize,
    /// Characters kept of each message.
    pub chars: usize,
    /// Whether new messages are recorded (cnc_startomhis / cnc_stopomhis).
    pub recording: bool,
    /// `[[operator_message_history.entry]]`, newest first.
    #[serde(rename = "entry")]
    pub entries: Vec<Message>,
    /// The messages on display at power-on are in (the first advance).
    #[serde(skip)]
    pub seeded: bool,
}

impl Default for MessageHistory {
    fn default() -> Self {
        MessageHistory {
            capacity: 50,
            chars: 255,
            recording: true,
            entries: Vec::new(),
            seeded: false,
        }
    }
}

/// One operator message: its number, text and when it appeared.
#[derive(Debug, Clone, Deserialize, Default, PartialEq, Eq)]
#[serde(deny_unknown_fields, default)]
pub struct Message {
    pub number: i32,
    pub text: String,
    pub time: String,
}
