//! A Rust-native, drop-in replacement for FANUC's FOCAS2 Ethernet library
//! (`libfwlib32.so`), and a CNC simulator speaking the same protocol.
//!
//! From Rust, start at [`native::Cnc`]: a connection to one CNC with typed
//! reads (status, positions, alarms, parameters, macros, PMC, programs) and
//! errors that name the FOCAS call and its `EW_*` code ([`native::Error`]).
//!
//! ```
//! use fwlib32::native::Cnc;
//! use fwlib32::sim::{Profile, Simulator};
//! use std::time::Duration;
//!
//! // A simulated 31i mill on a free loopback port; a real CNC is "host:8193".
//! let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
//! let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
//! let status = cnc.status()?;
//! println!("{} {}", status.mode, status.run); // MEM STRT
//! for axis in cnc.positions()? {
//!     println!("{} {}", axis.name, axis.absolute);
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! From C, link `libfwlib32.so.1` (or `libfwlib32.a`) and include
//! `include/fwlib32.h`: the same functions, structs and codes as FANUC's
//! header. The C functions are callable from Rust too (`fwlib32::cnc_statinfo`
//! ...), for tests and for porting C code.
//!
//! Features: `sim` ([`sim`], the `focas-sim` binary: tokio, toml), `cli` (the
//! `focas` binary), `serde` (`Serialize` on the API's types); all on by
//! default. With `default-features = false` the library needs only libc,
//! parking_lot and thiserror.
//!
//! The other modules are the layers under the API, public for the binaries
//! and the tests: [`spec`] (every function described as data), [`proto`] (the
//! sans-IO codec), [`client`] (connections and handles), [`ffi`] (the C
//! functions), [`types`] (the C structs), [`ew`] (the `EW_*` codes).

#![allow(non_snake_case)]

pub mod client;
pub mod error;
pub mod ew;
pub mod ffi;
pub mod native;
pub mod proto;
#[cfg(feature = "sim")]
pub mod sim;
pub mod spec;
pub mod types;

// The exported C functions, callable from Rust too (documented in the C
// header, not here).
#[doc(hidden)]
pub use ffi::machine::*;
#[allow(unused_imports)]
#[doc(hidden)]
pub use ffi::{
    absent::*, alarm::*, axisdata::*, described::*, download::*, dynamic::*, ext::*, folder::*,
    handle::*, history::*, macros::*, memory::*, offset::*, param::*, paraminfo::*, pmc::*,
    position::*, program::*, spindle::*, status::*, tool::*, upload::*,
};
