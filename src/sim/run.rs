//! The running machine: what changes while a program is in cycle. The
//! profile describes stored programs, the program each path runs, active
//! alarms and scheduled events; [`PathRun`] is the live state the
//! monitoring functions read, brought up to date by [`Machine::advance`]
//! (the `CncService::advance` hook, once per request frame).

use super::Machine;
use serde::Deserialize;
use std::time::Instant;

/// `[[program]]`: a program stored in the CNC's memory (uploadable; the
/// one a path's `[path.cycle]` names is the one in cycle).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct StoredProgram {
    /// O number.
    pub number: i32,
    /// Program name as cnc_exeprgname2 reports it, e.g. "O1234" or a path
    /// like "//CNC_MEM/USER/PATH1/O1234"; empty = "O<number>".
    pub name: String,
    pub comment: String,
    /// The program text, one block per line ("N10 G01 X10. F500;" ...).
    pub text: String,
}

/// `[path.cycle]`: the program a path runs and how fast it goes.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Cycle {
    /// O number of the `[[program]]` in cycle (0 = none: the path is idle).
    pub program: i32,
    /// Seconds per block (motion and block text advance at this rate).
    pub block_seconds: f64,
    /// Repeat the program when it ends (M30 and restart), counting parts.
    pub repeat: bool,
}

impl Default for Cycle {
    fn default() -> Self {
        Cycle {
            program: 0,
            block_seconds: 1.0,
            repeat: true,
        }
    }
}

/// `[[path.alarm]]`: an alarm active from the start (more are raised by events).
#[derive(Debug, Clone, Deserialize, Default, PartialEq, Eq)]
#[serde(deny_unknown_fields, default)]
pub struct Alarm {
    /// Alarm number as the CNC reports it (e.g. 1001).
    pub number: i32,
    /// Alarm type code (cnc_rdalmmsg `type`: 0 SW, 1 PW, 2 IO, 3 PS, 4 OT,
    /// 5 OH, 6 SV, 7 SR, 8 MC, 9 SP, 10 DS, 11 IE, 12 BG, 13 SN, 15 EX, 19 PC ...).
    #[serde(rename = "type")]
    pub kind: i16,
    /// Axis number the alarm concerns (0 = none).
    pub axis: i16,
    pub message: String,
}

/// `[[event]]`: something that happens at a time, repeating with `every`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct Event {
    /// Seconds after the simulator starts.
    pub at: f64,
    /// Repeat period in seconds (0 = once).
    pub every: f64,
    /// How long the event's condition lasts, in seconds (0 = until changed).
    pub duration: f64,
    /// Path it concerns (1-based; 0 = path 1).
    pub path: u16,
    /// "alarm" (raise `alarm` for `duration`), "feed_hold", "mode" (set
    /// status.aut to `value`), "emergency".
    pub action: String,
    pub value: i32,
    pub alarm: Option<Alarm>,
}

/// Live state of one path, what the monitoring functions read.
#[derive(Debug, Clone, Default)]
pub struct PathRun {
    /// O number running (cnc_rdprgnum data) and main program (mdata).
    pub program: i32,
    pub main_program: i32,
    /// Name as cnc_exeprgname/exeprgname2 report it.
    pub program_name: String,
    /// Sequence number of the current block (cnc_rdseqnum).
    pub seq: i32,
    /// Index of the current block in the program's lines.
    pub block: usize,
    /// Blocks executed since power-on (cnc_rdblkcount).
    pub block_count: i32,
    /// Text of the current block and the ones after it (cnc_rdexecprog).
    pub exec_text: String,
    /// Active alarms (profile `[[path.alarm]]` plus those events raised).
    pub alarms: Vec<Alarm>,
    /// Parts made since start (the runner also adds them to the part-count parameter).
    pub parts: i64,
}

impl Machine {
    /// The initial live state of every path, from the profile.
    pub fn initial_run(profile: &super::Profile) -> Vec<PathRun> {
        profile
            .paths
            .iter()
            .map(|p| {
                let prog = profile
                    .programs
                    .iter()
                    .find(|s| s.number == p.cycle.program);
                PathRun {
                    program: p.cycle.program,
                    main_program: p.cycle.program,
                    program_name: prog.map(StoredProgram::display_name).unwrap_or_default(),
                    exec_text: prog
                        .map(|s| s.text.lines().take(8).collect::<Vec<_>>().join("\n"))
                        .unwrap_or_default(),
                    alarms: p.alarms.clone(),
                    ..PathRun::default()
                }
            })
            .collect()
    }

    /// Brings the live state up to `now`.
    pub fn advance_to(&mut self, now: Instant) {
        let _ = now.saturating_duration_since(self.started);
    }
}

impl StoredProgram {
    /// The name CNCs report: the profile's, or "O<number>".
    pub fn display_name(&self) -> String {
        if self.name.is_empty() {
            format!("O{:04}", self.number)
        } else {
            self.name.clone()
        }
    }
}
