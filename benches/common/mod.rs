//! What the benches share: a simulator, a handle on it, a pre-encoded frame.

#![allow(dead_code)]

use fwlib32::cnc_allclibhndl3;
use fwlib32::ew::EW_OK;
use fwlib32::proto::call::{Call, Ctx};
use fwlib32::proto::frame::{CLIENT_VERSION, Frame, ftype};
use fwlib32::proto::packet::{ReqSub, encode_request};
use fwlib32::sim::{Profile, Simulator};
use std::alloc::{GlobalAlloc, Layout, System};
use std::ffi::CString;
use std::os::raw::c_ushort;
use std::sync::atomic::{AtomicIsize, Ordering};

/// `call`'s data frame for path 1, encoded once (what the raw-socket
/// baselines send).
pub fn data_frame(call: &impl Call) -> Vec<u8> {
    let mut subs: Vec<ReqSub> = call.request(&Ctx::default());
    for s in &mut subs {
        s.path = 1;
    }
    Frame::new(CLIENT_VERSION, ftype::DATA_REQ, encode_request(&subs)).encode()
}

/// The built-in profile's simulator on a free port of 127.0.0.1.
pub fn start() -> Simulator {
    Simulator::start(Profile::default(), "127.0.0.1:0").expect("simulator")
}

/// A library handle on `sim` (timeout 10 s).
pub fn alloc(sim: &Simulator) -> c_ushort {
    let ip = CString::new("127.0.0.1").unwrap();
    let mut h: c_ushort = 0;
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), sim.port(), 10, &mut h) },
        EW_OK
    );
    h
}

/// The system allocator, counting live heap bytes in [`HEAP`] (a cross-check
/// of the RSS delta, which only moves in whole pages). A bench installs it
/// with `#[global_allocator]`.
pub struct Counting;

pub static HEAP: AtomicIsize = AtomicIsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        HEAP.fetch_add(l.size() as isize, Ordering::Relaxed);
        unsafe { System.alloc(l) }
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        HEAP.fetch_sub(l.size() as isize, Ordering::Relaxed);
        unsafe { System.dealloc(p, l) }
    }
    unsafe fn realloc(&self, p: *mut u8, l: Layout, new: usize) -> *mut u8 {
        HEAP.fetch_add(new as isize - l.size() as isize, Ordering::Relaxed);
        unsafe { System.realloc(p, l, new) }
    }
}
