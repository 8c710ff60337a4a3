//! info, status, pos, alarms.

use crate::out::{Fail, Table, json_line, print, to_json};
use fwlib32::native::{AxisPosition, Cnc, Execution, Status};
use serde_json::{Value as Json, json};

/// `focas info`: the CNC id and every path's system information.
pub fn info(cnc: &Cnc, json: bool) -> Result<(), Fail> {
    let id = cnc
        .cnc_id()?
        .iter()
        .map(|w| format!("{w:08x}"))
        .collect::<Vec<_>>()
        .join("-");
    let mut paths = Vec::new();
    for p in 1..=cnc.path_count() {
        if let Ok(s) = cnc.sysinfo_of(p) {
            paths.push((p, s));
        }
    }
    if json {
        let list: Vec<Json> = paths
            .iter()
            .map(|(p, s)| {
                let mut o = json!({ "path": p });
                merge(&mut o, to_json(s));
                o
            })
            .collect();
        return json_line(&json!({
            "addr": cnc.addr(), "cnc_id": id, "path": cnc.path(), "paths": list,
        }));
    }
    let mut t = Table::new(&[]);
    t.row(["cnc", cnc.addr()]);
    t.row(["cnc id", &id]);
    t.row([
        "paths".to_string(),
        format!("{} (reading path {})", cnc.path_count(), cnc.path()),
    ]);
    for (p, s) in &paths {
        t.row([
            format!("path {p}"),
            format!(
                "{}{} series {} version {}, {} axes (max {})",
                s.cnc_type, s.mt_type, s.series, s.version, s.axes, s.max_axes
            ),
        ]);
    }
    print(&t.render())
}

/// The keys of object `b` added to object `a`.
fn merge(a: &mut Json, b: Json) {
    if let (Some(a), Json::Object(b)) = (a.as_object_mut(), b) {
        a.extend(b);
    }
}

/// The status words and what runs, one object.
pub fn status_json(s: &Status, x: &Execution) -> Json {
    let mut o = to_json(s);
    merge(&mut o, to_json(x));
    o
}

/// `focas status`: the status words and what runs, in one batch.
pub fn status(cnc: &Cnc, json: bool) -> Result<(), Fail> {
    let mut b = cnc.batch();
    let (st, ex) = (b.status(), b.execution());
    let mut r = b.send()?;
    let (s, x) = (r.take(st)?, r.take(ex)?);
    if json {
        return json_line(&status_json(&s, &x));
    }
    let mut t = Table::new(&[]);
    t.row(["mode".to_string(), s.mode.to_string()]);
    t.row(["run".to_string(), s.run.to_string()]);
    t.row(["motion".to_string(), s.motion.to_string()]);
    t.row(["emergency".to_string(), s.emergency.to_string()]);
    t.row(["alarm".to_string(), s.alarm.to_string()]);
    t.row(["mstb".to_string(), s.mstb.to_string()]);
    t.row(["edit".to_string(), s.edit.to_string()]);
    t.row([
        "program".to_string(),
        format!("O{} (main O{})", x.program, x.main_program),
    ]);
    t.row(["sequence".to_string(), format!("N{}", x.sequence)]);
    t.row(["feed".to_string(), x.feed.to_string()]);
    t.row(["spindle".to_string(), x.spindle_speed.to_string()]);
    print(&t.render())
}

pub fn axes_json(axes: &[AxisPosition]) -> Json {
    to_json(&axes)
}

/// `focas pos`.
pub fn positions(cnc: &Cnc, json: bool) -> Result<(), Fail> {
    let axes = cnc.positions()?;
    if json {
        return json_line(&json!({ "axes": axes_json(&axes) }));
    }
    let mut t = Table::new(&[false, true, true, true, true, false]);
    t.row([
        "axis", "absolute", "machine", "relative", "distance", "unit",
    ]);
    for a in &axes {
        t.row([
            a.name.clone(),
            a.absolute.to_string(),
            a.machine.to_string(),
            a.relative.to_string(),
            a.distance.to_string(),
            a.unit.to_string(),
        ]);
    }
    print(&t.render())
}

/// `focas alarms [--history]`.
pub fn alarms(cnc: &Cnc, history: bool, json: bool) -> Result<(), Fail> {
    if history {
        let h = cnc.alarm_history()?;
        if json {
            return json_line(&json!({ "history": to_json(&h) }));
        }
        if h.is_empty() {
            return print("no alarm history\n");
        }
        let mut t = Table::new(&[]);
        for e in &h {
            let axis = if e.axis > 0 {
                format!("axis {}", e.axis)
            } else {
                String::new()
            };
            t.row([e.time.to_string(), e.code(), axis, e.message.clone()]);
        }
        return print(&t.render());
    }
    let a = cnc.alarms()?;
    if json {
        return json_line(&json!({ "alarms": to_json(&a) }));
    }
    if a.is_empty() {
        return print("no alarm\n");
    }
    let mut t = Table::new(&[]);
    for x in &a {
        let axis = if x.axis > 0 {
            format!("axis {}", x.axis)
        } else {
            String::new()
        };
        t.row([x.code(), axis, x.message.clone()]);
    }
    print(&t.render())
}
