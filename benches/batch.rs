//! Call batching against a CNC that answers each request frame late, as a
//! real one does: c-examples/adapter.c's poll cycle (the MTConnect
//! adapter's 20 reads) made call by call, then `--batch` (one
//! fwlib_batch_begin / fwlib_batch_end a poll), against the in-process
//! simulator with a per-request delay. Reports round trips per cycle
//! (counted by the simulator) and cycles per second, and the ratio of the
//! two; every figure is measured in this run, never asserted on time.
//!
//!     cargo bench --bench batch [-- --delay-ms 2 --polls 50]

#[path = "../tests/toolchain/mod.rs"]
mod toolchain;

use fwlib32::sim::{Profile, Simulator};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

fn arg(name: &str, default: u64) -> u64 {
    let a: Vec<String> = std::env::args().collect();
    a.iter()
        .position(|x| x == name)
        .and_then(|i| a.get(i + 1)?.parse().ok())
        .unwrap_or(default)
}

/// c-examples/adapter.c built against our header and library.
fn adapter() -> (PathBuf, toolchain::Scratch) {
    let dir = toolchain::lib_dir("bench-batch");
    let root = toolchain::manifest_dir();
    let exe = dir.join("adapter");
    let st = Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()))
        .args(["-std=c99", "-O2", "-I"])
        .arg(root.join("include"))
        .arg(root.join("c-examples/adapter.c"))
        .arg("-L")
        .arg(&dir)
        .args(["-lfwlib32", "-o"])
        .arg(&exe)
        .status()
        .expect("cc");
    assert!(st.success(), "building adapter.c");
    (exe, dir)
}

/// One adapter run: seconds and the data frames the simulator answered.
fn run(exe: &Path, dir: &Path, sim: &Simulator, batch: bool, polls: u64) -> (f64, u64) {
    let mut c = Command::new(exe);
    if batch {
        c.arg("--batch");
    }
    c.args([
        "127.0.0.1",
        &sim.port().to_string(),
        &polls.to_string(),
        "0",
    ])
    .env("LD_LIBRARY_PATH", dir);
    let frames = sim.data_frames();
    let t = Instant::now();
    let out = c.output().expect("adapter");
    let secs = t.elapsed().as_secs_f64();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (secs, sim.data_frames() - frames)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    // `cargo test --benches` runs this with no --bench argument: a quick pass.
    let quick = !std::env::args().any(|a| a == "--bench");
    let delay = arg("--delay-ms", 2);
    let polls = if quick { 3 } else { arg("--polls", 50) };
    let rounds = if quick { 1 } else { 5 };
    let text = format!(
        "{}\n[[fault]]\nkind = \"delay\"\ndelay_ms = {delay}\n",
        fwlib32::sim::profile::DEFAULT_PROFILE
    );
    let sim = Simulator::start(Profile::parse(&text).expect("profile"), "127.0.0.1:0").unwrap();
    let (exe, dir) = adapter();
    let per = |batch: bool| {
        let mut cycles = Vec::new();
        let mut trips = 0;
        for _ in 0..rounds {
            // Start-up and upload alone, then with the polls: the difference.
            let (t0, f0) = run(&exe, &dir, &sim, batch, 0);
            let (t1, f1) = run(&exe, &dir, &sim, batch, polls);
            cycles.push(polls as f64 / (t1 - t0).max(1e-9));
            trips = (f1 - f0) / polls;
        }
        (median(cycles), trips)
    };
    let (alone, alone_trips) = per(false);
    let (batched, batched_trips) = per(true);
    println!(
        "adapter.c poll cycle, {delay} ms per request frame, {polls} polls x {rounds} rounds:"
    );
    println!("  call by call: {alone_trips:>2} round trips a cycle, {alone:>7.1} cycles/s");
    println!("  --batch:      {batched_trips:>2} round trips a cycle, {batched:>7.1} cycles/s");
    println!("  batched / call by call: {:.2}x cycles/s", batched / alone);
}
