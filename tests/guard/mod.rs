//! An output buffer followed by a guard the library must not touch
//! (tests/hostile.rs, tests/wire_faults.rs).

#![allow(dead_code)]

pub const GUARD: usize = 64;
pub const FILL: u8 = 0xA5;

/// An output of `n` bytes followed by a guard the library must not touch.
pub struct Out(pub Vec<u8>, pub usize);

impl Out {
    pub fn new(n: usize) -> Out {
        Out(vec![FILL; n + GUARD], n)
    }
    pub fn p<T>(&mut self) -> *mut T {
        self.0.as_mut_ptr().cast()
    }
    pub fn intact(&self) -> bool {
        self.0[self.1..].iter().all(|b| *b == FILL)
    }
}
