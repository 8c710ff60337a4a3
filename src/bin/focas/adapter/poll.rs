//! One poll of a path as batches, and the samples of a time series
//! between polls.

use super::condition::condition_of;
use super::model::*;
use super::shdr::{Cond, Level};
use fwlib32::native::{Cnc, Emergency, Error, Execution, PmcArea};

/// The values and condition activations of one poll of a path.
#[derive(Debug, Default)]
pub struct PathPoll {
    pub values: Vec<(String, String)>,
    pub conditions: Vec<Cond>,
    /// Request frames it took.
    pub frames: usize,
    /// The alarms could not be read: the conditions stay as they were.
    pub alarms_unknown: bool,
}

const UNAVAILABLE: &str = "UNAVAILABLE";

/// What a path's poller remembers from one poll to the next.
#[derive(Debug, Default)]
pub struct PathMemo {
    /// The program whose comment was read last, and that comment.
    comment: Option<(u32, String)>,
}

/// Polls one path (`cnc` set to it) in one batch, plus one read of the
/// program's directory entry when the running program changed. `Err` only
/// when an exchange failed as a whole (the CNC is gone); a read the CNC
/// refused leaves its items UNAVAILABLE.
pub fn poll_path(
    cnc: &Cnc,
    p: &PathLayout,
    systems: &[System],
    custom: &Custom,
    memo: &mut PathMemo,
) -> Result<PathPoll, Error> {
    let g = (p.number - 1) * 1000; // each path's G signals 1000 further on
    let first = p.number == 1;
    // Two batches, three frames on a 30i (16 subpackets a frame): first
    // positions, execution, part count and overrides (frame 1), status,
    // alarms and meters (frame 2); then, knowing the program running, the
    // block, the modal T and F, the tool group, the program's name, its
    // comment when it changed, the message and the systems' PMC bytes.
    let mut b = cnc.batch();
    let pos = b.positions();
    let ex = b.execution();
    let parts = first.then(|| b.param::<i32>(6711, None));
    // G12 (*FV0-7, feed override, negative logic) to G30 (SOV0-7, spindle
    // override): one read.
    let ovr = b.pmc::<u8>(PmcArea::G, g + 12..=g + 30);
    let st = b.status();
    let al = b.alarms();
    let sv = b.servo_loads();
    let sp = (!p.spindles.is_empty()).then(|| (b.spindle_meters(), b.spindle_speeds()));
    let mut r = b.send()?;
    let ex: Option<Execution> = r.take(ex).ok();
    let number = ex.map(|e| e.program).filter(|o| *o != 0);
    let mut b = cnc.batch();
    let blocks = b.executing(256);
    let (tool, fcmd) = (b.modal_code(108), b.modal_code(103));
    let group = b.tool_group_tools(0);
    let name = b.program_name();
    let entry = number
        .filter(|o| memo.comment.as_ref().is_none_or(|(was, _)| was != o))
        .map(|o| b.program_entry(o));
    let msg = first.then(|| b.operator_message());
    // The systems' bits: one read an area, from its lowest byte to its
    // highest.
    let mut areas: Vec<(PmcArea, u16, u16)> = Vec::new();
    for (area, at, ..) in systems.iter().filter(|_| first).filter_map(|s| s.pmc) {
        match areas.iter_mut().find(|a| a.0 == area) {
            Some(a) => (a.1, a.2) = (a.1.min(at), a.2.max(at)),
            None => areas.push((area, at, at)),
        }
    }
    let bytes: Vec<_> = (areas.iter())
        .map(|&(area, lo, hi)| (area, lo, b.pmc::<u8>(area, lo..=hi)))
        .collect();
    // Items configured by hand, on path 1.
    let none = Custom::default();
    let c = if first { custom } else { &none };
    let macros: Vec<_> = (c.macros.iter())
        .map(|(n, v)| (n.clone(), b.macro_var(*v)))
        .collect();
    let pmc: Vec<_> = (c.pmc.iter())
        .map(|(n, area, at, inv)| (n.clone(), *inv, b.pmc::<u8>(*area, *at..=*at)))
        .collect();
    let params: Vec<_> = (c.parameters.iter())
        .map(|(n, v)| (n.clone(), b.param_values(*v, None)))
        .collect();
    let diags: Vec<_> = (c.diagnostics.iter())
        .map(|(n, v, axis)| (n.clone(), b.diag_values(*v, *axis)))
        .collect();
    let mut r2 = b.send()?;
    let mut out = PathPoll {
        frames: r.frames() + r2.frames(),
        ..PathPoll::default()
    };
    let bytes: Vec<(PmcArea, u16, Option<Vec<u8>>)> = (bytes.into_iter())
        .map(|(area, lo, t)| (area, lo, r2.take(t).ok()))
        .collect();
    let n = |s: &str| format!("{s}{}", p.suffix);
    let mut put = |name: String, v: Option<String>| {
        out.values
            .push((name, v.unwrap_or_else(|| UNAVAILABLE.to_string())));
    };
    let st = r.take(st).ok();
    put(n("mode"), st.map(|s| mode(s.mode).to_string()));
    put(
        n("execution"),
        st.as_ref().map(|s| execution(s).to_string()),
    );
    if first {
        put(
            "estop".into(),
            st.map(|s| {
                if s.emergency == Emergency::Emergency {
                    "TRIGGERED"
                } else {
                    "ARMED"
                }
                .to_string()
            }),
        );
    }
    // The program as cnc_exeprgname2 names it; a CNC without it, its O
    // number.
    let name = r2.take(name).ok().filter(|s| !s.is_empty());
    put(
        n("program"),
        name.or_else(|| number.map(|o| format!("O{o:04}"))),
    );
    put(n("line"), ex.map(|e| e.sequence.to_string()));
    // The block executing: the text's first line.
    let block = r2
        .take(blocks)
        .ok()
        .map(|t| t.lines().next().unwrap_or("").trim().to_string());
    put(n("block"), block);
    put(n("tool_id"), r2.take(tool).ok().map(|t| t.to_string()));
    // The group cnc_rdntool(0) answers, as FANUC's adapter reads it.
    put(
        n("tool_group"),
        r2.take(group)
            .ok()
            .filter(|g| g.1 != 0)
            .map(|g| g.0.to_string()),
    );
    put(n("f_command"), r2.take(fcmd).ok().map(|f| f.to_string()));
    put(n("path_feedrate"), ex.map(|e| e.feed.to_string()));
    put(n("active_axes"), Some(p.axis_names.join(" ")));
    let ovr = r.take(ovr).ok();
    let fovr = ovr
        .as_ref()
        .and_then(|v| v.first())
        .map(|b| (!b).to_string());
    put(n("Fovr"), fovr);
    put(
        n("Sovr"),
        ovr.as_ref().and_then(|v| v.get(18)).map(|b| b.to_string()),
    );
    if let Some(t) = parts {
        put("part_count".into(), r.take(t).ok().map(|v| v.to_string()));
    }
    // The operator message on display; none: the last one stays, as
    // FANUC's adapter leaves it.
    if let Some(Ok(Some(m))) = msg.map(|t| r2.take(t)) {
        let sep = super::shdr::SEP;
        put(
            "message".into(),
            Some(format!("{}{sep}{}", m.number, m.text)),
        );
    }
    for (n, t) in macros {
        let v = r2
            .take(t)
            .ok()
            .map(|v| v.map_or_else(|| UNAVAILABLE.to_string(), |d| d.to_string()));
        put(n, v);
    }
    for (n, inv, t) in pmc {
        // As the C++ adapter: a byte, or for a negative address a byte
        // with its top bit set inverted (override signals).
        let v = r2.take(t).ok().and_then(|v| v.first().copied());
        put(
            n,
            v.map(|b| if inv && b >= 0x80 { !b } else { b }.to_string()),
        );
    }
    for (n, t) in params.into_iter().chain(diags) {
        let v = r2.take(t).ok().and_then(|p| p.values.first().cloned());
        put(
            n,
            v.map(|v| match v {
                fwlib32::native::Value::Bits(b) => b.to_string(),
                v => v.to_string(),
            }),
        );
    }
    let pos = r.take(pos).ok();
    let xyz = pos.as_ref().map(|pos| {
        ["X", "Y", "Z"]
            .map(|a| {
                pos.iter()
                    .find(|q| q.name == a)
                    .map_or_else(|| "0".to_string(), |q| q.absolute.to_string())
            })
            .join(" ")
    });
    let mut put = |name: String, v: Option<String>| {
        out.values
            .push((name, v.unwrap_or_else(|| UNAVAILABLE.to_string())));
    };
    put(n("path_position"), xyz);
    let loads = r.take(sv).ok();
    for (i, a) in p.axes.iter().enumerate() {
        put(
            format!("{a}act"),
            pos.as_ref()
                .and_then(|v| v.get(i))
                .map(|q| q.machine.to_string()),
        );
        put(
            format!("{a}load"),
            loads
                .as_ref()
                .and_then(|v| v.get(i))
                .map(|m| m.load.to_string()),
        );
    }
    let (meters, speeds) = match sp {
        Some((m, s)) => (r.take(m).ok(), r.take(s).ok()),
        None => (None, None),
    };
    for (i, s) in p.spindles.iter().enumerate() {
        let m = meters.as_ref().and_then(|v| v.get(i));
        // Each spindle's actual speed (cnc_acts2), as FANUC's adapter.
        put(
            format!("{s}speed"),
            speeds
                .as_ref()
                .and_then(|v| v.get(i))
                .map(|v| v.to_string()),
        );
        put(format!("{s}load"), m.map(|m| m.load.to_string()));
    }
    let alarms = r.take(al);
    // The C++ adapter's [alarms] and [critical]: the Nth active alarm as
    // "number message" ("" when fewer), [critical] only if of a critical
    // type (cnc_rdalmmsg types 1 2 5 6 9 10 13 19).
    if let Ok(al) = &alarms {
        let nth = |i: usize, critical: bool| {
            al.get(i)
                .filter(|a| !critical || [1, 2, 5, 6, 9, 10, 13, 19].contains(&a.kind.0))
                .map_or_else(String::new, |a| format!("{} {}", a.number, a.message))
        };
        for (i, n) in c.alarms.iter().enumerate() {
            put(n.clone(), Some(nth(i, false)));
        }
        for (i, n) in c.critical.iter().enumerate() {
            put(n.clone(), Some(nth(i, true)));
        }
    }
    match &alarms {
        Err(_) => out.alarms_unknown = true,
        Ok(alarms) => {
            for a in alarms {
                out.conditions.push(Cond {
                    name: condition_of(a, &p.axes, &p.spindles, &p.suffix),
                    level: Level::Fault,
                    code: a.code(),
                    severity: a.kind.0.to_string(),
                    qualifier: String::new(),
                    text: a.message.clone(),
                });
            }
        }
    }
    // Systems: a PMC bit at its active level, or one of their alarms.
    for s in systems.iter().filter(|_| first) {
        if let Some((area, at, bit, level)) = s.pmc {
            let byte = (bytes.iter().find(|b| b.0 == area))
                .map(|(_, lo, v)| v.as_ref().map(|v| v.get(usize::from(at - lo)).copied()));
            match byte {
                Some(Some(Some(v))) => {
                    if (v >> bit & 1 == 1) == level {
                        out.conditions.push(Cond {
                            name: s.name.clone(),
                            level: Level::Fault,
                            code: format!("{area}{at}.{bit}"),
                            severity: String::new(),
                            qualifier: String::new(),
                            text: s.text.clone(),
                        });
                    }
                }
                // Unknown: no sweep this poll.
                _ => out.alarms_unknown = true,
            }
        }
        if let Ok(alarms) = &alarms {
            for a in alarms.iter().filter(|a| s.alarms.contains(&a.number)) {
                out.conditions.push(Cond {
                    name: s.name.clone(),
                    level: Level::Fault,
                    code: a.code(),
                    severity: a.kind.0.to_string(),
                    qualifier: String::new(),
                    text: a.message.clone(),
                });
            }
        }
    }
    // The program's comment, from its directory entry, read again only
    // when another program runs.
    if let (Some(o), Some(t)) = (number, entry) {
        let c = r2.take(t).ok().flatten().map(|e| e.comment);
        memo.comment = c.map(|c| (o, c));
    }
    let comment = match (number, &memo.comment) {
        (Some(o), Some((was, c))) if *was == o => Some(c.clone()),
        _ => None,
    };
    put(n("program_comment"), comment);
    Ok(out)
}

/// One sample of a path's time series: servo loads and spindle speeds.
pub fn sample_path(cnc: &Cnc, s: &Series) -> Result<(Vec<String>, Vec<String>), Error> {
    let mut b = cnc.batch();
    let sv = s.load.then(|| b.servo_loads());
    let sp = s.speed.then(|| b.spindle_speeds());
    let mut r = b.send()?;
    let loads = match sv {
        Some(t) => r.take(t)?.iter().map(|m| m.load.to_string()).collect(),
        None => Vec::new(),
    };
    let speeds = match sp {
        Some(t) => r.take(t)?.iter().map(|v| v.to_string()).collect(),
        None => Vec::new(),
    };
    Ok((loads, speeds))
}
