//! Profile sections of the running machine (src/sim/clock.rs): stored
//! programs (and their dates), the program each path runs, alarms and
//! scheduled events.

use serde::Deserialize;

/// `[[program]]`: a program stored in the CNC's memory (uploadable; the
/// one a path's `[path.cycle]` names is the one in cycle).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct StoredProgram {
    /// O number.
    pub number: i32,
    /// Program name as cnc_exeprgname2 reports it, e.g. "O1234" or a path
    /// like "//CNC_MEM/USER/PATH1/O1234"; empty = "O`<number>`".
    pub name: String,
    pub comment: String,
    /// The program text, one block per line ("N10 G01 X10. F500;" ...).
    pub text: String,
    /// Last modification, "YYYY-MM-DD HH:MM" (cnc_rdprogdir3 type 2);
    /// absent: 2024-05-17 13:45 (src/sim/program.rs).
    pub date: Option<String>,
    /// The path whose memory holds it (0: every path's).
    pub path: u16,
    /// Edit protection: delete, rename and overwrite are refused (EW_PROT).
    pub protect: bool,
}

/// `[path.memory]`: the path's program memory (src/sim/store.rs).
#[derive(Debug, Clone, Copy, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct Memory {
    /// Bytes for programs (default 512 KiB).
    pub bytes: Option<usize>,
    /// Programs it holds at most (default 400).
    pub programs: Option<usize>,
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
    /// The multiple-piece machining number (cnc_rdmultipieceno; 0: none).
    pub multi_piece: i32,
}

impl Default for Cycle {
    fn default() -> Self {
        Cycle {
            program: 0,
            block_seconds: 1.0,
            repeat: true,
            multi_piece: 0,
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

impl Event {
    /// When the event holds.
    pub fn window(&self) -> super::window::Window {
        super::window::Window {
            at: self.at,
            every: self.every,
            duration: self.duration,
        }
    }
}

/// Event actions the runner knows.
pub const ACTIONS: [&str; 4] = ["alarm", "feed_hold", "mode", "emergency"];

/// A `[[program]]`'s date when the profile gives none.
pub const DEFAULT_PROGRAM_DATE: [u16; 5] = [2024, 5, 17, 13, 45];

/// A `[[program]]`'s modification date as year, month, day, hour, minute
/// (`date = "YYYY-MM-DD HH:MM"`).
pub fn program_date(p: &StoredProgram) -> Result<[u16; 5], String> {
    let Some(d) = &p.date else {
        return Ok(DEFAULT_PROGRAM_DATE);
    };
    let bad = || format!("date = {d:?} is not \"YYYY-MM-DD HH:MM\"");
    let (day, time) = d.trim().split_once(' ').ok_or_else(bad)?;
    let mut ymd = day.split('-').map(|x| x.parse::<u16>());
    let mut hm = time.trim().split(':').map(|x| x.parse::<u16>());
    let next = |it: &mut dyn Iterator<Item = Result<u16, _>>| -> Result<u16, String> {
        it.next().and_then(|x| x.ok()).ok_or_else(bad)
    };
    let v = [
        next(&mut ymd)?,
        next(&mut ymd)?,
        next(&mut ymd)?,
        next(&mut hm)?,
        next(&mut hm)?,
    ];
    if ymd.next().is_some()
        || hm.next().is_some()
        || !(1..=12).contains(&v[1])
        || !(1..=31).contains(&v[2])
        || v[3] > 23
        || v[4] > 59
    {
        return Err(bad());
    }
    Ok(v)
}
