#![no_main]
//! See fuzz/fuzzing.rs, `profile`.

#[path = "../fuzzing.rs"]
mod fuzzing;

libfuzzer_sys::fuzz_target!(|data: &[u8]| fuzzing::profile(data));
