//! focas-sim: serve a simulated FANUC CNC over the FOCAS2 Ethernet protocol.

use fwlib32::sim::{Machine, Profile, Shared, profile::DEFAULT_PROFILE, server};
use std::io::Write;
use std::process::ExitCode;

const USAGE: &str = "usage: focas-sim [--listen ADDR] [--profile FILE] [--print-profile]

  --listen ADDR     address to serve on (default 127.0.0.1:8193; use 127.0.0.1:0 for a free port)
  --profile FILE    machine profile (TOML); default: the built-in 3-axis mill
  --print-profile   print the built-in profile and exit

The first line on stdout is `listening on ADDR`. Serves until killed.";

fn main() -> ExitCode {
    let mut listen = "127.0.0.1:8193".to_string();
    let mut profile_path = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--listen" => match args.next() {
                Some(v) => listen = v,
                None => return usage_error("--listen needs an address"),
            },
            "--profile" => match args.next() {
                Some(v) => profile_path = Some(v),
                None => return usage_error("--profile needs a file"),
            },
            "--print-profile" => {
                print!("{DEFAULT_PROFILE}");
                return ExitCode::SUCCESS;
            }
            "-h" | "--help" => {
                println!("{USAGE}");
                return ExitCode::SUCCESS;
            }
            other => return usage_error(&format!("unknown argument {other}")),
        }
    }
    let profile = match profile_path {
        Some(p) => match Profile::load(std::path::Path::new(&p)) {
            Ok(p) => p,
            Err(e) => {
                eprintln!("focas-sim: {e}");
                return ExitCode::from(2);
            }
        },
        None => Profile::default(),
    };
    let rt = match tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
    {
        Ok(rt) => rt,
        Err(e) => {
            eprintln!("focas-sim: {e}");
            return ExitCode::FAILURE;
        }
    };
    rt.block_on(async {
        let listener = match tokio::net::TcpListener::bind(&listen).await {
            Ok(l) => l,
            Err(e) => {
                eprintln!("focas-sim: cannot listen on {listen}: {e}");
                return ExitCode::FAILURE;
            }
        };
        let addr = listener
            .local_addr()
            .map(|a| a.to_string())
            .unwrap_or(listen);
        let mut out = std::io::stdout();
        let _ = writeln!(out, "listening on {addr}");
        let _ = out.flush();
        let shared = Shared::new(Box::new(Machine::new(profile)));
        tokio::select! {
            _ = server::serve(listener, shared) => {}
            _ = tokio::signal::ctrl_c() => {}
        }
        ExitCode::SUCCESS
    })
}

fn usage_error(msg: &str) -> ExitCode {
    eprintln!("focas-sim: {msg}\n\n{USAGE}");
    ExitCode::from(2)
}
