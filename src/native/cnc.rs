//! [`Cnc`]: a connection to one CNC, over the library's own connection
//! pairs and handle table (src/client).

use super::error::{Error, Ew, Result};
use super::part::{AnyPart, Frame, One, Part};
use crate::client::handles::{self, Handle};
use crate::client::pair;
use crate::proto::call::Ctx;
use std::any::Any;
use std::sync::Arc;
use std::time::Duration;

/// A connection to a CNC.
///
/// Connections to the same host and port share one FOCAS connection pair
/// (the CNC's session count is spent once per process, as with FANUC's
/// library); each `Cnc` has its own current path and timeout. A `Cnc` is
/// `Send` and `Sync`: calls from several threads are serialised on the pair.
/// [`Cnc::try_clone`] gives another `Cnc` on the same pair (cheap: no
/// traffic). Dropping the last `Cnc` (and C handle) of a pair closes it.
///
/// ```
/// use fwlib32::native::Cnc;
/// use fwlib32::sim::{Profile, Simulator};
/// use std::time::Duration;
///
/// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
/// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
/// assert_eq!(cnc.path(), 1);
/// let other = cnc.try_clone()?;
/// std::thread::spawn(move || other.status()).join().unwrap()?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Cnc {
    number: u16,
    handle: Arc<Handle>,
    addr: String,
}

impl std::fmt::Debug for Cnc {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Cnc")
            .field("addr", &self.addr)
            .field("path", &self.path())
            .finish()
    }
}

/// FOCAS2's TCP port.
pub const DEFAULT_PORT: u16 = 8193;

/// Host and port of `"host:port"`, `"[v6]:port"`, `"host"` or `"v6"`.
fn split_addr(addr: &str) -> (String, u16) {
    let addr = addr.trim();
    if let Some(rest) = addr.strip_prefix('[')
        && let Some((host, tail)) = rest.split_once(']')
    {
        let port = tail.strip_prefix(':').and_then(|p| p.parse().ok());
        return (host.to_string(), port.unwrap_or(DEFAULT_PORT));
    }
    match addr.rsplit_once(':') {
        Some((host, port)) if !host.contains(':') => match port.parse() {
            Ok(p) => (host.to_string(), p),
            Err(_) => (addr.to_string(), DEFAULT_PORT),
        },
        _ => (addr.to_string(), DEFAULT_PORT),
    }
}

/// Whole seconds, as the library counts them: a part of a second counts as
/// one, zero is "wait for ever" (FOCAS's 0).
fn secs(timeout: Duration) -> i32 {
    let s = timeout.as_secs() + u64::from(timeout.subsec_nanos() > 0);
    i32::try_from(s).unwrap_or(i32::MAX)
}

impl Cnc {
    /// Connects to the CNC at `addr` (`"host:port"`, or `"host"` for port
    /// 8193), or shares the connection this process already has to it.
    /// Every later exchange waits at most `timeout` (whole seconds, a
    /// fraction rounded up; [`Duration::ZERO`] waits for ever).
    ///
    /// Fails with [`Error::Socket`] (`EW_SOCKET`) when the host does not
    /// resolve, refuses, or does not answer in time.
    pub fn connect(addr: &str, timeout: Duration) -> Result<Cnc> {
        const CALL: &str = "cnc_allclibhndl3";
        let (host, port) = split_addr(addr);
        let t = secs(timeout);
        let p = pair::acquire(&host, port, t, 0).map_err(|e| Error::of(CALL, e))?;
        let addr = if host.contains(':') {
            format!("[{host}]:{port}")
        } else {
            format!("{host}:{port}")
        };
        Cnc::on(p, t, addr, 1)
    }

    /// A new handle on the pair `p` (its reference already taken).
    fn on(p: Arc<pair::Pair>, timeout: i32, addr: String, path: u16) -> Result<Cnc> {
        let number = match handles::insert(p.clone(), timeout) {
            Ok(n) => n,
            Err(e) => {
                let _ = p.release(timeout);
                return Err(Error::of("cnc_allclibhndl3", e));
            }
        };
        let handle = handles::get(number).map_err(|e| Error::of("cnc_allclibhndl3", e))?;
        handle.state.lock().path = path;
        Ok(Cnc {
            number,
            handle,
            addr,
        })
    }

    /// Another `Cnc` on the same connection, with this one's path and
    /// timeout (no traffic). Fails with `EW_SOCKET` once the connection broke.
    pub fn try_clone(&self) -> Result<Cnc> {
        let p = self.handle.pair.clone();
        p.share().map_err(|e| Error::of("cnc_allclibhndl3", e))?;
        let (timeout, path) = {
            let s = self.handle.state.lock();
            (s.timeout, s.path)
        };
        Cnc::on(p, timeout, self.addr.clone(), path)
    }

    /// `"host:port"` as connected (`"[v6]:port"` for an IPv6 address).
    pub fn addr(&self) -> &str {
        &self.addr
    }

    /// The timeout of each exchange.
    pub fn timeout(&self) -> Duration {
        Duration::from_secs(self.handle.state.lock().timeout.max(0) as u64)
    }

    /// Sets the timeout of later exchanges (as [`Cnc::connect`]'s).
    pub fn set_timeout(&self, timeout: Duration) {
        self.handle.state.lock().timeout = secs(timeout);
    }

    /// The path later calls address (1 after connecting).
    pub fn path(&self) -> u16 {
        self.handle.state.lock().path
    }

    /// How many paths the CNC has.
    pub fn path_count(&self) -> u16 {
        self.handle.pair.info.open.path_count() as u16
    }

    /// Selects the path (1..=[`Cnc::path_count`]) later calls of this `Cnc`
    /// address; other `Cnc`s are not affected. Another number is `EW_PATH`.
    pub fn set_path(&self, path: u16) -> Result<()> {
        if path == 0 || path > self.path_count() {
            return Err(Error::invalid(
                "cnc_setpath",
                Ew::PATH,
                format!("the CNC has paths 1 to {}", self.path_count()),
            ));
        }
        self.handle.state.lock().path = path;
        Ok(())
    }

    pub(crate) fn handle(&self) -> &Handle {
        &self.handle
    }

    /// The handle's number in the library's table (the upload's owner).
    pub(crate) fn number(&self) -> u16 {
        self.number
    }

    pub(crate) fn ctx(&self) -> Ctx {
        self.handle.ctx()
    }

    /// Runs one part in its own frame.
    pub(crate) fn run<P: Part>(&self, p: P) -> Result<P::Out> {
        if p.subs(&self.ctx()).is_empty() {
            return p.decode(&self.ctx(), &[]);
        }
        self.handle
            .call(&One(&p))
            .map_err(|e| Error::of(p.call(), e))?
    }

    /// Runs parts in one frame: each part's result, boxed (see [`Frame`]).
    /// A failed exchange fails all of them; it is named after the first.
    pub(crate) fn run_frame(&self, parts: &[Box<dyn AnyPart>]) -> Result<Vec<Box<dyn Any + Send>>> {
        let cx = self.ctx();
        if parts.iter().all(|p| p.subs(&cx).is_empty()) {
            return Ok(parts.iter().map(|p| p.decode_any(&cx, &[])).collect());
        }
        let call = parts
            .iter()
            .find(|p| !p.subs(&cx).is_empty())
            .map_or("", |p| p.call());
        self.handle
            .call(&Frame(parts))
            .map_err(|e| Error::of(call, e))
    }
}

impl Drop for Cnc {
    /// Frees the handle; the last one of the pair closes it (close frames on
    /// both connections). Nothing happens if `cnc_exitprocess` freed it.
    fn drop(&mut self) {
        if handles::remove_exact(self.number, &self.handle) {
            let timeout = self.handle.state.lock().timeout;
            let _ = self.handle.pair.release(timeout);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn addresses() {
        let s = |a: &str| split_addr(a);
        assert_eq!(s("10.0.0.5"), ("10.0.0.5".into(), 8193));
        assert_eq!(s("cnc1:9000"), ("cnc1".into(), 9000));
        assert_eq!(s("[::1]:9000"), ("::1".into(), 9000));
        assert_eq!(s("[::1]"), ("::1".into(), 8193));
        assert_eq!(s("::1"), ("::1".into(), 8193));
        assert_eq!(s("cnc1:x"), ("cnc1:x".into(), 8193));
    }

    #[test]
    fn timeouts_in_whole_seconds() {
        assert_eq!(secs(Duration::ZERO), 0);
        assert_eq!(secs(Duration::from_millis(10)), 1);
        assert_eq!(secs(Duration::from_secs(5)), 5);
    }

    #[test]
    fn cnc_is_send_and_sync() {
        fn both<T: Send + Sync>() {}
        both::<Cnc>();
    }
}
