//! The CNC's screen and operator state (family A of the long tail): the
//! model, display language, operation and protection levels and menu
//! switches of the profile's `[system]` (the writes change them there),
//! the additional work coordinate systems of the path's offsets and the
//! running program's repeats.

use super::route::Route;
use super::service::{CncError, Reply};
use crate::ew::EW_DATA;
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
];

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
