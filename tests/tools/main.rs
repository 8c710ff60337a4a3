//! The programs: `focas` (its commands, `focas compat`, `focas adapter`) and
//! `focas-sim` (its options, fleets and faults from the command line).

#[path = "../toolchain/mod.rs"]
mod toolchain;

mod adapter;
mod cli;
mod compat_cli;
mod sim_cli;
