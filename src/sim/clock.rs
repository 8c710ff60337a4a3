//! The machine's clock: brings the live state of every path
//! (src/sim/run.rs) up to an instant, as a pure function of the time since
//! the simulator started; called once per request frame (the
//! `CncService::advance` hook) and by the operations that change it.

use super::Machine;
use super::modal;
use super::plan::{Block, Kind, Plan};
use super::run::{
    Alarm, DEFAULT_LEAD, Engine, Event, PathRun, active, covered, event_path, occurrence,
};
use std::time::{Duration, Instant};

/// The parameter a FANUC CNC counts machined parts in.
const PART_COUNT_PARAM: i32 = 6711;

/// Missed alarm occurrences reported at most per event when a poller
/// comes back after a long pause.
const MAX_CATCH_UP: u64 = 64;

impl Machine {
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

    /// Brings path `i` up to `t` seconds: its alarms and stops from the
    /// events, then (with a program in cycle) where the program is and
    /// what that makes of axes, feed, spindle, counters and timers.
    fn advance_path(&mut self, i: usize, t: f64, raised: &mut Vec<(u16, Alarm, Duration)>) {
        let profile = &mut self.profile;
        let run = &mut self.run[i];
        let mine: Vec<(usize, &Event)> = profile
            .events
            .iter()
            .enumerate()
            .filter(|(_, e)| event_path(e) == i)
            .collect();
        let now = events_at(
            &mine,
            &profile.paths[i].alarms,
            &mut run.engine,
            i,
            t,
            raised,
        );
        let mut st = run.engine.base_status;
        if !now.alarms.is_empty() {
            st.alarm = 1;
        }
        if now.emergency {
            st.emergency = 1;
        }
        if let Some(m) = now.mode {
            st.aut = m;
        }
        run.alarms = now.alarms;
        run.held = now.hold && !now.emergency;
        let path = &mut profile.paths[i];
        let Some(plan) = run.engine.plan.clone() else {
            run.operating = run.engine.op_before;
            run.cutting = run.engine.cut_before;
            if run.held {
                st.run = 2;
                st.motion = 0;
            }
            if now.emergency {
                st.run = 0;
                st.motion = 0;
            }
            path.status = st;
            return;
        };
        let tp = program_seconds(&mine, &mut run.engine, t);
        let Some(at) = Place::of(&plan, &run.engine, tp) else {
            path.status = st;
            return;
        };
        let b = &plan.blocks[at.k];
        let stopped = run.held || now.emergency || at.finished || at.starved;
        let moving = matches!(b.kind, Kind::Move { .. }) && !stopped;
        // The last macro message passed: in this pass, else the pass before.
        let shown = |bs: &[Block]| bs.iter().rev().find_map(|b| b.message.clone());
        run.message = shown(&plan.blocks[..=at.k]).or_else(|| {
            if at.pass > 0 {
                shown(&plan.blocks)
            } else {
                None
            }
        });
        let dist2 = move_axes(path, &run.engine, &plan, &at, moving);
        in_motion(path, run, &plan, &at, moving, now.emergency, dist2);
        count(run, &plan, &at);
        // Status words.
        if now.emergency || at.finished {
            st.run = 0;
            st.motion = 0;
        } else if run.held {
            st.run = 2;
            st.motion = 0;
        } else if at.starved {
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
        path.status = st;
    }
}

/// What a path's events make of it at an instant.
struct EventsNow {
    /// The active alarms: the profile's (less those cleared), the events'.
    alarms: Vec<Alarm>,
    hold: bool,
    emergency: bool,
    /// The mode an event selects.
    mode: Option<i16>,
}

/// The path's events (`mine`, with their index in the profile) at `t`:
/// the alarms, stops and mode active; the alarms raised since the last
/// call (the profile's own at the first) go into `raised`.
fn events_at(
    mine: &[(usize, &Event)],
    own: &[Alarm],
    eng: &mut Engine,
    i: usize,
    t: f64,
    raised: &mut Vec<(u16, Alarm, Duration)>,
) -> EventsNow {
    let path_no = i as u16 + 1;
    if !eng.initial_reported {
        eng.initial_reported = true;
        for a in own {
            raised.push((path_no, a.clone(), Duration::ZERO));
        }
    }
    let mut alarms = own.to_vec();
    alarms.retain(|a| !eng.cleared_types.contains(&a.kind));
    let mut now = EventsNow {
        alarms,
        hold: false,
        emergency: false,
        mode: None,
    };
    for (k, e) in mine {
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
            "alarm" => now.alarms.extend(e.alarm.clone()),
            "feed_hold" => now.hold = true,
            "emergency" => now.emergency = true,
            "mode" => now.mode = Some(e.value as i16),
            _ => {}
        }
    }
    now
}

/// The program clock at `t`: elapsed time since the plan started less the
/// time held (feed hold, emergency stop), memoised so each frame only
/// sweeps its own span.
fn program_seconds(mine: &[(usize, &Event)], eng: &mut Engine, t: f64) -> f64 {
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
    (t - eng.t0 - (held - eng.held0)).max(0.0)
}

/// Where a plan is after `tp` seconds of program time.
struct Place {
    /// Program time.
    tp: f64,
    /// Blocks done since the plan started, passes completed, the current
    /// block and the fraction of it done.
    done: u64,
    pass: u64,
    k: usize,
    frac: f64,
    /// The program ended and does not repeat.
    finished: bool,
    /// A DNC program waits at its last block for more data.
    starved: bool,
}

impl Place {
    /// None for a plan without blocks.
    fn of(plan: &Plan, eng: &Engine, tp: f64) -> Option<Place> {
        let n = plan.blocks.len() as u64;
        if n == 0 {
            return None;
        }
        let done = (tp / plan.block_seconds).floor() as u64;
        let frac = tp / plan.block_seconds - done as f64;
        let (pass, k, frac, finished) = if plan.repeat {
            (done / n, (done % n) as usize, frac, false)
        } else if done >= n {
            // A DNC program waits at its last block for more (not finished).
            (0, n as usize - 1, 1.0, !eng.streaming)
        } else {
            (0, done as usize, frac, false)
        };
        Some(Place {
            tp,
            done,
            pass,
            k,
            frac,
            finished,
            starved: eng.streaming && done >= n,
        })
    }
}

/// The axes of the path at `at`: interpolated from the previous block's
/// end point to this one's; the motor speeds while moving. Answers the
/// square of the block's move length (mm²).
fn move_axes(
    path: &mut super::profile::Path,
    eng: &Engine,
    plan: &Plan,
    at: &Place,
    moving: bool,
) -> f64 {
    let b = &plan.blocks[at.k];
    let before = (at.k > 0).then(|| &plan.blocks[at.k - 1]);
    let mut dist2 = 0.0;
    for (j, ax) in path.axes.iter_mut().enumerate() {
        let Some(base) = eng.base_axes.get(j) else {
            continue;
        };
        let start = plan.pass_start(j, at.pass, base[0]);
        let from = before.map_or(start, |p| p.end[j].at(start));
        let to = b.end[j].at(start);
        let cur = if matches!(b.kind, Kind::Move { .. }) {
            from + ((to - from) as f64 * at.frac.clamp(0.0, 1.0)).round() as i64
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
        ax.distance = if at.finished { 0 } else { clamp(to - cur) };
    }
    dist2
}

/// Modal codes, feed, spindle speed and loads at `at`: inherited from the
/// previous pass (or the programs before, the profile) until the program
/// sets them.
fn in_motion(
    path: &mut super::profile::Path,
    run: &mut PathRun,
    plan: &Plan,
    at: &Place,
    moving: bool,
    emergency: bool,
    dist2: f64,
) {
    let eng = &run.engine;
    let b = &plan.blocks[at.k];
    let last = plan.blocks.last().expect("a plan with blocks");
    let earlier = if at.pass > 0 {
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
    let prev_on = if at.pass > 0 { last.spin } else { None };
    let s = run.modal.aux_value(modal::S).unwrap_or(base_speed);
    let on = b.spin.or(prev_on).unwrap_or(base_speed != 0);
    run.spindle_speed = if on && !emergency { s } else { 0 };
    path.feed = run.feed;
    // Loads follow the work: the profile's servo load while moving, a
    // third of it at rest; the spindle's load while it turns.
    let spindle_on = run.spindle_speed != 0;
    if let Some(sp) = path.spindles.first_mut() {
        sp.speed = run.spindle_speed;
        sp.load = if spindle_on { eng.base_spindle_load } else { 0 };
    }
    for (ax, base) in path.axes.iter_mut().zip(&eng.base_loads) {
        ax.servo_load = if moving { *base } else { *base / 3 };
    }
}

/// The block, counters (blocks, runs, parts), timers and text at `at`.
fn count(run: &mut PathRun, plan: &Plan, at: &Place) {
    let b = &plan.blocks[at.k];
    let n = plan.blocks.len() as u64;
    let (pass, finished) = (at.pass, at.finished);
    run.seq = b.seq;
    run.block = b.line;
    run.finished = finished;
    run.block_count = i32::try_from(if plan.repeat { at.done } else { at.done.min(n) })
        .unwrap_or(i32::MAX)
        .saturating_add(run.engine.blocks_before);
    let ends_before = plan.blocks[..at.k]
        .iter()
        .filter(|x| x.end_of_program)
        .count() as i64;
    run.runs_done = if finished { 1 } else { pass };
    run.run_seconds = n as f64 * plan.block_seconds;
    // Timers: the program clock (holds stopped it) and the waits of a
    // DNC program for data; cutting, the feed moves run so far.
    let bs = plan.block_seconds;
    let eng = &mut run.engine;
    let operating = if finished { run.run_seconds } else { at.tp } + eng.waited;
    let feeding = matches!(b.kind, Kind::Move { rapid: false });
    let moves = |k: usize| f64::from(plan.feed_moves[k]);
    let cutting = (pass as f64 * moves(plan.blocks.len()) + moves(at.k)) * bs
        + if feeding {
            at.frac.clamp(0.0, 1.0) * bs
        } else {
            0.0
        };
    run.operating = eng.op_before + operating;
    run.cutting = eng.cut_before + cutting;
    run.cycle = if plan.repeat {
        at.tp - pass as f64 * run.run_seconds
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
    use crate::sim::Profile;

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
