//! fwlib32-rs: a Rust-native, drop-in replacement for FANUC's FOCAS2 Ethernet
//! library, and a CNC simulator speaking the same protocol.
//!
//! * [`spec`]: every FOCAS function described as data, read by all the layers above.
//! * [`proto`]: the sans-IO codec shared by the client and the simulator.
//! * [`client`]: connection pairs, sessions, the handle table (blocking std::net).
//! * [`ffi`]: the exported C functions of `fwlib32.h`.
//! * [`native`]: the safe Rust API over the same client and codec ([`native::Cnc`]).
//! * [`sim`]: the simulator (tokio), behind `focas-sim`.

#![allow(non_snake_case)]

pub mod client;
pub mod error;
pub mod ew;
pub mod ffi;
pub mod native;
pub mod proto;
pub mod sim;
pub mod spec;
pub mod types;

// The exported C functions, callable from Rust too. Areas fill in one at a time.
#[allow(unused_imports)]
pub use ffi::{
    absent::*, alarm::*, described::*, download::*, ext::*, folder::*, handle::*, history::*,
    macros::*, memory::*, offset::*, param::*, pmc::*, position::*, program::*, status::*, tool::*,
    upload::*,
};
// Machine data (issue 11).
pub use ffi::machine::*;
