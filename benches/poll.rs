//! Speed and memory of the library against the in-process simulator, each
//! reported as a ratio to a baseline measured in the same run (never as a
//! timed assertion). Run with `cargo bench --bench poll`.
//!
//! The baseline is the bare wire: one pre-encoded cnc_statinfo data frame
//! (3 subpackets) written to a std TcpStream with TCP_NODELAY and its answer
//! read back, on a session opened by hand with the codec. Every measurement
//! alternates rounds of baseline and candidate, so both see the same load
//! (the machine is shared); the ratio reported is the median over rounds of
//! candidate / baseline, the times are medians of the per-round means.

mod common;
use common::{Counting, HEAP, alloc, data_frame, start};
use fwlib32::ew::EW_OK;
use fwlib32::proto::frame::{CLIENT_VERSION, Frame, FrameHeader, HEADER_LEN, ftype};
use fwlib32::proto::position::Dynamic;
use fwlib32::proto::status::{StatInfo, Status};
use fwlib32::sim::Simulator;
use fwlib32::types::*;
use fwlib32::*;
use std::io::{Read, Write};
use std::net::TcpStream;
use std::os::raw::{c_char, c_short, c_ushort};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// Run as a test (`cargo test --benches`, no `--bench` argument): a few
/// samples only, to see that everything works; the numbers mean nothing.
static QUICK: AtomicBool = AtomicBool::new(false);

#[global_allocator]
static ALLOC: Counting = Counting;

// ---------------------------------------------------------------------------
// Timing helpers

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

/// Microseconds `f` takes, once.
fn time_us(f: &mut dyn FnMut()) -> f64 {
    let t = Instant::now();
    f();
    t.elapsed().as_nanos() as f64 / 1e3
}

struct Cmp {
    /// Baseline, median µs per call (× `mult`).
    base: f64,
    /// Candidate, median µs per call.
    us: f64,
    /// Candidate / baseline.
    ratio: f64,
}

/// After a warm-up, `samples` times: `mult` baseline calls, then one
/// candidate call, each call timed alone. Medians shrug off the preemptions
/// of a shared machine, and alternating gives both sides the same
/// conditions. `mult` is how many baseline round trips one candidate call is
/// compared with (a candidate of `mult` calls then spends as long as the
/// baseline calls of its sample).
fn compare(samples: usize, mult: usize, base: &mut dyn FnMut(), cand: &mut dyn FnMut()) -> Cmp {
    let samples = if QUICK.load(Ordering::Relaxed) {
        3
    } else {
        samples
    };
    for _ in 0..samples / 10 + 1 {
        base();
        cand();
    }
    let (mut b, mut c) = (
        Vec::with_capacity(samples * mult),
        Vec::with_capacity(samples),
    );
    for _ in 0..samples {
        for _ in 0..mult {
            b.push(time_us(base));
        }
        c.push(time_us(cand));
    }
    let (b, c) = (mult as f64 * median(&mut b), median(&mut c));
    Cmp {
        base: b,
        us: c,
        ratio: c / b,
    }
}

// ---------------------------------------------------------------------------
// The bare wire

/// A session opened by hand: the open handshake, then pre-encoded frames.
struct Raw {
    stream: TcpStream,
    body: Vec<u8>,
}

impl Raw {
    fn open(sim: &Simulator) -> Raw {
        let stream = TcpStream::connect(sim.addr()).expect("connect");
        stream.set_nodelay(true).expect("nodelay");
        let mut raw = Raw {
            stream,
            body: Vec::with_capacity(4096),
        };
        let open = Frame::new(CLIENT_VERSION, ftype::OPEN_REQ, 1u16.to_be_bytes().to_vec());
        assert_eq!(raw.exchange(&open.encode()), ftype::OPEN_RESP);
        raw
    }

    /// Writes one frame, reads one frame; returns the answer's type word.
    fn exchange(&mut self, frame: &[u8]) -> u16 {
        self.stream.write_all(frame).expect("send");
        let mut head = [0u8; HEADER_LEN];
        self.stream.read_exact(&mut head).expect("receive");
        let h = FrameHeader::decode(&head).expect("header");
        self.body.resize(h.len as usize, 0);
        self.stream.read_exact(&mut self.body).expect("receive");
        h.ftype
    }

    fn close(mut self) {
        let close = Frame::new(CLIENT_VERSION, ftype::CLOSE_REQ, Vec::new());
        assert_eq!(self.exchange(&close.encode()), ftype::CLOSE_RESP);
    }
}

// ---------------------------------------------------------------------------
// Through the C ABI

/// All-zero plain C structs (every type passed here is `repr(C)` data).
fn zeroed<T: Copy>() -> T {
    unsafe { std::mem::zeroed() }
}

fn statinfo(h: c_ushort) -> c_short {
    let mut st: ODBST = zeroed();
    unsafe { cnc_statinfo(h, &mut st) }
}

fn rddynamic2(h: c_ushort) -> c_short {
    let mut dy: ODBDY2 = zeroed();
    let len = size_of::<ODBDY2>() as c_short;
    unsafe { cnc_rddynamic2(h, ALL_AXES, len, &mut dy) }
}

/// The MTConnect adapter's poll (c-examples/adapter.c): one call each.
const POLL_CALLS: usize = 14;

fn poll(h: c_ushort) -> [c_short; POLL_CALLS] {
    let mut st2: ODBST2 = zeroed();
    let mut dy: ODBDY2 = zeroed();
    let mut sv: [ODBSVLOAD; MAX_AXIS] = zeroed();
    let mut act: ODBACT2 = zeroed();
    let mut sp: [ODBSPLOAD; MAX_SPINDLE] = zeroed();
    let mut name = [0 as c_char; 256];
    let mut block = [0 as c_char; 256];
    let mut mdl: ODBMDL = zeroed();
    let mut alm: [ODBALMMSG2; 10] = zeroed();
    let mut msg: OPMSG = zeroed();
    let mut prm: IODBPSD = zeroed();
    let mut dgn: ODBDGN = zeroed();
    let mut mcr: ODBM = zeroed();
    let mut pmc: IODBPMC = zeroed();
    let (mut nsv, mut nsp, mut nalm) = (MAX_AXIS as c_short, MAX_SPINDLE as c_short, 10);
    let (mut len, mut blk) = (255 as c_ushort, 0 as c_short);
    unsafe {
        [
            cnc_statinfo2(h, &mut st2),
            cnc_rddynamic2(h, ALL_AXES, size_of::<ODBDY2>() as c_short, &mut dy),
            cnc_rdsvmeter(h, &mut nsv, sv.as_mut_ptr()),
            cnc_acts2(h, ALL_SPINDLES, &mut act),
            cnc_rdspmeter(h, 0, &mut nsp, sp.as_mut_ptr()),
            cnc_exeprgname2(h, name.as_mut_ptr()),
            cnc_rdexecprog(h, &mut len, &mut blk, block.as_mut_ptr()),
            cnc_modal(h, 0, 0, &mut mdl),
            cnc_rdalmmsg2(h, -1, &mut nalm, alm.as_mut_ptr()),
            cnc_rdopmsg(h, 0, 6 + 256, &mut msg),
            cnc_rdparam(h, 6711, 0, 8, &mut prm),
            cnc_diagnoss(h, 308, 1, 4 + 1, &mut dgn),
            cnc_rdmacro(h, 500, 10, &mut mcr),
            pmc_rdpmcrng(h, 0, 0, 12, 12, 8 + 1, &mut pmc),
        ]
    }
}

/// Resident set size in bytes (/proc/self/statm, second field).
fn rss() -> usize {
    let s = std::fs::read_to_string("/proc/self/statm").expect("/proc/self/statm");
    let pages: usize = s
        .split_whitespace()
        .nth(1)
        .and_then(|x| x.parse().ok())
        .expect("statm");
    pages * unsafe { libc::sysconf(libc::_SC_PAGESIZE) } as usize
}

fn row(what: &str, c: &Cmp, against: &str) {
    println!(
        "{what:<44} {:>9.1} µs  {:>9.1} µs  {:>6.2}×  {against}",
        c.us, c.base, c.ratio
    );
}

fn main() {
    // `cargo bench` passes --bench; `cargo test --benches` does not.
    if std::env::args().any(|a| a == "--list") {
        println!("poll: bench");
        return;
    }
    if !std::env::args().any(|a| a == "--bench") {
        QUICK.store(true, Ordering::Relaxed);
        println!("quick run (no --bench): a smoke test, the numbers mean nothing");
    }
    let t0 = Instant::now();
    let sim = start();
    let mut raw = Raw::open(&sim);
    let stat_frame = data_frame(&StatInfo::<Status>::new());
    let dyn_frame = data_frame(&Dynamic { axis: ALL_AXES });
    assert_eq!(raw.exchange(&stat_frame), ftype::DATA_RESP);
    assert_eq!(raw.exchange(&dyn_frame), ftype::DATA_RESP);
    let mut base = || {
        raw.exchange(&stat_frame);
    };

    let h = alloc(&sim);
    assert_eq!(statinfo(h), EW_OK);
    assert_eq!(rddynamic2(h), EW_OK);
    assert_eq!(poll(h), [EW_OK; POLL_CALLS], "a poll call failed");

    println!();
    println!(
        "baseline: one pre-encoded cnc_statinfo frame (3 subpackets) on a raw TCP_NODELAY \
         socket to the same simulator"
    );
    println!(
        "{:<44} {:>12}  {:>12}  {:>7}",
        "", "time", "baseline", "ratio"
    );

    // 1. Round trip.
    println!("-- 1. round trip (per call)");
    let c = compare(2000, 1, &mut base, &mut || {
        let _ = statinfo(h);
    });
    row("cnc_statinfo", &c, "vs 1 raw round trip");
    let c = compare(2000, 1, &mut base, &mut || {
        let _ = rddynamic2(h);
    });
    row(
        "cnc_rddynamic2(ALL_AXES), 540 bytes",
        &c,
        "vs 1 raw round trip",
    );
    // The same 9-subpacket frame without the library: wire + simulator cost
    // of the bigger frame, so the library's share can be told apart.
    let mut raw2 = Raw::open(&sim);
    let c = compare(2000, 1, &mut base, &mut || {
        raw2.exchange(&dyn_frame);
    });
    row(
        "raw rddynamic2 frame (9 subpackets)",
        &c,
        "vs 1 raw round trip",
    );
    raw2.close();

    // 2. The adapter's poll loop.
    println!("-- 2. MTConnect adapter poll ({POLL_CALLS} calls)");
    let c = compare(300, POLL_CALLS, &mut base, &mut || {
        let _ = poll(h);
    });
    row(
        "poll iteration",
        &c,
        &format!("vs {POLL_CALLS} raw round trips"),
    );

    // 3. 1,000 handles on one connection pair.
    println!("-- 3. 1,000 handles to one simulator (one shared connection pair)");
    let sim3 = start();
    let first = alloc(&sim3);
    let before = rss();
    let heap_before = HEAP.load(Ordering::Relaxed);
    let t = Instant::now();
    let mut hs = vec![first];
    hs.extend((1..1000).map(|_| alloc(&sim3)));
    let alloc_us = t.elapsed().as_secs_f64() * 1e6 / 999.0;
    let per_handle = (rss() as f64 - before as f64) / 999.0;
    let heap_per_handle = (HEAP.load(Ordering::Relaxed) - heap_before) as f64 / 999.0;
    let last = hs[999];
    assert_eq!(sim3.sessions(), 1, "handles must share one pair");
    assert_eq!(statinfo(last), EW_OK);
    let c = compare(
        2000,
        1,
        &mut || {
            let _ = statinfo(first);
        },
        &mut || {
            let _ = statinfo(last);
        },
    );
    row(
        "cnc_statinfo on handle #1000",
        &c,
        "vs cnc_statinfo on handle #1",
    );
    println!(
        "{:<44} {alloc_us:>9.1} µs   (cnc_allclibhndl3 on an open pair)",
        "allocating a handle"
    );
    println!(
        "{:<44} {per_handle:>9.0} B    (RSS delta / 999, page granular)",
        "memory per handle"
    );
    println!(
        "{:<44} {heap_per_handle:>9.0} B    (live heap bytes delta / 999)",
        "heap per handle"
    );
    for x in hs {
        assert_eq!(cnc_freelibhndl(x), EW_OK);
    }
    drop(sim3);

    // 4. 50 machines polled in turn from one thread.
    println!("-- 4. 50 simulators, cnc_statinfo on each in turn from one thread");
    let sims: Vec<Simulator> = (0..50).map(|_| start()).collect();
    let handles: Vec<c_ushort> = sims.iter().map(alloc).collect();
    for x in &handles {
        assert_eq!(statinfo(*x), EW_OK);
    }
    let c = compare(150, 50, &mut base, &mut || {
        for x in &handles {
            let _ = statinfo(*x);
        }
    });
    row("round over 50 machines", &c, "vs 50 raw round trips");
    // The same round on the bare wire, alternating with the library's: what
    // 50 machines cost without the library (50 simulators' threads woken in
    // turn, 50 cold sockets), so the library's share can be told apart.
    let mut raws: Vec<Raw> = sims.iter().map(Raw::open).collect();
    let c = compare(
        150,
        1,
        &mut || {
            for r in &mut raws {
                r.exchange(&stat_frame);
            }
        },
        &mut || {
            for x in &handles {
                let _ = statinfo(*x);
            }
        },
    );
    row(
        "round over 50 machines",
        &c,
        "vs raw frames to the same 50 machines",
    );
    raws.into_iter().for_each(Raw::close);
    for x in handles {
        assert_eq!(cnc_freelibhndl(x), EW_OK);
    }
    drop(sims);

    assert_eq!(cnc_freelibhndl(h), EW_OK);
    raw.close();
    println!(
        "\ntimes are medians of alternating samples (baseline, candidate, ...); \
         total {:.1} s",
        t0.elapsed().as_secs_f64()
    );
}
