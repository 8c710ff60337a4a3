#![no_main]
//! See fuzz/fuzzing.rs, `request`.

#[path = "../fuzzing.rs"]
mod fuzzing;

libfuzzer_sys::fuzz_target!(|data: &[u8]| fuzzing::request(data));
