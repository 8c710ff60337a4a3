//! The simulator itself: the running machine as a function of time, fleets,
//! thousands of sessions, and the Rust API (fwlib32::native) against it.

#[path = "../sim/mod.rs"]
mod sim;

mod fleet;
mod native;
mod run;
mod sim_load;
