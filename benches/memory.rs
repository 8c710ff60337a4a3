//! Memory per handle: the heap bytes the library keeps for a handle on its
//! own CNC (its connection pair, two sockets' buffers, what the CNC said at
//! connect time, the handle) and for one more handle on a CNC already
//! connected; and the time `cnc_allclibhndl3` takes. Run with
//! `cargo bench --bench memory` (a few seconds).
//!
//! The simulators run in this process (one fleet, its own threads), so the
//! counting allocator counts only what the measuring thread allocates and
//! frees: the library has no thread of its own, so everything it keeps for
//! a handle is allocated by the thread that calls it, and the simulators'
//! memory is not counted. Live bytes are counted, not the allocator's
//! overhead (about 16 bytes a block with glibc) nor the kernel's socket
//! buffers. Goals (issue 22): at most 2 KB per handle on its own CNC, at
//! most 0.5 KB per handle on a shared one; the baseline is a plain-socket
//! client's least: two connected `TcpStream`s and nothing else, 0 heap
//! bytes, so the figures are absolute.

use fwlib32::ew::EW_OK;
use fwlib32::sim::{Fleet, FleetOptions, Profile};
use fwlib32::types::{ODBALMMSG2, ODBDY2, ODBST};
use fwlib32::*;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::ffi::CString;
use std::os::raw::{c_short, c_ushort};
use std::sync::atomic::{AtomicIsize, Ordering};
use std::time::Instant;

/// The system allocator, counting the live bytes of the threads that set
/// [`COUNT`] (only the measuring thread).
struct PerThread;

static LIVE: AtomicIsize = AtomicIsize::new(0);

thread_local! {
    static COUNT: Cell<bool> = const { Cell::new(false) };
}

fn counted() -> bool {
    COUNT.try_with(Cell::get).unwrap_or(false)
}

unsafe impl GlobalAlloc for PerThread {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        if counted() {
            LIVE.fetch_add(l.size() as isize, Ordering::Relaxed);
        }
        unsafe { System.alloc(l) }
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        if counted() {
            LIVE.fetch_sub(l.size() as isize, Ordering::Relaxed);
        }
        unsafe { System.dealloc(p, l) }
    }
    unsafe fn realloc(&self, p: *mut u8, l: Layout, new: usize) -> *mut u8 {
        if counted() {
            LIVE.fetch_add(new as isize - l.size() as isize, Ordering::Relaxed);
        }
        unsafe { System.realloc(p, l, new) }
    }
}

#[global_allocator]
static ALLOC: PerThread = PerThread;

fn live() -> isize {
    LIVE.load(Ordering::Relaxed)
}

fn alloc(port: u16) -> (c_ushort, f64) {
    let ip = CString::new("127.0.0.1").unwrap();
    let mut h = 0;
    let t = Instant::now();
    let r = unsafe { cnc_allclibhndl3(ip.as_ptr(), port, 10, &mut h) };
    let us = t.elapsed().as_nanos() as f64 / 1e3;
    assert_eq!(r, EW_OK);
    (h, us)
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

/// A collector's poll: status, positions of all axes, alarm messages.
fn poll(h: c_ushort) {
    let mut st = ODBST::default();
    let mut dy = ODBDY2::default();
    let mut alm = [ODBALMMSG2::default(); 10];
    let mut n: c_short = 10;
    unsafe {
        assert_eq!(cnc_statinfo(h, &mut st), EW_OK);
        assert_eq!(
            cnc_rddynamic2(h, -1, std::mem::size_of::<ODBDY2>() as _, &mut dy),
            EW_OK
        );
        assert_eq!(cnc_rdalmmsg2(h, -1, &mut n, alm.as_mut_ptr()), EW_OK);
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "--list") {
        println!("memory: bench");
        return;
    }
    // `cargo test --benches` (no --bench): fewer machines, same figures' meaning.
    let machines = if args.iter().any(|a| a == "--bench") {
        200
    } else {
        20
    };
    let fleet = Fleet::start(
        &[Profile::default()],
        "127.0.0.1:0",
        FleetOptions {
            machines: Some(machines),
            worker_threads: Some(1),
            ..FleetOptions::default()
        },
    )
    .expect("fleet");
    // Warm-up (not counted): the handle table, the pair slots and the
    // log's statics reach their steady state.
    let (h, _) = alloc(fleet.port(0));
    poll(h);
    assert_eq!(cnc_freelibhndl(h), EW_OK);

    COUNT.with(|c| c.set(true));
    let n = machines - 1;
    let before = live();
    let mut times = Vec::with_capacity(n);
    let own: Vec<c_ushort> = (1..machines)
        .map(|i| {
            let (h, us) = alloc(fleet.port(i));
            times.push(us);
            h
        })
        .collect();
    let allocated = live();
    for &h in &own {
        let mut st = ODBST::default();
        assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_OK);
    }
    let one_call = live();
    for &h in &own {
        poll(h);
    }
    let polled = live();
    // Handles sharing the pair of the first machine.
    let shared_n = 1000;
    let before_shared = live();
    let shared: Vec<c_ushort> = (0..shared_n).map(|_| alloc(fleet.port(1)).0).collect();
    let after_shared = live();
    for h in own.into_iter().chain(shared) {
        assert_eq!(cnc_freelibhndl(h), EW_OK);
    }
    let freed = live();
    COUNT.with(|c| c.set(false));

    let per = |a: isize, b: isize, k: usize| (b - a) as f64 / k as f64;
    println!("memory per handle (live heap bytes the library keeps; {n} CNCs, in-process fleet)");
    println!(
        "{:<58} {:>8.0} B   goal <= 2048 B: {}",
        "a handle on its own CNC, allocated",
        per(before, allocated, n),
        if per(before, allocated, n) <= 2048.0 {
            "met"
        } else {
            "NOT met"
        }
    );
    println!(
        "{:<58} {:>8.0} B",
        "... after one cnc_statinfo",
        per(before, one_call, n)
    );
    println!(
        "{:<58} {:>8.0} B",
        "... after a poll (statinfo, rddynamic2 all axes, rdalmmsg2)",
        per(before, polled, n)
    );
    println!(
        "{:<58} {:>8.0} B   goal <= 512 B: {}",
        "one more handle on a CNC already connected",
        per(before_shared, after_shared, shared_n),
        if per(before_shared, after_shared, shared_n) <= 512.0 {
            "met"
        } else {
            "NOT met"
        }
    );
    println!(
        "{:<58} {:>8} B",
        "left after every handle was freed (all handles)",
        freed - before
    );
    println!(
        "{:<58} {:>8.0} µs",
        "cnc_allclibhndl3 on its own CNC, median",
        median(&mut times)
    );
}
