//! The running machine: what changes while a program is in cycle. The
//! profile describes stored programs, the program each path runs, active
//! alarms and scheduled events; [`PathRun`] is the live state the
//! monitoring functions read, brought up to date by [`Machine::advance_to`]
//! (the `CncService::advance` hook, once per request frame).

use super::modal::{self, ProgramModal};
use super::plan::{EXEC_LINES, Kind, Plan};
use super::pmc::Pmc;
pub use super::profile::cycle::{ACTIONS, Alarm, Cycle, Event, StoredProgram};
use super::profile::{Profile, StatusWords};
use super::store::{Program, Store};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// The parameter a FANUC CNC counts machined parts in.
const PART_COUNT_PARAM: i32 = 6711;
/// Ball screw lead when the profile gives none, mm per motor turn.
pub(crate) const DEFAULT_LEAD: f64 = 10.0;

/// The simulated machine: the profile (with what writes change in it) and
/// the live state of its paths. The areas (src/sim/param.rs, position.rs
/// ...) add their methods; src/sim/machine.rs serves them as a CNC.
pub struct Machine {
    pub profile: Profile,
    /// When the simulator started: the running program's clock.
    pub started: std::time::Instant,
    /// The instant the state was last brought up to ([`Machine::advance_to`]):
    /// what the timers read, so a frozen clock gives the same answers.
    pub now: std::time::Instant,
    /// Live state per path (what a running machine changes).
    pub run: Vec<PathRun>,
    /// The program memory of each path (src/sim/store.rs): the profile's
    /// `[[program]]`s (taken out of `profile`) and what the program
    /// functions change.
    pub store: Store,
}

impl Machine {
    pub fn new(mut profile: Profile) -> Machine {
        let started = std::time::Instant::now();
        let store = Store::seed(&profile);
        profile.programs = Vec::new();
        Machine {
            run: Machine::initial_run(&profile, &store),
            store,
            profile,
            started,
            now: started,
        }
    }

    /// The PMC memory, for a running machine to set signals (F, X, Y ...)
    /// whatever their FOCAS write protection: e.g.
    /// `m.pmc_mut().area_by_letter_mut("F").unwrap().bytes_mut(0, 1)`.
    pub fn pmc_mut(&mut self) -> &mut Pmc {
        &mut self.profile.pmc
    }

    pub fn pmc(&self) -> &Pmc {
        &self.profile.pmc
    }
}

/// Live state of one path, what the monitoring functions read.
///
/// [`Machine::advance_to`] computes it as a pure function of the time since
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
    base_spindles: Vec<i32>,
    /// Servo loads per axis and the first spindle's load, as the profile gives them.
    base_loads: Vec<i32>,
    base_spindle_load: i32,
    /// Parts already added to the part-count parameter (6711).
    counted_parts: i64,
    /// Held time (feed hold, emergency) memo: (t, held seconds in [0, t)).
    held_memo: (f64, f64),
    /// Per profile event (by index): the last occurrence reported raised.
    raised: Vec<Option<u64>>,
    /// The profile's own alarms were reported raised.
    initial_reported: bool,
    /// exec_text was built for this line.
    text_line: Option<usize>,
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

/// Missed alarm occurrences reported at most per event when a poller
/// comes back after a long pause.
const MAX_CATCH_UP: u64 = 64;

/// The occurrence of the event whose start is the last at or before `t`.
pub(super) fn occurrence(e: &Event, t: f64) -> Option<u64> {
    e.window().occurrence(t)
}

/// Whether the event's condition holds at `t` (src/sim/profile/window.rs).
fn active(e: &Event, t: f64) -> bool {
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

impl Machine {
    /// The initial live state of every path, from the profile.
    pub fn initial_run(profile: &super::Profile, store: &Store) -> Vec<PathRun> {
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

    /// Brings the live state up to `now`: a pure function of the time
    /// since [`Machine::started`] (a `now` before it counts as 0).
    pub fn advance_to(&mut self, now: Instant) {
        self.now = now;
        let since = now.saturating_duration_since(self.started);
        let t = since.as_secs_f64();
        let power_on = std::time::SystemTime::now()
            .checked_sub(since)
            .unwrap_or(std::time::UNIX_EPOCH);
        self.seed_messages(power_on);
        let mut raised: Vec<(u16, Alarm, Duration)> = Vec::new();
        for i in 0..self.run.len() {
            let mode = self.profile.paths[i].status.aut;
            self.advance_path(i, t, &mut raised);
            let now = self.profile.paths[i].status.aut;
            if now != mode {
                // The mode switch's signals, MD1/MD2/MD4 ... G43 (path n:
                // G(43 + 1000·(n−1))), into the operation history.
                let byte = 43 + 1000 * i as i32;
                self.record_signal(0, byte, mode_signals(mode), mode_signals(now));
            }
        }
        for (i, r) in self.run.iter().enumerate() {
            let busy = self.profile.paths[i].status.run != 0;
            if let Ok(s) = self.store.path_mut(i as u16 + 1) {
                s.running = if busy { r.program } else { 0 };
            }
        }
        for (path, alarm, at) in raised {
            self.on_alarm_raised(path, &alarm, since.saturating_sub(at));
        }
        self.count_parts();
    }

    /// Each part path 1 finishes adds one to the part counter (parameter
    /// 6711, where the profile has it), as a CNC counts at M30: a value
    /// written through FOCAS counts on from there.
    fn count_parts(&mut self) {
        let Some(run) = self.run.first_mut() else {
            return;
        };
        let new = run.parts - run.engine.counted_parts;
        if new <= 0 {
            return;
        }
        run.engine.counted_parts = run.parts;
        if let Some(v) = self.param_value(PART_COUNT_PARAM, 0) {
            let add = i32::try_from(new).unwrap_or(i32::MAX);
            self.set_param_value(PART_COUNT_PARAM, 0, v.saturating_add(add));
        }
    }

    /// An alarm became active on `path` (1-based) at `at` after the start:
    /// the profile's own alarms at the first advance (0 s), an event's
    /// alarm at each occurrence (also those that came and went between two
    /// polls, at most 64 per event): it goes into the alarm history, stamped
    /// with the wall clock `ago` before now.
    fn on_alarm_raised(&mut self, path: u16, alarm: &Alarm, ago: Duration) {
        let _ = path;
        let at = std::time::SystemTime::now()
            .checked_sub(ago)
            .unwrap_or(std::time::UNIX_EPOCH);
        self.record_alarm(alarm.number, alarm.kind, alarm.axis, &alarm.message, at);
        let op = super::history::Operation {
            kind: "alarm".into(),
            number: alarm.number,
            group: alarm.kind,
            axis: alarm.axis,
            ..Default::default()
        };
        self.record_operation(op, at);
    }

    fn advance_path(&mut self, i: usize, t: f64, raised: &mut Vec<(u16, Alarm, Duration)>) {
        let profile = &mut self.profile;
        let run = &mut self.run[i];
        let eng = &mut run.engine;
        let path_no = i as u16 + 1;
        let mine: Vec<(usize, &Event)> = profile
            .events
            .iter()
            .enumerate()
            .filter(|(_, e)| event_path(e) == i)
            .collect();

        // Alarms: the profile's, then the events' active now.
        if !eng.initial_reported {
            eng.initial_reported = true;
            for a in &profile.paths[i].alarms {
                raised.push((path_no, a.clone(), Duration::ZERO));
            }
        }
        let mut alarms = profile.paths[i].alarms.clone();
        alarms.retain(|a| !eng.cleared_types.contains(&a.kind));
        let (mut hold, mut emergency, mut mode) = (false, false, None);
        for (k, e) in &mine {
            let now_k = occurrence(e, t);
            if e.action == "alarm" {
                if let (Some(a), Some(kn)) = (&e.alarm, now_k) {
                    let first = match eng.raised.get(*k).copied().flatten() {
                        Some(last) if last >= kn => kn + 1,
                        Some(last) => last + 1,
                        None => 0,
                    };
                    for occ in first.max((kn + 1).saturating_sub(MAX_CATCH_UP))..=kn {
                        let at = e.at + occ as f64 * e.every;
                        raised.push((path_no, a.clone(), Duration::from_secs_f64(at)));
                    }
                }
                if let Some(slot) = eng.raised.get_mut(*k) {
                    *slot = now_k;
                }
            }
            if !active(e, t) {
                continue;
            }
            let cleared = eng.cleared.get(*k).copied().flatten();
            match e.action.as_str() {
                "alarm" if cleared.is_some() && cleared >= occurrence(e, t) => {}
                "alarm" => alarms.extend(e.alarm.clone()),
                "feed_hold" => hold = true,
                "emergency" => emergency = true,
                "mode" => mode = Some(e.value as i16),
                _ => {}
            }
        }

        let mut st = eng.base_status;
        if !alarms.is_empty() {
            st.alarm = 1;
        }
        if emergency {
            st.emergency = 1;
        }
        if let Some(m) = mode {
            st.aut = m;
        }
        run.alarms = alarms;
        run.held = hold && !emergency;

        let Some(plan) = eng.plan.clone() else {
            run.operating = eng.op_before;
            run.cutting = eng.cut_before;
            if run.held {
                st.run = 2;
                st.motion = 0;
            }
            if emergency {
                st.run = 0;
                st.motion = 0;
            }
            profile.paths[i].status = st;
            return;
        };

        // The program clock: elapsed time less the time held (feed hold,
        // emergency stop), memoised so each frame only sweeps its own span.
        let stops: Vec<&Event> = mine
            .iter()
            .map(|(_, e)| *e)
            .filter(|e| e.action == "feed_hold" || e.action == "emergency")
            .collect();
        let held = if stops.is_empty() {
            0.0
        } else {
            let (mt, mh) = eng.held_memo;
            let h = if t >= mt {
                mh + covered(&stops, mt, t)
            } else {
                covered(&stops, 0.0, t)
            };
            eng.held_memo = (t, h);
            h
        };
        let tp = (t - eng.t0 - (held - eng.held0)).max(0.0);
        let n = plan.blocks.len() as u64;
        if n == 0 {
            profile.paths[i].status = st;
            return;
        }
        let done = (tp / plan.block_seconds).floor() as u64;
        let (pass, k, frac, finished) = if plan.repeat {
            (
                done / n,
                (done % n) as usize,
                tp / plan.block_seconds - done as f64,
                false,
            )
        } else if done >= n {
            // A DNC program waits at its last block for more (not finished).
            (0, n as usize - 1, 1.0, !eng.streaming)
        } else {
            (
                0,
                done as usize,
                tp / plan.block_seconds - done as f64,
                false,
            )
        };
        let b = &plan.blocks[k];
        // The last macro message passed: in this pass, else the pass before.
        let shown = |bs: &[super::plan::Block]| bs.iter().rev().find_map(|b| b.message.clone());
        run.message =
            shown(&plan.blocks[..=k]).or_else(|| if pass > 0 { shown(&plan.blocks) } else { None });
        let before = (k > 0).then(|| &plan.blocks[k - 1]);
        let last = plan.blocks.last().expect("n > 0");
        let starved = eng.streaming && done >= n;
        let stopped = run.held || emergency || finished || starved;
        let moving = matches!(b.kind, Kind::Move { .. }) && !stopped;

        // Axes: interpolate from the previous block's end point to this one's.
        let axes = &mut profile.paths[i].axes;
        let mut dist2 = 0.0;
        for (j, ax) in axes.iter_mut().enumerate() {
            let Some(base) = eng.base_axes.get(j) else {
                continue;
            };
            let start = plan.pass_start(j, pass, base[0]);
            let from = before.map_or(start, |p| p.end[j].at(start));
            let to = b.end[j].at(start);
            let cur = if matches!(b.kind, Kind::Move { .. }) {
                from + ((to - from) as f64 * frac.clamp(0.0, 1.0)).round() as i64
            } else {
                to
            };
            let mm = (to - from) as f64 / plan.scale[j];
            dist2 += mm * mm;
            // The motor turns while the axis moves: its feed over the lead.
            ax.servo_speed = if moving {
                let lead = ax.lead.unwrap_or(DEFAULT_LEAD);
                (mm.abs() * 60.0 / plan.block_seconds / lead).round() as i32
            } else {
                0
            };
            let clamp = |v: i64| v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32;
            ax.absolute = clamp(cur);
            ax.machine = clamp(cur + base[1] - base[0]);
            ax.relative = clamp(cur + base[2] - base[0]);
            ax.distance = if finished { 0 } else { clamp(to - cur) };
        }

        // Modal codes, feed and spindle: inherited from the previous pass
        // (or the programs before, the profile) until the program sets them.
        let earlier = if pass > 0 {
            last.modal.or(eng.modal_before)
        } else {
            eng.modal_before
        };
        run.modal = b.modal.or(earlier);
        let feed = run.modal.aux_value(modal::F).unwrap_or(0);
        run.feed = match b.kind {
            _ if !moving => 0,
            Kind::Move { rapid: false } => feed,
            _ => (dist2.sqrt() * 60.0 / plan.block_seconds).round() as i32,
        };
        let base_speed = eng.base_spindles.first().copied().unwrap_or(0);
        let prev_on = if pass > 0 { last.spin } else { None };
        let s = run.modal.aux_value(modal::S).unwrap_or(base_speed);
        let on = b.spin.or(prev_on).unwrap_or(base_speed != 0);
        run.spindle_speed = if on && !emergency { s } else { 0 };
        profile.paths[i].feed = run.feed;
        // Loads follow the work: the profile's servo load while moving, a
        // third of it at rest; the spindle's load while it turns.
        let spindle_on = run.spindle_speed != 0;
        if let Some(sp) = profile.paths[i].spindles.first_mut() {
            sp.speed = run.spindle_speed;
            sp.load = if spindle_on { eng.base_spindle_load } else { 0 };
        }
        for (ax, base) in profile.paths[i].axes.iter_mut().zip(&eng.base_loads) {
            ax.servo_load = if moving { *base } else { *base / 3 };
        }

        // Block, counters, text.
        run.seq = b.seq;
        run.block = b.line;
        run.finished = finished;
        run.block_count = i32::try_from(if plan.repeat { done } else { done.min(n) })
            .unwrap_or(i32::MAX)
            .saturating_add(eng.blocks_before);
        let ends_before = plan.blocks[..k].iter().filter(|x| x.end_of_program).count() as i64;
        run.runs_done = if finished { 1 } else { pass };
        run.run_seconds = n as f64 * plan.block_seconds;
        // Timers: the program clock (holds stopped it) and the waits of a
        // DNC program for data; cutting, the feed moves run so far.
        let bs = plan.block_seconds;
        let operating = if finished { run.run_seconds } else { tp } + eng.waited;
        let feeding = matches!(b.kind, Kind::Move { rapid: false });
        let moves = |k: usize| f64::from(plan.feed_moves[k]);
        let cutting = (pass as f64 * moves(plan.blocks.len()) + moves(k)) * bs
            + if feeding {
                frac.clamp(0.0, 1.0) * bs
            } else {
                0.0
            };
        run.operating = eng.op_before + operating;
        run.cutting = eng.cut_before + cutting;
        run.cycle = if plan.repeat {
            tp - pass as f64 * run.run_seconds
        } else {
            operating
        };
        run.parts = eng.parts_before
            + if finished {
                plan.parts_per_pass
            } else {
                (pass as i64).saturating_mul(plan.parts_per_pass) + ends_before
            };
        if eng.text_line != Some(b.line) {
            eng.text_line = Some(b.line);
            run.exec_text = b.text.clone();
        }

        // Status words.
        if emergency || finished {
            st.run = 0;
            st.motion = 0;
        } else if run.held {
            st.run = 2;
            st.motion = 0;
        } else if starved {
            st.run = 3;
            st.motion = 0;
        } else {
            st.run = 3;
            st.motion = match b.kind {
                Kind::Move { .. } => 1,
                Kind::Dwell => 2,
                Kind::Still => 0,
            };
        }
        profile.paths[i].status = st;
    }
}

impl Machine {
    /// What the CNC pushes for an upload request (0x1501): the stored
    /// programs of the O-number range ("O`<s>`-O`<e>`") or of the name
    /// ("N:`<name>`": a program's name, "O`<number>`" or the last part of its
    /// path name) as a CNC punches them. Errors (the CNC's error frame; a
    /// real CNC's codes are not known): data type other than 0 (NC
    /// program) EW_ATTRIB, no such path EW_PATH, a range with start > end
    /// EW_NUMBER, no program found or a name not understood EW_DATA.
    pub fn upload_text(
        &self,
        req: &crate::proto::upload::StartReq,
    ) -> super::service::Reply<Vec<u8>> {
        use super::service::CncError;
        use crate::ew::{EW_ATTRIB, EW_DATA};
        if req.dtype != 0 {
            return Err(CncError::new(EW_ATTRIB));
        }
        if req.path == 0 || usize::from(req.path) > self.profile.paths.len() {
            return Err(CncError::PATH);
        }
        let progs = self.store.iter(req.path);
        let start = req.start_text();
        let found: Vec<&Program> = if let Some(name) = start.strip_prefix("N:") {
            progs
                .filter(|p| !name.is_empty() && p.answers_to(name, req.path))
                .collect()
        } else {
            let (s, e) = req.range().ok_or(CncError::new(EW_DATA))?;
            if s > e {
                return Err(CncError::NUMBER);
            }
            progs
                .filter(|p| (s..=e).contains(&i64::from(p.number)))
                .collect()
        };
        if found.is_empty() {
            return Err(CncError::new(EW_DATA));
        }
        Ok(crate::proto::upload::punch(found.iter().map(|p| &*p.text)))
    }
}

/// The mode select signals of G43 for cnc_statinfo's `aut` (FANUC's mode
/// table: MD1 bit 0, MD2 bit 1, MD4 bit 2, DNCI bit 5, ZRN bit 7): MDI 000,
/// MEMORY 001, EDIT 011, HANDLE and INC 100, JOG 101, TEACH IN JOG 110,
/// TEACH IN HANDLE 111, REFERENCE = JOG + ZRN, REMOTE (DNC) = MEMORY + DNCI.
fn mode_signals(aut: i16) -> u8 {
    match aut {
        1 => 0b001,
        3 => 0b011,
        4 | 8 => 0b100,
        5 => 0b101,
        6 => 0b110,
        7 => 0b111,
        9 => 0b101 | 0x80,
        10 => 0b001 | 0x20,
        _ => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn raised_at(m: &mut Machine, t: f64) -> Vec<(u16, i32, f64)> {
        let mut v = Vec::new();
        m.advance_path(0, t, &mut v);
        v.into_iter()
            .map(|(p, a, d)| (p, a.number, d.as_secs_f64()))
            .collect()
    }

    #[test]
    fn the_alarm_hook_sees_every_occurrence_once() {
        let mut p = Profile::default();
        let ev = p.events[0].alarm.as_ref().expect("an alarm event").number;
        p.paths[0].alarms.push(Alarm {
            number: 9001,
            ..Alarm::default()
        });
        let mut m = Machine::new(p);
        // The profile's alarm at the first advance; the event (30 s, every 60 s) later.
        assert_eq!(raised_at(&mut m, 1.0), vec![(1, 9001, 0.0)]);
        assert_eq!(raised_at(&mut m, 29.0), vec![]);
        assert_eq!(raised_at(&mut m, 31.0), vec![(1, ev, 30.0)]);
        assert_eq!(raised_at(&mut m, 35.0), vec![]);
        // A long pause: the occurrences in between, in order.
        assert_eq!(
            raised_at(&mut m, 215.0),
            vec![(1, ev, 90.0), (1, ev, 150.0), (1, ev, 210.0)]
        );
        assert_eq!(raised_at(&mut m, 215.0), vec![]);
    }
}
