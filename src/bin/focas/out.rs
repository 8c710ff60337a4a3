//! Output: failures as one line, aligned text, JSON.

use fwlib32::native::{Decimal, Error};
use serde_json::{Value as Json, json};
use std::fmt;
use std::io::{ErrorKind, Write};

/// Why the command failed.
pub enum Fail {
    /// A FOCAS call failed, at this address; what it means, in words,
    /// where the call and its context tell.
    Focas(String, Option<String>, Error),
    /// A FOCAS call failed (the address is added by main).
    Api(Error),
    /// A FOCAS call failed, and what that means here (`O1234 is running`).
    Refused(String, Error),
    /// Bad input or a local problem (a file ...).
    Other(String),
    /// Stdout was closed (`focas pos | head`): stop, successfully.
    Quiet,
    /// Shown already (watch's last sample): exit status 1, nothing more.
    Shown,
    /// A bad command line (exit status 2).
    Usage(Box<clap::Error>),
}

impl From<Error> for Fail {
    fn from(e: Error) -> Fail {
        Fail::Api(e)
    }
}

impl Fail {
    /// The failure of a call made for `addr`.
    pub fn at(self, addr: &str) -> Fail {
        match self {
            Fail::Api(e) => Fail::Focas(addr.to_string(), None, e),
            Fail::Refused(why, e) => Fail::Focas(addr.to_string(), Some(why), e),
            f => f,
        }
    }
}

impl fmt::Display for Fail {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Fail::Focas(addr, None, e) => write!(f, "{addr}: {e}"),
            Fail::Focas(addr, Some(why), e) => write!(f, "{addr}: {why}: {e}"),
            Fail::Api(e) => write!(f, "{e}"),
            Fail::Refused(why, e) => write!(f, "{why}: {e}"),
            Fail::Other(m) => f.write_str(m),
            Fail::Quiet | Fail::Shown => Ok(()),
            Fail::Usage(e) => f.write_str(&usage_line(e)),
        }
    }
}

/// clap's message, on one line, without its `error: `.
fn usage_line(e: &clap::Error) -> String {
    let text = e.render().to_string();
    let line = text.lines().next().unwrap_or_default();
    line.strip_prefix("error: ").unwrap_or(line).to_string()
}

/// A failure as `{"error": {...}}`: always its `message` (the line the
/// text output prints); for a FOCAS call also `host`, `function`, `code`
/// (the EW_* number), `ew` (its name), `meaning`, `reason` (what it means
/// here, in words, when known: "O1234 is running") and `detail` (the
/// cnc_getdtailerr words, when not zero); `usage: true` for a bad command
/// line.
pub fn fail_json(f: &Fail) -> Json {
    let mut o = serde_json::Map::new();
    o.insert("message".into(), json!(f.to_string()));
    let (host, e) = match f {
        Fail::Focas(addr, why, e) => {
            if let Some(w) = why {
                o.insert("reason".into(), json!(w));
            }
            (Some(addr), Some(e))
        }
        Fail::Api(e) => (None, Some(e)),
        Fail::Refused(why, e) => {
            o.insert("reason".into(), json!(why));
            (None, Some(e))
        }
        Fail::Usage(_) => {
            o.insert("usage".into(), json!(true));
            (None, None)
        }
        _ => (None, None),
    };
    if let Some(h) = host {
        o.insert("host".into(), json!(h));
    }
    if let Some(e) = e {
        let (code, d) = (e.code(), e.detail());
        o.insert("function".into(), json!(e.call()));
        o.insert("code".into(), json!(code.0));
        o.insert("ew".into(), json!(code.name()));
        o.insert("meaning".into(), json!(code.meaning()));
        if d != Default::default() {
            o.insert("detail".into(), json!([d.err_no, d.err_dtno]));
        }
    }
    json!({ "error": o })
}

/// Writes `text` to stdout (a closed stdout ends the command quietly).
pub fn print(text: &str) -> Result<(), Fail> {
    let mut o = std::io::stdout().lock();
    match o.write_all(text.as_bytes()).and_then(|_| o.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == ErrorKind::BrokenPipe => Err(Fail::Quiet),
        Err(e) => Err(Fail::Other(format!("stdout: {e}"))),
    }
}

/// Prints one JSON value on one line.
pub fn json_line(v: &Json) -> Result<(), Fail> {
    print(&format!("{v}\n"))
}

/// Rows as aligned columns: text columns left, the others (numbers) right.
pub struct Table {
    rows: Vec<Vec<String>>,
    right: Vec<bool>,
}

impl Table {
    /// A table whose column `i` is right-aligned where `right[i]`.
    pub fn new(right: &[bool]) -> Table {
        Table {
            rows: Vec::new(),
            right: right.to_vec(),
        }
    }

    pub fn row<S: ToString>(&mut self, cells: impl IntoIterator<Item = S>) {
        self.rows
            .push(cells.into_iter().map(|c| c.to_string()).collect());
    }

    /// The text, columns two spaces apart, no trailing spaces.
    pub fn render(&self) -> String {
        let cols = self.rows.iter().map(Vec::len).max().unwrap_or(0);
        let width: Vec<usize> = (0..cols)
            .map(|c| {
                let w = |r: &Vec<String>| r.get(c).map_or(0, |s| s.chars().count());
                self.rows.iter().map(w).max().unwrap_or(0)
            })
            .collect();
        let mut out = String::new();
        for r in &self.rows {
            let mut line = String::new();
            for (c, cell) in r.iter().enumerate() {
                if c > 0 {
                    line.push_str("  ");
                }
                let pad = width[c] - cell.chars().count();
                if self.right.get(c).copied().unwrap_or(false) {
                    line.push_str(&" ".repeat(pad));
                    line.push_str(cell);
                } else {
                    line.push_str(cell);
                    line.push_str(&" ".repeat(pad));
                }
            }
            out.push_str(line.trim_end());
            out.push('\n');
        }
        out
    }
}

/// A value of the API as JSON (its `serde::Serialize`).
pub fn to_json<T: serde::Serialize>(v: &T) -> Json {
    // Only maps with keys that are not strings fail: the API has none.
    serde_json::to_value(v).unwrap_or(Json::Null)
}

/// Now, RFC 3339 with this computer's UTC offset, to the millisecond.
pub fn now() -> String {
    jiff::Zoned::now()
        .strftime("%Y-%m-%dT%H:%M:%S%.3f%:z")
        .to_string()
}

/// A decimal as a JSON number (the nearest double: 125.0, -0.125).
pub fn num(d: Decimal) -> Json {
    json!(d.to_f64())
}
