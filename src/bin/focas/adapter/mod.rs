//! `focas adapter`: an MTConnect adapter for one CNC or a whole shop, in
//! one process. Each device (a CNC) gets its own SHDR port and two kinds
//! of threads: one poller (discovery and the tool table on connecting,
//! then two batches per path and poll, three frames on a 30i; time series
//! sampled between polls; reconnecting after an outage) and one per
//! connected agent (the full state and assets, then every change;
//! `* PING` answered). Logs go to stderr; stdout says `listening on ADDR`
//! once per device.

mod assets;
mod condition;
mod config;
mod model;
mod poll;
mod poller;
mod server;
mod shdr;
mod xml;

use crate::out::Fail;
use config::devices;
use poller::{Polling, connect, poller};
use server::Hub;
use std::io::Write;
use std::net::TcpListener;
use std::path::PathBuf;
use std::time::Duration;

#[derive(clap::Args)]
pub struct Args {
    /// A CNC to serve, with its port if not 8193.
    #[arg(
        long,
        value_name = "HOST[:PORT]",
        help = "A CNC to serve (HOST[:PORT]); several --cnc serve several devices, on \
                consecutive ports from --listen's. Default: --host's"
    )]
    cnc: Vec<String>,
    /// Where agents connect (port 0: any free port; each device's address
    /// is printed as `listening on ADDR`)
    #[arg(long, value_name = "ADDR", default_value = "0.0.0.0:7878")]
    listen: String,
    /// Milliseconds between polls
    #[arg(long, value_name = "MS", default_value_t = 1000, value_parser = clap::value_parser!(u64).range(10..))]
    interval: u64,
    /// The heartbeat answered to an agent's `* PING`, milliseconds; an agent
    /// that pinged and is then silent twice as long is dropped
    #[arg(long, value_name = "MS", default_value_t = 10000, value_parser = clap::value_parser!(u64).range(100..))]
    heartbeat: u64,
    /// A TOML file listing the devices (see the README): many CNCs, a port
    /// each
    #[arg(long, value_name = "FILE")]
    config: Option<PathBuf>,
    /// Print an MTConnect Devices.xml for the discovered machines and exit
    #[arg(long)]
    devices_xml: bool,
    /// Stop after this many polls of each CNC (scripts, tests)
    #[arg(long, value_name = "N")]
    polls: Option<u64>,
}

/// Runs the adapter (or prints Devices.xml); `host`, `port` and `timeout`
/// are the global options'.
pub fn run(a: &Args, host: Option<String>, port: u16, timeout: Duration) -> Result<(), Fail> {
    let (devices, interval, heartbeat, extras) = devices(a, host, port)?;
    if a.devices_xml {
        let mut found = Vec::new();
        for d in &devices {
            let l = connect(&d.cnc, timeout, &extras).map_err(|e| Fail::Api(e).at(&d.cnc))?;
            found.push((d.name.clone(), l.layout));
        }
        let mut out = std::io::stdout().lock();
        return match out.write_all(xml::devices_xml(&found).as_bytes()) {
            Ok(()) => Ok(()),
            Err(_) => Err(Fail::Quiet),
        };
    }
    let mut pollers = Vec::new();
    for d in devices {
        let listener = TcpListener::bind(&d.listen)
            .map_err(|e| Fail::Other(format!("{}: listen on {}: {e}", d.name, d.listen)))?;
        let local = listener
            .local_addr()
            .map_err(|e| Fail::Other(format!("{}: {e}", d.name)))?;
        {
            let mut out = std::io::stdout().lock();
            let _ = writeln!(out, "listening on {local}");
            let _ = out.flush();
        }
        eprintln!("focas adapter: {}: {} served on {local}", d.name, d.cnc);
        let hub = Hub::new(&d.name, heartbeat);
        let h = hub.clone();
        std::thread::Builder::new()
            .name("listener".into())
            .stack_size(128 * 1024)
            .spawn(move || h.serve(listener))
            .map_err(|e| Fail::Other(format!("thread: {e}")))?;
        let cfg = Polling {
            addr: d.cnc.clone(),
            timeout,
            interval: Duration::from_millis(interval),
            polls: a.polls,
            extras: extras.clone(),
        };
        pollers.push(
            std::thread::Builder::new()
                .name("poller".into())
                .stack_size(512 * 1024)
                .spawn(move || poller(hub, cfg))
                .map_err(|e| Fail::Other(format!("thread: {e}")))?,
        );
    }
    for p in pollers {
        let _ = p.join();
    }
    Ok(())
}
