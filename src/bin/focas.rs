//! focas: read a FANUC CNC from the command line, over FOCAS2 Ethernet
//! (the crate's Rust API, `fwlib32::native`).
//!
//! Text output is aligned for people; `--json` prints one JSON object (one
//! per line for `watch`) whose keys are stable, times RFC 3339. Any failure
//! prints one line on stderr (`focas: HOST:PORT: FUNCTION: EW_CODE (n):
//! meaning ...`, with what it means in words where the call and the CNC
//! tell: `O1234 is running`), with `--json` one object on stdout
//! (`{"error": {...}}`), and exits with status 1; usage errors (checked
//! before connecting) exit with 2. `watch` goes on through outages.
//! `compat` reads a file, not a CNC: it exits with 1 when the program uses
//! a function this library lacks.

#[path = "focas/adapter/mod.rs"]
mod adapter;
#[path = "focas/binary.rs"]
mod binary;
#[path = "focas/compat.rs"]
mod compat;
#[path = "focas/data.rs"]
mod data;
#[path = "focas/out.rs"]
mod out;
#[path = "focas/prog.rs"]
mod prog;
#[path = "focas/show.rs"]
mod show;
#[path = "focas/watch.rs"]
mod watch;

use clap::{CommandFactory, Parser, Subcommand};
use fwlib32::native::Cnc;
use out::Fail;
use std::process::ExitCode;
use std::time::Duration;

#[derive(Parser)]
#[command(
    name = "focas",
    version,
    about = "Read a FANUC CNC over FOCAS2 Ethernet",
    after_help = "Examples:\n  focas --host 10.0.0.5 status\n  focas status -H 10.0.0.5:8193 --json\n  FOCAS_HOST=10.0.0.5 focas pos\n  focas --host cnc1 pmc D100..D120 --type word\n  focas --host cnc1 prog get 1234 O1234.nc\n  focas compat ./my-adapter"
)]
struct Cli {
    /// The CNC: a host name or address, with its port if not --port's.
    #[arg(
        long,
        short = 'H',
        env = "FOCAS_HOST",
        global = true,
        value_parser = host_port,
        help = "The CNC: a host name or address, with its port if not --port's \
                (cnc1, 10.0.0.5:8193, ::1, [::1]:8193); every command but compat"
    )]
    host: Option<HostPort>,
    /// FOCAS2 TCP port (a port in --host wins)
    #[arg(long, short = 'p', env = "FOCAS_PORT", global = true, default_value_t = fwlib32::native::DEFAULT_PORT)]
    port: u16,
    /// Seconds to wait for each answer (0: for ever)
    #[arg(long, short = 't', global = true, default_value_t = 10.0, value_parser = seconds)]
    timeout: f64,
    /// The CNC path to read (default 1)
    #[arg(long, global = true, value_parser = clap::value_parser!(u16).range(1..))]
    path: Option<u16>,
    /// Print JSON (stable keys) instead of text
    #[arg(long, global = true)]
    json: bool,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// System information, CNC id and paths
    Info,
    /// Mode, run state, alarms, program and speeds
    Status,
    /// Axis positions: absolute, machine, relative, distance to go
    Pos,
    /// Active alarms, or the alarm history
    Alarms {
        /// The alarm history, newest first
        #[arg(long)]
        history: bool,
    },
    /// A parameter: its value, or one per axis
    Param {
        number: u32,
        /// One axis (1..)
        #[arg(long, short = 'a', value_parser = clap::value_parser!(u16).range(1..))]
        axis: Option<u16>,
    },
    /// A diagnosis item: its value, or one per axis
    Diag {
        number: u32,
        /// One axis (1..)
        #[arg(long, short = 'a', value_parser = clap::value_parser!(u16).range(1..))]
        axis: Option<u16>,
    },
    /// A custom macro variable; N=V writes it (V a number, or "vacant")
    Macro {
        /// N, or N=V to write
        #[arg(value_parser = data::parse_macro)]
        spec: data::MacroSpec,
    },
    /// PMC data: ADDR (D100), a range (D100..D120) or a bit (R0.3)
    Pmc {
        #[arg(value_parser = data::parse_pmc)]
        address: data::PmcSpec,
        /// Element type of a range
        #[arg(long = "type", short = 'T', value_enum, default_value_t = data::PmcKind::Byte)]
        kind: data::PmcKind,
    },
    /// NC programs: ls, get, put, rm.
    #[command(subcommand, about = "NC programs: ls, get N [FILE], put FILE, rm N")]
    Prog(prog::Prog),
    /// A live status line (one JSON object per line with --json); keeps
    /// going while the CNC is unavailable (a line saying why) and connects
    /// again
    Watch {
        /// Seconds between samples
        #[arg(long, short = 'i', default_value_t = 1.0, value_parser = seconds)]
        interval: f64,
        /// Stop after this many samples (default: run until interrupted)
        #[arg(long, short = 'n')]
        count: Option<u64>,
    },
    /// An MTConnect adapter: serves SHDR to agents for one CNC (--cnc, or
    /// --host) or many (--config FILE), polling in batches, reconnecting
    Adapter(adapter::Args),
    /// Will a program built for FANUC's library work with this one? Lists
    /// the FOCAS functions it uses (linked, or named in its strings for a
    /// program that loads the library with dlopen; or in a source file):
    /// supported, answering EW_VERSION as FANUC's Ethernet library, or
    /// missing (exit status 1, as for a file that cannot load this library).
    /// No CNC needed
    Compat {
        /// The program or shared library (ELF), or a source file (.c, .cs,
        /// .java, .py, .go ...), that calls FOCAS functions
        file: std::path::PathBuf,
    },
}

/// A `--host` value: the host, and the port it names if any.
#[derive(Debug, Clone, PartialEq, Eq)]
struct HostPort {
    host: String,
    port: Option<u16>,
}

impl HostPort {
    /// `host:port` for [`Cnc::connect`], IPv6 addresses in brackets.
    fn addr(&self, default_port: u16) -> String {
        let port = self.port.unwrap_or(default_port);
        if self.host.contains(':') {
            format!("[{}]:{port}", self.host)
        } else {
            format!("{}:{port}", self.host)
        }
    }
}

/// `cnc1`, `cnc1:8193`, `10.0.0.5:8193`, `::1` (an IPv6 address alone),
/// `[::1]`, `[::1]:8193`.
fn host_port(s: &str) -> Result<HostPort, String> {
    let s = s.trim();
    let bad_port = |p: &str| format!("{p:?} in {s:?} is not a TCP port (1 to 65535)");
    let port = |p: &str| match p.parse::<u16>() {
        Ok(n) if n > 0 => Ok(Some(n)),
        _ => Err(bad_port(p)),
    };
    let (host, port) = if let Some(rest) = s.strip_prefix('[') {
        let (host, tail) = rest
            .split_once(']')
            .ok_or_else(|| format!("{s:?}: an IPv6 address in brackets needs its ']'"))?;
        match tail {
            "" => (host, None),
            t => match t.strip_prefix(':') {
                Some(p) => (host, port(p)?),
                None => return Err(format!("{s:?}: expected :PORT after ']'")),
            },
        }
    } else {
        match s.split_once(':') {
            // Two colons or more: an IPv6 address without a port.
            Some((_, rest)) if rest.contains(':') => (s, None),
            Some((host, p)) => (host, port(p)?),
            None => (s, None),
        }
    };
    if host.is_empty() {
        return Err(format!("{s:?} names no host"));
    }
    Ok(HostPort {
        host: host.to_string(),
        port,
    })
}

fn seconds(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() && (0.0..=86400.0).contains(&v) => Ok(v),
        _ => Err(format!("{s:?} is not a number of seconds (0 to 86400)")),
    }
}

fn run(cli: Cli) -> Result<(), Fail> {
    if let Command::Adapter(a) = &cli.command {
        let host = cli.host.as_ref().map(|h| h.addr(cli.port));
        return adapter::run(a, host, cli.port, Duration::from_secs_f64(cli.timeout));
    }
    let Some(host) = &cli.host else {
        return Err(Fail::Usage(Box::new(Cli::command().error(
            clap::error::ErrorKind::MissingRequiredArgument,
            "the following required argument was not provided: --host <HOST> (or FOCAS_HOST)",
        ))));
    };
    let addr = host.addr(cli.port);
    let at = |e| Fail::Api(e).at(&addr);
    let timeout = Duration::from_secs_f64(cli.timeout);
    if let Command::Watch { interval, count } = cli.command {
        let t = watch::Target {
            addr: &addr,
            timeout,
            path: cli.path,
        };
        return watch::run(&t, interval, count, cli.json).map_err(|f| f.at(&addr));
    }
    let cnc = Cnc::connect(&addr, timeout).map_err(at)?;
    if let Some(p) = cli.path {
        cnc.set_path(p).map_err(at)?;
    }
    let json = cli.json;
    let r = match cli.command {
        Command::Info => show::info(&cnc, json),
        Command::Status => show::status(&cnc, json),
        Command::Pos => show::positions(&cnc, json),
        Command::Alarms { history } => show::alarms(&cnc, history, json),
        Command::Param { number, axis } => data::param(&cnc, false, number, axis, json),
        Command::Diag { number, axis } => data::param(&cnc, true, number, axis, json),
        Command::Macro { spec } => data::macro_var(&cnc, spec, json),
        Command::Pmc { address, kind } => data::pmc(&cnc, address, kind, json),
        Command::Prog(p) => prog::run(&cnc, p, json),
        Command::Watch { .. } | Command::Compat { .. } | Command::Adapter(_) => {
            unreachable!("watch and adapter connect themselves, compat needs no CNC")
        }
    };
    r.map_err(|f| f.at(&addr))
}

fn main() -> ExitCode {
    // Never a backtrace: a bug is one line too.
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        eprintln!("focas: internal error: {msg}");
        std::process::exit(70);
    }));
    // Before parsing: a bad command line with --json is JSON too.
    let json = std::env::args_os().skip(1).any(|a| a == "--json");
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => return finish(Err(Fail::Usage(Box::new(e))), json),
    };
    let json = cli.json;
    if let Command::Compat { file } = &cli.command {
        return match compat::run(file, json) {
            Ok(0) => ExitCode::SUCCESS,
            Ok(_problems) => ExitCode::from(1),
            Err(f) => finish(Err(f), json),
        };
    }
    finish(run(cli), json)
}

/// The exit status of a command, its failure reported: one line on
/// stderr, or with `--json` one JSON object on stdout.
fn finish(r: Result<(), Fail>, json: bool) -> ExitCode {
    let f = match r {
        Ok(()) | Err(Fail::Quiet) => return ExitCode::SUCCESS,
        Err(Fail::Shown) => return ExitCode::from(1),
        Err(f) => f,
    };
    let code = match &f {
        Fail::Usage(e) => {
            use clap::error::ErrorKind::*;
            let shown = matches!(
                e.kind(),
                DisplayHelp | DisplayVersion | DisplayHelpOnMissingArgumentOrSubcommand
            );
            if shown || !json {
                e.exit()
            }
            2
        }
        _ => 1,
    };
    if json {
        // Stdout closed: nothing more to say.
        let _ = out::json_line(&out::fail_json(&f));
    } else {
        eprintln!("focas: {f}");
    }
    ExitCode::from(code)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hosts_with_and_without_ports() {
        let hp = |h: &str, p: Option<u16>| HostPort {
            host: h.to_string(),
            port: p,
        };
        assert_eq!(host_port("cnc1"), Ok(hp("cnc1", None)));
        assert_eq!(host_port("10.0.0.5:18193"), Ok(hp("10.0.0.5", Some(18193))));
        assert_eq!(host_port("::1"), Ok(hp("::1", None)));
        assert_eq!(host_port("[::1]"), Ok(hp("::1", None)));
        assert_eq!(host_port("[fe80::1]:8193"), Ok(hp("fe80::1", Some(8193))));
        assert_eq!(hp("::1", Some(9)).addr(8193), "[::1]:9");
        assert_eq!(hp("cnc1", None).addr(8193), "cnc1:8193");
        for bad in [
            "",
            ":8193",
            "cnc1:",
            "cnc1:x",
            "cnc1:0",
            "cnc1:70000",
            "[::1",
            "[::1]x",
        ] {
            assert!(host_port(bad).is_err(), "{bad:?}");
        }
    }
}
