//! SHDR, the MTConnect adapter protocol: `timestamp|name|value|...` lines,
//! conditions each on a line of their own, and the `* PING` heartbeat.

use std::fmt::Write as _;

/// A UTC time as SHDR writes it: `YYYY-MM-DDTHH:MM:SS.FFFZ` (milliseconds).
pub fn timestamp(t: jiff::Timestamp) -> String {
    let z = t.to_zoned(jiff::tz::TimeZone::UTC);
    format!(
        "{:04}-{:02}-{:02}T{:02}:{:02}:{:02}.{:03}Z",
        z.year(),
        z.month(),
        z.day(),
        z.hour(),
        z.minute(),
        z.second(),
        z.millisecond()
    )
}

/// Now, as [`timestamp`] writes it.
pub fn now() -> String {
    timestamp(jiff::Timestamp::now())
}

/// A value fit for one SHDR field: no `|` (the separator) and no line
/// breaks, which would end or split the line; they become spaces.
pub fn field(v: &str) -> String {
    v.chars()
        .map(|c| if c == '|' || c.is_control() { ' ' } else { c })
        .collect::<String>()
        .trim()
        .to_string()
}

/// `ts|name|value|name|value...` with a line feed, then a line
/// `ts|name|field|field...` for each value of several fields ([`SEP`]);
/// None for no pairs.
pub fn sample_line(ts: &str, pairs: &[(String, String)]) -> Option<String> {
    let mut s = String::new();
    let mut own = String::new();
    for (n, v) in pairs {
        if v.contains(SEP) {
            // Several fields (a message's code and text, a time series'
            // count, rate and values): a line of its own.
            let f: Vec<String> = v.split(SEP).map(field).collect();
            let _ = writeln!(own, "{ts}|{n}|{}", f.join("|"));
        } else {
            if s.is_empty() {
                s.push_str(ts);
            }
            let _ = write!(s, "|{n}|{}", field(v));
        }
    }
    if !s.is_empty() {
        s.push('\n');
    }
    s.push_str(&own);
    (!s.is_empty()).then_some(s)
}

/// An asset: `ts|@ASSET@|id|CuttingTool|--multiline--MARK`, the document's
/// lines, then the mark again.
pub fn asset(ts: &str, id: &str, doc: &str) -> String {
    const MARK: &str = "--multiline--0FED07ACED";
    format!(
        "{ts}|@ASSET@|{}|CuttingTool|{MARK}\n{}\n{MARK}\n",
        field(id),
        doc.trim_end()
    )
}

/// Separates the fields of a value of several (see [`sample_line`]).
pub const SEP: char = '\u{1f}';

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    Normal,
    Fault,
    Unavailable,
}

impl Level {
    pub fn as_str(self) -> &'static str {
        match self {
            Level::Normal => "NORMAL",
            Level::Fault => "FAULT",
            Level::Unavailable => "UNAVAILABLE",
        }
    }
}

/// One condition activation: `name|level|native_code|native_severity|qualifier|text`
/// (without the timestamp).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Cond {
    pub name: String,
    pub level: Level,
    pub code: String,
    pub severity: String,
    pub qualifier: String,
    pub text: String,
}

impl Cond {
    /// The level alone (bare NORMAL clears every activation of `name`;
    /// UNAVAILABLE says nothing is known).
    pub fn bare(name: &str, level: Level) -> Cond {
        Cond {
            name: name.to_string(),
            level,
            code: String::new(),
            severity: String::new(),
            qualifier: String::new(),
            text: String::new(),
        }
    }

    /// The line, timestamp first, with its line feed.
    pub fn line(&self, ts: &str) -> String {
        format!(
            "{ts}|{}|{}|{}|{}|{}|{}\n",
            self.name,
            self.level.as_str(),
            field(&self.code),
            field(&self.severity),
            field(&self.qualifier),
            field(&self.text)
        )
    }
}

/// The answer to an agent's `* PING`: `* PONG <ms>`, the heartbeat the
/// adapter expects (the agent drops the connection after twice as long
/// without a line).
pub fn pong(heartbeat_ms: u64) -> String {
    format!("* PONG {heartbeat_ms}\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn timestamps_are_utc_with_milliseconds() {
        let t: jiff::Timestamp = "2024-05-17T13:45:06.789123+02:00".parse().unwrap();
        assert_eq!(timestamp(t), "2024-05-17T11:45:06.789Z");
        let t: jiff::Timestamp = "2024-01-01T00:00:00Z".parse().unwrap();
        assert_eq!(timestamp(t), "2024-01-01T00:00:00.000Z");
    }

    #[test]
    fn lines() {
        let p = vec![
            ("mode".to_string(), "AUTOMATIC".to_string()),
            ("block".to_string(), "G01 X1|Y2\n".to_string()),
        ];
        assert_eq!(
            sample_line("T", &p).unwrap(),
            "T|mode|AUTOMATIC|block|G01 X1 Y2\n"
        );
        assert_eq!(sample_line("T", &[]), None);
        let m = vec![
            ("message".to_string(), format!("2001{SEP}CHECK | COOLANT")),
            ("mode".to_string(), "MANUAL".to_string()),
        ];
        assert_eq!(
            sample_line("T", &m).unwrap(),
            "T|mode|MANUAL\nT|message|2001|CHECK   COOLANT\n"
        );
        let c = Cond {
            name: "Xtravel".into(),
            level: Level::Fault,
            code: "OT0500".into(),
            severity: "4".into(),
            qualifier: String::new(),
            text: "OVER TRAVEL +X".into(),
        };
        assert_eq!(c.line("T"), "T|Xtravel|FAULT|OT0500|4||OVER TRAVEL +X\n");
        assert_eq!(
            Cond::bare("system", Level::Normal).line("T"),
            "T|system|NORMAL||||\n"
        );
        assert_eq!(pong(10000), "* PONG 10000\n");
    }
}
