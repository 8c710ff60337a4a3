#![no_main]
//! See fuzz/fuzzing.rs, `reply`.

#[path = "../fuzzing.rs"]
mod fuzzing;

libfuzzer_sys::fuzz_target!(|data: &[u8]| fuzzing::reply(data));
