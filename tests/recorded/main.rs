//! Behaviour recorded from FANUC's library, replayed: the golden vectors
//! (tests/focas-protocol) and the oracle's cases (tests/vectors) through our
//! exported functions (vectors.rs) and through the oracle's probe (oracle.rs),
//! the codec against them (codec.rs), and COMPATIBILITY.md generated from
//! them (compat.rs), and the learner's pure logic (learn.rs). vectors.rs replays cnc_exitprocess in this process
//! (under its own lock): no other module here holds a handle of the library
//! linked into this process.

#[path = "../../tools/oracle/cases.rs"]
#[allow(dead_code)]
mod cases;
#[path = "../common/mod.rs"]
mod common;
#[path = "../deviations/mod.rs"]
#[allow(dead_code)]
mod deviations;
#[path = "../../tools/oracle/fake.rs"]
#[allow(dead_code)]
mod fake;
#[path = "../../tools/oracle/probe.rs"]
#[allow(dead_code)]
mod probe;
#[path = "../../tools/oracle/profiles.rs"]
mod profiles;
#[path = "../../tools/oracle/replay.rs"]
#[allow(dead_code)]
mod replay;
#[path = "../toolchain/mod.rs"]
mod toolchain;

mod codec;
mod compat;
mod learn;
mod oracle;
mod vectors;
