//! The CNC's screen and operator state (family A of the long tail): the
//! model, display language, operation and protection levels and menu
//! switches of the profile's `[system]` (the writes change them there),
//! the additional work coordinate systems of the path's offsets, the
//! running program's repeats, and the stopped path's cursor (cnc_rewind,
//! cnc_seqsrch).

use super::Machine;
use super::plan::{EXEC_LINES, Plan};
use super::route::{Route, none};
use super::service::{CncError, Reply};
use crate::ew::{EW_BUSY, EW_DATA};
use crate::proto::cmd;

pub(super) const ROUTES: &[Route] = &[
    Route::table(cmd::GETCNCMODEL, |m, _| {
        Ok(vec![i64::from(m.profile.system.model)])
    }),
    Route::table(cmd::GETLANGUAGE, |m, _| {
        Ok(vec![i64::from(m.profile.system.language)])
    }),
    // A code past the CNC's languages is refused, nothing changed [ours].
    Route::table(cmd::CHGLANG, |m, q| {
        let lang = i16::try_from(q.arg(0))
            .ok()
            .filter(|l| (0..=LANGUAGES).contains(l));
        m.profile.system.language = lang.ok_or(CncError::new(EW_DATA))?;
        Ok(Vec::new())
    }),
    Route::table(cmd::RDOPE_LVL, |m, _| {
        Ok(vec![i64::from(m.profile.system.operation_level)])
    }),
    Route::table(cmd::RDPRT_LVL, |m, q| {
        let [rd, wt] = *protection(m, q.arg(0))?;
        Ok(vec![i64::from(rd), i64::from(wt)])
    }),
    // A level outside 0..=7 is refused, nothing changed [ours].
    Route::table(cmd::WRPRT_LVL, |m, q| {
        let level = |v: i32| i16::try_from(v).ok().filter(|l| (0..=7).contains(l));
        let (rd, wt) = (level(q.arg(1)), level(q.arg(2)));
        let (Some(rd), Some(wt)) = (rd, wt) else {
            protection(m, q.arg(0))?;
            return Err(CncError::new(EW_DATA));
        };
        *protection(m, q.arg(0))? = [rd, wt];
        Ok(Vec::new())
    }),
    Route::table(cmd::RDMENUSWITCH, |m, _| {
        Ok(vec![i64::from(m.profile.system.menu_switch)])
    }),
    Route::table(cmd::WRMENUSWITCH, |m, q| {
        let mask = q.payload.first().copied().unwrap_or(0) as u16;
        let data = q.arg(0) as u16;
        let s = &mut m.profile.system.menu_switch;
        *s = *s & !mask | data & mask;
        Ok(Vec::new())
    }),
    // The work zero offsets past G59 (rows 7..: G54.1 P1..).
    Route::table(cmd::RDCOORDNUM, |m, q| {
        let rows = m.path(q.path)?.offset.work.len();
        Ok(vec![rows.saturating_sub(7) as i64])
    }),
    Route::table(cmd::RDREPEATVAL, |m, q| {
        Ok(vec![m.live(q.path)?.runs_done as i64])
    }),
    // The value records' second words (decimals) are not read: 0.
    Route::table(cmd::RDFIXCYCLE, |m, q| {
        let f = &m.path(q.path)?.fixed_cycle;
        let head = [f.mode, f.plane_axes[0], f.plane_axes[1], f.drill_axis].map(i64::from);
        let values = [
            f.initial, f.r_point, f.z_point, f.cut, f.shift[0], f.shift[1],
        ];
        let values = values.into_iter().flat_map(|v| [i64::from(v), 0]);
        let counts = f.repeats.map(i64::from);
        Ok(head.into_iter().chain(counts).chain(values).collect())
    }),
    Route::table(cmd::REWIND, |m, q| none(m.cursor(q.path, None))),
    Route::table(cmd::SEQSRCH, |m, q| none(m.cursor(q.path, Some(q.arg(0))))),
];

impl Machine {
    /// cnc_rewind (`seq` None) / cnc_seqsrch: the cursor of the path's main
    /// program goes to its top (sequence number 0) or to the first block
    /// numbered N`seq`, as cnc_rdseqnum and cnc_rdexecprog then show; a
    /// path running or held is EW_BUSY, no such number EW_DATA, nothing
    /// changed [ours]. A cycle start still runs the program from its top.
    fn cursor(&mut self, path: u16, seq: Option<i32>) -> Reply<()> {
        let i = usize::from(path).wrapping_sub(1);
        let p = self.profile.paths.get(i).ok_or(CncError::PATH)?;
        if matches!(p.status.run, 2 | 3) {
            return Err(CncError::new(EW_BUSY));
        }
        let main = self.store.path(path)?.main;
        let prog = self.store.get(path, main).ok_or(CncError::new(EW_DATA))?;
        let top = || {
            prog.text
                .lines()
                .take(EXEC_LINES)
                .collect::<Vec<_>>()
                .join("\n")
        };
        let (seq, line, text) = match seq {
            None => (0, 0, top()),
            Some(n) => {
                let plan = Plan::parse(&prog.text, &p.axes, &p.cycle);
                // The first block with N`n` (blocks before any N: seq 0).
                let b = plan.blocks.iter().find(|b| b.seq == n && n != 0);
                let b = b.ok_or(CncError::new(EW_DATA))?;
                (b.seq, b.line, b.text.clone())
            }
        };
        let name = prog.display_name();
        let run = &mut self.run[i];
        (run.program, run.program_name) = (main, name);
        (run.seq, run.block, run.exec_text) = (seq, line, text);
        Ok(())
    }
}

/// The highest display language code the simulated CNC has [ours].
const LANGUAGES: i16 = 15;

/// Data kind `kind`'s [modify, output] levels (0 the first); no such kind
/// is EW_NUMBER.
fn protection(m: &mut super::Machine, kind: i32) -> Reply<&mut [i16; 2]> {
    let p = &mut m.profile.system.protection;
    usize::try_from(kind)
        .ok()
        .and_then(|k| p.get_mut(k))
        .ok_or(CncError::NUMBER)
}
