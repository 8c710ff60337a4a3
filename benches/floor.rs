//! The library's per-call cost against the floor: a plain-socket client
//! sending the same bytes to the same simulator, measured in the same run
//! (ratios, never timed assertions). Run with `cargo bench --bench floor`
//! (about 25 s), or some sections: `cargo bench --bench floor -- threads`
//! (pinned, syscalls, threads, loading); `FLOOR_THREADS=4,8` runs only
//! those thread counts.
//!
//! The **floor** is the least any client can do for `cnc_statinfo`: one
//! pre-encoded data frame (3 subpackets) written to a std `TcpStream` with
//! `TCP_NODELAY`, and the answer read into a fixed buffer until the whole
//! frame is in (one `recv` when it has all arrived), on a session opened by
//! hand with the codec.
//!
//! 1. One thread pinned to one core (`sched_setaffinity`; the simulator's
//!    threads run where the scheduler puts them): p50 latency of single
//!    calls, alternating floor and library, and CPU time per call of the
//!    calling thread (`CLOCK_THREAD_CPUTIME_ID` around alternating batches).
//! 2. System calls per call: this program runs itself under `strace` (when
//!    it is installed) in a child mode that does N floor exchanges, then N
//!    `cnc_statinfo`, between marker `getppid` calls on its main thread; the
//!    simulator's threads are not traced (no `-f`). Every system call of the
//!    calling thread is counted, not only the network ones.
//! 3. Threads: 1 … 64 threads, each on its own simulated CNC, then all on
//!    one CNC; aggregate calls/s against plain-socket threads doing the
//!    same (on one CNC: sharing one socket under a mutex, as the library
//!    shares one connection pair per CNC, as FANUC's does). The same
//!    threads run 25 ms of floor and 25 ms of library calls in turn, 30
//!    times; the ratio is the median of the 30 ratios. On one CNC each
//!    thread count runs `FLOOR_RUNS` times (3): every run's ratio is shown,
//!    and the library's rate against its own 1-thread rate.
//! 4. Loading: a C host (benches/load.c, built with `cc`) timing `dlopen`,
//!    the first `cnc_allclibhndl3`, `cnc_freelibhndl` and `dlclose` of the
//!    library this bench was built with, one fresh process per sample,
//!    against `dlopen` + `dlclose` of an empty C library.

mod common;
use common::{alloc, data_frame, start};
use fwlib32::ew::EW_OK;
use fwlib32::proto::frame::{CLIENT_VERSION, Frame, FrameHeader, HEADER_LEN, ftype};
use fwlib32::proto::status::{StatInfo, Status};
use fwlib32::sim::Simulator;
use fwlib32::types::ODBST;
use fwlib32::{cnc_freelibhndl, cnc_statinfo};
use std::collections::BTreeMap;
use std::io::{Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::os::raw::{c_short, c_ushort};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Barrier, Mutex};
use std::time::{Duration, Instant};

/// Run as a test (`cargo test --benches`, no `--bench` argument): a few
/// samples only, to see that everything works; the numbers mean nothing.
static QUICK: AtomicBool = AtomicBool::new(false);

fn quick() -> bool {
    QUICK.load(Ordering::Relaxed)
}

/// `n`, or `q` in a quick run.
fn count(n: usize, q: usize) -> usize {
    if quick() { q } else { n }
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

// ---------------------------------------------------------------------------
// The floor: a plain socket

/// A session opened by hand, then pre-encoded frames; answers are read into
/// a fixed buffer until the whole frame is in.
struct Plain {
    stream: TcpStream,
    buf: Box<[u8; 16384]>,
}

impl Plain {
    fn open(addr: SocketAddr) -> Plain {
        let stream = TcpStream::connect(addr).expect("connect");
        stream.set_nodelay(true).expect("nodelay");
        let mut p = Plain {
            stream,
            buf: Box::new([0; 16384]),
        };
        let open = Frame::new(CLIENT_VERSION, ftype::OPEN_REQ, 1u16.to_be_bytes().to_vec());
        assert_eq!(p.exchange(&open.encode()), ftype::OPEN_RESP);
        p
    }

    /// Writes one frame, reads one frame; returns the answer's type word.
    fn exchange(&mut self, frame: &[u8]) -> u16 {
        self.stream.write_all(frame).expect("send");
        let mut got = 0;
        loop {
            if got >= HEADER_LEN {
                let h = FrameHeader::decode(&self.buf[..HEADER_LEN]).expect("header");
                if got >= HEADER_LEN + h.len as usize {
                    return h.ftype;
                }
            }
            let n = self.stream.read(&mut self.buf[got..]).expect("receive");
            assert!(n > 0, "the simulator closed the connection");
            got += n;
        }
    }

    fn close(mut self) {
        let close = Frame::new(CLIENT_VERSION, ftype::CLOSE_REQ, Vec::new());
        assert_eq!(self.exchange(&close.encode()), ftype::CLOSE_RESP);
    }
}

// ---------------------------------------------------------------------------
// The library, through its C ABI

fn statinfo(h: c_ushort) -> c_short {
    let mut st: ODBST = unsafe { std::mem::zeroed() };
    unsafe { cnc_statinfo(h, &mut st) }
}

// ---------------------------------------------------------------------------
// 1. One pinned thread: latency and CPU time

/// Pins the calling thread to the last CPU it may run on; returns that CPU.
fn pin_last_cpu() -> Option<usize> {
    unsafe {
        let mut set: libc::cpu_set_t = std::mem::zeroed();
        let size = size_of::<libc::cpu_set_t>();
        if libc::sched_getaffinity(0, size, &mut set) != 0 {
            return None;
        }
        let cpu = (0..libc::CPU_SETSIZE as usize)
            .rev()
            .find(|c| libc::CPU_ISSET(*c, &set))?;
        let mut one: libc::cpu_set_t = std::mem::zeroed();
        libc::CPU_SET(cpu, &mut one);
        (libc::sched_setaffinity(0, size, &one) == 0).then_some(cpu)
    }
}

/// CPU time the calling thread has used, in nanoseconds.
fn thread_cpu_ns() -> f64 {
    let mut ts: libc::timespec = unsafe { std::mem::zeroed() };
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    ts.tv_sec as f64 * 1e9 + ts.tv_nsec as f64
}

struct Pinned {
    cpu: Option<usize>,
    /// p50 µs per call: floor, library.
    p50: (f64, f64),
    /// Median over batches of CPU µs per call: floor, library.
    cpu_us: (f64, f64),
}

fn pinned(sim: &Simulator, frame: &[u8]) -> Pinned {
    let cpu = pin_last_cpu();
    let mut plain = Plain::open(sim.addr());
    let h = alloc(sim);
    let mut floor = || {
        plain.exchange(frame);
    };
    let ours = || {
        statinfo(h);
    };
    for _ in 0..count(500, 5) {
        floor();
        ours();
    }
    let samples = count(5000, 5);
    let (mut a, mut b) = (Vec::with_capacity(samples), Vec::with_capacity(samples));
    for _ in 0..samples {
        let t = Instant::now();
        floor();
        a.push(t.elapsed().as_nanos() as f64 / 1e3);
        let t = Instant::now();
        ours();
        b.push(t.elapsed().as_nanos() as f64 / 1e3);
    }
    let p50 = (median(&mut a), median(&mut b));
    let (batches, per) = (count(100, 2), count(200, 5));
    let (mut a, mut b) = (Vec::with_capacity(batches), Vec::with_capacity(batches));
    for _ in 0..batches {
        let t0 = thread_cpu_ns();
        for _ in 0..per {
            floor();
        }
        let t1 = thread_cpu_ns();
        for _ in 0..per {
            ours();
        }
        let t2 = thread_cpu_ns();
        a.push((t1 - t0) / 1e3 / per as f64);
        b.push((t2 - t1) / 1e3 / per as f64);
    }
    assert_eq!(cnc_freelibhndl(h), EW_OK);
    plain.close();
    Pinned {
        cpu,
        p50,
        cpu_us: (median(&mut a), median(&mut b)),
    }
}

// ---------------------------------------------------------------------------
// 2. System calls per call (strace)

const SYSCALLS_CHILD: &str = "--syscalls-child";

/// The child: N floor exchanges, then N cnc_statinfo, each run between
/// marker getppid calls, all on the main thread.
fn syscalls_child(n: usize) {
    let sim = start();
    let frame = data_frame(&StatInfo::<Status>::new());
    let mut plain = Plain::open(sim.addr());
    let h = alloc(&sim);
    for _ in 0..10 {
        plain.exchange(&frame);
        assert_eq!(statinfo(h), EW_OK);
    }
    unsafe { libc::getppid() };
    for _ in 0..n {
        plain.exchange(&frame);
    }
    unsafe { libc::getppid() };
    for _ in 0..n {
        statinfo(h);
    }
    unsafe { libc::getppid() };
    assert_eq!(cnc_freelibhndl(h), EW_OK);
    plain.close();
}

/// System calls by name per call, floor and library; None without strace.
type PerCall = BTreeMap<String, f64>;

fn syscalls(dir: &Path) -> Option<(PerCall, PerCall)> {
    Command::new("strace").arg("-V").output().ok()?;
    let n = count(1000, 20);
    let out = dir.join("strace.txt");
    let st = Command::new("strace")
        .arg("-o")
        .arg(&out)
        .arg(std::env::current_exe().ok()?)
        .args([SYSCALLS_CHILD, &n.to_string()])
        .status()
        .ok()?;
    assert!(st.success(), "the strace child failed");
    let text = std::fs::read_to_string(&out).ok()?;
    let mut runs: Vec<PerCall> = vec![PerCall::new()];
    let mut marks = 0;
    for line in text.lines() {
        let Some(name) = line.split('(').next().filter(|s| !s.contains(' ')) else {
            continue;
        };
        if name == "getppid" {
            marks += 1;
            runs.push(PerCall::new());
            continue;
        }
        *runs
            .last_mut()
            .unwrap()
            .entry(name.to_string())
            .or_default() += 1.0 / n as f64;
    }
    assert_eq!(marks, 3, "expected three marker getppid calls in {out:?}");
    Some((runs[1].clone(), runs[2].clone()))
}

fn describe(calls: &PerCall) -> String {
    let total: f64 = calls.values().sum();
    let parts: Vec<String> = calls
        .iter()
        .map(|(k, v)| format!("{k} {}", round2(*v)))
        .collect();
    format!("{}  ({})", round2(total), parts.join(", "))
}

fn round2(v: f64) -> String {
    let s = format!("{v:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

// ---------------------------------------------------------------------------
// 3. Threads

/// `n` threads, thread `i` calling `floor(i)` for `dur`, then (after all
/// have) `ours(i)` for `dur`, and so on for `rounds` rounds, the order
/// swapped every round so that both sides see the same machine. Returns
/// the medians over rounds of the aggregate calls/s of the floor and the
/// library (each thread's count over its own time, summed), and of their
/// ratio.
fn alternate(
    n: usize,
    floor: &(dyn Fn(usize) + Sync),
    ours: &(dyn Fn(usize) + Sync),
) -> (f64, f64, f64) {
    let (rounds, dur) = (count(30, 1), Duration::from_millis(count(25, 2) as u64));
    let barrier = Barrier::new(n);
    let run = |i: usize, f: &(dyn Fn(usize) + Sync)| {
        barrier.wait();
        let t = Instant::now();
        let mut k = 0u64;
        while !k.is_multiple_of(4) || t.elapsed() < dur {
            f(i);
            k += 1;
        }
        k as f64 / t.elapsed().as_secs_f64()
    };
    // rates[thread][round] = (floor, library)
    let rates: Vec<Vec<(f64, f64)>> = std::thread::scope(|s| {
        let ts: Vec<_> = (0..n)
            .map(|i| {
                let run = &run;
                s.spawn(move || {
                    (0..rounds)
                        .map(|r| {
                            if r % 2 == 0 {
                                let a = run(i, floor);
                                (a, run(i, ours))
                            } else {
                                let b = run(i, ours);
                                (run(i, floor), b)
                            }
                        })
                        .collect()
                })
            })
            .collect();
        ts.into_iter().map(|t| t.join().expect("thread")).collect()
    });
    let (mut a, mut b, mut r) = (vec![], vec![], vec![]);
    for round in 0..rounds {
        let x: f64 = rates.iter().map(|t| t[round].0).sum();
        let y: f64 = rates.iter().map(|t| t[round].1).sum();
        a.push(x);
        b.push(y);
        r.push(y / x);
    }
    (median(&mut a), median(&mut b), median(&mut r))
}

const THREADS: [usize; 6] = [1, 2, 4, 8, 16, 64];

/// Runs of each thread count on one CNC: `FLOOR_RUNS`, else 3 (1 quick).
fn runs() -> usize {
    std::env::var("FLOOR_RUNS")
        .ok()
        .and_then(|v| v.parse().ok())
        .filter(|n| *n > 0)
        .unwrap_or(count(3, 1))
}

/// The thread counts to run: all, or those in `FLOOR_THREADS` (`4,8`).
fn thread_counts() -> Vec<usize> {
    match std::env::var("FLOOR_THREADS") {
        Ok(v) => v
            .split(',')
            .filter_map(|n| n.trim().parse().ok())
            .filter(|n| THREADS.contains(n))
            .collect(),
        Err(_) => THREADS.to_vec(),
    }
}

fn threads(sims: &[Simulator], frame: &[u8]) {
    println!(
        "{:<34} {:>12}  {:>12}  {:>7}",
        "", "library", "floor", "ratio"
    );
    let plains: Vec<Mutex<Plain>> = sims
        .iter()
        .map(|s| Mutex::new(Plain::open(s.addr())))
        .collect();
    let handles: Vec<c_ushort> = sims.iter().map(alloc).collect();
    for n in thread_counts() {
        // Each thread has its own plain socket; the mutex is never contended.
        let (f, o, r) = alternate(
            n,
            &|i| {
                plains[i].lock().unwrap().exchange(frame);
            },
            &|i| {
                statinfo(handles[i]);
            },
        );
        println!(
            "{:<34} {:>9.0}/s  {:>9.0}/s  {:>6.2}×",
            format!("{n} thread(s), one CNC each"),
            o,
            f,
            r
        );
    }
    // All on one CNC: one handle per thread, all on one connection pair.
    // Each thread count runs `runs` times: the spread between runs (a
    // shared machine, the scheduler's hand-offs) is part of the figure.
    let runs = runs();
    println!(
        "all on one CNC, {runs} runs each: median of the runs' ratios, then each run's, and the library's rate against its own 1-thread rate"
    );
    let one: Vec<c_ushort> = (0..64).map(|_| alloc(&sims[0])).collect();
    let mut single = None;
    for n in thread_counts() {
        let (mut fs, mut os, mut rs) = (vec![], vec![], vec![]);
        for _ in 0..runs {
            let (f, o, r) = alternate(
                n,
                &|_| {
                    plains[0].lock().unwrap().exchange(frame);
                },
                &|i| {
                    statinfo(one[i]);
                },
            );
            fs.push(f);
            os.push(o);
            rs.push(r);
        }
        let each: Vec<String> = rs.iter().map(|r| format!("{r:.2}")).collect();
        let (o, lowest) = (
            median(&mut os.clone()),
            os.iter().copied().fold(f64::MAX, f64::min),
        );
        if n == 1 {
            single = Some(o);
        }
        println!(
            "{:<34} {:>9.0}/s  {:>9.0}/s  {:>6.2}×  runs {} (min {:.2}×){}",
            format!("{n} thread(s), all on one CNC"),
            o,
            median(&mut fs),
            median(&mut rs.clone()),
            each.join(" "),
            rs.iter().copied().fold(f64::MAX, f64::min),
            single.map_or(String::new(), |s| format!(
                ", {:.2}× 1 thread (slowest run {:.2}×)",
                o / s,
                lowest / s
            )),
        );
    }
    for h in one.into_iter().chain(handles) {
        assert_eq!(cnc_freelibhndl(h), EW_OK);
    }
    for p in plains {
        p.into_inner().unwrap().close();
    }
}

// ---------------------------------------------------------------------------
// 4. Loading

/// The cdylib cargo built with this bench (target/<profile>/deps).
fn cdylib() -> Option<PathBuf> {
    let exe = std::env::current_exe().ok()?;
    let deps = exe.parent()?;
    [
        deps.join("libfwlib32.so"),
        deps.parent()?.join("libfwlib32.so"),
    ]
    .into_iter()
    .find(|p| p.exists())
}

fn cc(dir: &Path, args: &[&str]) -> Option<()> {
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    let st = Command::new(cc).current_dir(dir).args(args).status().ok()?;
    st.success().then_some(())
}

/// Medians over fresh processes of (dlopen, first cnc_allclibhndl3,
/// cnc_freelibhndl, dlclose) µs of the library, and of (dlopen, dlclose)
/// of an empty C library.
fn loading(dir: &Path, sim: &Simulator) -> Option<([f64; 4], [f64; 2], PathBuf)> {
    let lib = cdylib()?;
    std::fs::write(dir.join("load.c"), include_str!("load.c")).ok()?;
    std::fs::write(
        dir.join("empty.c"),
        "int fwlib32_empty(void) { return 0; }\n",
    )
    .ok()?;
    cc(dir, &["-O2", "-o", "load", "load.c", "-ldl"])?;
    cc(
        dir,
        &["-O2", "-shared", "-fPIC", "-o", "empty.so", "empty.c"],
    )?;
    let run = |args: &[&str]| -> Vec<f64> {
        let out = Command::new(dir.join("load"))
            .args(args)
            .output()
            .expect("run load");
        assert!(
            out.status.success(),
            "load {args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout)
            .split_whitespace()
            .map(|x| x.parse().expect("a number"))
            .collect()
    };
    let empty = dir.join("empty.so");
    let (lib_s, empty_s, port) = (
        lib.to_string_lossy().into_owned(),
        empty.to_string_lossy().into_owned(),
        sim.port().to_string(),
    );
    let mut ours: [Vec<f64>; 4] = Default::default();
    let mut base: [Vec<f64>; 2] = Default::default();
    for _ in 0..count(41, 1) {
        let v = run(&[&empty_s]);
        base[0].push(v[0]);
        base[1].push(v[3]);
        let v = run(&[&lib_s, &port]);
        for (o, x) in ours.iter_mut().zip(v) {
            o.push(x);
        }
    }
    Some((
        ours.map(|mut v| median(&mut v)),
        base.map(|mut v| median(&mut v)),
        lib,
    ))
}

// ---------------------------------------------------------------------------

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "--list") {
        println!("floor: bench");
        return;
    }
    if let Some(i) = args.iter().position(|a| a == SYSCALLS_CHILD) {
        let n = args.get(i + 1).and_then(|n| n.parse().ok()).expect("N");
        syscalls_child(n);
        return;
    }
    // `cargo bench` passes --bench; `cargo test --benches` does not.
    if !args.iter().any(|a| a == "--bench") {
        QUICK.store(true, Ordering::Relaxed);
        println!("quick run (no --bench): a smoke test, the numbers mean nothing");
    }
    // Sections named on the command line (`cargo bench --bench floor --
    // threads loading`) run alone; none named: all.
    let named: Vec<&str> = args[1..]
        .iter()
        .map(String::as_str)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let want = |s: &str| named.is_empty() || named.contains(&s);
    let t0 = Instant::now();
    let dir = std::env::temp_dir().join(format!("fwlib32-floor-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch directory");
    let frame = data_frame(&StatInfo::<Status>::new());
    // The simulators start before any thread is pinned: their threads must
    // not inherit the pinning.
    let sims: Vec<Simulator> = (0..64).map(|_| start()).collect();

    if want("pinned") {
        pinned_section(&sims[0], &frame);
    }
    if want("syscalls") {
        println!("\n-- 2. system calls per cnc_statinfo (strace, calling thread only)");
        match syscalls(&dir) {
            Some((floor, ours)) => {
                println!("{:<34} {}", "library", describe(&ours));
                println!("{:<34} {}", "floor", describe(&floor));
            }
            None => println!("strace is not installed: not counted"),
        }
    }
    if want("threads") {
        println!("\n-- 3. threads: aggregate cnc_statinfo calls/s");
        threads(&sims, &frame);
    }
    if want("loading") {
        loading_section(&dir, &sims[0]);
    }
    let _ = std::fs::remove_dir_all(&dir);
    drop(sims);
    println!("\ntotal {:.1} s", t0.elapsed().as_secs_f64());
}

fn pinned_section(sim: &Simulator, frame: &[u8]) {
    println!("\n-- 1. cnc_statinfo, one thread pinned to one core, vs the plain-socket floor");
    let p = std::thread::scope(|s| s.spawn(|| pinned(sim, frame)).join().expect("pinned"));
    match p.cpu {
        Some(c) => println!("(calling thread pinned to CPU {c})"),
        None => println!("(could not pin the calling thread)"),
    }
    println!(
        "{:<34} {:>9}  {:>9}  {:>7}",
        "", "library", "floor", "ratio"
    );
    println!(
        "{:<34} {:>6.2} µs  {:>6.2} µs  {:>6.3}×",
        "p50 latency per call",
        p.p50.1,
        p.p50.0,
        p.p50.1 / p.p50.0
    );
    println!(
        "{:<34} {:>6.2} µs  {:>6.2} µs  {:>6.3}×",
        "CPU time per call (calling thread)",
        p.cpu_us.1,
        p.cpu_us.0,
        p.cpu_us.1 / p.cpu_us.0
    );
}

fn loading_section(dir: &Path, sim: &Simulator) {
    println!("\n-- 4. loading: a C host, one fresh process per sample (medians)");
    match loading(dir, sim) {
        Some((ours, empty, lib)) => {
            println!("library: {}", lib.display());
            println!("{:<34} {:>9.1} µs", "dlopen", ours[0]);
            println!("{:<34} {:>9.1} µs", "first cnc_allclibhndl3", ours[1]);
            println!("{:<34} {:>9.1} µs", "cnc_freelibhndl", ours[2]);
            println!("{:<34} {:>9.1} µs", "dlclose", ours[3]);
            println!(
                "{:<34} {:>9.1} µs   (empty C library: {:.1} µs, {:.1} + {:.1})",
                "dlopen + dlclose",
                ours[0] + ours[3],
                empty[0] + empty[1],
                empty[0],
                empty[1]
            );
        }
        None => println!("no cc or no cdylib next to this bench: not measured"),
    }
}
