//! Robustness: faults the simulator injects, the wire-fault matrix, a hostile
//! CNC, the header's promises under bad memory, the connection's reading of
//! answers, reconnecting handles, and the fuzz corpora replayed. (The
//! reliability suite, log.rs and bad_input.rs are crates of their own: they
//! change what the whole process shares, its allocator, the library's
//! handles and log, or its working directory.)

#[path = "../cabi/mod.rs"]
mod cabi;
#[path = "../common/mod.rs"]
mod common;
#[path = "../../fuzz/fuzzing.rs"]
mod fuzzing;
#[path = "../guard/mod.rs"]
mod guard;
#[path = "../sim/mod.rs"]
mod sim;
#[path = "../toolchain/mod.rs"]
mod toolchain;

mod faults;
mod fuzz_corpus;
mod hostile;
mod promises;
mod reconnect;
mod transport;
mod wire_faults;
