//! watch: a live status line that keeps going through outages.

use crate::out::{Fail, fail_json, json_line, now, print, to_json};
use crate::show::{axes_json, status_json};
use fwlib32::native::{Alarm, AxisPosition, Cnc, Error, Execution, Status};
use serde_json::json;
use std::io::IsTerminal;
use std::time::Duration;

/// What `watch` connects to.
pub struct Target<'a> {
    /// `host:port`.
    pub addr: &'a str,
    pub timeout: Duration,
    pub path: Option<u16>,
}

/// The least wait before trying an unavailable CNC again.
const RETRY: f64 = 0.5;

type Sample = (Status, Execution, Vec<AxisPosition>, Vec<Alarm>);

/// One batch: status, execution, positions and alarms.
fn sample(cnc: &Cnc) -> Result<Sample, Error> {
    let mut b = cnc.batch();
    let (st, ex, pos, al) = (b.status(), b.execution(), b.positions(), b.alarms());
    let mut r = b.send()?;
    Ok((r.take(st)?, r.take(ex)?, r.take(pos)?, r.take(al)?))
}

/// A connection, on the path asked for.
fn connect(t: &Target) -> Result<Cnc, Fail> {
    let cnc = Cnc::connect(t.addr, t.timeout).map_err(Fail::Api)?;
    if let Some(p) = t.path {
        cnc.set_path(p).map_err(Fail::Api)?;
    }
    Ok(cnc)
}

/// Does `e` leave the connection broken (connect again)?
fn broken(e: &Error) -> bool {
    matches!(e, Error::Socket { .. } | Error::Protocol { .. })
}

/// Samples the CNC every `interval` seconds, `count` times or until
/// interrupted: on a terminal one line rewritten in place, else one line
/// (or JSON object) per sample. A failed sample (the CNC off, unplugged,
/// refusing) is a line of its own, `UNAVAILABLE` and the error (with
/// `--json` an object with `"available": false` and the `error`), and
/// the next sample connects again (at least every half second). The exit
/// status is 1 when the last sample failed.
pub fn run(t: &Target, interval: f64, count: Option<u64>, json: bool) -> Result<(), Fail> {
    let in_place = !json && std::io::stdout().is_terminal();
    let mut cnc: Option<Cnc> = None;
    let mut done = 0u64;
    let mut failed;
    loop {
        let got = match &cnc {
            Some(c) => sample(c).map_err(Fail::Api),
            None => match connect(t) {
                Ok(c) => sample(cnc.insert(c)).map_err(Fail::Api),
                // A path the CNC lacks will not come back: stop.
                Err(Fail::Api(e)) if !broken(&e) && done == 0 => {
                    return Err(Fail::Api(e));
                }
                Err(f) => Err(f),
            },
        };
        failed = got.is_err();
        match got {
            Ok(s) => show(s, json, in_place)?,
            Err(f) => {
                if let Fail::Api(e) = &f
                    && broken(e)
                {
                    cnc = None;
                }
                let f = f.at(t.addr);
                if json {
                    let mut o = json!({ "time": now(), "available": false });
                    o["error"] = fail_json(&f)["error"].take();
                    json_line(&o)?;
                } else if in_place {
                    print(&format!("\r\x1b[2KUNAVAILABLE  {f}\n"))?;
                } else {
                    print(&format!("UNAVAILABLE  {f}\n"))?;
                }
            }
        }
        done += 1;
        if count.is_some_and(|c| done >= c) {
            break;
        }
        let wait = if failed {
            interval.max(RETRY)
        } else {
            interval
        };
        std::thread::sleep(Duration::from_secs_f64(wait));
    }
    if in_place && !failed {
        print("\n")?;
    }
    if failed {
        // Shown already: only the exit status says it.
        return Err(Fail::Shown);
    }
    Ok(())
}

fn show((s, x, axes, alarms): Sample, json: bool, in_place: bool) -> Result<(), Fail> {
    if json {
        return json_line(&json!({
            "time": now(),
            "available": true,
            "status": status_json(&s, &x),
            "axes": axes_json(&axes),
            "alarms": to_json(&alarms),
        }));
    }
    let pos: Vec<String> = axes
        .iter()
        .map(|a| format!("{}{}", a.name, a.absolute))
        .collect();
    let alarm = match alarms.first() {
        None => "no alarm".to_string(),
        Some(a) => format!("ALM {}", a.code()),
    };
    let line = format!(
        "{} {} {}  O{} N{}  F{} S{}  {}  {}",
        s.mode,
        s.run,
        s.motion,
        x.program,
        x.sequence,
        x.feed,
        x.spindle_speed,
        pos.join(" "),
        alarm
    );
    if in_place {
        print(&format!("\r\x1b[2K{line}"))
    } else {
        print(&format!("{line}\n"))
    }
}
