//! Shared by tests/hostile.rs and tests/wire_faults.rs: an output buffer
//! followed by a guard the library must not touch, and their fake CNCs'
//! plumbing (a listener on a free port, frames read off a connection).

#![allow(dead_code)]

use fwlib32::proto::frame::Frame;
use std::io::Read;
use std::net::{TcpListener, TcpStream};

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

/// A fake CNC on a free port of 127.0.0.1 (returned): a thread hands each
/// connection to `accept` with its number (0, 1 ...), and stops accepting,
/// closing the listener, when `accept` returns false or accepting fails.
pub fn listen(mut accept: impl FnMut(usize, TcpStream) -> bool + Send + 'static) -> u16 {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    std::thread::spawn(move || {
        for (i, s) in listener.incoming().enumerate() {
            let Ok(s) = s else { return };
            if !accept(i, s) {
                return;
            }
        }
    });
    port
}

/// The FOCAS frames a fake CNC reads off one connection.
pub struct Frames {
    buf: Vec<u8>,
    chunk: [u8; 4096],
}

impl Frames {
    pub fn new() -> Frames {
        Frames {
            buf: Vec::new(),
            chunk: [0; 4096],
        }
    }

    /// The next whole frame from `s`: None at the end of the stream, on a
    /// read error, or on bytes that are not a frame.
    pub fn read(&mut self, s: &mut impl Read) -> Option<Frame> {
        loop {
            match Frame::decode(&self.buf) {
                Ok(Some((f, used))) => {
                    self.buf.drain(..used);
                    return Some(f);
                }
                Ok(None) => {}
                Err(_) => return None,
            }
            match s.read(&mut self.chunk) {
                Ok(0) | Err(_) => return None,
                Ok(n) => self.buf.extend_from_slice(&self.chunk[..n]),
            }
        }
    }
}
