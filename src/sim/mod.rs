//! `focas-sim`: a CNC simulator speaking the FOCAS2 Ethernet protocol,
//! configured from a machine profile. It runs on its own threads with its
//! own tokio runtime, so tests and tools can block while it serves.

pub mod history;
pub mod machine;
pub mod macros;
pub mod offset;
pub mod param;
pub mod pmc;
pub mod position;
pub mod profile;
pub mod program;
pub mod run;
pub mod server;
pub mod service;

use std::net::SocketAddr;
use std::sync::Arc;

pub use machine::Machine;
pub use profile::Profile;
pub use server::Shared;

/// A running simulator. Dropping it stops it.
pub struct Simulator {
    addr: SocketAddr,
    shared: Arc<Shared>,
    runtime: Option<tokio::runtime::Runtime>,
}

impl Simulator {
    /// Starts serving `profile` on `listen` (use "127.0.0.1:0" for a free port).
    pub fn start(profile: Profile, listen: &str) -> std::io::Result<Simulator> {
        let runtime = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(2)
            .thread_name("focas-sim")
            .enable_all()
            .build()?;
        let shared = Shared::new(Box::new(Machine::new(profile)));
        let listener = runtime.block_on(tokio::net::TcpListener::bind(listen))?;
        let addr = listener.local_addr()?;
        runtime.spawn(server::serve(listener, shared.clone()));
        Ok(Simulator {
            addr,
            shared,
            runtime: Some(runtime),
        })
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
}

impl Drop for Simulator {
    fn drop(&mut self) {
        if let Some(rt) = self.runtime.take() {
            rt.shutdown_background();
        }
    }
}
