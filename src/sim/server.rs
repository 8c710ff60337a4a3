//! The simulator's network side (tokio): one listener per machine, each
//! connection served by a task (src/sim/session.rs) that answers the
//! open/close handshake and data frames through a [`CncService`](super::service::CncService). The
//! machine's `[[fault]]`s (src/sim/faults.rs) decide when it refuses
//! connections, stays silent, answers late or cuts answers short.

pub use super::shared::{Net, Shared};
use std::os::fd::AsRawFd;
use std::sync::Arc;
use std::sync::atomic::Ordering;
use tokio::net::TcpListener;

/// A listener on `addr`, bound to an explicit port even for port 0 (a
/// free one is found first): a listener bound to port 0 loses its port
/// when it stops listening, and a refusing machine must get it back.
pub fn bind(addr: std::net::SocketAddr) -> std::io::Result<std::net::TcpListener> {
    if addr.port() != 0 {
        return std::net::TcpListener::bind(addr);
    }
    let mut last = None;
    for _ in 0..64 {
        let port = std::net::TcpListener::bind(addr)?.local_addr()?.port();
        match std::net::TcpListener::bind(std::net::SocketAddr::new(addr.ip(), port)) {
            Ok(l) => return Ok(l),
            Err(e) => last = Some(e),
        }
    }
    Err(last.unwrap_or_else(|| std::io::ErrorKind::AddrInUse.into()))
}

/// Accepts connections until the task is dropped.
pub async fn serve(mut listener: TcpListener, shared: Arc<Shared>) {
    if !shared.net.faults.refuses() {
        loop {
            accept_one(&listener, &shared).await;
        }
    }
    *shared.listener.lock() = Some((listener.as_raw_fd(), true));
    let _forget = ForgetListener(&shared);
    let mut clock = shared.clock.subscribe();
    let mut registered = shared.relistens.load(Ordering::Acquire);
    loop {
        clock.borrow_and_update();
        // Not listening: a connection attempt is refused (RST), as by a
        // host whose FOCAS server is down. Open connections stay.
        let refusing = shared.apply_listening();
        let relistens = shared.relistens.load(Ordering::Acquire);
        if relistens != registered {
            registered = relistens;
            listener = match reregister(listener) {
                Ok(l) => l,
                Err(_) => return,
            };
        }
        let t = shared.fault_time(shared.now());
        // In real time the next change comes by the clock; a frozen clock
        // moves only when a test sets it.
        let wake = shared
            .net
            .faults
            .next_refusal_change(t)
            .filter(|_| !shared.frozen())
            .map(|s| shared.net.zero + std::time::Duration::from_secs_f64(s));
        let until = async {
            match wake {
                Some(at) => tokio::time::sleep_until(at.into()).await,
                None => std::future::pending().await,
            }
        };
        if refusing {
            tokio::select! {
                _ = until => {}
                _ = clock.changed() => {}
            }
        } else {
            tokio::select! {
                _ = accept_one(&listener, &shared) => {}
                _ = until => {}
                _ = clock.changed() => {}
            }
        }
    }
}

/// The same socket, registered anew with the runtime.
fn reregister(l: TcpListener) -> std::io::Result<TcpListener> {
    let l = l.into_std()?;
    l.set_nonblocking(true)?;
    TcpListener::from_std(l)
}

/// The listener's socket is no longer the machine's once serving stops.
struct ForgetListener<'a>(&'a Shared);
impl Drop for ForgetListener<'_> {
    fn drop(&mut self) {
        *self.0.listener.lock() = None;
    }
}

async fn accept_one(listener: &TcpListener, shared: &Arc<Shared>) {
    match listener.accept().await {
        Ok((stream, _)) => {
            let _ = stream.set_nodelay(true);
            let id = shared.next_conn.fetch_add(1, Ordering::Relaxed);
            tokio::spawn(super::session::connection(stream, shared.clone(), id));
        }
        // Out of file descriptors and the like: back off briefly, keep serving.
        Err(_) => tokio::time::sleep(std::time::Duration::from_millis(10)).await,
    }
}
