//! A fleet of simulated machines polled from one process: `focas-sim
//! --fleet N` (the real program, its own process) against one handle per
//! machine in this one. Every figure is a count or a ratio measured in
//! this run (never a timed assertion). Run with `cargo bench --bench fleet`.
//!
//! * polls per second over 100 and 1,000 machines, by 1 and 8 polling
//!   threads each owning a share of the machines; a poll is what a
//!   collector reads each time: cnc_statinfo, cnc_rddynamic2 (all axes)
//!   and cnc_rdalmmsg2, three exchanges;
//! * memory per machine on the simulator's side: its resident set (VmRSS)
//!   with 1,000 machines less that with one, per machine, idle and with a
//!   client session each;
//! * memory per handle on the library's side: this process's resident set
//!   and live heap before and after connecting a handle (its own
//!   connection pair) to each of 1,000 machines;
//! * threads of both processes.

mod common;
use common::{Counting, HEAP};
use fwlib32::ew::EW_OK;
use fwlib32::types::*;
use fwlib32::*;
use std::ffi::CString;
use std::io::{BufRead, BufReader};
use std::mem::zeroed;
use std::os::raw::{c_short, c_ushort};
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

#[global_allocator]
static ALLOC: Counting = Counting;

/// A `/proc/<pid>/status` field's number (kB for sizes).
fn status(pid: &str, key: &str) -> usize {
    std::fs::read_to_string(format!("/proc/{pid}/status"))
        .unwrap()
        .lines()
        .find_map(|l| l.strip_prefix(key))
        .and_then(|v| v.split_whitespace().next()?.parse().ok())
        .unwrap()
}

/// focas-sim serving a fleet, killed when dropped.
struct Sim {
    child: Child,
    ports: Vec<u16>,
}

impl Sim {
    fn start(machines: usize) -> Sim {
        let mut child = Command::new(env!("CARGO_BIN_EXE_focas-sim"))
            .args(["--fleet", &machines.to_string(), "--listen", "127.0.0.1:0"])
            .stdout(Stdio::piped())
            .spawn()
            .expect("focas-sim");
        let mut out = BufReader::new(child.stdout.take().unwrap());
        let ports = (0..machines)
            .map(|_| {
                let mut l = String::new();
                out.read_line(&mut l).unwrap();
                l.trim().rsplit(':').next().unwrap().parse().unwrap()
            })
            .collect();
        Sim { child, ports }
    }
    fn pid(&self) -> String {
        self.child.id().to_string()
    }
    fn rss_kb(&self) -> usize {
        status(&self.pid(), "VmRSS:")
    }
}

impl Drop for Sim {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn alloc(port: u16) -> c_ushort {
    let ip = CString::new("127.0.0.1").unwrap();
    let mut h = 0;
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), port, 10, &mut h) },
        EW_OK
    );
    h
}

/// One collector poll: status, positions and program, alarms.
fn poll(h: c_ushort) -> [c_short; 3] {
    unsafe {
        let mut st: ODBST = zeroed();
        let mut dy: ODBDY2 = zeroed();
        let mut alm: [ODBALMMSG2; 10] = zeroed();
        let mut n: c_short = 10;
        [
            cnc_statinfo(h, &mut st),
            cnc_rddynamic2(h, ALL_AXES, size_of::<ODBDY2>() as c_short, &mut dy),
            cnc_rdalmmsg2(h, -1, &mut n, alm.as_mut_ptr()),
        ]
    }
}

/// Polls per second over `handles` by `threads` threads, each polling its
/// share in turn until `time` is up.
fn polls_per_second(handles: &[c_ushort], threads: usize, time: Duration) -> f64 {
    let done = AtomicU64::new(0);
    let share = handles.len().div_ceil(threads);
    let t = Instant::now();
    std::thread::scope(|s| {
        for part in handles.chunks(share) {
            let done = &done;
            s.spawn(move || {
                let mut n = 0;
                'run: loop {
                    for &h in part {
                        assert_eq!(poll(h), [EW_OK; 3], "a poll failed");
                        n += 1;
                        if n % 16 == 0 && t.elapsed() >= time {
                            break 'run;
                        }
                    }
                    if t.elapsed() >= time {
                        break;
                    }
                }
                done.fetch_add(n, Ordering::Relaxed);
            });
        }
    });
    done.load(Ordering::Relaxed) as f64 / t.elapsed().as_secs_f64()
}

/// The median, `v` left sorted.
fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn raise_file_limit() {
    let mut l = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    unsafe {
        if libc::getrlimit(libc::RLIMIT_NOFILE, &mut l) == 0 && l.rlim_cur < l.rlim_max {
            l.rlim_cur = l.rlim_max;
            libc::setrlimit(libc::RLIMIT_NOFILE, &l);
        }
    }
}

fn main() {
    if std::env::args().any(|a| a == "--list") {
        println!("fleet: bench");
        return;
    }
    // `cargo bench` passes --bench; `cargo test --benches` does not.
    let quick = !std::env::args().any(|a| a == "--bench");
    let (small, large, time, rounds) = if quick {
        println!("quick run (no --bench): a smoke test, the numbers mean nothing");
        (10, 30, Duration::from_millis(50), 1)
    } else {
        (100, 1000, Duration::from_millis(700), 7)
    };
    raise_file_limit();

    // The simulator's memory: one machine, then the large fleet.
    let one = Sim::start(1);
    let (rss_one, threads_one) = (one.rss_kb(), status(&one.pid(), "Threads:"));
    drop(one);
    let sim = Sim::start(large);
    let rss_idle = sim.rss_kb();
    let sim_threads = status(&sim.pid(), "Threads:");

    // The library's memory: a handle, on its own connection pair, per machine.
    let me = std::process::id().to_string();
    let (rss_before, heap_before) = (status(&me, "VmRSS:"), HEAP.load(Ordering::Relaxed));
    let threads_before = status(&me, "Threads:");
    let handles: Vec<c_ushort> = sim.ports.iter().map(|&p| alloc(p)).collect();
    let (rss_after, heap_after) = (status(&me, "VmRSS:"), HEAP.load(Ordering::Relaxed));
    let threads_after = status(&me, "Threads:");
    let rss_sessions = sim.rss_kb();
    for &h in &handles {
        assert_eq!(poll(h), [EW_OK; 3]);
    }

    println!();
    println!(
        "focas-sim --fleet {large} (its own process) and one handle per machine here; \
         a poll = cnc_statinfo + cnc_rddynamic2 + cnc_rdalmmsg2 (3 exchanges)"
    );
    println!("{:<58} {:>12}", "", "machines");
    // Rounds alternate the two fleet sizes, so both see the same machine
    // load; the figures are medians over the rounds.
    for threads in [1, 8] {
        let (mut at_small, mut at_large, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..rounds {
            let a = polls_per_second(&handles[..small], threads, time);
            let b = polls_per_second(&handles[..large], threads, time);
            at_small.push(a);
            at_large.push(b);
            ratios.push(b / a);
        }
        for (n, v) in [(small, &mut at_small), (large, &mut at_large)] {
            let r = median(v);
            println!(
                "{:<58} {:>12} {:>9.0} /s  ({:.0} exchanges/s; rounds {:.0} to {:.0})",
                format!("polls per second, {threads} polling thread(s)"),
                n,
                r,
                3.0 * r,
                v[0],
                v[v.len() - 1]
            );
        }
        println!(
            "{:<58} {:>12} {:>9.2}×",
            format!("polls/s at {large} / at {small} machines, {threads} thread(s)"),
            "",
            median(&mut ratios)
        );
    }
    let rss_polled = sim.rss_kb();
    let per = |kb: f64, n: usize| kb * 1024.0 / n as f64;
    println!();
    println!(
        "{:<58} {:>9.0} B   (VmRSS {} kB with {large} machines, {} kB with one)",
        "simulator memory per machine, idle",
        per(rss_idle as f64 - rss_one as f64, large - 1),
        rss_idle,
        rss_one
    );
    println!(
        "{:<58} {:>9.0} B   (VmRSS {} kB after connecting, {} kB after polling)",
        "simulator memory per machine with a session, polled",
        per(rss_polled as f64 - rss_one as f64, large - 1),
        rss_sessions,
        rss_polled
    );
    println!(
        "{:<58} {:>9.0} B   (live heap {:.0} B per handle)",
        "library memory per handle (own connection pair), RSS",
        per(rss_after as f64 - rss_before as f64, large),
        (heap_after - heap_before) as f64 / large as f64
    );
    println!(
        "{:<58} {:>12}   (one machine: {threads_one})",
        format!("simulator threads, {large} machines"),
        sim_threads
    );
    println!(
        "{:<58} {:>12}   (before: {threads_before})",
        format!("threads here after connecting {large} handles"),
        threads_after
    );
    for h in handles {
        assert_eq!(cnc_freelibhndl(h), EW_OK);
    }
}
