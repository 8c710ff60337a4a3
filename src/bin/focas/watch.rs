//! watch: a live status line.

use crate::out::{Fail, json_line, print};
use crate::show::{alarm_json, axes_json, status_json};
use fwlib32::native::Cnc;
use serde_json::json;
use std::io::IsTerminal;
use std::time::{Duration, SystemTime, UNIX_EPOCH};

/// Samples status, execution, positions and alarms (one batch each time)
/// every `interval` seconds, `count` times or until interrupted: on a
/// terminal one line rewritten in place, else one line (or JSON object)
/// per sample.
pub fn run(cnc: &Cnc, interval: f64, count: Option<u64>, json: bool) -> Result<(), Fail> {
    let in_place = !json && std::io::stdout().is_terminal();
    let mut done = 0u64;
    loop {
        let mut b = cnc.batch();
        let (st, ex, pos, al) = (b.status(), b.execution(), b.positions(), b.alarms());
        let mut r = b.send()?;
        let (s, x, axes, alarms) = (r.take(st)?, r.take(ex)?, r.take(pos)?, r.take(al)?);
        if json {
            let time = SystemTime::now()
                .duration_since(UNIX_EPOCH)
                .map_or(0.0, |d| d.as_secs_f64());
            let alarms: Vec<_> = alarms.iter().map(alarm_json).collect();
            json_line(&json!({
                "time": time,
                "status": status_json(&s, &x),
                "axes": axes_json(&axes),
                "alarms": alarms,
            }))?;
        } else {
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
                print(&format!("\r\x1b[2K{line}"))?;
            } else {
                print(&format!("{line}\n"))?;
            }
        }
        done += 1;
        if count.is_some_and(|c| done >= c) {
            break;
        }
        std::thread::sleep(Duration::from_secs_f64(interval));
    }
    if in_place {
        print("\n")?;
    }
    Ok(())
}
