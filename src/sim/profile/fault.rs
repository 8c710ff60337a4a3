//! `[[fault]]`: the network misbehaving on a schedule (src/sim/faults.rs
//! applies them), in the style of `[[event]]`: `at`, `every`, `duration`.
//! On the command line: `--fault KIND[:KEY=VALUE,...]`, the same keys.

use super::window::Window;
use serde::{Deserialize, Deserializer};

/// What goes wrong (docs/simulator.md: the real situation each stands for).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FaultKind {
    /// Switched off or rebooting: new connections refused, open ones reset.
    Off,
    /// New connections refused; open ones go on.
    Refuse,
    /// Nothing answered (requests read and dropped), connections kept.
    Silent,
    /// An answer cut half-way, then the connection reset (RST).
    Reset,
    /// An answer cut half-way, then the connection closed (FIN).
    Close,
    /// Every answer `delay_ms` late.
    Delay,
    /// At most `sessions` FOCAS sessions.
    Sessions,
    /// `code` answered for the chosen commands.
    Error,
    /// Off the network during a program upload: connection 1 cut after
    /// part of the text, every connection of the CNC reset.
    UploadDrop,
}

pub const KINDS: &str = "off, refuse, silent, reset, close, delay, sessions, error, upload_drop";

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Fault {
    pub kind: FaultKind,
    /// Seconds after the simulator starts (0: from the start).
    #[serde(default)]
    pub at: f64,
    /// Repeat period in seconds (0 = once).
    #[serde(default)]
    pub every: f64,
    /// How long each occurrence lasts, in seconds (0 = for ever).
    #[serde(default)]
    pub duration: f64,
    /// Fleet members it concerns (1-based); empty: every machine.
    #[serde(default)]
    pub machines: Vec<usize>,
    /// delay: milliseconds added before each answer.
    #[serde(default)]
    pub delay_ms: u64,
    /// sessions: sessions allowed while the fault holds.
    #[serde(default)]
    pub sessions: Option<usize>,
    /// error: the code answered (a number or an `EW_*` name; default EW_BUSY).
    #[serde(default, deserialize_with = "code")]
    pub code: Option<i16>,
    /// error: FOCAS functions whose commands get `code` (src/proto/names.rs).
    #[serde(default)]
    pub functions: Vec<String>,
    /// error: command numbers that get `code` (CNC or PMC class).
    #[serde(default)]
    pub commands: Vec<u16>,
    /// reset, close, upload_drop: answers cut per occurrence (0 = every one
    /// while it holds).
    #[serde(default)]
    pub count: u32,
}

fn code<'de, D: Deserializer<'de>>(d: D) -> Result<Option<i16>, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Code {
        Number(i16),
        Name(String),
    }
    match Code::deserialize(d)? {
        Code::Number(n) => Ok(Some(n)),
        Code::Name(s) => crate::proto::names::ew_code(&s)
            .map(Some)
            .ok_or_else(|| serde::de::Error::custom(format!("unknown code {s:?}"))),
    }
}

impl Fault {
    pub fn window(&self) -> Window {
        Window {
            at: self.at,
            every: self.every,
            duration: self.duration,
        }
    }

    /// Whether it concerns fleet member `machine` (1-based).
    pub fn concerns(&self, machine: usize) -> bool {
        self.machines.is_empty() || self.machines.contains(&machine)
    }

    /// The code an `error` fault answers.
    pub fn error_code(&self) -> i16 {
        self.code.unwrap_or(crate::ew::EW_BUSY)
    }

    /// The (class, command) pairs an `error` fault answers `code` for.
    pub fn error_commands(&self) -> Vec<(u16, u16)> {
        let mut out: Vec<(u16, u16)> = self
            .functions
            .iter()
            .flat_map(|f| crate::proto::names::function_commands(f))
            .collect();
        for &c in &self.commands {
            let class = if c >= 0x8000 {
                crate::proto::packet::CLASS_PMC
            } else {
                crate::proto::packet::CLASS_CNC
            };
            out.push((class, c));
        }
        out
    }

    /// What is wrong with it, if anything (`machines`: the fleet's size).
    pub fn check(&self, machines: usize) -> Result<(), String> {
        self.window().check()?;
        if let Some(m) = self.machines.iter().find(|&&m| m == 0 || m > machines) {
            return Err(format!(
                "machine {m} does not exist (machines are numbered 1 to {machines})"
            ));
        }
        let k = self.kind;
        let only = |given: bool, key: &str, kinds: &[FaultKind], name: &str| {
            if given && !kinds.contains(&k) {
                Err(format!("only a {name} fault takes {key}"))
            } else {
                Ok(())
            }
        };
        only(self.delay_ms > 0, "delay_ms", &[FaultKind::Delay], "delay")?;
        only(
            self.sessions.is_some(),
            "sessions",
            &[FaultKind::Sessions],
            "sessions",
        )?;
        let error = [FaultKind::Error];
        only(self.code.is_some(), "code", &error, "error")?;
        only(!self.functions.is_empty(), "functions", &error, "error")?;
        only(!self.commands.is_empty(), "commands", &error, "error")?;
        let cuts = [FaultKind::Reset, FaultKind::Close, FaultKind::UploadDrop];
        only(
            self.count > 0,
            "count",
            &cuts,
            "reset, close or upload_drop",
        )?;
        match k {
            FaultKind::Delay if self.delay_ms == 0 => {
                Err("a delay fault needs delay_ms (milliseconds, > 0)".into())
            }
            FaultKind::Delay if self.delay_ms > 3_600_000 => {
                Err("delay_ms is at most an hour".into())
            }
            FaultKind::Sessions if self.sessions.is_none() => {
                Err("a sessions fault needs sessions (how many, 0 or more)".into())
            }
            FaultKind::Error if self.functions.is_empty() && self.commands.is_empty() => {
                Err("an error fault needs functions (FOCAS names) or commands (numbers)".into())
            }
            FaultKind::Error => {
                match self
                    .functions
                    .iter()
                    .find(|f| crate::proto::names::function_commands(f).is_empty())
                {
                    Some(f) => Err(format!(
                        "function {f:?} sends no command the simulator knows"
                    )),
                    None => Ok(()),
                }
            }
            _ => Ok(()),
        }
    }

    /// A fault from the command line: `KIND[:KEY=VALUE,...]` with the keys of
    /// `[[fault]]`; lists as `[a,b]` or `a+b`, machine ranges as `1..10`.
    pub fn parse_spec(spec: &str) -> Result<Fault, String> {
        let (kind, rest) = spec.split_once(':').unwrap_or((spec, ""));
        let mut toml = format!("kind = {:?}\n", kind.trim());
        for item in split_top(rest) {
            let item = item.trim();
            if item.is_empty() {
                continue;
            }
            let (k, v) = item
                .split_once('=')
                .ok_or_else(|| format!("{item:?} is not KEY=VALUE"))?;
            let (k, v) = (k.trim(), v.trim());
            let value = if ["machines", "functions", "commands"].contains(&k) {
                let inner = v.strip_prefix('[').and_then(|x| x.strip_suffix(']'));
                let items: Vec<String> = inner
                    .map_or_else(
                        || v.split('+').collect::<Vec<_>>(),
                        |x| x.split(',').collect(),
                    )
                    .into_iter()
                    .map(str::trim)
                    .filter(|x| !x.is_empty())
                    .flat_map(expand_range)
                    .collect();
                format!("[{}]", items.join(", "))
            } else {
                scalar(v)
            };
            toml.push_str(&format!("{k} = {value}\n"));
        }
        let f: Fault = toml::from_str(&toml).map_err(|e| {
            format!("--fault {spec:?}: {}", e.message())
                + &format!(" (kinds: {KINDS}; keys as in [[fault]])")
        })?;
        Ok(f)
    }
}

/// `spec` split at commas outside brackets.
fn split_top(spec: &str) -> Vec<&str> {
    let (mut out, mut depth, mut from) = (Vec::new(), 0i32, 0);
    for (i, c) in spec.char_indices() {
        match c {
            '[' => depth += 1,
            ']' => depth -= 1,
            ',' if depth == 0 => {
                out.push(&spec[from..i]);
                from = i + 1;
            }
            _ => {}
        }
    }
    out.push(&spec[from..]);
    out
}

/// `v` as a TOML value: itself if it is one (a number, a boolean), else a string.
fn scalar(v: &str) -> String {
    let is_value = toml::from_str::<toml::Table>(&format!("v = {v}"))
        .is_ok_and(|t| !matches!(t.get("v"), Some(toml::Value::Table(_))));
    if is_value {
        v.to_string()
    } else {
        format!("{v:?}")
    }
}

/// A list element: `a..b` as the numbers a to b, others as one value.
fn expand_range(x: &str) -> Vec<String> {
    if let Some((a, b)) = x.split_once("..")
        && let (Ok(a), Ok(b)) = (a.trim().parse::<u64>(), b.trim().parse::<u64>())
        && b >= a
        && b - a < 1_000_000
    {
        return (a..=b).map(|n| n.to_string()).collect();
    }
    vec![scalar(x)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proto::cmd::{self, CLASS_CNC};

    #[test]
    fn command_line_specs() {
        let f = Fault::parse_spec("off:at=10,duration=2.5,machines=1..3+7").unwrap();
        assert_eq!(f.kind, FaultKind::Off);
        assert_eq!((f.at, f.duration), (10.0, 2.5));
        assert_eq!(f.machines, vec![1, 2, 3, 7]);
        let f =
            Fault::parse_spec("error:functions=[cnc_rdparam,pmc_rdpmcrng],code=EW_NOOPT").unwrap();
        assert_eq!(f.code, Some(6));
        assert_eq!(f.functions, vec!["cnc_rdparam", "pmc_rdpmcrng"]);
        assert!(f.check(1).is_ok());
        let f = Fault::parse_spec("error:commands=0x19,code=-1").unwrap();
        assert_eq!(
            (f.commands.clone(), f.code),
            (vec![cmd::STATINFO], Some(-1))
        );
        assert_eq!(f.error_commands(), vec![(CLASS_CNC, cmd::STATINFO)]);
        assert_eq!(Fault::parse_spec("delay:delay_ms=2").unwrap().delay_ms, 2);
        assert!(Fault::parse_spec("melt").is_err());
        assert!(Fault::parse_spec("off:colour=red").is_err());
        assert!(Fault::parse_spec("off:at").is_err());
    }

    #[test]
    fn the_built_in_profile_s_commented_example_is_valid() {
        let text = crate::sim::profile::DEFAULT_PROFILE;
        let tail = &text[text.find("# [fleet]").expect("the example")..];
        let example: String = tail
            .lines()
            .take_while(|l| !l.starts_with("# Other kinds"))
            .map(|l| l.strip_prefix("# ").unwrap_or(l.trim_start_matches('#')))
            .collect::<Vec<_>>()
            .join("\n");
        let p = crate::sim::Profile::parse(&format!("{text}\n{example}\n")).unwrap();
        assert_eq!((p.fleet.machines, p.faults.len()), (20, 2));
        assert_eq!(p.faults[1].code, Some(crate::ew::EW_NOOPT));
    }

    #[test]
    fn checks() {
        let f = |s: &str| Fault::parse_spec(s).unwrap().check(5);
        assert!(f("delay").is_err());
        assert!(f("off:delay_ms=3").is_err());
        assert!(f("sessions").is_err());
        assert!(f("sessions:sessions=0").is_ok());
        assert!(f("error").is_err());
        assert!(f("error:functions=cnc_nothing").is_err());
        assert!(f("off:machines=6").is_err());
        assert!(f("reset:count=1,every=0.001").is_err());
        assert!(f("upload_drop:count=1").is_ok());
    }
}
