//! Reliability under load and outages, through the C API: many threads
//! allocating, calling and freeing handles against one simulator and
//! against several, with file descriptors and memory back where they
//! started; handles polling a simulator that is killed and started again
//! on the same port; a write whose connection drops while it is in flight,
//! never sent again. Each test is bounded (fixed call counts, every wait
//! on a condition with a deadline) and deterministic in what it checks.
//! The wire faults against every family of calls are in
//! tests/robust/wire_faults.rs, bad C arguments in tests/bad_input.rs.

mod common;
#[allow(dead_code)]
mod deviations;
mod guard;
mod sim;

use fwlib32::ew::*;
use fwlib32::sim::fleet::TraceTo;
use fwlib32::sim::profile::fault::Fault;
use fwlib32::sim::{Fleet, FleetOptions, Profile, Simulator};
use fwlib32::types::{IODBPSD, ODBAXIS, ODBDY2, ODBERR, ODBM, ODBST};
use fwlib32::*;
use guard::{Hostile, Mode};
use std::alloc::{GlobalAlloc, Layout, System};
use std::ffi::CString;
use std::os::raw::{c_short, c_ushort};
use std::sync::atomic::{AtomicBool, AtomicIsize, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Bytes allocated and not yet freed, by everything in this process.
struct Counting;
static LIVE: AtomicIsize = AtomicIsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        LIVE.fetch_add(l.size() as isize, Ordering::Relaxed);
        unsafe { System.alloc(l) }
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        LIVE.fetch_sub(l.size() as isize, Ordering::Relaxed);
        unsafe { System.dealloc(p, l) }
    }
    unsafe fn realloc(&self, p: *mut u8, l: Layout, new: usize) -> *mut u8 {
        LIVE.fetch_add(new as isize - l.size() as isize, Ordering::Relaxed);
        unsafe { System.realloc(p, l, new) }
    }
}

#[global_allocator]
static A: Counting = Counting;

/// Handles' timeout, seconds.
const TIMEOUT: i32 = 1;
/// Longest a call may take: its timeout and a margin for a loaded machine.
const BOUND: Duration = Duration::from_secs(TIMEOUT as u64 + 8);

/// Waits until `cond` holds; fails after `secs` seconds.
fn until(what: &str, secs: u64, cond: impl Fn() -> bool) {
    let end = Instant::now() + Duration::from_secs(secs);
    while !cond() {
        assert!(Instant::now() < end, "timed out waiting for {what}");
        std::thread::yield_now();
    }
}

fn alloc(host: &str, port: u16) -> Result<c_ushort, c_short> {
    let ip = CString::new(host).unwrap();
    let mut h = 0;
    match unsafe { cnc_allclibhndl3(ip.as_ptr(), port, TIMEOUT as _, &mut h) } {
        EW_OK => Ok(h),
        r => Err(r),
    }
}

/// A call and how long it took.
fn timed(f: impl FnOnce() -> c_short) -> (c_short, Duration) {
    let t = Instant::now();
    let r = f();
    (r, t.elapsed())
}

fn statinfo(h: c_ushort) -> c_short {
    let mut st = ODBST::default();
    unsafe { cnc_statinfo(h, &mut st) }
}

/// Open file descriptors of this process.
fn fds() -> usize {
    std::fs::read_dir("/proc/self/fd").unwrap().count()
}

/// Tests of this file measure the whole process (descriptors, memory):
/// they run one at a time.
static SERIAL: Mutex<()> = Mutex::new(());

fn serial() -> std::sync::MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

/// `threads` threads, each `rounds` times: a handle to one of `ports` (in
/// turn), four calls of different areas, the handle freed. Every call
/// returns EW_OK.
fn churn(ports: &[u16], threads: usize, rounds: usize) {
    std::thread::scope(|s| {
        for t in 0..threads {
            s.spawn(move || {
                for r in 0..rounds {
                    let port = ports[(t + r) % ports.len()];
                    let h = alloc("127.0.0.1", port).expect("a handle");
                    let mut st = ODBST::default();
                    let mut p = IODBPSD::default();
                    let mut m = ODBM::default();
                    let mut ax = ODBAXIS::default();
                    let codes = unsafe {
                        [
                            cnc_statinfo(h, &mut st),
                            cnc_rdparam(h, 6711, 0, 8, &mut p),
                            cnc_rdmacro(h, 500, 10, &mut m),
                            cnc_absolute(h, 1, 8, &mut ax),
                        ]
                    };
                    assert_eq!(codes, [EW_OK; 4], "thread {t} round {r}");
                    assert_eq!(cnc_freelibhndl(h), EW_OK);
                }
            });
        }
    });
}

/// Churns against the simulators of `sessions` (their open-session
/// counts), first to warm up (the handle table and the allocator's pools
/// reach their size), then measured: descriptors back to where they were,
/// memory within `slack` bytes.
fn churn_and_measure(ports: &[u16], sessions: impl Fn() -> usize) {
    const THREADS: usize = 8;
    // FWLIB32_SOAK=<rounds per thread>: a longer run by hand (docs/reliability.md,
    // "Reliability and fuzzing"); 25 in CI.
    let rounds: usize = std::env::var("FWLIB32_SOAK")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(25);
    churn(ports, THREADS, 2);
    until("the warm-up sessions to close", 10, || sessions() == 0);
    let (fd0, mem0) = (fds(), LIVE.load(Ordering::Relaxed));
    churn(ports, THREADS, rounds);
    until("every session to close", 10, || sessions() == 0);
    // A session's count drops just before its socket closes, and a
    // simulator of an earlier test may still be closing its own: wait
    // (bounded) for the count to come back, then compare.
    let end = Instant::now() + Duration::from_secs(10);
    while fds() > fd0 && Instant::now() < end {
        std::thread::yield_now();
    }
    let (fd1, mem1) = (fds(), LIVE.load(Ordering::Relaxed));
    println!(
        "{} handles, {} calls on {} simulator(s): descriptors {fd0} -> {fd1}, live bytes {mem0} -> {mem1}",
        THREADS * rounds,
        THREADS * rounds * 4,
        ports.len()
    );
    assert!(fd1 <= fd0, "file descriptors leaked: {fd0} -> {fd1}");
    // A few kilobytes may move (a pool, a timer wheel): a leak per handle
    // or per call would be hundreds of kilobytes.
    let slack = 64 * 1024;
    assert!(
        mem1 - mem0 < slack,
        "memory grew by {} bytes over {} handles",
        mem1 - mem0,
        THREADS * rounds
    );
}

#[test]
fn many_threads_against_one_simulator_leave_nothing_behind() {
    let _g = serial();
    let s = sim::start(Profile::default());
    churn_and_measure(&[s.port()], || s.sessions());
}

#[test]
fn many_threads_against_several_simulators_leave_nothing_behind() {
    let _g = serial();
    let fleet = Fleet::start(
        &[Profile::default()],
        "127.0.0.1:0",
        FleetOptions {
            machines: Some(4),
            worker_threads: Some(2),
            ..FleetOptions::default()
        },
    )
    .expect("fleet");
    let ports: Vec<u16> = (0..4).map(|i| fleet.port(i)).collect();
    churn_and_measure(&ports, || (0..4).map(|i| fleet.sessions(i)).sum());
}

/// A simulator on `port` again: the old one's listener closes in the
/// background, so binding is retried until the port is free.
fn restart(port: u16) -> Simulator {
    let end = Instant::now() + Duration::from_secs(10);
    loop {
        match Simulator::start(Profile::default(), &format!("127.0.0.1:{port}")) {
            Ok(s) => return s,
            Err(e) if Instant::now() < end => {
                assert_eq!(e.kind(), std::io::ErrorKind::AddrInUse, "{e}");
                std::thread::yield_now();
            }
            Err(e) => panic!("port {port} still taken: {e}"),
        }
    }
}

/// What a polling thread saw.
#[derive(Default)]
struct Seen {
    ok: AtomicUsize,
    failed: AtomicUsize,
    /// Failures other than EW_SOCKET within the bound.
    bad: Mutex<Vec<String>>,
}

#[test]
fn handles_polling_a_simulator_killed_and_restarted() {
    let _g = serial();
    let s = sim::start(Profile::default());
    let port = s.port();
    let mut s = Some(s);
    // Three handles on two connection pairs (the library keeps one per
    // host string and port): two reconnect, one keeps FANUC's default.
    let handles = [
        (alloc("127.0.0.1", port).unwrap(), true),
        (alloc("127.0.0.1", port).unwrap(), true),
        (alloc("localhost", port).unwrap(), false),
    ];
    for (h, re) in handles {
        assert_eq!(fwlib_set_reconnect(h, re as _), EW_OK);
    }
    let stop = AtomicBool::new(false);
    let seen: Vec<Arc<Seen>> = (0..3).map(|_| Arc::default()).collect();
    std::thread::scope(|sc| {
        for (i, (h, _)) in handles.iter().enumerate() {
            let (seen, stop, h) = (seen[i].clone(), &stop, *h);
            sc.spawn(move || {
                // A fixed number of polls at most: the test ends them sooner.
                for _ in 0..200_000 {
                    if stop.load(Ordering::Relaxed) {
                        return;
                    }
                    let (r, took) = timed(|| statinfo(h));
                    if r == EW_OK {
                        seen.ok.fetch_add(1, Ordering::Relaxed);
                    } else {
                        seen.failed.fetch_add(1, Ordering::Relaxed);
                        if r != EW_SOCKET || took > BOUND {
                            seen.bad
                                .lock()
                                .unwrap()
                                .push(format!("handle {h}: {r} after {took:?}"));
                        }
                        // The CNC is away: no need to spin faster than
                        // a connect attempt takes.
                        std::thread::yield_now();
                    }
                }
            });
        }
        let ok = |i: usize| seen[i].ok.load(Ordering::Relaxed);
        let failed = |i: usize| seen[i].failed.load(Ordering::Relaxed);
        until("every handle to poll", 10, || (0..3).all(|i| ok(i) >= 5));
        drop(s.take());
        until("every handle to notice the outage", 10, || {
            (0..3).all(|i| failed(i) >= 3)
        });
        let before: Vec<usize> = (0..3).map(ok).collect();
        let _back = restart(port);
        until("the reconnecting handles to work again", 10, || {
            ok(0) > before[0] && ok(1) > before[1]
        });
        stop.store(true, Ordering::Relaxed);
        // The plain handle stays failed (FANUC's behaviour) ...
        assert_eq!(ok(2), before[2], "no reconnection without the extension");
        assert_eq!(statinfo(handles[2].0), EW_SOCKET);
        // ... and so does cnc_resetconnect (tests/robust/reconnect.rs): a new handle works.
        assert_eq!(cnc_resetconnect(handles[2].0), EW_OK);
        assert_eq!(statinfo(handles[2].0), EW_SOCKET);
        assert_eq!(cnc_freelibhndl(handles[2].0), EW_OK);
        let h = alloc("localhost", port).expect("a new handle");
        assert_eq!(statinfo(h), EW_OK);
        assert_eq!(cnc_freelibhndl(h), EW_OK);
        for (h, _) in handles.iter().take(2) {
            assert_eq!(statinfo(*h), EW_OK);
            assert_eq!(cnc_freelibhndl(*h), EW_OK);
        }
    });
    for s in &seen {
        let bad = s.bad.lock().unwrap();
        assert!(bad.is_empty(), "{bad:?}");
    }
}

/// Trace lines, shared with the test.
#[derive(Clone, Default)]
struct Lines(Arc<Mutex<Vec<u8>>>);

impl std::io::Write for Lines {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        self.0.lock().unwrap().extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl Lines {
    /// Requests of `function` the simulator received.
    fn requests(&self, function: &str) -> usize {
        let text = String::from_utf8_lossy(&self.0.lock().unwrap()).into_owned();
        let want = format!("<- data {function} ");
        text.lines().filter(|l| l.contains(&want)).count()
    }
}

/// One machine with `fault`, traced into lines the test reads; its clock at 1 s.
fn traced_machine(fault: &str) -> (Fleet, Lines) {
    let lines = Lines::default();
    let f = Fleet::start(
        &[Profile::default()],
        "127.0.0.1:0",
        FleetOptions {
            faults: vec![Fault::parse_spec(fault).unwrap()],
            worker_threads: Some(1),
            trace: Some(TraceTo::Writer(Box::new(lines.clone()))),
            ..FleetOptions::default()
        },
    )
    .expect("simulator");
    f.set_elapsed(Duration::from_secs(1));
    (f, lines)
}

fn wrmacro(h: c_ushort, v: i32) -> c_short {
    timed(|| unsafe { cnc_wrmacro(h, 510, 10, v as _, 0) }).0
}

fn rdmacro(h: c_ushort) -> (c_short, i32) {
    let mut m = ODBM::default();
    let (r, took) = timed(|| unsafe { cnc_rdmacro(h, 510, 10, &mut m) });
    assert!(took < BOUND, "cnc_rdmacro took {took:?}");
    (r, m.mcr_val)
}

/// A write whose answer is lost (`fault` from 10 s to 20 s; the CNC did
/// the write if `done`) is sent once; the calls after it, on a reconnecting
/// handle and on a plain one, never send it again.
fn write_in_flight(fault: &str, done: bool) {
    let (f, lines) = traced_machine(fault);
    for reconnect in [true, false] {
        f.set_elapsed(Duration::from_secs(1));
        let h = alloc("127.0.0.1", f.port(0)).expect("a handle");
        assert_eq!(fwlib_set_reconnect(h, reconnect as _), EW_OK);
        let before = lines.requests("cnc_wrmacro");
        assert_eq!(wrmacro(h, 1), EW_OK);
        f.set_elapsed(Duration::from_secs(12));
        let t = Instant::now();
        assert_eq!(wrmacro(h, 4242), EW_SOCKET, "the answer was lost");
        assert!(t.elapsed() < BOUND, "{:?}", t.elapsed());
        f.set_elapsed(Duration::from_secs(30));
        let (r, v) = rdmacro(h);
        if reconnect {
            let v_now = if done { 4242 } else { 1 };
            assert_eq!((r, v), (EW_OK, v_now), "the value the CNC holds");
        } else {
            assert_eq!(r, EW_SOCKET, "FANUC's default: the handle stays failed");
        }
        // More calls, reads and a new write: only the new write is sent.
        for _ in 0..3 {
            let _ = rdmacro(h);
        }
        let expect = if reconnect {
            assert_eq!(wrmacro(h, 7), EW_OK);
            3
        } else {
            2
        };
        assert_eq!(
            lines.requests("cnc_wrmacro") - before,
            expect,
            "writes the simulator received (reconnect {reconnect})"
        );
        let _ = cnc_freelibhndl(h);
    }
}

#[test]
fn a_write_whose_answer_is_reset_is_never_sent_again() {
    let _g = serial();
    write_in_flight("reset:at=10,duration=10", true);
}

#[test]
fn a_write_whose_answer_never_comes_is_never_sent_again() {
    let _g = serial();
    // A silent CNC took the frame and did nothing.
    write_in_flight("silent:at=10,duration=10", false);
}

#[test]
fn a_write_whose_answer_is_cut_by_a_close_is_never_sent_again() {
    let _g = serial();
    write_in_flight("close:at=10,duration=10", true);
}

// ---------------------------------------------------------------------------
// A hostile CNC (tests/guard): answers that are not this call's, frames of
// the wrong type on connection 1, waits behind stuck calls. Every call's
// time is measured and bounded by its own timeout and MARGIN.
// ---------------------------------------------------------------------------

/// What a loaded machine may add to a call's own timeout.
const MARGIN: Duration = Duration::from_secs(2);

/// The detail words cnc_getdtailerr reports on `h`.
fn detail(h: c_ushort) -> (i16, i16) {
    let mut e = ODBERR::default();
    assert_eq!(unsafe { cnc_getdtailerr(h, &mut e) }, EW_OK);
    (e.err_no, e.err_dtno)
}

/// `f` on `h`, asserted to return within the handle's timeout and MARGIN.
fn bounded(what: &str, f: impl FnOnce() -> c_short) -> c_short {
    let (r, took) = timed(f);
    assert!(
        took <= Duration::from_secs(TIMEOUT as u64) + MARGIN,
        "{what} took {took:?}"
    );
    r
}

#[test]
fn a_reply_that_does_not_echo_the_request_is_never_ew_ok() {
    let _g = serial();
    let listed = deviations::UNRECORDED
        .iter()
        .any(|d| d.test == "reliability::a_reply_that_does_not_echo_the_request_is_never_ew_ok");
    assert!(
        listed,
        "the reply check is a listed deviation (tests/deviations)"
    );
    for mode in [Mode::Plain, Mode::OtherCommand, Mode::Reversed] {
        let cnc = Hostile::start(mode);
        let h = alloc("127.0.0.1", cnc.port).expect("the open and start-up are plain");
        let mut dy = ODBDY2::default();
        let mut m = ODBM::default();
        // cnc_statinfo: 3 subpackets (0x19, 0xe1, 0x98); cnc_rddynamic2 (all axes): 9.
        let st = bounded("cnc_statinfo", || statinfo(h));
        let dyn2 = bounded("cnc_rddynamic2", || unsafe {
            cnc_rddynamic2(h, -1, std::mem::size_of::<ODBDY2>() as _, &mut dy)
        });
        // One subpacket each: reversed, it is the same answer.
        let wr = bounded("cnc_wrmacro", || unsafe { cnc_wrmacro(h, 510, 10, 77, 0) });
        let rd = bounded("cnc_rdmacro", || unsafe { cnc_rdmacro(h, 510, 10, &mut m) });
        match mode {
            Mode::Plain => assert_eq!([st, dyn2, wr, rd], [EW_OK; 4], "the fake CNC works"),
            Mode::OtherCommand => {
                // A cnc_wrmacro answered with cnc_statinfo's answer is no success.
                assert_eq!([st, dyn2, wr, rd], [EW_PROTOCOL; 4], "{mode:?}");
                assert_eq!(detail(h), (3, 0));
            }
            _ => {
                assert_eq!([st, dyn2], [EW_PROTOCOL; 2], "{mode:?}");
                assert_eq!([wr, rd], [EW_OK; 2], "{mode:?}: one subpacket, in order");
            }
        }
        assert_eq!(cnc_freelibhndl(h), EW_OK);
    }
}

/// cnc_upload3 until the upload ends: the code it ended with and the text
/// read. Waits for text by calling again (EW_BUFFER: nothing yet), at most
/// the handle's timeout and MARGIN.
fn upload_all(h: c_ushort) -> (c_short, Vec<u8>) {
    let end = Instant::now() + Duration::from_secs(TIMEOUT as u64) + MARGIN;
    let mut all = Vec::new();
    loop {
        let mut buf = [0u8; 1024];
        let mut len = buf.len() as _;
        match unsafe { cnc_upload3(h, &mut len, buf.as_mut_ptr().cast()) } {
            EW_OK => all.extend_from_slice(&buf[..len as usize]),
            EW_BUFFER => assert!(Instant::now() < end, "the upload never ended"),
            r => return (r, all),
        }
    }
}

#[test]
fn a_frame_of_the_wrong_type_on_connection_1_is_never_dropped_in_silence() {
    let _g = serial();
    // An upload whose text frames are typed 0x2102 instead of 0x1604.
    for mode in [Mode::Plain, Mode::UploadWrongType] {
        let cnc = Hostile::start(mode);
        let h = alloc("127.0.0.1", cnc.port).expect("a handle");
        assert_eq!(
            bounded("cnc_upstart3", || cnc_upstart3(h, 0, 1, 9999)),
            EW_OK
        );
        let (ended, text) = upload_all(h);
        let end = bounded("cnc_upend3", || cnc_upend3(h));
        if mode == Mode::Plain {
            assert!(!text.is_empty(), "the fake CNC uploads its programs");
            assert_eq!((ended, end), (EW_RESET, EW_OK));
        } else {
            assert!(text.is_empty(), "no 0x1604 frame came");
            assert_eq!(ended, EW_PROTOCOL, "never an upload ended as complete");
            assert_eq!(end, EW_PROTOCOL, "cnc_upend3 reports no success");
        }
        assert_eq!(cnc_freelibhndl(h), EW_OK);
    }
    // A download and a DNC operation answered by a stray 0x2102 frame
    // after their first data frame: their end reports no success.
    let text = b"\nO0123\nG01X1.\nM30\n%";
    for mode in [Mode::Plain, Mode::DownloadWrongType] {
        let cnc = Hostile::start(mode);
        let h = alloc("127.0.0.1", cnc.port).expect("a handle");
        assert_eq!(bounded("cnc_dwnstart3", || cnc_dwnstart3(h, 0)), EW_OK);
        let mut len = text.len() as _;
        let sent = bounded("cnc_download3", || unsafe {
            cnc_download3(h, &mut len, text.as_ptr().cast_mut().cast())
        });
        assert_eq!(sent, EW_OK, "cnc_download3: the stray frame comes after it");
        let end = bounded("cnc_dwnend3", || cnc_dwnend3(h));
        let expect = if mode == Mode::Plain {
            EW_OK
        } else {
            EW_PROTOCOL
        };
        assert_eq!((mode, end), (mode, expect), "cnc_dwnend3");

        assert_eq!(bounded("cnc_dncstart", || cnc_dncstart(h)), EW_OK);
        let sent = bounded("cnc_dnc", || unsafe {
            cnc_dnc(h, text.as_ptr().cast_mut().cast(), text.len() as _)
        });
        assert_eq!(sent, EW_OK, "cnc_dnc: the stray frame comes after it");
        let end = bounded("cnc_dncend", || cnc_dncend(h));
        assert_eq!((mode, end), (mode, expect), "cnc_dncend");
        assert_eq!(cnc_freelibhndl(h), EW_OK);
    }
}

/// A handle to the fake CNC with `timeout` seconds (0: forever).
fn alloc_with(port: u16, timeout: i32) -> Result<c_ushort, c_short> {
    let ip = CString::new("127.0.0.1").unwrap();
    let mut h = 0;
    match unsafe { cnc_allclibhndl3(ip.as_ptr(), port, timeout as _, &mut h) } {
        EW_OK => Ok(h),
        r => Err(r),
    }
}

/// Asserts `took` is within `timeout` seconds and MARGIN; prints the overshoot.
fn within(what: &str, took: Duration, timeout: u64) {
    let bound = Duration::from_secs(timeout);
    println!(
        "{what}: {took:?} (its timeout {timeout} s, over it by {:?})",
        took.saturating_sub(bound)
    );
    assert!(took <= bound + MARGIN, "{what} took {took:?}");
}

#[test]
fn a_short_timeout_handle_behind_a_stuck_one_waits_only_its_own_timeout() {
    let _g = serial();
    // A's timeout 0 (forever) and 6 s: B (1 s) waits 1 s either way.
    for a_timeout in [0, 6] {
        let cnc = Hostile::start(Mode::SilentData);
        let a = alloc_with(cnc.port, a_timeout).expect("handle A");
        let b = alloc_with(cnc.port, TIMEOUT).expect("handle B, sharing A's pair");
        std::thread::scope(|s| {
            let stuck = s.spawn(|| timed(|| statinfo(a)));
            until("A's request at the CNC", 10, || {
                cnc.data.load(Ordering::SeqCst) >= 1
            });
            let (r, took) = timed(|| statinfo(b));
            within("B behind A", took, TIMEOUT as u64);
            assert_eq!(r, EW_BUSY, "B: the connection stayed busy, nothing sent");
            assert_eq!(cnc.data.load(Ordering::SeqCst), 1, "B sent nothing");
            // Freeing both returns at once and ends A's call (EW_SOCKET).
            let (r, took) = timed(|| cnc_freelibhndl(b) + cnc_freelibhndl(a));
            within("cnc_freelibhndl of A and B while A waits", took, 0);
            assert_eq!(r, EW_OK);
            let (r, _) = stuck.join().unwrap();
            assert_eq!(r, EW_SOCKET, "A's call ends when its pair is closed");
        });
    }
}

#[test]
fn an_alloc_behind_a_stuck_alloc_waits_only_its_own_timeout() {
    let _g = serial();
    let cnc = Hostile::start(Mode::SilentOpen);
    std::thread::scope(|s| {
        // A: no timeout, its open never answered.
        let stuck = s.spawn(|| alloc_with(cnc.port, 0));
        until("A's connection", 10, || {
            cnc.accepted.load(Ordering::SeqCst) >= 1
        });
        let t = Instant::now();
        let r = alloc_with(cnc.port, TIMEOUT);
        within(
            "cnc_allclibhndl3 behind a stuck one",
            t.elapsed(),
            TIMEOUT as u64,
        );
        assert_eq!(r, Err(EW_SOCKET));
        // The CNC closing its connections ends A (EW_SOCKET).
        cnc.close_all();
        assert_eq!(stuck.join().unwrap(), Err(EW_SOCKET));
    });
}

#[test]
fn exitprocess_while_a_call_is_blocked_returns_at_once() {
    let _g = serial();
    let cnc = Hostile::start(Mode::SilentData);
    let a = alloc_with(cnc.port, 0).expect("a handle without timeout");
    std::thread::scope(|s| {
        let stuck = s.spawn(|| timed(|| statinfo(a)));
        until("the request at the CNC", 10, || {
            cnc.data.load(Ordering::SeqCst) >= 1
        });
        let t = Instant::now();
        assert_eq!(cnc_exitprocess(), EW_OK);
        within("cnc_exitprocess while a call waits", t.elapsed(), 0);
        let (r, _) = stuck.join().unwrap();
        within("the blocked call after cnc_exitprocess", t.elapsed(), 0);
        assert_eq!(r, EW_SOCKET);
    });
    assert_eq!(cnc_freelibhndl(a), EW_HANDLE, "cnc_exitprocess freed it");
}

#[test]
fn a_silent_dripping_or_truncating_cnc_ends_each_call_by_its_timeout() {
    let _g = serial();
    for mode in [Mode::SilentData, Mode::Drip, Mode::Truncated] {
        let cnc = Hostile::start(mode);
        let h = alloc_with(cnc.port, TIMEOUT).expect("a handle");
        let (r, took) = timed(|| statinfo(h));
        within(&format!("cnc_statinfo, {mode:?}"), took, TIMEOUT as u64);
        assert_eq!(r, EW_SOCKET, "{mode:?}");
        // The pair is torn down: the next call fails at once, as FANUC's.
        let (r, took) = timed(|| statinfo(h));
        within(&format!("the next call, {mode:?}"), took, 0);
        assert_eq!(r, EW_SOCKET);
        let (r, took) = timed(|| cnc_freelibhndl(h));
        within(&format!("cnc_freelibhndl, {mode:?}"), took, 0);
        assert_eq!(r, EW_OK);
    }
}
