//! What the adapter reads: the machine's layout found on connecting
//! (paths, axes, spindles) and the data items named from it (one poll of a
//! path: poll.rs).

use fwlib32::native::{Cnc, Error, Mode, Motion, PmcArea, Run, Status, Unit};

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

#[cfg(test)]
mod tests {
    use super::*;
    use fwlib32::native::Emergency;

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
