//! The running machine's live state: what changes while a program is in
//! cycle. The profile describes stored programs, the program each path
//! runs, active alarms and scheduled events; [`PathRun`] is the live state
//! the monitoring functions read, brought up to date by the clock
//! (src/sim/clock.rs, `Machine::advance_to`), and the events' timing.

use super::modal::ProgramModal;
use super::plan::{EXEC_LINES, Plan};
pub use super::profile::cycle::{ACTIONS, Alarm, Cycle, Event, StoredProgram};
use super::profile::{Profile, SampleChannel, StatusWords};
use super::store::{Program, Store};
use std::sync::Arc;

/// Ball screw lead when the profile gives none, mm per motor turn.
pub(crate) const DEFAULT_LEAD: f64 = 10.0;

/// Live state of one path, what the monitoring functions read.
///
/// The clock (`Machine::advance_to`) computes it as a pure function of the time since
/// the simulator started (state(t)): the same elapsed time always gives the
/// same state, whatever was polled before. It also writes the profile's
/// status words, axis positions and spindle speeds of the path.
#[derive(Debug, Clone, Default)]
pub struct PathRun {
    /// O number running (cnc_rdprgnum data; the main program, mdata, is
    /// the store's selection, [`super::store::PathStore::main`]).
    pub program: i32,
    /// Name as cnc_exeprgname/exeprgname2 report it.
    pub program_name: String,
    /// Sequence number of the current block (cnc_rdseqnum): the last N
    /// number seen up to the current block in this pass of the program.
    pub seq: i32,
    /// Index of the current block in the program's lines (`text.lines()`,
    /// line 0 being the "O1234" line).
    pub block: usize,
    /// Blocks executed since power-on (cnc_rdblkcount).
    pub block_count: i32,
    /// Text of the current block and the ones after it (cnc_rdexecprog),
    /// lines joined by '\n'.
    pub exec_text: String,
    /// Active alarms (profile `[[path.alarm]]` plus those events raised).
    pub alarms: Vec<Alarm>,
    /// Parts made since start: M30 (or M02) blocks completed.
    pub parts: i64,
    /// Actual feed rate of the path, mm/min (cnc_actf): the modal F of a
    /// G01 move, the traverse speed of a G00 move, 0 when not moving.
    pub feed: i32,
    /// Actual speed of the first spindle, min^-1 (cnc_acts): the modal S
    /// while M03/M04 is on, 0 after M05 or in an emergency stop.
    pub spindle_speed: i32,
    /// The program ended and does not repeat (status run 0).
    pub finished: bool,
    /// Runs of the program completed (cnc_rdproctime), and the program
    /// time one run takes, in seconds (holds not counted).
    pub runs_done: u64,
    pub run_seconds: f64,
    /// Feed hold (an event) is active on the path.
    pub held: bool,
    /// The modal codes the programs run so far set, as at the current
    /// block (cnc_modal; what no program set is the profile's table).
    pub modal: ProgramModal,
    /// Seconds the path ran (STRT) and moved at feed (G01/G02/G03) since
    /// the simulator started, and the seconds of the current (or last)
    /// run of a program (cnc_rdtimer 1, 2, 3): holds stop them.
    pub operating: f64,
    pub cutting: f64,
    pub cycle: f64,
    /// The macro message on display (`#3006=n(TEXT)` of the last such
    /// block the program passed): number and text (cnc_rdopmsg3, type 4).
    pub message: Option<(i32, String)>,
    /// Where the last reset (or cycle start) interrupted a running program
    /// (cnc_rdprstrinfo's program restart data); None before any.
    pub restart: Option<Restart>,
    /// Servo data sampling: its channels and whether it runs (cnc_sdt*).
    pub sampling: Sampling,
    /// What the clock needs: parsed program, profile base values, caches.
    pub(crate) engine: Engine,
}

/// Program restart data: where a running program was interrupted.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Restart {
    /// The block interrupted, counted from the program's first (1..).
    pub block: i32,
    /// The modal codes there (M, T, S, B for the restart).
    pub modal: ProgramModal,
    /// The absolute position of each axis of the path there.
    pub dest: Vec<i32>,
}

/// The runner's own state for one path (not part of the visible model).
#[derive(Debug, Clone, Default)]
pub(crate) struct Engine {
    /// The parsed program in cycle (None: the path is idle).
    pub(super) plan: Option<Arc<Plan>>,
    /// Status words, positions and spindle speeds as the profile gives them
    /// (positions: where the plan started from).
    pub(super) base_status: StatusWords,
    pub(super) base_axes: Vec<[i64; 3]>,
    pub(super) base_spindles: Vec<i32>,
    /// Servo loads per axis and the first spindle's load, as the profile gives them.
    pub(super) base_loads: Vec<i32>,
    pub(super) base_spindle_load: i32,
    /// Parts already added to the part-count parameter (6711).
    pub(super) counted_parts: i64,
    /// Held time (feed hold, emergency) memo: (t, held seconds in [0, t)).
    pub(super) held_memo: (f64, f64),
    /// Per profile event (by index): the last occurrence reported raised.
    pub(super) raised: Vec<Option<u64>>,
    /// The profile's own alarms were reported raised.
    pub(super) initial_reported: bool,
    /// exec_text was built for this line.
    pub(super) text_line: Option<usize>,
    /// The plan's clock origin, seconds since the simulator started, and
    /// the time held before it (cnc_start starts a plan from that moment).
    pub(super) t0: f64,
    pub(super) held0: f64,
    /// Parts and blocks of plans that ran before this one.
    pub(super) parts_before: i64,
    pub(super) blocks_before: i32,
    /// Per profile event (by index): alarm occurrences up to this one were
    /// cleared (cnc_reset, cnc_clralm).
    pub(super) cleared: Vec<Option<u64>>,
    /// Alarm types a reset or cnc_clralm cleared from the profile's own.
    pub(super) cleared_types: Vec<i16>,
    /// The plan is a DNC program still arriving: at its last block it waits.
    pub(super) streaming: bool,
    /// Seconds a DNC plan waited for data (its clock origin moved on by
    /// them): still operating time.
    pub(super) waited: f64,
    /// Modal codes, operating and cutting seconds of plans that ran before.
    pub(super) modal_before: ProgramModal,
    pub(super) op_before: f64,
    pub(super) cut_before: f64,
}

/// The occurrence of the event whose start is the last at or before `t`.
pub(super) fn occurrence(e: &Event, t: f64) -> Option<u64> {
    e.window().occurrence(t)
}

/// Whether the event's condition holds at `t` (src/sim/profile/window.rs).
pub(super) fn active(e: &Event, t: f64) -> bool {
    e.window().active(t).is_some()
}

/// Seconds of [a, b) covered by the union of the events' conditions.
pub(super) fn covered(events: &[&Event], a: f64, b: f64) -> f64 {
    if b <= a {
        return 0.0;
    }
    let mut iv: Vec<(f64, f64)> = Vec::new();
    for e in events {
        if e.duration <= 0.0 || (e.every > 0.0 && e.duration >= e.every) {
            iv.push((e.at, f64::INFINITY));
            continue;
        }
        if e.every <= 0.0 {
            iv.push((e.at, e.at + e.duration));
            continue;
        }
        let mut k = if a > e.at {
            ((a - e.at) / e.every).floor()
        } else {
            0.0
        };
        loop {
            let s = e.at + k * e.every;
            if s >= b {
                break;
            }
            iv.push((s, s + e.duration));
            k += 1.0;
        }
    }
    iv.sort_by(|x, y| x.0.total_cmp(&y.0));
    let (mut sum, mut cur): (f64, Option<(f64, f64)>) = (0.0, None);
    for (s, e) in iv {
        let (s, e) = (s.max(a), e.min(b));
        if e <= s {
            continue;
        }
        cur = match cur {
            Some((cs, ce)) if s <= ce => Some((cs, ce.max(e))),
            Some((cs, ce)) => {
                sum += ce - cs;
                Some((s, e))
            }
            None => Some((s, e)),
        };
    }
    if let Some((cs, ce)) = cur {
        sum += ce - cs;
    }
    sum
}

/// The event's path as an index (path 0 means path 1).
pub(super) fn event_path(e: &Event) -> usize {
    usize::from(e.path.max(1)) - 1
}

impl PathRun {
    /// The initial live state of every path, from the profile.
    pub fn initial(profile: &Profile, store: &Store) -> Vec<PathRun> {
        profile
            .paths
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let prog = store.get(i as u16 + 1, p.cycle.program);
                let plan = prog
                    .filter(|_| p.cycle.program != 0)
                    .map(|s| Arc::new(Plan::parse(&s.text, &p.axes, &p.cycle)));
                PathRun {
                    program: p.cycle.program,
                    program_name: prog.map(Program::display_name).unwrap_or_default(),
                    exec_text: prog
                        .map(|s| {
                            s.text
                                .lines()
                                .take(EXEC_LINES)
                                .collect::<Vec<_>>()
                                .join("\n")
                        })
                        .unwrap_or_default(),
                    alarms: p.alarms.clone(),
                    spindle_speed: p.spindles.first().map_or(0, |s| s.speed),
                    sampling: Sampling::new(&p.sample_channels),
                    engine: Engine {
                        plan,
                        base_status: p.status,
                        base_axes: p
                            .axes
                            .iter()
                            .map(|a| [a.absolute, a.machine, a.relative].map(i64::from))
                            .collect(),
                        base_spindles: p.spindles.iter().map(|s| s.speed).collect(),
                        base_loads: p.axes.iter().map(|a| a.servo_load).collect(),
                        base_spindle_load: p.spindles.first().map_or(0, |s| s.load),
                        raised: vec![None; profile.events.len()],
                        cleared: vec![None; profile.events.len()],
                        ..Engine::default()
                    },
                    ..PathRun::default()
                }
            })
            .collect()
    }
}

/// A path's sampling state.
#[derive(Debug, Clone, Default)]
pub struct Sampling {
    /// The channels, channel 1 first (at most 8 answered: src/sim/sampling.rs).
    pub channels: Vec<SampleChannel>,
    /// Sampling runs: since when, with cnc_sdtstartsmpl's two arguments.
    pub running: Option<Running>,
}

/// Sampling started by cnc_sdtstartsmpl.
#[derive(Debug, Clone, Copy)]
pub struct Running {
    pub since: std::time::Instant,
    pub kind: i32,
    pub cycle: i32,
}

impl Sampling {
    /// The state a path starts with: its profile's channels.
    pub fn new(channels: &[SampleChannel]) -> Sampling {
        Sampling {
            channels: channels.to_vec(),
            running: None,
        }
    }
}
