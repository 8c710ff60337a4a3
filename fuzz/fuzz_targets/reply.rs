#![no_main]
//! See fwlib32::fuzzing::reply.

libfuzzer_sys::fuzz_target!(|data: &[u8]| fwlib32::fuzzing::reply(data));
