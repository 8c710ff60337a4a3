//! The `[[fault]]`s of one machine at an instant: what the network side
//! (src/sim/server.rs, session.rs) asks before it accepts, reads or answers.
//! Times are seconds since the simulator's start (the faults' time zero).

use super::profile::fault::{Fault, FaultKind};
use parking_lot::Mutex;
use std::time::Duration;

/// How an answer is cut short.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cut {
    /// Half the answer, then a reset (RST).
    Reset,
    /// Half the answer, then a close (FIN).
    Close,
}

/// The faults concerning one machine.
#[derive(Debug, Default)]
pub struct FaultPlan {
    faults: Vec<Fault>,
    /// Per fault: the (class, command) pairs an error fault answers for.
    errors: Vec<Vec<(u16, u16)>>,
    /// Per fault: the occurrence last counted, and how many answers it cut.
    used: Mutex<Vec<(u64, u32)>>,
}

impl FaultPlan {
    pub fn new(faults: Vec<Fault>) -> FaultPlan {
        FaultPlan {
            errors: faults.iter().map(Fault::error_commands).collect(),
            used: Mutex::new(vec![(u64::MAX, 0); faults.len()]),
            faults,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.faults.is_empty()
    }

    fn of(&self, kinds: &'static [FaultKind]) -> impl Iterator<Item = (usize, &Fault)> + '_ {
        self.faults
            .iter()
            .enumerate()
            .filter(move |(_, f)| kinds.contains(&f.kind))
    }

    fn holds(&self, kinds: &'static [FaultKind], t: f64) -> bool {
        self.of(kinds).any(|(_, f)| f.window().active(t).is_some())
    }

    /// Whether the machine ever refuses connections (`off`, `refuse`).
    pub fn refuses(&self) -> bool {
        self.of(REFUSING).next().is_some()
    }

    /// Whether new connections are refused at `t`.
    pub fn refusing(&self, t: f64) -> bool {
        self.holds(REFUSING, t)
    }

    /// The next instant after `t` at which refusing may start or stop.
    pub fn next_refusal_change(&self, t: f64) -> Option<f64> {
        self.of(REFUSING)
            .filter_map(|(_, f)| f.window().next_change(t))
            .min_by(f64::total_cmp)
    }

    /// Whether the machine was off at some instant of (a, b]: a connection
    /// open before is gone.
    pub fn off_between(&self, a: f64, b: f64) -> bool {
        self.of(&[FaultKind::Off])
            .any(|(_, f)| f.window().hit(a, b))
    }

    /// Whether requests go unanswered at `t`.
    pub fn silent(&self, t: f64) -> bool {
        self.holds(&[FaultKind::Silent], t)
    }

    /// How late answers are at `t` (the longest delay holding).
    pub fn delay(&self, t: f64) -> Duration {
        self.of(&[FaultKind::Delay])
            .filter(|(_, f)| f.window().active(t).is_some())
            .map(|(_, f)| Duration::from_millis(f.delay_ms))
            .max()
            .unwrap_or_default()
    }

    /// The session limit at `t` (the smallest holding), if a fault sets one.
    pub fn session_cap(&self, t: f64) -> Option<usize> {
        self.of(&[FaultKind::Sessions])
            .filter(|(_, f)| f.window().active(t).is_some())
            .filter_map(|(_, f)| f.sessions)
            .min()
    }

    /// The code answered for a subpacket of `class`/`cmd` at `t`, if an
    /// error fault holds for it.
    pub fn error_for(&self, class: u16, cmd: u16, t: f64) -> Option<i16> {
        self.of(&[FaultKind::Error])
            .find(|(i, f)| {
                f.window().active(t).is_some() && self.errors[*i].contains(&(class, cmd))
            })
            .map(|(_, f)| f.error_code())
    }

    /// Takes one cut of a fault of `kinds` holding at `t`, within its count.
    fn take(&self, kinds: &'static [FaultKind], t: f64) -> Option<FaultKind> {
        if self.faults.is_empty() {
            return None;
        }
        let mut used = self.used.lock();
        for (i, f) in self.of(kinds) {
            let Some(k) = f.window().active(t) else {
                continue;
            };
            let u = &mut used[i];
            if u.0 != k {
                *u = (k, 0);
            }
            if f.count == 0 || u.1 < f.count {
                u.1 += 1;
                return Some(f.kind);
            }
        }
        None
    }

    /// Whether (and how) the data answer given at `t` is cut short.
    pub fn cut(&self, t: f64) -> Option<Cut> {
        match self.take(&[FaultKind::Reset, FaultKind::Close], t)? {
            FaultKind::Close => Some(Cut::Close),
            _ => Some(Cut::Reset),
        }
    }

    /// Whether an upload started at `t` drops the machine off the network.
    pub fn upload_drop(&self, t: f64) -> bool {
        self.take(&[FaultKind::UploadDrop], t).is_some()
    }
}

const REFUSING: &[FaultKind] = &[FaultKind::Off, FaultKind::Refuse];

#[cfg(test)]
mod tests {
    use super::*;

    fn plan(specs: &[&str]) -> FaultPlan {
        FaultPlan::new(
            specs
                .iter()
                .map(|s| Fault::parse_spec(s).unwrap())
                .collect(),
        )
    }

    #[test]
    fn what_holds_when() {
        let p = plan(&[
            "off:at=10,duration=5",
            "delay:delay_ms=3",
            "delay:delay_ms=7,at=1,duration=1",
            "sessions:sessions=2,at=20",
            "error:functions=cnc_statinfo,code=EW_NOOPT,at=30,duration=1",
        ]);
        assert!(!p.refusing(9.0) && p.refusing(10.0) && !p.refusing(15.0));
        assert_eq!(p.next_refusal_change(0.0), Some(10.0));
        assert!(p.off_between(0.0, 20.0) && !p.off_between(15.0, 20.0));
        assert_eq!(p.delay(0.5), Duration::from_millis(3));
        assert_eq!(p.delay(1.5), Duration::from_millis(7));
        assert_eq!((p.session_cap(19.0), p.session_cap(21.0)), (None, Some(2)));
        assert_eq!(p.error_for(1, 0x19, 30.5), Some(6));
        assert_eq!(p.error_for(1, 0x19, 31.5), None);
        assert_eq!(p.error_for(1, 0x18, 30.5), None);
    }

    #[test]
    fn cuts_are_counted_per_occurrence() {
        let p = plan(&[
            "reset:count=1,every=10,duration=5",
            "close:at=107,duration=2",
        ]);
        assert_eq!(p.cut(1.0), Some(Cut::Reset));
        assert_eq!(p.cut(2.0), None, "one per occurrence");
        assert_eq!(p.cut(6.0), None);
        assert_eq!(p.cut(11.0), Some(Cut::Reset), "the next occurrence");
        assert_eq!(p.cut(107.0), Some(Cut::Close));
        assert_eq!(p.cut(108.0), Some(Cut::Close), "count 0: every answer");
        assert!(!p.upload_drop(1.0));
    }
}
