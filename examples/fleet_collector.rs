//! A collector polling a whole fleet of CNCs with the safe Rust API
//! (`fwlib32::native::Cnc`): every round, each machine's status, program
//! execution and alarms in one batched exchange, by a few threads each
//! owning a share of the machines. A machine that fails is counted by its
//! error code, dropped, and connected again at its next poll, so a CNC that
//! was switched off comes back into the table by itself.
//!
//! Against a simulated fleet with an outage of machines 1 to 10:
//!
//! ```sh
//! focas-sim --fleet 100 --listen 127.0.0.1:0 \
//!     --fault off:at=5,duration=5,machines=1..10 > /tmp/fleet.txt &
//! cargo run --release --example fleet_collector -- --from /tmp/fleet.txt --rounds 15
//! ```
//!
//! or with a fleet of its own, in the same process: `-- --spawn 100`.

use fwlib32::native::{Cnc, Error, Ew};
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

const USAGE: &str = "usage: fleet_collector [--from FILE | --spawn N | ADDR...] [--rounds N]
                      [--interval-ms MS] [--threads T] [--timeout S] [--table]

  ADDR            host:port of a CNC (several)
  --from FILE     the addresses from `listening on ADDR` lines (focas-sim's output)
  --spawn N       simulate N machines in this process (fwlib32::sim::Fleet)
  --rounds N      polls of every machine (default 5)
  --interval-ms   pause between rounds (default 1000)
  --threads T     polling threads (default 8)
  --timeout S     each exchange's timeout in seconds (default 2)
  --table         print every machine's last state at the end";

/// What one poll read.
#[derive(Debug, Clone)]
struct Reading {
    mode: String,
    run: String,
    program: u32,
    sequence: i32,
    feed: i32,
    alarms: Vec<String>,
}

/// One machine: its connection (None until connected, or after a failure).
struct Machine {
    addr: String,
    cnc: Option<Cnc>,
    last: Option<Reading>,
    /// Failed polls by EW_* name.
    errors: BTreeMap<&'static str, u32>,
    ok: u32,
}

impl Machine {
    /// One poll; the connection is kept unless it broke (EW_SOCKET).
    fn poll(&mut self, timeout: Duration) -> Result<Reading, Error> {
        let cnc = match self.cnc.take() {
            Some(c) => c,
            None => Cnc::connect(&self.addr, timeout)?,
        };
        let r = read(&cnc);
        if !matches!(&r, Err(e) if e.code() == Ew::SOCKET) {
            self.cnc = Some(cnc);
        }
        r
    }

    fn poll_and_note(&mut self, timeout: Duration) {
        match self.poll(timeout) {
            Ok(r) => {
                self.last = Some(r);
                self.ok += 1;
            }
            Err(e) => {
                *self.errors.entry(e.code().name()).or_default() += 1;
                self.last = None;
            }
        }
    }
}

/// Status, execution and alarms in one batch (one exchange).
fn read(cnc: &Cnc) -> Result<Reading, Error> {
    let mut batch = cnc.batch();
    let (status, exec, alarms) = (batch.status(), batch.execution(), batch.alarms());
    let mut replies = batch.send()?;
    let status = replies.take(status)?;
    let exec = replies.take(exec)?;
    let alarms = replies.take(alarms)?;
    Ok(Reading {
        mode: status.mode.to_string(),
        run: status.run.to_string(),
        program: exec.program,
        sequence: exec.sequence,
        feed: exec.feed,
        alarms: alarms.iter().map(|a| a.code()).collect(),
    })
}

struct Options {
    addrs: Vec<String>,
    spawn: usize,
    rounds: usize,
    interval: Duration,
    threads: usize,
    timeout: Duration,
    table: bool,
}

fn parse() -> Result<Options, String> {
    let mut o = Options {
        addrs: Vec::new(),
        spawn: 0,
        rounds: 5,
        interval: Duration::from_millis(1000),
        threads: 8,
        timeout: Duration::from_secs(2),
        table: false,
    };
    let mut args = std::env::args().skip(1);
    let num = |v: Option<String>, what: &str| -> Result<u64, String> {
        v.and_then(|v| v.parse().ok())
            .ok_or_else(|| format!("{what} needs a number"))
    };
    while let Some(a) = args.next() {
        match a.as_str() {
            "--from" => {
                let f = args.next().ok_or("--from needs a file")?;
                let text = std::fs::read_to_string(&f).map_err(|e| format!("{f}: {e}"))?;
                o.addrs.extend(
                    text.lines()
                        .filter_map(|l| l.trim().strip_prefix("listening on "))
                        .map(str::to_string),
                );
            }
            "--spawn" => o.spawn = num(args.next(), "--spawn")? as usize,
            "--rounds" => o.rounds = num(args.next(), "--rounds")? as usize,
            "--interval-ms" => {
                o.interval = Duration::from_millis(num(args.next(), "--interval-ms")?)
            }
            "--threads" => o.threads = (num(args.next(), "--threads")? as usize).max(1),
            "--timeout" => o.timeout = Duration::from_secs(num(args.next(), "--timeout")?),
            "--table" => o.table = true,
            "-h" | "--help" => return Err(String::new()),
            s if s.starts_with("--") => return Err(format!("unknown option {s}")),
            addr => o.addrs.push(addr.to_string()),
        }
    }
    Ok(o)
}

fn main() -> std::process::ExitCode {
    let o = match parse() {
        Ok(o) => o,
        Err(m) => {
            eprintln!("{m}\n{USAGE}");
            return std::process::ExitCode::from(2);
        }
    };
    let mut addrs = o.addrs.clone();
    let _fleet = if o.spawn > 0 {
        let fleet = fwlib32::sim::Fleet::start(
            &[fwlib32::sim::Profile::default()],
            "127.0.0.1:0",
            fwlib32::sim::FleetOptions {
                machines: Some(o.spawn),
                ..Default::default()
            },
        )
        .expect("a simulated fleet");
        addrs.extend(fleet.addrs().iter().map(|a| a.to_string()));
        Some(fleet)
    } else {
        None
    };
    if addrs.is_empty() {
        eprintln!("no machines\n{USAGE}");
        return std::process::ExitCode::from(2);
    }
    let mut machines: Vec<Machine> = addrs
        .into_iter()
        .map(|addr| Machine {
            addr,
            cnc: None,
            last: None,
            errors: BTreeMap::new(),
            ok: 0,
        })
        .collect();
    let threads = o.threads.min(machines.len());
    let share = machines.len().div_ceil(threads);
    println!(
        "polling {} machines with {threads} threads, {} rounds",
        machines.len(),
        o.rounds
    );
    for round in 1..=o.rounds {
        let t = Instant::now();
        let timeout = o.timeout;
        std::thread::scope(|s| {
            for part in machines.chunks_mut(share) {
                s.spawn(move || {
                    for m in part {
                        m.poll_and_note(timeout);
                    }
                });
            }
        });
        let up: Vec<&Reading> = machines.iter().filter_map(|m| m.last.as_ref()).collect();
        let running = up.iter().filter(|r| r.run == "STRT").count();
        let alarmed = up.iter().filter(|r| !r.alarms.is_empty()).count();
        let mut down: BTreeMap<&str, usize> = BTreeMap::new();
        for m in machines.iter().filter(|m| m.last.is_none()) {
            let last = m.errors.keys().next().copied().unwrap_or("?");
            *down.entry(last).or_default() += 1;
        }
        println!(
            "round {round}: {} up ({running} running, {alarmed} with alarms), {} down{} in {:.1} ms",
            up.len(),
            machines.len() - up.len(),
            if down.is_empty() {
                String::new()
            } else {
                format!(" {down:?}")
            },
            t.elapsed().as_secs_f64() * 1e3
        );
        if round < o.rounds {
            std::thread::sleep(o.interval);
        }
    }
    if o.table {
        println!(
            "{:<22} {:<5} {:<5} {:>8} {:>6} {:>6}  {:<14} {:>4}  errors",
            "machine", "mode", "run", "program", "seq", "feed", "alarms", "ok"
        );
        for m in &machines {
            let (mode, run, prog, seq, feed, alarms) = match &m.last {
                Some(r) => (
                    r.mode.clone(),
                    r.run.clone(),
                    format!("O{:04}", r.program),
                    format!("N{}", r.sequence),
                    r.feed.to_string(),
                    r.alarms.join(","),
                ),
                None => (
                    "-".into(),
                    "-".into(),
                    "-".into(),
                    "-".into(),
                    "-".into(),
                    String::new(),
                ),
            };
            println!(
                "{:<22} {mode:<5} {run:<5} {prog:>8} {seq:>6} {feed:>6}  {:<14} {:>4}  {:?}",
                m.addr,
                if alarms.is_empty() { "-" } else { &alarms },
                m.ok,
                m.errors
            );
        }
    }
    std::process::ExitCode::SUCCESS
}
