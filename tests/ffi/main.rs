//! The exported C functions by area (as src/ffi), called as Rust functions
//! against the in-process simulator, or against a fake CNC replaying
//! exchanges recorded from FANUC's library (exchanges.rs); the 16i class
//! (s16.rs) and batches (batch.rs, fwlib32_ext.h). One module per area.

#[path = "../../tools/oracle/cases.rs"]
#[allow(dead_code)]
mod cases;
#[path = "../common/mod.rs"]
mod common;
#[path = "../../tools/oracle/fake.rs"]
#[allow(dead_code)]
mod fake;
#[path = "../../tools/oracle/probe.rs"]
#[allow(dead_code)]
mod probe;
#[path = "../../tools/oracle/profiles.rs"]
mod profiles;
#[path = "../sim/mod.rs"]
mod sim;
#[path = "../toolchain/mod.rs"]
mod toolchain;

mod absent;
mod alarm;
mod batch;
mod download;
mod exchanges;
mod ffi_sim;
mod history;
mod machine;
mod macros;
mod maintenance;
mod offset;
mod operate;
mod param;
mod pmc;
mod position;
mod program;
mod s16;
mod state;
mod tool_life;
mod upload;
