//! What the adapter reads: the machine's layout found on connecting
//! (paths, axes, spindles), the data items named from it, and one poll of
//! a path as one batch.

use super::condition::condition_of;
use super::shdr::{Cond, Level};
use fwlib32::native::{Cnc, Emergency, Error, Execution, Mode, Motion, PmcArea, Run, Status, Unit};

/// An item's MTConnect category.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Category {
    Sample,
    Event,
    Condition,
}

/// Where an item sits in the device's component tree.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Place {
    Device,
    Controller,
    /// Path number.
    Path(u16),
    /// Axis item prefix (`X`, `Y2`), rotary or not.
    Axis(String, bool),
    /// Spindle item prefix (`S1`).
    Spindle(String),
    /// A system component (`Coolant`, `Hydraulic` ...) and its name.
    System(&'static str, String),
}

/// A data item the adapter sends.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Item {
    pub name: String,
    pub category: Category,
    /// MTConnect type (`EXECUTION`), subtype, units and native units.
    pub kind: &'static str,
    pub sub: Option<&'static str>,
    pub units: Option<&'static str>,
    pub native_units: Option<&'static str>,
    pub place: Place,
    /// A time series' sample rate, Hz (`representation="TIME_SERIES"`).
    pub series_rate: Option<u32>,
}

/// One path of the machine as discovered.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PathLayout {
    pub number: u16,
    /// Appended to path items: "" for path 1, else the path number.
    pub suffix: String,
    /// Item prefixes of the axes (the CNC's names; path number added
    /// after a name an earlier path has).
    pub axes: Vec<String>,
    /// The CNC's axis names (to find X, Y and Z).
    pub axis_names: Vec<String>,
    pub rotary: Vec<bool>,
    /// Item prefixes of the spindles (`S1`; path number added after path 1).
    pub spindles: Vec<String>,
}

/// The machine: its paths, and what the configuration adds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Layout {
    pub paths: Vec<PathLayout>,
    /// Systems conditions from PMC bits or alarm numbers.
    pub systems: Vec<System>,
    /// Time series sampled between polls.
    pub series: Option<Series>,
    /// Items configured by hand, as in the C++ adapter's `adapter.ini`.
    pub custom: Custom,
}

/// Items configured by hand (the C++ adapter's `adapter.ini` sections),
/// each (item name, what to read), in name order.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Custom {
    /// `[macros]`: custom macro variable numbers.
    pub macros: Vec<(String, u32)>,
    /// `[pmc]`: area, byte, and whether a byte with its top bit set is
    /// sent inverted (the C++ adapter's negative addresses).
    pub pmc: Vec<(String, PmcArea, u16, bool)>,
    /// `[parameters]`: parameter numbers (of the path, no axis).
    pub parameters: Vec<(String, u32)>,
    /// `[diagnostics]`: number and axis.
    pub diagnostics: Vec<(String, u32, Option<u16>)>,
    /// `[alarms]`: the first, second ... active alarm.
    pub alarms: Vec<String>,
    /// `[critical]`: the Nth active alarm if of a critical type.
    pub critical: Vec<String>,
}

/// A system (coolant, hydraulics ...) as a condition: FAULT while its PMC
/// bit is at its active level or one of its alarms is active.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct System {
    /// The condition item's name.
    pub name: String,
    /// The MTConnect component (`Coolant`, `Hydraulic`, `Pneumatic`,
    /// `Electric`).
    pub component: &'static str,
    /// PMC area, byte address, bit, and the level meaning a fault.
    pub pmc: Option<(PmcArea, u16, u8, bool)>,
    /// Alarm numbers (cnc_rdalmmsg2's numbers) meaning a fault.
    pub alarms: Vec<i32>,
    /// The text of a PMC fault.
    pub text: String,
}

/// Time series: servo loads and/or spindle speeds sampled at `rate` Hz
/// between polls, sent once a poll.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Series {
    pub rate: u32,
    pub load: bool,
    pub speed: bool,
}

impl Layout {
    /// Reads the paths, each path's axes (names and units) and spindles
    /// (one batch a path). `cnc`'s current path is left as found.
    pub fn discover(cnc: &Cnc) -> Result<Layout, Error> {
        let mut paths = Vec::new();
        let mut seen: Vec<String> = Vec::new();
        for number in 1..=cnc.path_count() {
            let c = cnc.try_clone()?;
            c.set_path(number)?;
            let mut b = c.batch();
            let (pos, sp) = (b.positions(), b.spindle_meters());
            let mut r = b.send()?;
            let pos = r.take(pos)?;
            // No spindle information: a path without spindles.
            let sp = r.take(sp).unwrap_or_default();
            let suffix = if number > 1 {
                number.to_string()
            } else {
                String::new()
            };
            let axes = pos
                .iter()
                .map(|a| {
                    if seen.contains(&a.name) {
                        format!("{}{suffix}", a.name)
                    } else {
                        a.name.clone()
                    }
                })
                .collect::<Vec<_>>();
            seen.extend(axes.iter().cloned());
            paths.push(PathLayout {
                number,
                axis_names: pos.iter().map(|a| a.name.clone()).collect(),
                rotary: pos
                    .iter()
                    .map(|a| {
                        a.unit == Unit::Degree
                            || matches!(a.name.as_bytes().first(), Some(b'A' | b'B' | b'C'))
                    })
                    .collect(),
                axes,
                spindles: sp.iter().map(|s| format!("{}{suffix}", s.name)).collect(),
                suffix,
            });
        }
        Ok(Layout {
            paths,
            systems: Vec::new(),
            series: None,
            custom: Custom::default(),
        })
    }

    /// Every item, in the order the full state lists them.
    pub fn items(&self) -> Vec<Item> {
        let mut v = vec![
            item("avail", Category::Event, "AVAILABILITY", Place::Device),
            item(
                "estop",
                Category::Event,
                "EMERGENCY_STOP",
                Place::Controller,
            ),
            item("part_count", Category::Event, "PART_COUNT", Place::Path(1)),
            item("message", Category::Event, "MESSAGE", Place::Controller),
        ];
        let c = &self.custom;
        for (n, _) in &c.macros {
            v.push(item(
                n,
                Category::Sample,
                "x:MACRO_VARIABLE",
                Place::Controller,
            ));
        }
        for (n, ..) in &c.pmc {
            v.push(item(n, Category::Event, "x:PMC", Place::Controller));
        }
        for (n, _) in &c.parameters {
            v.push(item(n, Category::Event, "x:PARAMETER", Place::Controller));
        }
        for (n, ..) in &c.diagnostics {
            v.push(item(n, Category::Event, "x:DIAGNOSTIC", Place::Controller));
        }
        for n in c.alarms.iter().chain(&c.critical) {
            v.push(item(n, Category::Event, "x:ALARM", Place::Controller));
        }
        for s in &self.systems {
            v.push(item(
                &s.name,
                Category::Condition,
                "SYSTEM",
                Place::System(s.component, s.name.clone()),
            ));
        }
        let series = |name: String, kind, units, place: Place, rate| Item {
            sub: Some("ACTUAL"),
            units: Some(units),
            native_units: Some(units),
            series_rate: Some(rate),
            ..item(&name, Category::Sample, kind, place)
        };
        for p in &self.paths {
            let at = Place::Path(p.number);
            let n = |s: &str| format!("{s}{}", p.suffix);
            for (name, kind) in [
                ("servo", "ACTUATOR"),
                ("comms", "COMMUNICATIONS"),
                ("logic", "LOGIC_PROGRAM"),
                ("motion", "MOTION_PROGRAM"),
                ("system", "SYSTEM"),
            ] {
                v.push(item(&n(name), Category::Condition, kind, Place::Controller));
            }
            v.push(item(
                &n("mode"),
                Category::Event,
                "CONTROLLER_MODE",
                at.clone(),
            ));
            v.push(item(
                &n("execution"),
                Category::Event,
                "EXECUTION",
                at.clone(),
            ));
            v.push(item(&n("program"), Category::Event, "PROGRAM", at.clone()));
            v.push(item(&n("line"), Category::Event, "LINE", at.clone()));
            v.push(item(&n("block"), Category::Event, "BLOCK", at.clone()));
            v.push(item(
                &n("program_comment"),
                Category::Event,
                "PROGRAM_COMMENT",
                at.clone(),
            ));
            v.push(item(&n("tool_id"), Category::Event, "TOOL_ID", at.clone()));
            v.push(item(
                &n("tool_group"),
                Category::Event,
                "TOOL_GROUP",
                at.clone(),
            ));
            v.push(item(
                &n("active_axes"),
                Category::Event,
                "ACTIVE_AXES",
                at.clone(),
            ));
            v.push(Item {
                sub: Some("ACTUAL"),
                units: Some("MILLIMETER/SECOND"),
                native_units: Some("MILLIMETER/MINUTE"),
                ..item(
                    &n("path_feedrate"),
                    Category::Sample,
                    "PATH_FEEDRATE",
                    at.clone(),
                )
            });
            v.push(Item {
                sub: Some("COMMANDED"),
                units: Some("MILLIMETER/SECOND"),
                native_units: Some("MILLIMETER/MINUTE"),
                ..item(
                    &n("f_command"),
                    Category::Sample,
                    "PATH_FEEDRATE",
                    at.clone(),
                )
            });
            v.push(Item {
                sub: Some("ACTUAL"),
                units: Some("MILLIMETER_3D"),
                native_units: Some("MILLIMETER_3D"),
                ..item(
                    &n("path_position"),
                    Category::Sample,
                    "PATH_POSITION",
                    at.clone(),
                )
            });
            v.push(Item {
                sub: Some("OVERRIDE"),
                units: Some("PERCENT"),
                native_units: Some("PERCENT"),
                ..item(&n("Fovr"), Category::Sample, "PATH_FEEDRATE", at.clone())
            });
            v.push(Item {
                sub: Some("OVERRIDE"),
                units: Some("PERCENT"),
                native_units: Some("PERCENT"),
                ..item(&n("Sovr"), Category::Sample, "ROTARY_VELOCITY", at.clone())
            });
            for (a, rotary) in p.axes.iter().zip(&p.rotary) {
                let place = Place::Axis(a.clone(), *rotary);
                let (kind, units) = if *rotary {
                    ("ANGLE", "DEGREE")
                } else {
                    ("POSITION", "MILLIMETER")
                };
                v.push(Item {
                    sub: Some("ACTUAL"),
                    units: Some(units),
                    native_units: Some(units),
                    ..item(&format!("{a}act"), Category::Sample, kind, place.clone())
                });
                v.push(percent(&format!("{a}load"), "LOAD", place.clone()));
                if let Some(s) = self.series.as_ref().filter(|s| s.load) {
                    let name = format!("{a}load_ts");
                    v.push(series(name, "LOAD", "PERCENT", place.clone(), s.rate));
                }
                for (c, kind) in [
                    ("travel", "POSITION"),
                    ("overheat", "TEMPERATURE"),
                    ("servo", "LOAD"),
                ] {
                    v.push(item(
                        &format!("{a}{c}"),
                        Category::Condition,
                        kind,
                        place.clone(),
                    ));
                }
            }
            for s in &p.spindles {
                let place = Place::Spindle(s.clone());
                v.push(Item {
                    sub: Some("ACTUAL"),
                    units: Some("REVOLUTION/MINUTE"),
                    native_units: Some("REVOLUTION/MINUTE"),
                    ..item(
                        &format!("{s}speed"),
                        Category::Sample,
                        "ROTARY_VELOCITY",
                        place.clone(),
                    )
                });
                v.push(percent(&format!("{s}load"), "LOAD", place.clone()));
                if let Some(t) = self.series.as_ref().filter(|t| t.speed) {
                    let name = format!("{s}speed_ts");
                    let u = "REVOLUTION/MINUTE";
                    v.push(series(name, "ROTARY_VELOCITY", u, place.clone(), t.rate));
                }
                v.push(item(
                    &format!("{s}servo"),
                    Category::Condition,
                    "LOAD",
                    place,
                ));
            }
        }
        v
    }
}

fn item(name: &str, category: Category, kind: &'static str, place: Place) -> Item {
    Item {
        name: name.to_string(),
        category,
        kind,
        sub: None,
        units: None,
        native_units: None,
        place,
        series_rate: None,
    }
}

fn percent(name: &str, kind: &'static str, place: Place) -> Item {
    Item {
        sub: Some("ACTUAL"),
        units: Some("PERCENT"),
        native_units: Some("PERCENT"),
        ..item(name, Category::Sample, kind, place)
    }
}

/// MTConnect's CONTROLLER_MODE from cnc_statinfo's `aut`: JOG and teach
/// JOG are MANUAL, MDI MANUAL_DATA_INPUT, EDIT MANUAL, the rest AUTOMATIC.
pub fn mode(m: Mode) -> &'static str {
    match m.code() {
        5 | 6 | 3 => "MANUAL",
        0 => "MANUAL_DATA_INPUT",
        _ => "AUTOMATIC",
    }
}

/// MTConnect's EXECUTION from cnc_statinfo: a feed hold, or motion waiting
/// (dwell, or an M/S/T/B function waiting for its finish signal) while not
/// running, is INTERRUPTED; running (STRT, MSTR) ACTIVE; stopped in a
/// program (STOP) STOPPED; reset READY.
pub fn execution(s: &Status) -> &'static str {
    match s.run {
        Run::Start | Run::Mstr => "ACTIVE",
        Run::Hold => "INTERRUPTED",
        _ if s.motion == Motion::Dwell || s.mstb != 0 => "INTERRUPTED",
        Run::Stop => "STOPPED",
        _ => "READY",
    }
}

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn modes() {
        let m = |c| mode(Mode::from_code(c));
        assert_eq!(m(5), "MANUAL");
        assert_eq!(m(6), "MANUAL");
        assert_eq!(m(3), "MANUAL");
        assert_eq!(m(0), "MANUAL_DATA_INPUT");
        assert_eq!(m(1), "AUTOMATIC");
        assert_eq!(m(10), "AUTOMATIC");
    }

    #[test]
    fn executions() {
        let s = |run, motion, mstb| Status {
            mode: Mode::Mem,
            run: Run::from_code(run),
            motion: Motion::from_code(motion),
            mstb,
            emergency: Emergency::Clear,
            alarm: fwlib32::native::AlarmState::Clear,
            edit: 0,
        };
        assert_eq!(execution(&s(3, 1, 0)), "ACTIVE");
        assert_eq!(execution(&s(2, 0, 0)), "INTERRUPTED");
        assert_eq!(execution(&s(1, 2, 0)), "INTERRUPTED");
        assert_eq!(execution(&s(1, 0, 1)), "INTERRUPTED");
        assert_eq!(execution(&s(1, 0, 0)), "STOPPED");
        assert_eq!(execution(&s(0, 0, 0)), "READY");
    }
}
