//! The oracle's fake CNC: our simulator behind a recording proxy that can
//! break the conversation on purpose (a reply shape, a refused or silent
//! handshake step). Every frame in both directions is logged in order, with
//! the TCP events (accept, end of file, drop) the replay server needs.

use fwlib32::sim::{Profile, Simulator};
use std::io::{Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// One logged event: `dir` is accept | req | resp | eof | drop.
#[derive(Debug, Clone)]
pub struct Rec {
    pub conn: u8,
    pub dir: &'static str,
    pub bytes: Vec<u8>,
}

/// A change made to the next data response (0x2102) the CNC sends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// Subpacket i answers this error code, with an empty payload.
    Error(usize, i16),
    /// Subpacket i answers this error code with these two detail words
    /// (the words cnc_getdtailerr reports), with an empty payload.
    ErrorDetail(usize, i16, u16, u16),
    /// Subpacket i's payload is empty (no error).
    Empty(usize),
    /// Subpacket i's payload cut to half its length (a multiple of 4).
    Half(usize),
    /// Subpacket i's payload one byte short.
    MinusOne(usize),
    /// Subpacket i's payload longer by n bytes (0x5a).
    Longer(usize, usize),
    /// Subpacket i left out.
    Missing(usize),
    /// Subpacket i's payload replaced by these bytes (a crafted answer:
    /// cases.rs `REPLIES`).
    Payload(usize, &'static [u8]),
}

/// A broken connection set-up.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// Nothing listens on the port.
    Refuse,
    /// The open request of connection n (1, 2) is answered by closing it.
    CloseOpen(u8),
    /// The open request of connection n is never answered.
    SilentOpen(u8),
    /// The open response of connection n is two bytes short.
    ShortOpen(u8),
    /// The start-up sysinfo frame is answered with this error in every subpacket.
    SysinfoError(i16),
    /// The 16i-class option probe (the second start-up frame) is answered
    /// with this error.
    ProbeError(i16),
    /// The option probe's payload is cut to half.
    ProbeHalf,
    /// The start-up sysinfo frame is never answered.
    SysinfoSilent,
    /// The start-up sysinfo frame is answered by closing the connection.
    SysinfoClose,
}

/// A change made to the next data response by the fuzzer (tools/oracle/fuzz.rs).
pub type Mutator = Box<dyn FnOnce(&mut Vec<Sub>) + Send>;

struct State {
    log: Mutex<Vec<Rec>>,
    shape: Mutex<Option<Shape>>,
    mutator: Mutex<Option<Mutator>>,
    /// The last shape applied changed the frame.
    shaped: AtomicBool,
    fault: Option<Fault>,
    stop: AtomicBool,
    next_conn: AtomicU8,
    /// Data frames seen so far (the first one is the start-up sysinfo).
    data_frames: Mutex<usize>,
}

impl State {
    fn push(&self, conn: u8, dir: &'static str, bytes: &[u8]) {
        self.log.lock().unwrap().push(Rec {
            conn,
            dir,
            bytes: bytes.to_vec(),
        });
    }
}

/// The fake CNC's clock at its start: 2026-11-25 12:00:00 UTC (Unix
/// seconds), so that both libraries' runs of a case read one time.
pub const CLOCK_AT_START: i64 = 1_795_608_000;

pub struct Fake {
    pub port: u16,
    state: Arc<State>,
    /// The CNC behind the proxy (kept alive with it).
    _sim: Simulator,
}

impl Fake {
    /// Serves `profile` on 127.0.0.1 (a free port) with its clock stopped at
    /// `elapsed`, so that two runs of a case see one machine state.
    /// Its CNC clock (cnc_gettimer) is fixed too: [`CLOCK_AT_START`] plus
    /// `elapsed`, whatever the time of the run.
    pub fn start(mut profile: Profile, elapsed: Duration, fault: Option<Fault>) -> Fake {
        profile.timers.clock_at_start = Some(CLOCK_AT_START);
        let sim = Simulator::start(profile, "127.0.0.1:0").expect("simulator");
        sim.set_elapsed(elapsed);
        let state = Arc::new(State {
            log: Mutex::new(Vec::new()),
            shape: Mutex::new(None),
            mutator: Mutex::new(None),
            shaped: AtomicBool::new(false),
            fault,
            stop: AtomicBool::new(false),
            next_conn: AtomicU8::new(1),
            data_frames: Mutex::new(0),
        });
        let listener = TcpListener::bind("127.0.0.1:0").expect("bind 127.0.0.1:0");
        let port = listener.local_addr().unwrap().port();
        if fault == Some(Fault::Refuse) {
            drop(listener); // the port is free again: connecting is refused
        } else {
            let (st, upstream) = (state.clone(), sim.port());
            listener.set_nonblocking(true).unwrap();
            std::thread::spawn(move || accept_loop(listener, st, upstream));
        }
        Fake {
            port,
            state,
            _sim: sim,
        }
    }

    /// The next data response gets this shape.
    pub fn shape_next(&self, s: Option<Shape>) {
        *self.state.shape.lock().unwrap() = s;
    }

    /// The next data response is changed by `m`.
    #[allow(dead_code)] // fuzz only
    pub fn mutate_next(&self, m: Mutator) {
        *self.state.mutator.lock().unwrap() = Some(m);
    }

    /// Clears a pending mutator; true when it was used.
    #[allow(dead_code)] // fuzz only
    pub fn mutate_done(&self) -> bool {
        self.state.mutator.lock().unwrap().take().is_none()
    }

    /// Clears a pending shape; true when the last one changed a frame.
    pub fn shape_done(&self) -> bool {
        *self.state.shape.lock().unwrap() = None;
        self.state.shaped.swap(false, Ordering::SeqCst)
    }

    /// Everything logged since the last call, once nothing more arrived for
    /// `quiet` (the probe has returned: what is still in flight is the
    /// closing of sockets, which the proxy sees a moment later).
    /// The records so far, once the requests among them hold at least
    /// `sent` bytes (what the library wrote during the call: the probe's
    /// count), or after 3 s.
    #[allow(dead_code)] // tests/recorded/compat.rs; the recorder waits for quiet
    pub fn take_sent(&self, sent: u64) -> Vec<Rec> {
        let deadline = Instant::now() + Duration::from_secs(3);
        loop {
            let mut log = self.state.log.lock().unwrap();
            let got: usize = log
                .iter()
                .filter(|r| r.dir == "req")
                .map(|r| r.bytes.len())
                .sum();
            if got as u64 >= sent || Instant::now() > deadline {
                return std::mem::take(&mut *log);
            }
            drop(log);
            std::thread::yield_now();
        }
    }

    pub fn take(&self, quiet: Duration) -> Vec<Rec> {
        let mut last = usize::MAX;
        let deadline = Instant::now() + Duration::from_secs(3);
        loop {
            let n = self.state.log.lock().unwrap().len();
            if n == last || Instant::now() > deadline {
                break;
            }
            last = n;
            std::thread::sleep(quiet);
        }
        std::mem::take(&mut *self.state.log.lock().unwrap())
    }
}

impl Drop for Fake {
    fn drop(&mut self) {
        self.state.stop.store(true, Ordering::SeqCst);
    }
}

fn accept_loop(listener: TcpListener, st: Arc<State>, upstream: u16) {
    while !st.stop.load(Ordering::SeqCst) {
        match listener.accept() {
            Ok((client, _)) => {
                client.set_nonblocking(false).ok();
                client.set_nodelay(true).ok();
                let conn = st.next_conn.fetch_add(1, Ordering::SeqCst);
                st.push(conn, "accept", &[]);
                let Ok(sim) = TcpStream::connect(("127.0.0.1", upstream)) else {
                    st.push(conn, "drop", &[]);
                    continue;
                };
                sim.set_nodelay(true).ok();
                let (c2, s2, st2) = (
                    client.try_clone().unwrap(),
                    sim.try_clone().unwrap(),
                    st.clone(),
                );
                let dropped = Arc::new(AtomicBool::new(false));
                let d2 = dropped.clone();
                let st1 = st.clone();
                std::thread::spawn(move || upward(conn, client, sim, st1, dropped));
                std::thread::spawn(move || downward(conn, s2, c2, st2, d2));
            }
            Err(e) if e.kind() == std::io::ErrorKind::WouldBlock => {
                std::thread::sleep(Duration::from_millis(2));
            }
            Err(_) => return,
        }
    }
}

fn read_frame(s: &mut TcpStream) -> Option<Vec<u8>> {
    let mut head = [0u8; 10];
    s.read_exact(&mut head).ok()?;
    let len = u16::from_be_bytes([head[8], head[9]]) as usize;
    let mut f = head.to_vec();
    f.resize(10 + len, 0);
    s.read_exact(&mut f[10..]).ok()?;
    Some(f)
}

fn ftype(f: &[u8]) -> u16 {
    u16::from_be_bytes([f[6], f[7]])
}

/// Client to CNC: log each request, then forward it, swallow it or hang up.
fn upward(
    conn: u8,
    mut client: TcpStream,
    mut sim: TcpStream,
    st: Arc<State>,
    dropped: Arc<AtomicBool>,
) {
    let open_no = |f: &[u8]| (f.len() >= 12).then(|| f[11]);
    let mut silent = false;
    while let Some(f) = read_frame(&mut client) {
        st.push(conn, "req", &f);
        let is_open = ftype(&f) == 0x0101;
        let is_sysinfo = ftype(&f) == 0x2101 && {
            let mut n = st.data_frames.lock().unwrap();
            *n += 1;
            *n == 1
        };
        let hang_up = match st.fault {
            Some(Fault::CloseOpen(k)) => is_open && open_no(&f) == Some(k),
            Some(Fault::SysinfoClose) => is_sysinfo,
            _ => false,
        };
        if hang_up {
            dropped.store(true, Ordering::SeqCst);
            st.push(conn, "drop", &[]);
            let _ = client.shutdown(Shutdown::Both);
            let _ = sim.shutdown(Shutdown::Both);
            return;
        }
        silent |= match st.fault {
            Some(Fault::SilentOpen(k)) => is_open && open_no(&f) == Some(k),
            Some(Fault::SysinfoSilent) => is_sysinfo,
            _ => false,
        };
        if silent {
            continue;
        }
        if sim.write_all(&f).is_err() {
            break;
        }
    }
    if !dropped.swap(true, Ordering::SeqCst) {
        st.push(conn, "eof", &[]);
    }
    let _ = sim.shutdown(Shutdown::Both);
}

/// CNC to client: shape the response if asked, log it, forward it.
fn downward(
    conn: u8,
    mut sim: TcpStream,
    mut client: TcpStream,
    st: Arc<State>,
    dropped: Arc<AtomicBool>,
) {
    let mut data_resps = 0usize;
    let mut closed = false;
    while let Some(mut f) = read_frame(&mut sim) {
        closed = ftype(&f) == 0x0202;
        match ftype(&f) {
            0x0102 => {
                if let Some(Fault::ShortOpen(k)) = st.fault
                    && conn == k
                {
                    f.truncate(f.len() - 2);
                    let n = (f.len() - 10) as u16;
                    f[8..10].copy_from_slice(&n.to_be_bytes());
                }
            }
            0x2102 => {
                data_resps += 1;
                if let Some(Fault::SysinfoError(code)) = st.fault
                    && data_resps == 1
                    && conn == 2
                {
                    f = reshape(&f, |subs| {
                        for s in subs.iter_mut() {
                            set_error(s, code);
                        }
                    });
                }
                if conn == 2 && data_resps == 2 {
                    match st.fault {
                        Some(Fault::ProbeError(code)) => f = apply(&f, Shape::Error(0, code)),
                        Some(Fault::ProbeHalf) => f = apply(&f, Shape::Half(0)),
                        _ => {}
                    }
                }
                if let Some(shape) = st.shape.lock().unwrap().take() {
                    let g = apply(&f, shape);
                    st.shaped.store(g != f, Ordering::SeqCst);
                    f = g;
                }
                if let Some(m) = st.mutator.lock().unwrap().take() {
                    f = reshape(&f, m);
                }
            }
            _ => {}
        }
        if dropped.load(Ordering::SeqCst) {
            return;
        }
        st.push(conn, "resp", &f);
        if client.write_all(&f).is_err() {
            return;
        }
    }
    // The simulator hung up: after a close response the client hangs up
    // too (its end of file is logged upward); otherwise it is the CNC's drop.
    if closed {
        return;
    }
    if !dropped.swap(true, Ordering::SeqCst) {
        st.push(conn, "drop", &[]);
        let _ = client.shutdown(Shutdown::Both);
    }
}

/// A response subpacket: (16-byte head with the length word, payload).
pub type Sub = (Vec<u8>, Vec<u8>);

fn set_error(s: &mut Sub, code: i16) {
    s.0[8..10].copy_from_slice(&code.to_be_bytes());
    s.1.clear();
}

/// Splits a data response into subpackets, lets `f` change them, joins
/// them again with every length word recomputed. A body it cannot split is
/// returned as it was.
fn reshape(frame: &[u8], f: impl FnOnce(&mut Vec<Sub>)) -> Vec<u8> {
    let body = &frame[10..];
    if body.len() < 2 {
        return frame.to_vec();
    }
    let count = u16::from_be_bytes([body[0], body[1]]) as usize;
    let mut subs = Vec::new();
    let mut at = 2;
    for _ in 0..count {
        if at + 16 > body.len() {
            return frame.to_vec();
        }
        let plen = u16::from_be_bytes([body[at + 14], body[at + 15]]) as usize;
        if at + 16 + plen > body.len() {
            return frame.to_vec();
        }
        subs.push((
            body[at..at + 16].to_vec(),
            body[at + 16..at + 16 + plen].to_vec(),
        ));
        at += 16 + plen;
    }
    f(&mut subs);
    let mut out = frame[..10].to_vec();
    out.extend_from_slice(&(subs.len() as u16).to_be_bytes());
    for (mut head, payload) in subs {
        head[0..2].copy_from_slice(&((16 + payload.len()) as u16).to_be_bytes());
        head[14..16].copy_from_slice(&(payload.len() as u16).to_be_bytes());
        out.extend_from_slice(&head);
        out.extend_from_slice(&payload);
    }
    let n = (out.len() - 10) as u16;
    out[8..10].copy_from_slice(&n.to_be_bytes());
    out
}

pub fn apply(frame: &[u8], shape: Shape) -> Vec<u8> {
    reshape(frame, |subs| {
        let i = match shape {
            Shape::Error(i, _)
            | Shape::ErrorDetail(i, ..)
            | Shape::Empty(i)
            | Shape::Half(i)
            | Shape::MinusOne(i)
            | Shape::Longer(i, _)
            | Shape::Missing(i)
            | Shape::Payload(i, _) => i,
        };
        let Some(s) = subs.get_mut(i) else { return };
        match shape {
            Shape::Error(_, code) => set_error(s, code),
            Shape::ErrorDetail(_, code, d1, d2) => {
                set_error(s, code);
                s.0[10..12].copy_from_slice(&d1.to_be_bytes());
                s.0[12..14].copy_from_slice(&d2.to_be_bytes());
            }
            Shape::Empty(_) => s.1.clear(),
            Shape::Half(_) => s.1.truncate(s.1.len() / 2 / 4 * 4),
            Shape::MinusOne(_) => {
                s.1.pop();
            }
            Shape::Longer(_, n) => s.1.extend(std::iter::repeat_n(0x5a, n)),
            Shape::Missing(_) => {
                subs.remove(i);
            }
            Shape::Payload(_, b) => s.1 = b.to_vec(),
        }
    })
}
