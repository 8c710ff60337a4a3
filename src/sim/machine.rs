//! The simulated machine: the profile (with what writes change in it), the
//! live state of its paths and its program memory. The areas
//! (src/sim/status.rs, position.rs, param.rs ...) add the answers of their
//! requests to it; src/sim/dispatch.rs serves them as a CNC.

use super::pmc::Pmc;
use super::profile::Profile;
use super::run::PathRun;
use super::service::{CncError, Reply};
use super::store::Store;

/// The simulated machine (see the module).
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
            run: PathRun::initial(&profile, &store),
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

    /// The profile's path `path` (1-based); EW_PATH if there is none.
    pub(crate) fn path(&self, path: u16) -> Reply<&super::profile::Path> {
        self.profile
            .paths
            .get(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)
    }

    /// The live state of path `path` (1-based); EW_PATH if there is none.
    pub(crate) fn live(&self, path: u16) -> Reply<&PathRun> {
        self.run
            .get(usize::from(path).wrapping_sub(1))
            .ok_or(CncError::PATH)
    }
}
