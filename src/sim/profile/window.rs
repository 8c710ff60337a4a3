//! When a scheduled thing holds: `[[event]]`s and `[[fault]]`s share one
//! schedule, `at` seconds after the start, repeating `every` seconds (0 =
//! once), lasting `duration` seconds (0 = for ever after `at`). Occurrence
//! k covers [at + k·every, at + k·every + duration).

/// A schedule: the three numbers of an `[[event]]` or a `[[fault]]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Window {
    pub at: f64,
    pub every: f64,
    pub duration: f64,
}

impl Window {
    /// The occurrence whose start is the last at or before `t` (None before `at`).
    pub fn occurrence(&self, t: f64) -> Option<u64> {
        if t < self.at {
            return None;
        }
        Some(if self.every > 0.0 {
            ((t - self.at) / self.every).floor() as u64
        } else {
            0
        })
    }

    fn start(&self, k: u64) -> f64 {
        self.at + k as f64 * self.every
    }

    /// The occurrence holding at `t`, if one does.
    pub fn active(&self, t: f64) -> Option<u64> {
        let k = self.occurrence(t)?;
        (self.duration <= 0.0 || t - self.start(k) < self.duration).then_some(k)
    }

    /// Whether it held at some instant of (a, b] (at `b` when a >= b).
    pub fn hit(&self, a: f64, b: f64) -> bool {
        let Some(k) = self.occurrence(b) else {
            return false;
        };
        if a >= b || self.duration <= 0.0 {
            return self.active(b).is_some();
        }
        // Only the last occurrence started by `b` can reach past `a`.
        self.start(k) + self.duration > a
    }

    /// The first instant after `t` at which [`Window::active`] may change
    /// (None: never again).
    pub fn next_change(&self, t: f64) -> Option<f64> {
        let Some(k) = self.occurrence(t) else {
            return Some(self.at);
        };
        if self.duration <= 0.0 || (self.every > 0.0 && self.duration >= self.every) {
            return None;
        }
        let end = self.start(k) + self.duration;
        if t < end {
            Some(end)
        } else if self.every > 0.0 {
            Some(self.start(k + 1))
        } else {
            None
        }
    }

    /// A description of what is wrong with the numbers, if anything.
    pub fn check(&self) -> Result<(), String> {
        for (name, v) in [
            ("at", self.at),
            ("every", self.every),
            ("duration", self.duration),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(format!("{name} must be a number of seconds >= 0"));
            }
        }
        if self.every > 0.0 && self.every < 0.01 {
            return Err("every must be 0 (once) or at least 0.01 s".into());
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::Window;

    const W: Window = Window {
        at: 10.0,
        every: 60.0,
        duration: 5.0,
    };

    #[test]
    fn occurrences_hold_for_their_duration() {
        assert_eq!(W.active(9.9), None);
        assert_eq!(W.active(10.0), Some(0));
        assert_eq!(W.active(14.9), Some(0));
        assert_eq!(W.active(15.0), None);
        assert_eq!(W.active(70.5), Some(1));
        let once = Window {
            every: 0.0,
            duration: 0.0,
            ..W
        };
        assert_eq!(once.active(1e6), Some(0));
    }

    #[test]
    fn hits_and_changes() {
        assert!(!W.hit(0.0, 9.0));
        assert!(W.hit(0.0, 20.0), "a whole occurrence inside");
        assert!(W.hit(12.0, 13.0));
        assert!(!W.hit(15.0, 69.0));
        assert!(W.hit(69.0, 71.0));
        assert!(W.hit(12.0, 12.0));
        assert_eq!(W.next_change(0.0), Some(10.0));
        assert_eq!(W.next_change(10.0), Some(15.0));
        assert_eq!(W.next_change(15.0), Some(70.0));
        let once = Window { every: 0.0, ..W };
        assert_eq!(once.next_change(16.0), None);
    }
}
