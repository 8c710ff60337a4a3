//! Operating the simulated machine through FOCAS: cycle start runs the
//! selected main program from that moment, reset stops it and clears the
//! reset-clearable alarms, cnc_clralm clears alarms of one type. The
//! running machine (src/sim/clock.rs) then moves the axes, the spindle and
//! the counters from the program, as for the profile's own cycle.

use super::Machine;
use super::plan::Plan;
use super::profile::cycle::Cycle;
use super::route::{Asked, Route, none};
use super::run::{covered, event_path, occurrence};
use super::service::{CncError, Reply};
use crate::ew::{EW_DATA, EW_REJECT};
use crate::proto::cmd::{CLRALM, RDOPNLSGNL, RESET, RESET2, START};
use crate::proto::machine::RDPRSTR;
use std::sync::Arc;

pub(super) const ROUTES: &[Route] = &[
    Route::table(START, |m, q| none(m.cycle_start(q.path))),
    Route::table(RESET, |m, q| none(m.reset(q.path))),
    Route::table(RESET2, |m, q| none(m.reset(q.path))),
    Route::table(CLRALM, |m, q| none(m.clear_alarms(q.path, q.arg(0) as i16))),
    // [k]: the program restart data a reset or cycle start recorded.
    Route::cnc(RDPRSTR, |m, q| m.restart_info(q.path, q.args[0])),
    Route::table(RDOPNLSGNL, panel_signals),
];

/// F-area bytes of the software operator panel's output signals: F0073
/// (mode MD1O/MD2O/MD4O, ZRNO), F0075 (BDTO, SBKO, MLKO, DRNO, KEYO, SPO
/// at bits 2..=7), F0076 (MP1O/MP2O at bits 0..=1, ROV1O/ROV2O at bits
/// 4..=5), F0077 (handle axis HS1AO..HS1DO), F0078 (feed override
/// *FV0O..*FV7O), F0079..F0080 (jog override *JV0O..*JV15O).
const PANEL_F: (u16, u16) = (73, 80);

/// cnc_rdopnlsgnl: the panel's signals as the ladder set them in the F
/// area of PMC unit 1 (an absent area reads as zeros), after `type`,
/// which FANUC's library writes back (not on the wire). The spindle
/// override word is FANUC's "not used": no signal feeds it.
fn panel_signals(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    use crate::proto::pmc::PmcRange;
    let (s, e) = PANEL_F;
    let range = PmcRange {
        adr_type: 1,
        data_type: 0,
        s,
        e,
    };
    let n = usize::from(e - s + 1);
    let f = m.profile.pmc.read(1, &range).unwrap_or(vec![0; n]);
    let byte = |addr: u16| i64::from(f[usize::from(addr - s)]);
    let bit = |addr: u16, b: u32| (byte(addr) >> b) & 1;
    Ok(vec![
        i64::from(q.arg(0)),
        byte(73) & 0x17,
        byte(77) & 0x0f,
        byte(76) & 0x03,
        (byte(76) >> 4) & 0x03,
        i64::from((byte(79) | byte(80) << 8) as u16 as i16),
        byte(78),
        0,
        bit(75, 2),
        bit(75, 3),
        bit(75, 4),
        bit(75, 5),
        bit(75, 6),
        bit(75, 7),
    ])
}

/// Alarm types a reset clears (IO, PS, macro); the others need the cause
/// removed (overtravel, servo, overheat ...) or the power cycled.
const RESET_CLEARS: [i16; 3] = [2, 3, 8];

impl Machine {
    /// Seconds since the simulator started, at the last advance.
    fn elapsed(&self) -> f64 {
        self.now
            .saturating_duration_since(self.started)
            .as_secs_f64()
    }

    /// Ends the path's plan where it is: the axes, the modal codes stay,
    /// the counters and timers keep what it made, the status shows the
    /// path stopped.
    fn stop_plan(&mut self, i: usize) {
        let path = &self.profile.paths[i];
        let run = &mut self.run[i];
        // A program interrupted where it runs: its program restart data.
        if let Some(plan) = &run.engine.plan
            && !run.finished
        {
            let k = plan.blocks.iter().position(|b| b.line == run.block);
            run.restart = Some(super::run::Restart {
                block: k.map_or(0, |k| k as i32 + 1),
                modal: run.modal,
                dest: path.axes.iter().map(|a| a.absolute).collect(),
            });
        }
        let eng = &mut run.engine;
        eng.plan = None;
        eng.parts_before = run.parts;
        eng.blocks_before = run.block_count;
        eng.modal_before = run.modal;
        eng.op_before = run.operating;
        eng.cut_before = run.cutting;
        eng.waited = 0.0;
        eng.base_axes = path
            .axes
            .iter()
            .map(|a| [a.absolute, a.machine, a.relative].map(i64::from))
            .collect();
        eng.base_status.run = 0;
        eng.base_status.motion = 0;
        run.feed = 0;
        run.finished = true;
    }

    /// cnc_start: cycle start on `path`. The selected main program runs
    /// once from now. Refused (EW_REJECT) unless the path is in MEMORY
    /// mode, without alarm or emergency stop; a path already running
    /// goes on (a CNC ignores cycle start then); no main program is EW_DATA.
    pub(crate) fn cycle_start(&mut self, path: u16) -> Reply<()> {
        let i = usize::from(path).wrapping_sub(1);
        let st = self.profile.paths.get(i).ok_or(CncError::PATH)?.status;
        if st.aut != 1 || st.alarm != 0 || st.emergency != 0 {
            return Err(CncError::new(EW_REJECT));
        }
        if st.run == 3 {
            return Ok(());
        }
        let main = self.store.path(path)?.main;
        let prog = self.store.get(path, main).ok_or(CncError::new(EW_DATA))?;
        let (text, name) = (prog.text.clone(), prog.display_name());
        self.stop_plan(i);
        let t = self.elapsed();
        let p = &self.profile.paths[i];
        let cycle = Cycle {
            program: main,
            block_seconds: p.cycle.block_seconds,
            repeat: false,
        };
        let plan = Arc::new(Plan::parse(&text, &p.axes, &cycle));
        let held0 = self.held_before(i, t);
        let run = &mut self.run[i];
        run.engine.plan = Some(plan);
        run.engine.t0 = t;
        run.engine.held0 = held0;
        run.engine.base_status.run = 3;
        run.program = main;
        run.program_name = name;
        run.finished = false;
        self.record_press(i, 0, 7, 0x04);
        let now = self.now;
        self.advance_to(now);
        Ok(())
    }

    /// The panel signal a FOCAS command stands for goes into the operation
    /// history as pressed [ours]: bit `bit` of PMC byte `byte` of address
    /// type `adr_type` (unit 1, path n's byte 1000·(n−1) further) from its
    /// value to the value with the bit set. Cycle start: ST (G7.2); reset:
    /// RST (F1.1).
    fn record_press(&mut self, i: usize, adr_type: i16, byte: u16, bit: u8) {
        let byte = byte + 1000 * i as u16;
        let r = crate::proto::pmc::PmcRange {
            adr_type,
            data_type: 0,
            s: byte,
            e: byte,
        };
        let old = self
            .profile
            .pmc
            .read(1, &r)
            .ok()
            .and_then(|v| v.first().copied());
        let old = old.unwrap_or(0);
        self.record_signal(adr_type, i32::from(byte), old, old | bit);
    }

    /// cnc_reset: stops the path's program and clears its reset-clearable
    /// alarms (the profile's and the events' raised so far).
    pub(crate) fn reset(&mut self, path: u16) -> Reply<()> {
        let i = usize::from(path).wrapping_sub(1);
        if i >= self.run.len() {
            return Err(CncError::PATH);
        }
        if self.run[i].engine.plan.is_some() {
            self.stop_plan(i);
        }
        self.record_press(i, 1, 1, 0x02);
        for k in RESET_CLEARS {
            self.clear_alarms(path, k)?;
        }
        Ok(())
    }

    /// cnc_clralm: clears the alarms of type `kind` active on `path`.
    pub(crate) fn clear_alarms(&mut self, path: u16, kind: i16) -> Reply<()> {
        let i = usize::from(path).wrapping_sub(1);
        if i >= self.run.len() {
            return Err(CncError::PATH);
        }
        let t = self.elapsed();
        let eng = &mut self.run[i].engine;
        if !eng.cleared_types.contains(&kind) {
            eng.cleared_types.push(kind);
        }
        for (k, e) in self.profile.events.iter().enumerate() {
            let ours = event_path(e) == i && e.alarm.as_ref().is_some_and(|a| a.kind == kind);
            if ours && let Some(slot) = eng.cleared.get_mut(k) {
                *slot = occurrence(e, t).or(*slot);
            }
        }
        let now = self.now;
        self.advance_to(now);
        Ok(())
    }
}

impl Machine {
    /// A DNC operation on `path`: `text` is what has arrived so far, `done`
    /// once the client ended it. The program runs from its first block as
    /// it arrives, waiting at the last block received (status STRT, no
    /// motion) until more comes; it is not stored. Refused: an active alarm
    /// or emergency stop EW_REJECT, a block that is not address words EW_DATA.
    pub(crate) fn dnc(&mut self, path: u16, text: &[u8], done: bool) -> Reply<()> {
        let i = usize::from(path).wrapping_sub(1);
        let st = self.profile.paths.get(i).ok_or(CncError::PATH)?.status;
        // Complete lines only, until the end.
        let upto = if done {
            text.len()
        } else {
            text.iter().rposition(|&c| c == b'\n').map_or(0, |p| p + 1)
        };
        let progs = super::download::programs(&text[..upto])?;
        let body = progs.join("\n");
        let t = self.elapsed();
        let eng = &self.run[i].engine;
        if !eng.streaming {
            if st.alarm != 0 || st.emergency != 0 {
                return Err(CncError::new(EW_REJECT));
            }
            self.stop_plan(i);
            let held0 = self.held_before(i, t);
            let run = &mut self.run[i];
            run.engine.t0 = t;
            run.engine.held0 = held0;
            run.engine.streaming = true;
            run.engine.base_status.run = 3;
            run.finished = false;
            run.program_name = "DNC".into();
        }
        let p = &self.profile.paths[i];
        let cycle = Cycle {
            program: 0,
            block_seconds: p.cycle.block_seconds,
            repeat: false,
        };
        let plan = Plan::parse(&body, &p.axes, &cycle);
        let first = body.lines().next().unwrap_or("");
        let run = &mut self.run[i];
        // A program that waited for data goes on from where it waited.
        if let Some(old) = &run.engine.plan {
            let bs = old.block_seconds();
            let waited = (t - run.engine.t0) - old.len() as f64 * bs;
            if waited > 0.0 && plan.len() > old.len() {
                run.engine.t0 += waited;
                run.engine.waited += waited;
            }
        }
        run.program = super::store::Program::new(first, [0; 5]).number;
        run.engine.plan = Some(Arc::new(plan));
        run.engine.streaming = !done;
        let now = self.now;
        self.advance_to(now);
        Ok(())
    }

    /// Seconds the path was held (feed hold, emergency) before `t`.
    fn held_before(&self, i: usize, t: f64) -> f64 {
        let stops: Vec<_> = self
            .profile
            .events
            .iter()
            .filter(|e| event_path(e) == i)
            .filter(|e| e.action == "feed_hold" || e.action == "emergency")
            .collect();
        covered(&stops, 0.0, t)
    }
}

impl Machine {
    /// 0x0043 [k] (cnc_rdprstrinfo): the program restart data of the last
    /// interruption, k 0 the block counter, 1 the M code, 2 the T code, 3
    /// the S code, 4 the B code, each a big-endian i32 when there is one;
    /// before any interruption, nothing.
    pub(crate) fn restart_info(&mut self, path: u16, k: i32) -> Reply<Vec<u8>> {
        let run = self.live(path)?;
        let Some(r) = &run.restart else {
            return if (0..=4).contains(&k) {
                Ok(Vec::new())
            } else {
                Err(CncError::NUMBER)
            };
        };
        // cnc_modal's types 100 + k: 0 B, 6 M, 7 S, 8 T.
        let v = match k {
            0 => Some(r.block),
            1 => r.modal.aux_value(6),
            2 => r.modal.aux_value(8),
            3 => r.modal.aux_value(7),
            4 => r.modal.aux_value(0),
            _ => return Err(CncError::NUMBER),
        };
        Ok(v.map(|v| v.to_be_bytes().to_vec()).unwrap_or_default())
    }
}
