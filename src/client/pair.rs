//! One connection pair per (host, port) per process (SPEC.md §1, §3):
//! connection 1 (program transfer) and connection 2 (data), shared and
//! reference-counted by every handle to that CNC.

use super::conn::{Conn, Deadline, close_conn};
use super::conn1::Conn1;
use super::log;
use crate::error::{Error, Result, detail};
use crate::proto::call::{self, Ctx, Erased};
use crate::proto::frame::{CLIENT_VERSION, Frame, ftype};
use crate::proto::open::{CncClass, OpenBody};
use crate::proto::packet::{CLASS_PMC, ReqSub};
use crate::proto::param::Param16;
use crate::proto::status::{SysInfo, sysinfo_at_connect};
use crate::proto::{OPTION_PARAM_15, OPTION_PARAM_16, cmd};
use parking_lot::{Condvar, Mutex, MutexGuard};
use std::collections::HashMap;
use std::net::{SocketAddr, TcpStream, ToSocketAddrs};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// What the CNC told us at connect time; immutable afterwards.
#[derive(Debug, Clone)]
pub struct CncInfo {
    pub open: OpenBody,
    /// Start-up sysinfo answers, by path number (1-based); None for absent paths.
    pub sysinfo: Vec<Option<SysInfo>>,
    /// The FOCAS option flags the library learns at connect.
    pub option: u16,
    /// Series 15: word 0 of the start-up 0x8c answer (path 1's axis count,
    /// cnc_sysinfo_ex's `ctrl_axis` \[oracle\]); 0 on other classes.
    pub axes15: u16,
}

impl CncInfo {
    pub fn ctx(&self, path: u16) -> Ctx {
        Ctx {
            class: self.open.class(),
            max_axes: self.open.max_axes(path as usize),
            max_spindles: self.open.max_spindles(),
            path,
            mt_type: self
                .sysinfo
                .get(usize::from(path).wrapping_sub(1))
                .copied()
                .flatten()
                .map_or([0; 2], |s| s.mt_type),
        }
    }
}

struct Conns {
    c1: Conn,
    c2: Conn,
}

pub struct Pair {
    pub key: String,
    /// Where and as whom the pair connected, for [`Pair::revive`].
    host: String,
    port: u16,
    id: u32,
    /// Serialises revivals: one reconnect at a time per pair, waited for
    /// at most the call's timeout.
    revive: Mutex<()>,
    pub info: CncInfo,
    /// Connection 2, the data requests. One exchange at a time: waited for
    /// at most the call's timeout ([`Deadline::lock`]; EW_BUSY, nothing
    /// sent, when another call kept it that long), and handed to the
    /// longest waiter at each release (`unlock_fair`), so that threads
    /// on one CNC take turns instead of one taking it again and again.
    io: Mutex<Option<Conn>>,
    /// Connection 1 and the program upload on it (src/client/upload.rs).
    /// Its own lock, never held together with `io`: an upload never holds
    /// up the data requests of other handles.
    pub(super) c1: Mutex<Option<Conn1>>,
    /// Both connections' sockets, so that [`Pair::kill`] and the last
    /// free shut them down without waiting for a call that holds them
    /// (that call then fails at once).
    shutters: Mutex<[Option<Arc<TcpStream>>; 2]>,
    /// Number of handles using the pair; the last free closes it.
    refs: Mutex<usize>,
    dead: AtomicBool,
}

/// What is known of the pair to one "host:port".
#[derive(Default)]
enum SlotState {
    #[default]
    Empty,
    /// A handle is connecting: others wait for its pair (to share it), at
    /// most their own timeout.
    Connecting,
    Ready(Arc<Pair>),
}

/// A slot's lock is held only to look and to set its state, never across
/// the connect, so a connect that hangs holds up no other call; handles
/// made at the same time still share one pair.
#[derive(Default)]
struct Slot {
    state: Mutex<SlotState>,
    changed: Condvar,
}

static SLOTS: Mutex<Option<HashMap<String, Arc<Slot>>>> = Mutex::new(None);

fn slot(key: &str) -> Arc<Slot> {
    let mut g = SLOTS.lock();
    g.get_or_insert_with(HashMap::new)
        .entry(key.to_string())
        .or_default()
        .clone()
}

/// Sets a slot back to Empty if its connect did not finish (a panic).
struct Connecting<'a>(&'a Slot, bool);

impl Drop for Connecting<'_> {
    fn drop(&mut self) {
        if !self.1 {
            *self.0.state.lock() = SlotState::Empty;
            self.0.changed.notify_all();
        }
    }
}

/// A live pair to `host:port`, shared if one exists, else a new connection.
/// Returns the pair with its reference count already taken. Waits for
/// another handle connecting to the same CNC at most until this one's
/// timeout (EW_SOCKET, as a connect that timed out), then connects itself
/// if that one failed.
pub fn acquire(host: &str, port: u16, timeout: i32, id: u32) -> Result<Arc<Pair>> {
    let key = format!("{host}:{port}");
    let deadline = Deadline::after_secs(timeout);
    let slot = slot(&key);
    let mut g = slot.state.lock();
    loop {
        match &*g {
            SlotState::Ready(p) => {
                let mut refs = p.refs.lock();
                if *refs > 0 && !p.is_dead() {
                    *refs += 1;
                    return Ok(p.clone());
                }
                break;
            }
            SlotState::Empty => break,
            SlotState::Connecting => match deadline.at() {
                None => slot.changed.wait(&mut g),
                Some(at) => {
                    if slot.changed.wait_until(&mut g, at).timed_out() {
                        return Err(Error::socket(
                            detail::CONNECT,
                            "connect: timed out waiting for another handle's connection to this CNC",
                        ));
                    }
                }
            },
        }
    }
    *g = SlotState::Connecting;
    drop(g);
    let mut guard = Connecting(&slot, false);
    let r = Pair::connect(key, host, port, deadline, timeout, id).map(Arc::new);
    guard.1 = true;
    *slot.state.lock() = match &r {
        Ok(p) => SlotState::Ready(p.clone()),
        Err(_) => SlotState::Empty,
    };
    slot.changed.notify_all();
    r
}

/// Lets go of `pair` if its slot still holds it (its last handle was
/// freed): the pair's memory goes with it; the slot stays, empty.
fn vacate(pair: &Pair) {
    let slot = SLOTS
        .lock()
        .as_ref()
        .and_then(|m| m.get(&pair.key).cloned());
    if let Some(slot) = slot {
        let mut g = slot.state.lock();
        if matches!(&*g, SlotState::Ready(p) if std::ptr::eq(&**p, pair)) {
            *g = SlotState::Empty;
        }
    }
}

/// Closes every pair (cnc_exitprocess), waiting for no call.
pub fn forget_all() {
    let slots: Vec<Arc<Slot>> = SLOTS
        .lock()
        .take()
        .map(|m| m.into_values().collect())
        .unwrap_or_default();
    for s in slots {
        if let SlotState::Ready(p) = std::mem::take(&mut *s.state.lock()) {
            p.kill();
        }
    }
}

fn resolve(host: &str, port: u16) -> Result<Vec<SocketAddr>> {
    let addrs: Vec<SocketAddr> = (host, port)
        .to_socket_addrs()
        .map_err(|e| Error::socket(detail::CONNECT, format!("resolve {host}: {e}")))?
        .collect();
    if addrs.is_empty() {
        return Err(Error::socket(
            detail::CONNECT,
            format!("resolve {host}: no address"),
        ));
    }
    Ok(addrs)
}

/// Open handshake on one connection (optionally preceded by the 0xf501 id frame).
fn open(conn: &mut Conn, number: u16, id: u32, deadline: Deadline) -> Result<Frame> {
    if id != 0 {
        conn.send(
            &Frame::new(CLIENT_VERSION, ftype::ID_REQ, id.to_be_bytes().to_vec()),
            deadline,
        )?;
        let r = conn.recv_kind(0xf5, deadline)?;
        if r.ftype == ftype::ID_REJECT {
            return Err(Error::protocol(
                detail::REJECTED,
                "CNC rejected the connection id",
            ));
        }
    }
    conn.send(
        &Frame::new(
            CLIENT_VERSION,
            ftype::OPEN_REQ,
            number.to_be_bytes().to_vec(),
        ),
        deadline,
    )?;
    let r = conn.recv_kind(0x01, deadline)?;
    if r.ftype == ftype::OPEN_REJECT {
        return Err(Error::socket(
            detail::REJECTED,
            "CNC refused the session (session limit reached)",
        ));
    }
    Ok(r)
}

impl Pair {
    /// Opens both connections and makes the start-up exchanges by
    /// `deadline`; a failed start-up is closed within a fresh `timeout`.
    fn connect(
        key: String,
        host: &str,
        port: u16,
        deadline: Deadline,
        timeout: i32,
        id: u32,
    ) -> Result<Pair> {
        let addrs = resolve(host, port)?;
        let mut c1 = Conn::connect(&addrs, 1, deadline)?;
        // FANUC's library checks the conn-1 answer's size before connecting
        // conn 2 (SPEC.md §3.2): a bad one fails with EW_PROTOCOL right here.
        let r1 = open(&mut c1, 1, id, deadline)?;
        OpenBody::decode(r1.version, &r1.body).map_err(Error::from)?;
        let mut c2 = Conn::connect(&addrs, 2, deadline)?;
        let r = open(&mut c2, 2, id, deadline)?;
        let open_body = OpenBody::decode(r.version, &r.body).map_err(Error::from)?;
        let mut conns = Conns { c1, c2 };
        match Self::startup(&mut conns, &open_body, deadline) {
            Ok((sysinfo, option, axes15)) => {
                crate::log_at!(
                    log::CALLS,
                    "connected to {key}: {:?}, {} path(s)",
                    open_body.class(),
                    open_body.path_count()
                );
                let shutters = [Some(conns.c1.shutter()), Some(conns.c2.shutter())];
                Ok(Pair {
                    key,
                    host: host.to_string(),
                    port,
                    id,
                    revive: Mutex::new(()),
                    info: CncInfo {
                        open: open_body,
                        sysinfo,
                        option,
                        axes15,
                    },
                    io: Mutex::new(Some(conns.c2)),
                    c1: Mutex::new(Some(Conn1::new(conns.c1))),
                    shutters: Mutex::new(shutters),
                    refs: Mutex::new(1),
                    dead: AtomicBool::new(false),
                })
            }
            Err(e) => {
                // Start-up failed: close politely, as FANUC's library does,
                // each connection in its own exchange. A connection 2 that
                // timed out or broke gets the close frame but no wait.
                let fresh = Deadline::after_secs(timeout);
                let _ = close_conn(&mut conns.c1, fresh);
                if e.kills_connection() {
                    let _ = conns.c2.send(
                        &Frame::new(CLIENT_VERSION, ftype::CLOSE_REQ, Vec::new()),
                        fresh,
                    );
                } else {
                    let _ = close_conn(&mut conns.c2, fresh);
                }
                Err(e)
            }
        }
    }

    /// Start-up traffic on connection 2 (SPEC.md §3.1, §3.4).
    fn startup(
        conns: &mut Conns,
        open: &OpenBody,
        deadline: Deadline,
    ) -> Result<(Vec<Option<SysInfo>>, u16, u16)> {
        let words = open.path_words();
        let paths: Vec<u16> = (1..=words.len() as u16)
            .filter(|p| words[*p as usize - 1] != 0)
            .collect();
        let mut subs = sysinfo_at_connect(&paths);
        let class = open.class();
        if class == (CncClass::Series16 { kind: 2 }) {
            let mut s = ReqSub::cnc(cmd::SYSINFO15, &[]);
            s.path = 1;
            subs.push(s);
        }
        let resp = conns.c2.exchange(&subs, deadline)?;
        let mut sysinfo = vec![None; words.len()];
        for (i, p) in paths.iter().enumerate() {
            sysinfo[*p as usize - 1] = Some(call::payload::<SysInfo>(resp, i)?);
        }
        let mut axes15 = 0;
        if class == (CncClass::Series16 { kind: 2 }) {
            // Series 15: the companion's error fails the connect, as FANUC's library.
            let p = &call::sub(resp, paths.len())?.payload;
            axes15 = p.get(..2).map_or(0, |w| u16::from_be_bytes([w[0], w[1]]));
        }
        let option_param = match class {
            CncClass::Series30 => None,
            CncClass::Series16 { kind: 3 } => None,
            CncClass::Series16 { kind: 2 } => Some((cmd::RDPARAM, OPTION_PARAM_15, 0x3f)),
            CncClass::Series16 { .. } => Some((cmd::RDPARAM16, OPTION_PARAM_16, 0x01)),
        };
        let mut option = open_option(open);
        if let Some((command, number, mask)) = option_param {
            let mut s = ReqSub::cnc(command, &[number, number]);
            s.path = 1;
            let resp = conns.c2.exchange(&[s], deadline)?;
            // An error here fails the connect, as in FANUC's library.
            let p = call::payload::<Param16>(resp, 0)?;
            option = p.values.first().map_or(0, |v| (*v as u16) & 0xff & mask);
        }
        Ok((sysinfo, option, axes15))
    }

    /// Takes one more reference for a new handle on this live pair (the
    /// Rust API's `Cnc::try_clone`); a pair already closed or torn down
    /// gives EW_SOCKET.
    pub fn share(&self) -> Result<()> {
        let mut refs = self.refs.lock();
        if *refs == 0 || self.is_dead() {
            return Err(dead());
        }
        *refs += 1;
        Ok(())
    }

    pub fn is_dead(&self) -> bool {
        self.dead.load(Ordering::Acquire)
    }

    /// Tears the pair down ("circuit destroyed"): every later call on any of
    /// its handles fails with EW_SOCKET without traffic. Waits for no call:
    /// the sockets are shut down, which ends a call waiting on them at once
    /// (EW_SOCKET), and the connections are dropped now or by that call.
    pub fn kill(&self) {
        self.dead.store(true, Ordering::Release);
        self.shut();
        if let Some(mut g) = self.c1.try_lock() {
            g.take();
        }
        if let Some(mut g) = self.io.try_lock() {
            g.take();
        }
    }

    /// Shuts both sockets down, whoever holds the connections.
    fn shut(&self) {
        for s in self.shutters.lock().iter_mut() {
            if let Some(s) = s.take() {
                let _ = s.shutdown(std::net::Shutdown::Both);
            }
        }
    }

    /// Reconnects a pair torn down by a failure (fwlib_set_reconnect): the
    /// open on both connections and the start-up exchanges again, by
    /// `deadline`. The CNC must answer the open as before (the handles keep
    /// what they learnt at connect time); a pair its handles freed stays
    /// dead. Nothing sent before is sent again.
    pub fn revive(&self, deadline: Deadline, timeout: i32) -> Result<()> {
        let Some(_one) = deadline.lock(&self.revive) else {
            return Err(Error::socket(
                detail::CONNECT,
                "connect: timed out waiting for another handle's reconnect",
            ));
        };
        if !self.is_dead() {
            return Ok(());
        }
        if *self.refs.lock() == 0 {
            return Err(dead());
        }
        let fresh = Pair::connect(
            self.key.clone(),
            &self.host,
            self.port,
            deadline,
            timeout,
            self.id,
        )?;
        if fresh.info.open != self.info.open {
            fresh.kill();
            return Err(Error::socket(
                detail::CONNECT,
                "the CNC answered the open as another machine",
            ));
        }
        let (Some(mut c1), Some(mut io)) = (deadline.lock(&self.c1), deadline.lock(&self.io))
        else {
            fresh.kill();
            return Err(busy());
        };
        *c1 = fresh.c1.lock().take();
        *io = fresh.io.lock().take();
        *self.shutters.lock() = std::mem::take(&mut *fresh.shutters.lock());
        self.dead.store(false, Ordering::Release);
        crate::log_at!(log::CALLS, "reconnected to {}", self.key);
        Ok(())
    }

    /// Sends `c`'s subpackets on connection 2 with the handle's path and
    /// decodes the answer (still holding the connection: the answer is
    /// read into its reused buffers). One exchange at a time per pair.
    ///
    /// CNC subpackets without a path get the handle's `path`; PMC
    /// subpackets carry the handle's selected PMC unit (`pmc_unit`, 1 until
    /// pmc_select_pmc_unit), as FANUC's library sends them.
    #[inline(always)]
    pub fn call(
        &self,
        c: &mut Erased<'_>,
        path: u16,
        pmc_unit: u16,
        deadline: Deadline,
    ) -> Result<()> {
        let cx = self.info.ctx(path);
        let Some(mut io) = deadline.lock(&self.io) else {
            return Err(busy());
        };
        if self.is_dead() {
            // Torn down while a call held the connection: dropped now.
            io.take();
        }
        let Some(c2) = io.as_mut() else {
            return Err(dead());
        };
        let mut subs = c2.take_request();
        (c.request)(&cx, &mut subs);
        for s in &mut subs {
            if s.class == CLASS_PMC {
                s.path = pmc_unit;
            } else if s.path == 0 {
                s.path = path;
            }
        }
        let r = c2
            .exchange(&subs, deadline)
            .map(|resp| (c.decode)(&cx, resp));
        c2.give_request(subs);
        match r {
            Ok(r) => {
                MutexGuard::unlock_fair(io);
                r
            }
            Err(e) => {
                if stream_broken(&e) {
                    drop(io);
                    self.kill();
                } else {
                    MutexGuard::unlock_fair(io);
                }
                Err(e)
            }
        }
    }

    /// Drops one handle's reference; the last one sends the close frames
    /// (their answers waited for at most `timeout`). It waits for no call:
    /// when one still holds a connection (a handle freed while another
    /// thread calls on it, cnc_exitprocess), the sockets are shut down
    /// instead, which ends that call at once (EW_SOCKET).
    pub fn release(&self, timeout: i32) -> Result<()> {
        let mut refs = self.refs.lock();
        *refs = refs.saturating_sub(1);
        if *refs > 0 {
            return Ok(());
        }
        self.dead.store(true, Ordering::Release);
        drop(refs);
        vacate(self);
        let c1 = self.c1.try_lock().map(|mut g| g.take());
        let c2 = self.io.try_lock().map(|mut g| g.take());
        let (Some(c1), Some(c2)) = (c1, c2) else {
            self.shut();
            return Ok(());
        };
        match (c1, c2) {
            (Some(mut c1), Some(mut c2)) => {
                let deadline = Deadline::after_secs(timeout);
                let r = c1
                    .close(deadline)
                    .and_then(|_| close_conn(&mut c2, deadline));
                c1.conn.shutdown();
                c2.shutdown();
                r
            }
            (c1, c2) => {
                c1.inspect(|c| c.conn.shutdown());
                c2.inspect(|c| c.shutdown());
                Ok(())
            }
        }
    }
}

/// A call that waited its whole timeout for the connection another
/// handle's call held: nothing was sent.
pub(crate) fn busy() -> Error {
    Error::local(
        crate::ew::EW_BUSY,
        "another call held the CNC's connection for this call's whole timeout; nothing was sent",
    )
}

pub(crate) fn dead() -> Error {
    Error::socket(
        detail::DEAD,
        "connection was torn down by an earlier failure",
    )
}

/// Socket errors and header-level protocol errors leave the stream unusable;
/// body-level errors (count, subpacket lengths) do not.
pub(crate) fn stream_broken(e: &Error) -> bool {
    match e {
        Error::Socket { .. } => true,
        Error::Protocol { detail: d, .. } => *d == detail::BAD_MAGIC || *d == detail::OVERSIZE,
        _ => false,
    }
}

fn open_option(open: &OpenBody) -> u16 {
    match open {
        OpenBody::Series30 { header, .. } => header[14],
        OpenBody::Series16 { header, .. } if header[1] == 3 => 1,
        OpenBody::Series16 { .. } => 0,
    }
}
