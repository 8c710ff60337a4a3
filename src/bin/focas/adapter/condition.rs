//! Alarms as MTConnect conditions, by mark and sweep: every poll marks the
//! alarms active now; an activation not marked is swept (cleared by its
//! native code), and a condition left without any goes back to a bare
//! NORMAL.

use super::shdr::{Cond, Level};
use fwlib32::native::Alarm;
use std::collections::BTreeMap;

/// Where a FANUC alarm goes: the condition item's name, given the path's
/// axis and spindle item prefixes and the path's suffix. The alarm's type
/// (`cnc_rdalmmsg2`'s `type`) chooses, as the C++ FANUC adapter sorts them:
/// overtravel, overheat and servo alarms of an axis to that axis, spindle
/// alarms to the first spindle, the rest to the controller's conditions.
pub fn condition_of(alarm: &Alarm, axes: &[String], spindles: &[String], suffix: &str) -> String {
    let axis = usize::try_from(alarm.axis)
        .ok()
        .and_then(|a| a.checked_sub(1))
        .and_then(|i| axes.get(i));
    let path = |n: &str| format!("{n}{suffix}");
    match alarm.kind.0 {
        0 | 19 => path("logic"),
        2 | 7 => path("comms"),
        3 | 8 | 12 => path("motion"),
        4 => axis.map_or_else(|| path("system"), |a| format!("{a}travel")),
        5 => axis.map_or_else(|| path("system"), |a| format!("{a}overheat")),
        6 => axis.map_or_else(|| path("servo"), |a| format!("{a}servo")),
        9 => spindles
            .first()
            .map_or_else(|| path("system"), |s| format!("{s}servo")),
        _ => path("system"),
    }
}

/// The conditions of one device and their active alarms.
#[derive(Debug, Default)]
pub struct Conditions {
    /// Condition name to its activations by native code (None: unavailable).
    active: BTreeMap<String, Option<BTreeMap<String, Cond>>>,
}

impl Conditions {
    /// Conditions named `names`, all unavailable until the first sweep.
    #[cfg(test)]
    pub fn new(names: impl IntoIterator<Item = String>) -> Conditions {
        Conditions {
            active: names.into_iter().map(|n| (n, None)).collect(),
        }
    }

    /// Marks `now` (activations, any condition) and sweeps the rest: the
    /// lines that tell an agent what changed.
    pub fn sweep(&mut self, now: Vec<Cond>) -> Vec<Cond> {
        let mut marked: BTreeMap<String, BTreeMap<String, Cond>> = BTreeMap::new();
        for c in now {
            self.active.entry(c.name.clone()).or_insert(None);
            marked
                .entry(c.name.clone())
                .or_default()
                .insert(c.code.clone(), c);
        }
        let mut out = Vec::new();
        for (name, was) in self.active.iter_mut() {
            let is = marked.remove(name).unwrap_or_default();
            match was {
                Some(was) if is.is_empty() && !was.is_empty() => {
                    out.push(Cond::bare(name, Level::Normal));
                }
                Some(was) => {
                    for code in was.keys().filter(|c| !is.contains_key(*c)) {
                        let mut clear = Cond::bare(name, Level::Normal);
                        clear.code = code.clone();
                        out.push(clear);
                    }
                    out.extend(is.values().filter(|c| was.get(&c.code) != Some(c)).cloned());
                }
                None if is.is_empty() => out.push(Cond::bare(name, Level::Normal)),
                None => out.extend(is.values().cloned()),
            }
            *was = Some(is);
        }
        out
    }

    /// Every condition unavailable (the CNC is gone): their lines, for
    /// those not unavailable already.
    pub fn unavailable(&mut self) -> Vec<Cond> {
        let mut out = Vec::new();
        for (name, was) in self.active.iter_mut() {
            if was.take().is_some() {
                out.push(Cond::bare(name, Level::Unavailable));
            }
        }
        out
    }

    /// The whole current state, for an agent that just connected: each
    /// condition's activations, or its bare NORMAL or UNAVAILABLE.
    pub fn current(&self) -> Vec<Cond> {
        let mut out = Vec::new();
        for (name, now) in &self.active {
            match now {
                None => out.push(Cond::bare(name, Level::Unavailable)),
                Some(a) if a.is_empty() => out.push(Cond::bare(name, Level::Normal)),
                Some(a) => out.extend(a.values().cloned()),
            }
        }
        out
    }

    /// Adds a condition (unavailable until swept), unless known.
    pub fn add(&mut self, name: &str) {
        if !self.active.contains_key(name) {
            self.active.insert(name.to_string(), None);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use fwlib32::native::AlarmKind;

    fn fault(name: &str, code: &str) -> Cond {
        Cond {
            level: Level::Fault,
            code: code.into(),
            text: format!("alarm {code}"),
            ..Cond::bare(name, Level::Fault)
        }
    }

    fn levels(v: &[Cond]) -> Vec<(String, &'static str, String)> {
        v.iter()
            .map(|c| (c.name.clone(), c.level.as_str(), c.code.clone()))
            .collect()
    }

    #[test]
    fn mark_and_sweep() {
        let mut c = Conditions::new(["system".to_string(), "Xtravel".to_string()]);
        assert_eq!(c.current().len(), 2);
        assert!(c.current().iter().all(|c| c.level == Level::Unavailable));
        let first = c.sweep(vec![]);
        assert_eq!(levels(&first).len(), 2);
        assert!(
            first
                .iter()
                .all(|c| c.level == Level::Normal && c.code.is_empty())
        );
        assert!(c.sweep(vec![]).is_empty(), "nothing changed, nothing sent");
        let s = |n: &str, l: &'static str, c: &str| (n.to_string(), l, c.to_string());
        let two = c.sweep(vec![fault("system", "SR1"), fault("system", "SR2")]);
        assert_eq!(
            levels(&two),
            [s("system", "FAULT", "SR1"), s("system", "FAULT", "SR2")]
        );
        assert!(
            c.sweep(vec![fault("system", "SR1"), fault("system", "SR2")])
                .is_empty()
        );
        let one = c.sweep(vec![fault("system", "SR2")]);
        assert_eq!(levels(&one), [s("system", "NORMAL", "SR1")]);
        assert_eq!(
            levels(&c.current()),
            [s("Xtravel", "NORMAL", ""), s("system", "FAULT", "SR2")]
        );
        let none = c.sweep(vec![]);
        assert_eq!(
            levels(&none),
            [s("system", "NORMAL", "")],
            "a bare NORMAL clears all"
        );
        let gone = c.unavailable();
        assert_eq!(gone.len(), 2);
        assert!(c.unavailable().is_empty());
    }

    #[test]
    fn alarms_go_to_their_axis_or_the_controller() {
        let axes = ["X".to_string(), "Y".to_string()];
        let sp = ["S1".to_string()];
        let a = |kind: i16, axis: i16| Alarm {
            number: 500,
            kind: AlarmKind(kind),
            axis,
            message: String::new(),
        };
        assert_eq!(condition_of(&a(4, 1), &axes, &sp, ""), "Xtravel");
        assert_eq!(condition_of(&a(4, 0), &axes, &sp, ""), "system");
        assert_eq!(condition_of(&a(6, 2), &axes, &sp, "2"), "Yservo");
        assert_eq!(condition_of(&a(6, 0), &axes, &sp, "2"), "servo2");
        assert_eq!(condition_of(&a(9, 0), &axes, &sp, ""), "S1servo");
        assert_eq!(condition_of(&a(19, 0), &axes, &sp, ""), "logic");
        assert_eq!(condition_of(&a(2, 0), &axes, &sp, ""), "comms");
        assert_eq!(condition_of(&a(12, 0), &axes, &sp, ""), "motion");
        assert_eq!(condition_of(&a(4, 9), &axes, &sp, ""), "system");
    }
}
