//! `focas-sim`: a CNC simulator speaking the FOCAS2 Ethernet protocol,
//! configured from a machine profile. It runs on its own threads with its
//! own tokio runtime, so tests and tools can block while it serves.
//!
//! Layers, each using only those before it (tests/artifacts/layers.rs checks it):
//! service (the CncService trait, errors) and pmc (pmc_data) → profile (pure data,
//! with its sections in profile/) → store (program memory) → run (the live
//! state of the paths) → machine (the [`Machine`]) → route (a dispatch
//! row) → the areas answering its requests, each declaring its `ROUTES`
//! (status, position, program, operate, param, macros, pmc_answers,
//! offset, tool, history, memory, folder, maintenance), the clock and the
//! transfers (upload, download) → dispatch (the one lookup over all rows,
//! and the CncService impl); faults (the `[[fault]]`s at an instant) and
//! trace (frames as text) → shared ([`Shared`]: what a machine's
//! connections share) → session (one connection) → server (listeners) →
//! fleet (many machines on one runtime).

pub mod axes;
pub mod clock;
pub mod dispatch;
pub mod download;
pub mod faults;
pub mod fleet;
pub mod folder;
pub mod history;
pub mod machine;
pub mod macros;
pub mod magazine;
pub mod maintenance;
pub mod memory;
pub mod modal;
pub mod offset;
pub mod operate;
pub mod param;
pub mod plan;
pub mod pmc;
pub mod pmc_answers;
pub mod pmc_data;
pub mod position;
pub mod profile;
pub mod program;
pub mod route;
pub mod run;
pub mod sampling;
pub mod screen;
pub mod server;
pub mod service;
pub mod session;
pub mod setting;
pub mod shared;
pub mod status;
pub mod store;
pub mod tool;
pub mod trace;
pub mod upload;

use std::net::SocketAddr;
use std::sync::Arc;

pub use fleet::{Fleet, FleetOptions};
pub use machine::Machine;
pub use profile::Profile;
pub use shared::Shared;

/// A running simulator: one machine (a [`Fleet`] serves many on one
/// runtime). The profile's `[[fault]]`s for machine 1 apply, timed from its
/// start. Dropping it stops it.
pub struct Simulator {
    addr: SocketAddr,
    shared: Arc<Shared>,
    runtime: Option<tokio::runtime::Runtime>,
    /// The machine's start: time zero of the running program.
    started: std::time::Instant,
}

impl Simulator {
    /// Starts serving `profile` on `listen` (use "127.0.0.1:0" for a free port).
    pub fn start(profile: Profile, listen: &str) -> std::io::Result<Simulator> {
        let runtime = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(2)
            .thread_name("focas-sim")
            .enable_all()
            .build()?;
        let faults = profile
            .faults
            .iter()
            .filter(|f| f.concerns(1))
            .cloned()
            .collect();
        // The dispatch table, checked before serving (src/sim/dispatch.rs).
        dispatch::rows();
        let machine = Machine::new(profile);
        let started = machine.started;
        let net = server::Net {
            zero: started,
            faults: faults::FaultPlan::new(faults),
            ..server::Net::plain()
        };
        let shared = Shared::with_net(Box::new(machine), net);
        let addr = resolve(listen)?;
        let listener = server::bind(addr)?;
        listener.set_nonblocking(true)?;
        let listener = {
            let _guard = runtime.enter();
            tokio::net::TcpListener::from_std(listener)?
        };
        let addr = listener.local_addr()?;
        runtime.spawn(server::serve(listener, shared.clone()));
        Ok(Simulator {
            addr,
            shared,
            runtime: Some(runtime),
            started,
        })
    }

    /// Stops the simulator's clock at `elapsed` after its start: every
    /// later frame sees the machine as it is then (deterministic tests).
    pub fn set_elapsed(&self, elapsed: std::time::Duration) {
        self.shared.set_clock(Some(self.started + elapsed));
    }

    /// Lets the clock run in real time again.
    pub fn real_time(&self) {
        self.shared.set_clock(None);
    }

    pub fn addr(&self) -> SocketAddr {
        self.addr
    }

    pub fn port(&self) -> u16 {
        self.addr.port()
    }

    /// Sessions (client connection pairs) open right now.
    pub fn sessions(&self) -> usize {
        self.shared.sessions()
    }

    /// Data request frames answered so far: the round trips clients made
    /// on connection 2 (tests and benches count them).
    pub fn data_frames(&self) -> u64 {
        self.shared.data_frames()
    }
}

impl Drop for Simulator {
    fn drop(&mut self) {
        if let Some(rt) = self.runtime.take() {
            rt.shutdown_background();
        }
    }
}

/// The first address `listen` ("host:port") resolves to.
pub(crate) fn resolve(listen: &str) -> std::io::Result<SocketAddr> {
    use std::net::ToSocketAddrs;
    listen.to_socket_addrs()?.next().ok_or_else(|| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            format!("{listen}: no address"),
        )
    })
}
