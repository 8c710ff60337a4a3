//! focas-sim: serve simulated FANUC CNCs over the FOCAS2 Ethernet protocol.

use clap::{CommandFactory, Parser};
use fwlib32::sim::fleet::TraceTo;
use fwlib32::sim::profile::fault::Fault;
use fwlib32::sim::profile::fleet::MAX_MACHINES;
use fwlib32::sim::{Fleet, FleetOptions, Profile, profile::DEFAULT_PROFILE};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

/// Serve simulated FANUC CNCs over the FOCAS2 Ethernet protocol.
#[derive(Parser)]
#[command(
    name = "focas-sim",
    version,
    about = "Serve simulated FANUC CNCs over the FOCAS2 Ethernet protocol",
    after_help = "Prints `listening on ADDR` on stdout, one line per machine in order. \
                  Serves until killed.\n\n\
                  Examples:\n  focas-sim --listen 127.0.0.1:0\n  \
                  focas-sim --fleet 20 --fault off:at=30,duration=10,machines=1..5\n  \
                  focas-sim --profile lathe.toml --delay-ms 50 --trace"
)]
struct Args {
    /// Address to serve on (127.0.0.1:0 for a free port); a fleet takes
    /// consecutive ports from it, or with port 0 a free port each
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1:8193", value_parser = listen_addr)]
    listen: String,
    /// Machine profile (TOML); default: the built-in 3-axis mill. Several:
    /// each serves its own `[fleet] machines`, or with --fleet in turn
    #[arg(long = "profile", value_name = "FILE")]
    profiles: Vec<PathBuf>,
    /// Serve N machines (each its own port, state, program clock, CNC id)
    #[arg(long, value_name = "N", value_parser = machines)]
    fleet: Option<usize>,
    /// Inject a fault: KIND[:KEY=VALUE,...], the keys of a profile's
    /// [[fault]] (at, every, duration, machines, delay_ms, sessions, code,
    /// functions, commands, count); e.g. off:at=30,duration=10,machines=1..5
    /// or error:functions=cnc_rdparam,code=EW_NOOPT
    #[arg(long = "fault", value_name = "SPEC", value_parser = fault)]
    faults: Vec<Fault>,
    /// Answer every request MS milliseconds late, and send or take each
    /// frame of a program transfer MS late (all machines)
    #[arg(long, value_name = "MS", default_value_t = 0, value_parser = millis)]
    delay_ms: u64,
    /// At most N FOCAS sessions per machine
    #[arg(long, value_name = "N")]
    max_sessions: Option<usize>,
    /// Every frame in both directions, decoded, one line each on stderr
    #[arg(long, conflicts_with = "trace_file")]
    trace: bool,
    /// The same into FILE
    #[arg(long, value_name = "FILE")]
    trace_file: Option<PathBuf>,
    /// Print the built-in profile and exit
    #[arg(long)]
    print_profile: bool,
}

/// `HOST:PORT` (`[v6]:PORT`): checked here, resolved when serving.
fn listen_addr(s: &str) -> Result<String, String> {
    let (host, port) = s
        .rsplit_once(':')
        .ok_or_else(|| "expected HOST:PORT (127.0.0.1:8193, [::1]:0)".to_string())?;
    if host.is_empty() {
        return Err("expected HOST:PORT: no host".into());
    }
    port.parse::<u16>()
        .map_err(|_| format!("{port:?} is not a TCP port (0 to 65535)"))?;
    Ok(s.to_string())
}

fn fault(s: &str) -> Result<Fault, String> {
    Fault::parse_spec(s)
}

fn machines(s: &str) -> Result<usize, String> {
    match s.parse::<usize>() {
        Ok(n) if (1..=MAX_MACHINES).contains(&n) => Ok(n),
        _ => Err(format!("a fleet has 1 to {MAX_MACHINES} machines")),
    }
}

fn millis(s: &str) -> Result<u64, String> {
    s.parse()
        .map_err(|_| "not a number of milliseconds".to_string())
}

impl Args {
    fn options(&self) -> Result<FleetOptions, String> {
        let mut opts = FleetOptions {
            machines: self.fleet,
            faults: self.faults.clone(),
            ..FleetOptions::default()
        };
        if self.delay_ms > 0 {
            let spec = format!("delay:delay_ms={}", self.delay_ms);
            let f = Fault::parse_spec(&spec)
                .map_err(|e| format!("--delay-ms {}: {e}", self.delay_ms))?;
            opts.faults.push(f);
        }
        if let Some(n) = self.max_sessions {
            let f = Fault::parse_spec(&format!("sessions:sessions={n}"))
                .map_err(|e| format!("--max-sessions {n}: {e}"))?;
            opts.faults.push(f);
        }
        opts.trace = match (&self.trace_file, self.trace) {
            (Some(f), _) => Some(TraceTo::File(f.clone())),
            (None, true) => Some(TraceTo::Stderr),
            (None, false) => None,
        };
        Ok(opts)
    }
}

/// Room for a large fleet's sockets: the soft limit on open files raised
/// to the hard one.
fn raise_file_limit() {
    let mut l = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: plain struct out-parameter.
    unsafe {
        if libc::getrlimit(libc::RLIMIT_NOFILE, &mut l) == 0 && l.rlim_cur < l.rlim_max {
            l.rlim_cur = l.rlim_max;
            libc::setrlimit(libc::RLIMIT_NOFILE, &l);
        }
    }
}

fn main() -> ExitCode {
    let args = Args::parse();
    if args.print_profile {
        print!("{DEFAULT_PROFILE}");
        return ExitCode::SUCCESS;
    }
    let opts = match args.options() {
        Ok(o) => o,
        Err(m) => Args::command()
            .error(clap::error::ErrorKind::ValueValidation, m)
            .exit(),
    };
    let mut profiles = Vec::new();
    for p in &args.profiles {
        match Profile::load(p) {
            Ok(p) => profiles.push(p),
            Err(e) => {
                eprintln!("focas-sim: {e}");
                return ExitCode::from(2);
            }
        }
    }
    if profiles.is_empty() {
        profiles.push(Profile::default());
    }
    raise_file_limit();
    let fleet = match Fleet::start(&profiles, &args.listen, opts) {
        Ok(f) => f,
        Err(e) if e.kind() == std::io::ErrorKind::InvalidInput => {
            eprintln!("focas-sim: {e}");
            return ExitCode::from(2);
        }
        Err(e) => {
            let e = e.to_string();
            if e.contains(&args.listen) {
                eprintln!("focas-sim: {e}");
            } else {
                eprintln!("focas-sim: --listen {}: {e}", args.listen);
            }
            return ExitCode::FAILURE;
        }
    };
    let mut out = std::io::stdout().lock();
    for a in fleet.addrs() {
        let _ = writeln!(out, "listening on {a}");
    }
    let _ = out.flush();
    drop(out);
    let _ = fleet.block_on(tokio::signal::ctrl_c());
    ExitCode::SUCCESS
}
