//! Servo data sampling (cnc_sdt*, FANUC's 32-bit library): the channels
//! each path samples (the profile's `[[path.sample_channel]]`, set by
//! cnc_sdtsetchnl, cleared by cnc_sdtclrchnl), whether sampling runs (cnc_sdtstartsmpl until
//! cnc_sdtcancelsmpl or cnc_sdtendsmpl), and each channel's current value
//! (cnc_sdtread1shot) read from the servo state the simulator models for
//! the axis: its motor speed, load meter or current, as the running
//! program leaves them.

use super::Machine;
use super::profile::SampleChannel;
use super::profile::{Axis, Datum};
use super::route::{Asked, Route};
use super::run::{Running, Sampling};
use super::service::{CncError, Reply};
use crate::ew::{EW_DATA, EW_PATH};
use crate::proto::cmd::{
    SDTCANCELSMPL, SDTCLRCHNL, SDTENDSMPL, SDTREAD1SHOT, SDTSETCHNL, SDTSTARTSMPL,
};

pub(super) const ROUTES: &[Route] = &[
    Route::table(SDTSETCHNL, set_channels),
    Route::table(SDTCLRCHNL, |m, q| {
        m.sampling_mut(q.path)?.channels.clear();
        Ok(Vec::new())
    }),
    Route::table(SDTSTARTSMPL, start),
    Route::table(SDTCANCELSMPL, stop),
    Route::table(SDTENDSMPL, stop),
    Route::table(SDTREAD1SHOT, one_shot),
];

/// The most channels a CNC samples (cnc_sdtread1shot writes 8 values).
pub const MAX_CHANNELS: usize = 8;

/// The current value of `d` of axis `a`, as the channel's 16 bits.
fn value(a: &Axis, d: Datum) -> u16 {
    let v = match d {
        Datum::Speed => i64::from(a.servo_speed),
        Datum::Load => i64::from(a.servo_load),
        Datum::Current => i64::from(super::position::current_tenths(a)),
        Datum::Other => 0,
    };
    v as u16
}

impl Machine {
    fn sampling_mut(&mut self, path: u16) -> Reply<&mut Sampling> {
        (self.run.get_mut(usize::from(path).wrapping_sub(1)))
            .map(|r| &mut r.sampling)
            .ok_or(CncError::new(EW_PATH))
    }
}

/// cnc_sdtsetchnl: each channel record (`chno`, `axis`, `cycle`, the
/// shift byte, 0, the code) sets channel `chno` to the figure its code's
/// magnitude names in the profile's `sample_code` list (another: a figure
/// not modelled) of axis `axis` (-1, a spindle: none modelled); channels
/// before it that were never set sample nothing. A channel outside 1..8
/// is EW_DATA, nothing set.
fn set_channels(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let codes = m.path(q.path)?.sample_codes.clone();
    let records: Vec<&[i64]> = q.payload.chunks_exact(6).collect();
    if records
        .iter()
        .any(|r| !(1..=MAX_CHANNELS as i64).contains(&r[0]))
    {
        return Err(CncError::new(EW_DATA));
    }
    let s = m.sampling_mut(q.path)?;
    for r in records {
        let at = r[0] as usize - 1;
        let datum = (codes.iter().find(|c| i64::from(c.code) == r[5].abs()))
            .map_or(Datum::Other, |c| c.datum);
        let channel = SampleChannel {
            axis: u16::try_from(r[1]).unwrap_or(0),
            datum,
        };
        if s.channels.len() <= at {
            s.channels.resize(
                at + 1,
                SampleChannel {
                    axis: 0,
                    datum: Datum::Other,
                },
            );
        }
        s.channels[at] = channel;
    }
    Ok(Vec::new())
}

/// cnc_sdtstartsmpl: sampling runs from now on; with no channel to sample
/// EW_DATA, nothing started.
fn start(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let now = m.now;
    let s = m.sampling_mut(q.path)?;
    if s.channels.is_empty() {
        return Err(CncError::new(EW_DATA));
    }
    s.running = Some(Running {
        since: now,
        kind: q.arg(0),
        cycle: q.arg(1),
    });
    Ok(Vec::new())
}

/// cnc_sdtcancelsmpl, cnc_sdtendsmpl: sampling stops (none running: nothing
/// to stop, no error).
fn stop(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    m.sampling_mut(q.path)?.running = None;
    Ok(Vec::new())
}

/// cnc_sdtread1shot: each channel's current value, 8 values, the ones
/// past the channels (and a channel on an axis the path lacks) 0.
fn one_shot(m: &mut Machine, q: &Asked<'_>) -> Reply<Vec<i64>> {
    let p = m.path(q.path)?;
    let s = &m.live(q.path)?.sampling;
    let mut v: Vec<i64> = (s.channels.iter().take(MAX_CHANNELS))
        .map(|c| {
            let a = p.axes.get(usize::from(c.axis).wrapping_sub(1));
            i64::from(a.map_or(0, |a| value(a, c.datum)))
        })
        .collect();
    v.resize(MAX_CHANNELS, 0);
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proto::packet::ReqSub;
    use crate::sim::Profile;
    use crate::sim::service::CncService;

    fn ask(m: &mut Machine, cmd: u16, args: &[i32]) -> i16 {
        let q = ReqSub {
            path: 1,
            ..ReqSub::cnc(cmd, args)
        };
        m.answer(&q).error
    }

    #[test]
    fn start_runs_until_cancel_or_end_and_needs_a_channel() {
        let mut m = Machine::new(Profile::default());
        assert!(!m.run[0].sampling.channels.is_empty());
        assert_eq!(ask(&mut m, SDTSTARTSMPL, &[3, 250]), 0);
        let r = m.run[0].sampling.running.expect("sampling runs");
        assert_eq!((r.kind, r.cycle, r.since), (3, 250, m.now));
        assert_eq!(ask(&mut m, SDTCANCELSMPL, &[]), 0);
        assert!(m.run[0].sampling.running.is_none());
        assert_eq!(ask(&mut m, SDTSTARTSMPL, &[0, 8]), 0);
        assert_eq!(ask(&mut m, SDTENDSMPL, &[]), 0);
        assert!(m.run[0].sampling.running.is_none());
        // Cleared channels: a start is refused and changes nothing.
        assert_eq!(ask(&mut m, SDTCLRCHNL, &[]), 0);
        assert!(m.run[0].sampling.channels.is_empty());
        assert_eq!(ask(&mut m, SDTSTARTSMPL, &[0, 8]), EW_DATA);
        assert!(m.run[0].sampling.running.is_none());
    }

    /// One cnc_sdtsetchnl record: `chno`, `axis`, `cycle` 8, shift byte
    /// 0x0c, 0, `code`.
    fn record(chno: i16, axis: i16, code: i16) -> Vec<u8> {
        let mut b = Vec::new();
        b.extend(chno.to_be_bytes());
        b.extend(axis.to_be_bytes());
        b.extend(8i32.to_be_bytes());
        b.extend([0x0c, 0]);
        b.extend(code.to_be_bytes());
        b
    }

    fn set(m: &mut Machine, records: &[Vec<u8>]) -> i16 {
        let n = records.len() as i32;
        let q = ReqSub {
            path: 1,
            ..ReqSub::cnc(SDTSETCHNL, &[n, 0, 0, 0, 12 * n]).with_payload(records.concat())
        };
        m.answer(&q).error
    }

    #[test]
    fn set_channels_sample_the_codes_figures_by_magnitude() {
        let mut m = Machine::new(Profile::default());
        let codes = m.profile.paths[0].sample_codes.clone();
        let load = codes.iter().find(|c| c.datum == Datum::Load);
        let load = load.expect("the default profile names a load code").code;
        assert_eq!(ask(&mut m, SDTCLRCHNL, &[]), 0);
        // Channel 2 on Y, its code negated (an even servo axis number);
        // channel 1, never set, samples nothing.
        assert_eq!(set(&mut m, &[record(2, 2, -load)]), 0);
        let ch = &m.run[0].sampling.channels;
        assert_eq!(ch.len(), 2);
        assert_eq!((ch[1].axis, ch[1].datum), (2, Datum::Load));
        assert_eq!(ch[0].datum, Datum::Other);
        // A code the profile does not name, a spindle: figures not modelled.
        assert_eq!(set(&mut m, &[record(1, -1, 13), record(3, 1, 999)]), 0);
        let ch = &m.run[0].sampling.channels;
        assert_eq!((ch[0].axis, ch[0].datum), (0, Datum::Other));
        assert_eq!((ch[2].axis, ch[2].datum), (1, Datum::Other));
        // A channel outside 1..8: EW_DATA, nothing set (the first record
        // neither).
        let before = m.run[0].sampling.channels.clone();
        assert_eq!(
            set(&mut m, &[record(4, 1, load), record(9, 1, load)]),
            EW_DATA
        );
        assert_eq!(m.run[0].sampling.channels, before);
    }
}
