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
use crate::ew::{EW_DATA, EW_NOPMC, EW_REJECT};
use crate::proto::cmd::{
    CLRALM, RDOPNLGNRL, RDOPNLGSNAME, RDOPNLSGNL, RESET, RESET2, START, WROPNLGNRL, WROPNLGSNAME,
    WROPNLSGNL,
};
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
    Route::table(WROPNLSGNL, write_panel_signals),
    Route::table(RDOPNLGNRL, |m, q| {
        let f = (m.pmc().area(1)).and_then(|a| a.bytes(GENERAL_F, 1));
        let f = f.ok_or(CncError::new(EW_NOPMC))?[0];
        Ok(vec![i64::from(q.arg(0)), 0, i64::from(f as i8)])
    }),
    Route::table(WROPNLGNRL, |m, q| {
        let select = q.arg(0) as u8;
        let on = q.payload.first().copied().unwrap_or(0) as u8;
        let f = general_switches(m)?;
        *f = *f & !select | on & select;
        Ok(Vec::new())
    }),
    Route::table(RDOPNLGSNAME, switch_names),
    Route::table(WROPNLGSNAME, write_switch_names),
];

/// F-area bytes of the software operator panel's output signals: F0073
/// (mode MD1O/MD2O/MD4O, ZRNO), F0075 (BDTO, SBKO, MLKO, DRNO, KEYO, SPO
/// at bits 2..=7), F0076 (MP1O/MP2O at bits 0..=1, ROV1O/ROV2O at bits
/// 4..=5), F0077 (handle axis HS1AO..HS1DO), F0078 (feed override
/// *FV0O..*FV7O), F0079..F0080 (jog override *JV0O..*JV15O).
const PANEL_F: (u16, u16) = (73, 80);

/// Where each word of IODBSGNL after `type` lives in the F area, in order
/// (`mode` .. `feed_hold`, the bits of cnc_wropnlsgnl's `type`): the
/// address of its low byte, the mask of its bits in the little-endian
/// 16-bit word from there, and the shift of its lowest bit. `None`: the
/// spindle override, FANUC's "not used", which no signal feeds.
const PANEL: [Option<(u16, u16, u32)>; 13] = [
    Some((73, 0x17, 0)),   // mode: MD1O, MD2O, MD4O, ZRNO
    Some((77, 0x0f, 0)),   // hndl_ax: HS1AO..HS1DO
    Some((76, 0x03, 0)),   // hndl_mv: MP1O, MP2O
    Some((76, 0x30, 4)),   // rpd_ovrd: ROV1O, ROV2O
    Some((79, 0xffff, 0)), // jog_ovrd: *JV0O..*JV15O
    Some((78, 0xff, 0)),   // feed_ovrd: *FV0O..*FV7O
    None,                  // spdl_ovrd
    Some((75, 0x04, 2)),   // blck_del: BDTO
    Some((75, 0x08, 3)),   // sngl_blck: SBKO
    Some((75, 0x10, 4)),   // machn_lock: MLKO
    Some((75, 0x20, 5)),   // dry_run: DRNO
    Some((75, 0x40, 6)),   // mem_prtct: KEYO
    Some((75, 0x80, 7)),   // feed_hold: SPO
];

/// The panel's F bytes (`PANEL_F`) of PMC unit 1; an absent area reads as
/// zeros.
fn panel_bytes(m: &Machine) -> Vec<u8> {
    let (s, e) = PANEL_F;
    let n = usize::from(e - s + 1);
    (m.profile.pmc.area(1))
        .and_then(|a| a.bytes(s, n))
        .map_or(vec![0; n], <[u8]>::to_vec)
}

/// The little-endian word of `f` (the panel's bytes) from F `addr` on.
fn panel_word(f: &[u8], addr: u16) -> u16 {
    let at = |a: u16| {
        let i = usize::from(a.wrapping_sub(PANEL_F.0));
        u16::from(f.get(i).copied().unwrap_or(0))
    };
    at(addr) | at(addr + 1) << 8
}

/// cnc_rdopnlsgnl: the panel's signals as the ladder (or cnc_wropnlsgnl)
/// set them in the F area of PMC unit 1, after `type`, which FANUC's
/// library writes back (not on the wire).
fn panel_signals(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let f = panel_bytes(m);
    let mut v = vec![i64::from(q.arg(0))];
    v.extend(PANEL.iter().map(|p| match *p {
        // The jog override's 16 bits are the short's.
        Some((addr, 0xffff, _)) => i64::from(panel_word(&f, addr) as i16),
        Some((addr, mask, shift)) => i64::from((panel_word(&f, addr) & mask) >> shift),
        None => 0,
    }));
    Ok(v)
}

/// cnc_wropnlsgnl: the signals `type` selects (bit k, the k-th word after
/// `type`) set in the F area as cnc_rdopnlsgnl reads them back. A value
/// its bits cannot hold is EW_DATA, nothing written; without an F area
/// EW_NOPMC.
fn write_panel_signals(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let select = q.arg(0);
    let (s, _) = PANEL_F;
    let mut f = panel_bytes(m);
    for (k, p) in PANEL.iter().enumerate() {
        let (Some((addr, mask, shift)), Some(&v)) = (p, q.payload.get(k)) else {
            continue;
        };
        if select >> k & 1 == 0 {
            continue;
        }
        let bits = if *mask == 0xffff {
            v as u16
        } else {
            match u16::try_from(v) {
                Ok(v) if v << shift & !mask == 0 && v <= mask >> shift => v << shift,
                _ => return Err(CncError::new(EW_DATA)),
            }
        };
        let word = panel_word(&f, *addr) & !mask | bits;
        for (i, b) in word.to_le_bytes().into_iter().enumerate() {
            if let Some(x) = f.get_mut(usize::from(addr - s) + i) {
                *x = b;
            }
        }
    }
    let area = (m.pmc_mut().area_mut(1)).ok_or(CncError::new(EW_NOPMC))?;
    let n = f.len();
    let bytes = area.bytes_mut(s, n).ok_or(CncError::new(EW_NOPMC))?;
    bytes.copy_from_slice(&f);
    Ok(Vec::new())
}

/// F0072, the byte before the panel's other signals: the software
/// operator panel's general purpose switches OUT0 .. OUT7 (cnc_rdopnlgnrl,
/// cnc_wropnlgnrl): bit k is switch k + 1.
const GENERAL_F: u16 = PANEL_F.0 - 1;

/// The general purpose switches' F byte of PMC unit 1 (EW_NOPMC without
/// an F area holding it).
fn general_switches(m: &mut Machine) -> Reply<&mut u8> {
    let f = (m.pmc_mut().area_mut(1)).and_then(|a| a.bytes_mut(GENERAL_F, 1));
    f.map(|b| &mut b[0]).ok_or(CncError::new(EW_NOPMC))
}

/// The general purpose switches, as many as IODBRDNA2 names (IODBRDNA
/// the first 8), and the characters of a name.
const SWITCHES: usize = 16;
const NAME: usize = 8;

/// cnc_rdopnlgsname, cnc_rdopnlgsname2: `type` (written back), then each
/// of the 16 switches' names, 8 bytes zero-padded, and the NUL FANUC's
/// library writes after it (not on the wire); cnc_rdopnlgsname reads the
/// first 8.
fn switch_names(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let names = &m.profile.operator_panel.switch_names;
    let mut v = vec![i64::from(q.arg(0))];
    for k in 0..SWITCHES {
        // One byte a character (Latin-1, as the write stores them).
        let name: Vec<u8> = names
            .get(k)
            .map_or(Vec::new(), |s| s.chars().map(|c| c as u32 as u8).collect());
        v.extend((0..NAME).map(|i| i64::from(name.get(i).copied().unwrap_or(0) as i8)));
        v.push(0);
    }
    Ok(v)
}

/// cnc_wropnlgsname (8 names), cnc_wropnlgsname2 (16): the names `type`
/// selects (bit k: switch k + 1) from the payload's 8 bytes each, up to
/// the first NUL; switches before a named one stay unnamed.
fn write_switch_names(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let select = q.arg(0);
    // The bytes as sent: the two writes share the command, and their
    // payloads (8 or 16 names) one layout.
    if q.bytes.len() < 8 * NAME {
        return Err(CncError::new(EW_DATA));
    }
    let names = &mut m.profile.operator_panel.switch_names;
    for (k, b) in q.bytes.chunks_exact(NAME).enumerate().take(SWITCHES) {
        if select >> k & 1 == 0 {
            continue;
        }
        if names.len() <= k {
            names.resize(k + 1, String::new());
        }
        // Each byte kept as one character (Latin-1).
        let bytes = b.iter().copied().take_while(|&c| c != 0);
        names[k] = bytes.map(char::from).collect();
    }
    Ok(Vec::new())
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
            multi_piece: p.cycle.multi_piece,
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
            multi_piece: p.cycle.multi_piece,
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
