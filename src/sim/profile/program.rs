//! Profile sections of the program area (src/sim/program.rs): timers,
//! modal codes and operator messages.

use serde::Deserialize;
use std::collections::BTreeMap;

/// `[timers]`: cnc_rdtimer's counters at simulator start, in minutes; they
/// run on from there on the simulator's clock (operating only while path 1
/// runs, cutting while it moves at feed; a hold stops them).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct Timers {
    pub power_on: i32,
    pub operating: i32,
    pub cutting: i32,
    pub free: i32,
    /// Seconds cnc_settimer moved the CNC clock from the system clock.
    #[serde(skip)]
    pub clock_offset: i64,
    /// The CNC clock at the simulator's start (Unix seconds) instead of the
    /// system clock's: with a frozen simulator clock (`Simulator::set_elapsed`)
    /// cnc_gettimer then reads the same time in every run (the oracle).
    #[serde(skip)]
    pub clock_at_start: Option<i64>,
    /// Milliseconds cnc_wrtimer moved each timer (cnc_rdtimer's kinds 0..4)
    /// from the profile's and the run's.
    #[serde(skip)]
    pub written_ms: [i64; 5],
}

/// `[path.modal]`: what cnc_modal reads.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct Modal {
    /// Per G-code group (cnc_modal type 0, 1, ...): the code within the
    /// group as the CNC encodes it (e.g. group 0: 0 G00, 1 G01, 2 G02 ...).
    pub g: Vec<u8>,
    /// Other modal codes by cnc_modal type (100..126) → value.
    pub aux: BTreeMap<String, i32>,
}

/// `[[path.opmsg]]`: an operator message on display (cnc_rdopmsg).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
pub struct OperatorMessage {
    pub number: i32,
    /// Message type 0..4 (cnc_rdopmsg `type`).
    #[serde(rename = "type")]
    pub kind: i16,
    pub text: String,
}
