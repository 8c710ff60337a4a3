//! `[fleet]`: one profile serving several machines (`focas-sim --fleet N`
//! overrides `machines`), and whether the machines after the first differ
//! from it (src/sim/fleet.rs varies them).

use serde::Deserialize;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FleetSection {
    /// How many machines this profile serves.
    pub machines: usize,
    /// Machines 2, 3 ... differ from machine 1 (src/sim/fleet.rs); false: clones.
    pub vary: bool,
}

impl Default for FleetSection {
    fn default() -> Self {
        FleetSection {
            machines: 1,
            vary: true,
        }
    }
}

/// Most machines one simulator serves.
pub const MAX_MACHINES: usize = 10_000;
