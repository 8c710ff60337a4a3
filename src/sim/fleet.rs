//! Many simulated machines from one process (`focas-sim --fleet N`): each
//! its own listener, port, state, program clock and faults, all served by
//! one tokio runtime (a task per listener and per connection, no thread
//! per machine).

use super::faults::FaultPlan;
use super::machine::Machine;
use super::profile::Profile;
use super::profile::fault::Fault;
use super::profile::fleet::MAX_MACHINES;
use super::server::{self, Net, Shared};
use super::trace::Trace;
use std::io::{Error, ErrorKind, Result};
use std::net::SocketAddr;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Where `--trace` lines go.
pub enum TraceTo {
    Stderr,
    File(std::path::PathBuf),
    Writer(Box<dyn std::io::Write + Send>),
}

/// How a fleet is started, besides its profiles.
#[derive(Default)]
pub struct FleetOptions {
    /// How many machines (None: each profile's `[fleet] machines`, in turn).
    pub machines: Option<usize>,
    /// Faults for every machine they concern, besides the profiles' own.
    pub faults: Vec<Fault>,
    pub trace: Option<TraceTo>,
    /// Runtime worker threads (None: one per core).
    pub worker_threads: Option<usize>,
}

struct Member {
    addr: SocketAddr,
    shared: Arc<Shared>,
}

/// Running machines. Dropping it stops them.
pub struct Fleet {
    runtime: Option<tokio::runtime::Runtime>,
    members: Vec<Member>,
    /// The fleet's start: time zero of every fault schedule.
    zero: Instant,
}

fn invalid(m: String) -> Error {
    Error::new(ErrorKind::InvalidInput, m)
}

/// The parameter counting parts (varied per machine).
const PART_COUNT: i32 = 6711;

/// Fleet member `n` (1-based) of `base`, and how long before the fleet's
/// start its clock started. Member 1 is `base` itself at phase 0; member n
/// runs its program 0.05 × ((n - 1) mod 7) slower, its clock started
/// 3.7 × (n - 1) mod 60 seconds earlier (another block of its program,
/// events and alarms at other times), and has its own CNC id (last word
/// + n - 1), part count (+ 13 per member) and power-on time. With `[fleet]
/// vary = false` every member is `base`.
pub fn vary(base: &Profile, n: usize) -> (Profile, Duration) {
    let mut p = base.clone();
    let k = n.saturating_sub(1);
    if k == 0 || !base.fleet.vary {
        return (p, Duration::ZERO);
    }
    for path in &mut p.paths {
        path.cycle.block_seconds *= 1.0 + (k % 7) as f64 * 0.05;
    }
    if p.cnc.cnc_id.is_empty() {
        p.cnc.cnc_id = vec![0; 4];
    }
    if let Some(last) = p.cnc.cnc_id.last_mut() {
        *last = last.wrapping_add(k as u32);
    }
    if let Some(e) = p
        .param
        .parameters
        .iter_mut()
        .find(|e| e.number == PART_COUNT)
        && let Some(v) = e.values.first_mut()
    {
        *v = v.saturating_add(13 * k as i32);
    }
    p.timers.power_on = p.timers.power_on.saturating_add(60 * k as i32);
    let tenths = (k as u64 * 37) % 600;
    (p, Duration::from_millis(tenths * 100))
}

/// Which profile each machine serves: with a count, the profiles in turn;
/// without, each profile for its own `[fleet] machines`.
fn assign(profiles: &[Profile], machines: Option<usize>) -> Vec<usize> {
    match machines {
        Some(n) => (0..n).map(|i| i % profiles.len()).collect(),
        None => profiles
            .iter()
            .enumerate()
            .flat_map(|(k, p)| std::iter::repeat_n(k, p.fleet.machines))
            .collect(),
    }
}

impl Fleet {
    /// Starts the machines on `listen`: with port 0 each on a free port,
    /// otherwise on consecutive ports from the one given.
    pub fn start(profiles: &[Profile], listen: &str, opts: FleetOptions) -> Result<Fleet> {
        if profiles.is_empty() {
            return Err(invalid("no profile".into()));
        }
        let which = assign(profiles, opts.machines);
        let n = which.len();
        if !(1..=MAX_MACHINES).contains(&n) {
            return Err(invalid(format!("a fleet has 1 to {MAX_MACHINES} machines")));
        }
        for p in profiles {
            p.check_faults(n).map_err(invalid)?;
        }
        for (k, f) in opts.faults.iter().enumerate() {
            f.check(n)
                .map_err(|m| invalid(format!("fault {} ({:?}): {m}", k + 1, f.kind)))?;
        }
        let base = super::resolve(listen)?;
        if base.port() != 0 && usize::from(base.port()) + n - 1 > usize::from(u16::MAX) {
            return Err(invalid(format!(
                "{n} ports from {} do not fit",
                base.port()
            )));
        }
        let mut rt = tokio::runtime::Builder::new_multi_thread();
        if let Some(w) = opts.worker_threads {
            rt.worker_threads(w.max(1));
        }
        let runtime = rt.thread_name("focas-sim").enable_all().build()?;
        let zero = Instant::now();
        let trace = match opts.trace {
            None => None,
            Some(TraceTo::Stderr) => Some(Trace::stderr(zero)),
            Some(TraceTo::File(p)) => Some(Trace::file(&p, zero)?),
            Some(TraceTo::Writer(w)) => Some(Trace::to(w, zero)),
        };
        let mut members = Vec::with_capacity(n);
        let _guard = runtime.enter();
        for (i, &k) in which.iter().enumerate() {
            let number = i + 1;
            let (profile, phase) = vary(&profiles[k], number);
            let faults: Vec<Fault> = profile
                .faults
                .iter()
                .chain(&opts.faults)
                .filter(|f| f.concerns(number))
                .cloned()
                .collect();
            super::dispatch::rows();
            let mut machine = Machine::new(profile);
            machine.started = zero.checked_sub(phase).unwrap_or(zero);
            machine.now = machine.started;
            let net = Net {
                zero,
                faults: FaultPlan::new(faults),
                trace: trace.clone(),
                label: format!("m{number}"),
            };
            let shared = Shared::with_net(Box::new(machine), net);
            let addr = if base.port() == 0 {
                base
            } else {
                SocketAddr::new(base.ip(), base.port() + i as u16)
            };
            let listener = server::bind(addr)
                .map_err(|e| Error::new(e.kind(), format!("cannot listen on {addr}: {e}")))?;
            listener.set_nonblocking(true)?;
            let listener = tokio::net::TcpListener::from_std(listener)?;
            let addr = listener.local_addr()?;
            runtime.spawn(server::serve(listener, shared.clone()));
            members.push(Member { addr, shared });
        }
        drop(_guard);
        Ok(Fleet {
            runtime: Some(runtime),
            members,
            zero,
        })
    }

    pub fn len(&self) -> usize {
        self.members.len()
    }

    pub fn is_empty(&self) -> bool {
        self.members.is_empty()
    }

    /// The address machine `i` (0-based) listens on.
    pub fn addr(&self, i: usize) -> SocketAddr {
        self.members[i].addr
    }

    pub fn port(&self, i: usize) -> u16 {
        self.addr(i).port()
    }

    pub fn addrs(&self) -> Vec<SocketAddr> {
        self.members.iter().map(|m| m.addr).collect()
    }

    /// Sessions open on machine `i` (0-based).
    pub fn sessions(&self, i: usize) -> usize {
        self.members[i].shared.sessions()
    }

    /// Stops every machine's clock at `elapsed` after the fleet's start
    /// (each machine's program runs its own phase ahead of it; faults are
    /// scheduled from the fleet's start).
    pub fn set_elapsed(&self, elapsed: Duration) {
        for m in &self.members {
            m.shared.set_clock(Some(self.zero + elapsed));
        }
    }

    /// Lets the clocks run in real time again.
    pub fn real_time(&self) {
        for m in &self.members {
            m.shared.set_clock(None);
        }
    }

    /// Runs `f` to completion on the fleet's runtime (a binary waiting for
    /// its signal).
    pub fn block_on<F: std::future::Future>(&self, f: F) -> F::Output {
        self.runtime.as_ref().expect("running").block_on(f)
    }
}

impl Drop for Fleet {
    fn drop(&mut self) {
        if let Some(rt) = self.runtime.take() {
            rt.shutdown_background();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn members_differ_from_the_first() {
        let base = Profile::default();
        let (one, phase) = vary(&base, 1);
        assert_eq!(phase, Duration::ZERO);
        assert_eq!(one.cnc.cnc_id, base.cnc.cnc_id);
        let (two, phase) = vary(&base, 2);
        assert_eq!(phase.as_millis(), 3700);
        assert_ne!(two.cnc.cnc_id, base.cnc.cnc_id);
        assert!(two.paths[0].cycle.block_seconds > base.paths[0].cycle.block_seconds);
        let mut same = base.clone();
        same.fleet.vary = false;
        assert_eq!(vary(&same, 9).0.cnc.cnc_id, base.cnc.cnc_id);
    }
}
