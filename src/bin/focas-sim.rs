//! focas-sim: serve simulated FANUC CNCs over the FOCAS2 Ethernet protocol.

use fwlib32::sim::fleet::TraceTo;
use fwlib32::sim::profile::fault::{Fault, KINDS};
use fwlib32::sim::{Fleet, FleetOptions, Profile, profile::DEFAULT_PROFILE};
use std::io::Write;
use std::process::ExitCode;

const USAGE: &str = "usage: focas-sim [--listen ADDR] [--profile FILE]... [--fleet N]
                 [--fault SPEC]... [--delay-ms MS] [--max-sessions N]
                 [--trace | --trace-file FILE] [--print-profile]

  --listen ADDR       address to serve on (default 127.0.0.1:8193; use 127.0.0.1:0 for a
                      free port); a fleet takes consecutive ports from it, or with port 0
                      a free port each
  --profile FILE      machine profile (TOML); default: the built-in 3-axis mill. Several:
                      each serves its own `[fleet] machines`, or with --fleet in turn
  --fleet N           serve N machines (each its own port, state, program clock, CNC id)
  --fault SPEC        inject a fault: KIND[:KEY=VALUE,...], the keys of a profile's
                      [[fault]] (at, every, duration, machines, delay_ms, sessions, code,
                      functions, commands, count); KIND is one of
                      off, refuse, silent, reset, close, delay, sessions, error, upload_drop.
                      e.g. off:at=30,duration=10,machines=1..5
                           error:functions=cnc_rdparam,code=EW_NOOPT
  --delay-ms MS       answer every request MS milliseconds late (all machines)
  --max-sessions N    at most N FOCAS sessions per machine
  --trace             every frame in both directions, decoded, one line each on stderr
  --trace-file FILE   the same into FILE
  --print-profile     print the built-in profile and exit

Prints `listening on ADDR` on stdout, one line per machine in order. Serves until killed.";

struct Args {
    listen: String,
    profiles: Vec<String>,
    opts: FleetOptions,
}

fn parse() -> Result<Option<Args>, String> {
    let mut a = Args {
        listen: "127.0.0.1:8193".into(),
        profiles: Vec::new(),
        opts: FleetOptions::default(),
    };
    let mut args = std::env::args().skip(1);
    let value = |args: &mut dyn Iterator<Item = String>, what: &str| {
        args.next().ok_or_else(|| what.to_string())
    };
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--listen" => a.listen = value(&mut args, "--listen needs an address")?,
            "--profile" => a.profiles.push(value(&mut args, "--profile needs a file")?),
            "--fleet" => {
                let v = value(&mut args, "--fleet needs a number of machines")?;
                let n = v
                    .parse::<usize>()
                    .map_err(|_| format!("--fleet {v:?}: not a number of machines"))?;
                a.opts.machines = Some(n);
            }
            "--fault" => {
                let v = value(
                    &mut args,
                    &format!("--fault needs KIND[:KEY=VALUE,...] ({KINDS})"),
                )?;
                a.opts.faults.push(Fault::parse_spec(&v)?);
            }
            "--delay-ms" => {
                let v = value(&mut args, "--delay-ms needs milliseconds")?;
                let ms = v
                    .parse::<u64>()
                    .map_err(|_| format!("--delay-ms {v:?}: not a number of milliseconds"))?;
                if ms > 0 {
                    a.opts
                        .faults
                        .push(Fault::parse_spec(&format!("delay:delay_ms={ms}"))?);
                }
            }
            "--max-sessions" => {
                let v = value(&mut args, "--max-sessions needs a number")?;
                let n = v
                    .parse::<usize>()
                    .map_err(|_| format!("--max-sessions {v:?}: not a number"))?;
                a.opts
                    .faults
                    .push(Fault::parse_spec(&format!("sessions:sessions={n}"))?);
            }
            "--trace" => a.opts.trace = Some(TraceTo::Stderr),
            "--trace-file" => {
                let f = value(&mut args, "--trace-file needs a file")?;
                a.opts.trace = Some(TraceTo::File(f.into()));
            }
            "--print-profile" => {
                print!("{DEFAULT_PROFILE}");
                return Ok(None);
            }
            "-h" | "--help" => {
                println!("{USAGE}");
                return Ok(None);
            }
            other => return Err(format!("unknown argument {other}")),
        }
    }
    Ok(Some(a))
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
    let args = match parse() {
        Ok(Some(a)) => a,
        Ok(None) => return ExitCode::SUCCESS,
        Err(m) => {
            eprintln!("focas-sim: {m}\n\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    let mut profiles = Vec::new();
    for p in &args.profiles {
        match Profile::load(std::path::Path::new(p)) {
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
    let fleet = match Fleet::start(&profiles, &args.listen, args.opts) {
        Ok(f) => f,
        Err(e) if e.kind() == std::io::ErrorKind::InvalidInput => {
            eprintln!("focas-sim: {e}");
            return ExitCode::from(2);
        }
        Err(e) => {
            eprintln!("focas-sim: {e}");
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
