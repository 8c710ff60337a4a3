//! Axes, modes and settings of the long tail: the positions with extra
//! digits (from the axes' positions, as cnc_absolute & co. read them),
//! the synchronous errors, the `[MEASURE]` keys' availability, the tool
//! interference check and the coordinate rotation of the path's profile;
//! cnc_wrtimer's write of the timers cnc_rdtimer reads.

use super::route::{Route, none};
use super::service::CncError;
use crate::ew::EW_DATA;
use crate::proto::cmd;

pub(super) const ROUTES: &[Route] = &[
    // [code]: each axis's position (code as cnc_absolute2's, cnc_machine's,
    // cnc_relative2's, cnc_distance's), a double, its decimal places and
    // its digits.
    Route::table(cmd::EXDGT, |m, q| {
        let v = m.positions(q.path, q.words[0], -1)?;
        Ok(v.iter()
            .flat_map(|r| {
                let (digits, places) = r.to_decimal();
                let data = f64::from(digits) / 10f64.powi(i32::from(places));
                [data.to_bits() as i64, i64::from(places), i64::from(digits)]
            })
            .collect())
    }),
    Route::table(cmd::SYNERR, |m, q| {
        let s = &m.path(q.path)?.sync_error;
        Ok(vec![i64::from(match q.words[0] {
            0 => s.synchronous,
            _ => s.rigid_tap,
        })])
    }),
    Route::table(cmd::RDENBLINFO, |m, q| {
        Ok(vec![i64::from(m.path(q.path)?.measure.enabled)])
    }),
    Route::table(cmd::RDCENBLINFO, |m, q| {
        Ok(vec![i64::from(m.path(q.path)?.measure.center_enabled)])
    }),
    Route::table(cmd::RDINTERFERENCE, |m, q| {
        Ok(m.path(q.path)?.interference.tools.map(i64::from).to_vec())
    }),
    // The center's value records' second words (decimals) are not read: 0.
    Route::table(cmd::RDCDROTATE, |m, q| {
        let r = &m.path(q.path)?.rotation;
        let head = [r.mode, r.plane_axes[0], r.plane_axes[1]].map(i64::from);
        let values = [r.center[0], r.center[1], r.angle];
        let values = values.into_iter().flat_map(|v| [i64::from(v), 0]);
        Ok(head.into_iter().chain(values).collect())
    }),
    // The profile's bytes, zeros after them (128 in all).
    Route::table(cmd::RDMDLCONFIG2, |m, _| {
        let c = &m.profile.system.module_config;
        let mut v: Vec<i64> = c.iter().take(128).map(|&b| i64::from(b)).collect();
        v.resize(128, 0);
        Ok(v)
    }),
    // [type], payload minutes and milliseconds: cnc_rdtimer reads them from
    // now on (the timer runs on from them). No such timer EW_NUMBER (as the
    // read), negative minutes or milliseconds past a minute EW_DATA, nothing
    // changed [ours].
    Route::table(cmd::WRTIMER, |m, q| {
        let now = m.timer(q.arg(0))?;
        let (minute, msec) = match *q.payload {
            [minute, msec] if minute >= 0 && (0..60_000).contains(&msec) => (minute, msec),
            _ => return Err(CncError::new(EW_DATA)),
        };
        let was = i64::from(now.minute) * 60_000 + i64::from(now.msec);
        m.profile.timers.written_ms[q.arg(0) as usize] += minute * 60_000 + msec - was;
        none(Ok(()))
    }),
];
