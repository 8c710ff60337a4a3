//! Shared helpers of the golden-vector tests (tests/recorded/vectors.rs, tests/recorded/codec.rs):
//! loading `focas-protocol/vectors/*.json`, hex, and a replay CNC server.
//!
//! The vectors were recorded from FANUC's own library against a fake CNC
//! (see focas-protocol/README.md); every frame in both directions is in them.

#![allow(dead_code)]

use serde_json::Value;
use std::collections::BTreeMap;
use std::io::{ErrorKind, Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

// ---------------------------------------------------------------------------
// Where the vectors are
// ---------------------------------------------------------------------------

/// The recorded set: `tests/focas-protocol` in this repository (see its
/// README.md for where it comes from). Nothing outside the repository is read.
pub fn protocol_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/focas-protocol")
}

/// The vector files' directory. There is no skipping: [`load_vectors`]
/// fails when it is missing or holds no vector.
pub fn vectors_dir() -> PathBuf {
    protocol_dir().join("vectors")
}

// ---------------------------------------------------------------------------
// Hex
// ---------------------------------------------------------------------------

pub fn hex(b: &[u8]) -> String {
    use std::fmt::Write as _;
    let mut s = String::with_capacity(b.len() * 2);
    for x in b {
        let _ = write!(s, "{x:02x}");
    }
    s
}

pub fn unhex(s: &str) -> Vec<u8> {
    assert!(s.len().is_multiple_of(2), "odd-length hex string {s:?}");
    (0..s.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(&s[i..i + 2], 16).unwrap_or_else(|_| panic!("bad hex {s:?}")))
        .collect()
}

// ---------------------------------------------------------------------------
// The vector model
// ---------------------------------------------------------------------------

/// One step of a replay script, on connection `conn` (1 or 2).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Ev {
    /// Accept the next TCP connection as `conn`.
    Accept,
    /// Read one whole frame from the client; it must equal these bytes.
    Req(Vec<u8>),
    /// Write these bytes to the client.
    Resp(Vec<u8>),
    /// The client closes `conn`: read until end of file (nothing may arrive).
    Eof,
    /// The server closes `conn`.
    Drop,
    /// The server waits (a slow CNC; only used by the timing tests).
    Delay(Duration),
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Event {
    pub conn: u8,
    pub ev: Ev,
}

impl Event {
    pub fn new(conn: u8, ev: Ev) -> Event {
        Event { conn, ev }
    }
    /// From the JSON spelling: dir = accept | req | resp | eof | drop.
    pub fn parse(conn: u8, dir: &str, hex: &str) -> Event {
        let ev = match dir {
            "accept" => Ev::Accept,
            "req" => Ev::Req(unhex(hex)),
            "resp" => Ev::Resp(unhex(hex)),
            "eof" => Ev::Eof,
            "drop" => Ev::Drop,
            d => panic!("unknown frame direction {d:?}"),
        };
        Event { conn, ev }
    }
    /// The frame type word of a req/resp event.
    pub fn ftype(&self) -> Option<u16> {
        match &self.ev {
            Ev::Req(b) | Ev::Resp(b) if b.len() >= 8 => Some(u16::from_be_bytes([b[6], b[7]])),
            _ => None,
        }
    }
}

impl std::fmt::Display for Event {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.ev {
            Ev::Accept => write!(f, "accept conn {}", self.conn),
            Ev::Req(b) => write!(f, "req conn {} {}", self.conn, hex(b)),
            Ev::Resp(b) => write!(f, "resp conn {} {}", self.conn, hex(b)),
            Ev::Eof => write!(f, "eof conn {}", self.conn),
            Ev::Drop => write!(f, "drop conn {}", self.conn),
            Ev::Delay(d) => write!(f, "delay {d:?}"),
        }
    }
}

/// A caller buffer after the call: the first `hex.len()` bytes; every byte
/// after them is still 0xCC.
#[derive(Debug, Clone)]
pub struct Output {
    pub hex: Vec<u8>,
    pub written_ranges: Vec<(usize, usize)>,
}

#[derive(Debug, Clone)]
pub struct Call {
    pub probe_cmd: String,
    /// What FANUC's library returned (None: it crashed).
    pub ret: Option<i16>,
    pub frames: Vec<Event>,
    pub outputs: BTreeMap<String, Output>,
    /// In-out values reported next to the call (h, num, length, ...).
    pub fields: BTreeMap<String, i64>,
    pub crashed: bool,
}

impl Call {
    pub fn word(&self) -> &str {
        self.probe_cmd.split_whitespace().next().unwrap_or("")
    }
    pub fn args(&self) -> Vec<String> {
        self.probe_cmd
            .split_whitespace()
            .skip(1)
            .map(str::to_string)
            .collect()
    }
}

#[derive(Debug, Clone)]
pub struct Case {
    /// The C function of the vector file, e.g. "cnc_statinfo".
    pub function: String,
    pub name: String,
    /// "v3" (30i class) or "v2" (16i class).
    pub profile: String,
    pub notes: String,
    pub calls: Vec<Call>,
}

impl Case {
    /// True when the case records its own connection set-up.
    pub fn records_connect(&self) -> bool {
        self.calls
            .iter()
            .any(|c| c.frames.iter().any(|f| f.ev == Ev::Accept))
    }
}

#[derive(Debug, Clone)]
pub struct VectorFile {
    pub function: String,
    pub cases: Vec<Case>,
}

fn int(v: &Value) -> Option<i64> {
    v.as_i64().or_else(|| v.as_bool().map(i64::from))
}

fn parse_call(v: &Value) -> Call {
    let probe_cmd = v["probe_cmd"].as_str().expect("probe_cmd").to_string();
    let ret = v["return"].as_i64().map(|r| r as i16);
    let frames = v["frames"]
        .as_array()
        .map(|a| {
            a.iter()
                .map(|f| {
                    Event::parse(
                        f["conn"].as_u64().expect("conn") as u8,
                        f["dir"].as_str().expect("dir"),
                        f["hex"].as_str().unwrap_or(""),
                    )
                })
                .collect()
        })
        .unwrap_or_default();
    let mut outputs = BTreeMap::new();
    if let Some(o) = v["outputs"].as_object() {
        for (name, out) in o {
            let written_ranges = out["written_ranges"]
                .as_array()
                .map(|r| {
                    r.iter()
                        .map(|p| {
                            (
                                p[0].as_u64().unwrap() as usize,
                                p[1].as_u64().unwrap() as usize,
                            )
                        })
                        .collect()
                })
                .unwrap_or_default();
            outputs.insert(
                name.clone(),
                Output {
                    hex: unhex(out["hex"].as_str().unwrap_or("")),
                    written_ranges,
                },
            );
        }
    }
    let mut fields = BTreeMap::new();
    for (k, x) in v.as_object().expect("call object") {
        if matches!(
            k.as_str(),
            "probe_cmd" | "return" | "frames" | "outputs" | "crashed"
        ) {
            continue;
        }
        if let Some(n) = int(x) {
            fields.insert(k.clone(), n);
        }
    }
    Call {
        probe_cmd,
        ret,
        frames,
        outputs,
        fields,
        crashed: v["crashed"].as_bool().unwrap_or(false),
    }
}

/// The vector files were written by Python's json module, which spells
/// non-finite floats (in the decoded `fields_*` views) as bare `NaN`,
/// `Infinity`, `-Infinity`: not JSON. Those tokens become `null` here.
fn strict_json(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let (mut in_str, mut esc) = (false, false);
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        if in_str {
            out.push(c);
            if esc {
                esc = false;
            } else if c == '\\' {
                esc = true;
            } else if c == '"' {
                in_str = false;
            }
            rest = &rest[c.len_utf8()..];
            continue;
        }
        if let Some(tok) = ["-Infinity", "Infinity", "NaN"]
            .iter()
            .find(|t| rest.starts_with(**t))
        {
            out.push_str("null");
            rest = &rest[tok.len()..];
            continue;
        }
        if c == '"' {
            in_str = true;
        }
        out.push(c);
        rest = &rest[c.len_utf8()..];
    }
    out
}

pub fn load_file(path: &std::path::Path) -> VectorFile {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let v: Value = serde_json::from_str(&strict_json(&text))
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let function = v["function"].as_str().expect("function").to_string();
    let cases = v["cases"]
        .as_array()
        .expect("cases")
        .iter()
        .map(|c| Case {
            function: function.clone(),
            name: c["name"].as_str().expect("case name").to_string(),
            profile: c["profile"].as_str().unwrap_or("v3").to_string(),
            notes: c["notes"].as_str().unwrap_or("").to_string(),
            calls: c["calls"]
                .as_array()
                .expect("calls")
                .iter()
                .map(parse_call)
                .collect(),
        })
        .collect();
    VectorFile { function, cases }
}

/// Every vectors/*.json, in file-name order.
pub fn load_vectors() -> Vec<VectorFile> {
    let dir = vectors_dir();
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    assert!(!paths.is_empty(), "{} holds no vector file", dir.display());
    paths.iter().map(|p| load_file(p)).collect()
}

/// One case by function and name.
pub fn find_case<'a>(files: &'a [VectorFile], function: &str, name: &str) -> &'a Case {
    files
        .iter()
        .filter(|f| f.function == function)
        .flat_map(|f| &f.cases)
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no vector case {function}/{name}"))
}

// ---------------------------------------------------------------------------
// The replay CNC server
// ---------------------------------------------------------------------------

/// Bound on every single wait of the replay server (accept, read, EOF).
pub const IO_TIMEOUT: Duration = Duration::from_secs(10);

/// [`IO_TIMEOUT`], or `FOCAS_REPLAY_TIMEOUT_MS` (a shorter wait makes a run
/// with many differences, such as an oracle triage, finish sooner).
pub fn io_timeout() -> Duration {
    std::env::var("FOCAS_REPLAY_TIMEOUT_MS")
        .ok()
        .and_then(|v| v.parse().ok())
        .map_or(IO_TIMEOUT, Duration::from_millis)
}
/// Bound on the harness' wait for the server to finish one step.
const STEP_TIMEOUT: Duration = Duration::from_secs(60);

enum Msg {
    Step(String, Vec<Event>),
    Finish,
}

enum Reply {
    /// The step's events were received and the previous call checked (nothing
    /// left over); the client may call now.
    Ready(Vec<String>),
    /// The step was played; `broken`: an I/O failure ended it early.
    Done {
        mismatches: Vec<String>,
        broken: bool,
    },
}

/// A fake CNC on 127.0.0.1 (ephemeral port) that plays a script of frame
/// events, one step (the frames of one C call) at a time:
///
/// ```text
/// server.begin("label", events);   // the server starts on them ...
/// let r = unsafe { cnc_statinfo(h, buf) };   // ... while the client calls
/// mismatches.extend(server.end());  // the server has played every event
/// ```
///
/// Mismatches (a request that differs, a missing or extra frame, a connection
/// left open) come back as readable strings with both hex strings.
pub struct Replay {
    pub port: u16,
    tx: mpsc::Sender<Msg>,
    rx: mpsc::Receiver<Reply>,
    thread: Option<JoinHandle<()>>,
    pending: Option<Vec<String>>,
    broken: bool,
    /// Set once the client's call has returned: a blocking library sends
    /// nothing more for it, so the server stops waiting for frames that
    /// will not come (a listed deviation that sends less than FANUC's
    /// library) instead of waiting out [`IO_TIMEOUT`].
    returned: Arc<AtomicBool>,
}

impl Replay {
    pub fn start() -> Replay {
        let listener = TcpListener::bind("127.0.0.1:0").expect("bind 127.0.0.1:0");
        let port = listener.local_addr().expect("local_addr").port();
        let (tx, srx) = mpsc::channel::<Msg>();
        let (stx, rx) = mpsc::channel::<Reply>();
        let returned = Arc::new(AtomicBool::new(false));
        let flag = returned.clone();
        let thread = std::thread::Builder::new()
            .name(format!("replay-cnc-{port}"))
            .spawn(move || {
                let mut s = Server {
                    listener,
                    conns: BTreeMap::new(),
                    last_label: String::from("(start)"),
                    broken: false,
                    returned: flag,
                };
                while let Ok(m) = srx.recv() {
                    match m {
                        Msg::Step(label, events) => {
                            if stx.send(Reply::Ready(s.pending_check())).is_err() {
                                return;
                            }
                            s.last_label = label.clone();
                            let mismatches = s.play(&label, &events);
                            let broken = s.broken;
                            if stx.send(Reply::Done { mismatches, broken }).is_err() {
                                return;
                            }
                        }
                        Msg::Finish => {
                            let out = s.finish();
                            let _ = stx.send(Reply::Done {
                                mismatches: out,
                                broken: false,
                            });
                            return;
                        }
                    }
                }
            })
            .expect("spawn replay server");
        Replay {
            port,
            tx,
            rx,
            thread: Some(thread),
            pending: None,
            broken: false,
            returned,
        }
    }

    fn reply(&self) -> Reply {
        match self.rx.recv_timeout(STEP_TIMEOUT) {
            Ok(r) => r,
            Err(e) => panic!("replay server did not answer within {STEP_TIMEOUT:?}: {e}"),
        }
    }

    /// Starts the server on the events of one call; returns once the server
    /// has checked that nothing is left over from the previous call.
    pub fn begin(&mut self, label: &str, events: Vec<Event>) {
        assert!(self.pending.is_none(), "begin without end");
        self.returned.store(false, Ordering::SeqCst);
        self.tx
            .send(Msg::Step(label.to_string(), events))
            .expect("replay server gone");
        match self.reply() {
            Reply::Ready(m) => self.pending = Some(m),
            Reply::Done { .. } => panic!("replay server out of step"),
        }
    }

    /// Waits until the server has played the step; its mismatches.
    pub fn end(&mut self) -> Vec<String> {
        let mut out = self.pending.take().expect("end without begin");
        self.returned.store(true, Ordering::SeqCst);
        match self.reply() {
            Reply::Done { mismatches, broken } => {
                out.extend(mismatches);
                self.broken = broken;
            }
            Reply::Ready(_) => panic!("replay server out of step"),
        }
        out
    }

    /// True once a step ended early on an I/O failure (a missing request, a
    /// connection that never came): the rest of the script is not played.
    pub fn broken(&self) -> bool {
        self.broken
    }

    /// Plays one step while `f` runs (the C call); returns f's result and the mismatches.
    /// Frees handle `h` (both connections closed as FANUC's library
    /// closes them), then checks that the script was played to its end.
    pub fn close(mut self, h: u16) {
        let (r, m) = self.step(
            "free",
            ev(&[
                (1, "req", CLOSE_REQ),
                (1, "resp", CLOSE_RESP),
                (2, "req", CLOSE_REQ),
                (2, "resp", CLOSE_RESP),
            ]),
            || fwlib32::cnc_freelibhndl(h),
        );
        assert!(m.is_empty(), "{}", m.join("\n"));
        assert_eq!(r, fwlib32::ew::EW_OK);
        let m = self.finish();
        assert!(m.is_empty(), "{}", m.join("\n"));
    }

    pub fn step<T>(
        &mut self,
        label: &str,
        events: Vec<Event>,
        f: impl FnOnce() -> T,
    ) -> (T, Vec<String>) {
        self.begin(label, events);
        let r = f();
        (r, self.end())
    }

    /// Ends the script: nothing more may arrive, no connection may be
    /// pending, and the client must have closed every connection.
    pub fn finish(mut self) -> Vec<String> {
        assert!(self.pending.is_none(), "finish during a step");
        self.returned.store(true, Ordering::SeqCst);
        let _ = self.tx.send(Msg::Finish);
        let r = match self.rx.recv_timeout(STEP_TIMEOUT) {
            Ok(Reply::Done { mismatches, .. }) => mismatches,
            Ok(Reply::Ready(_)) => vec!["replay server out of step".to_string()],
            Err(e) => vec![format!("replay server did not finish: {e}")],
        };
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
        r
    }
}

impl Drop for Replay {
    fn drop(&mut self) {
        // A test that panicked mid-case: let the server thread end on its own
        // (its waits are bounded); never block a panicking test on it.
        let _ = self.tx.send(Msg::Finish);
    }
}

struct Server {
    listener: TcpListener,
    conns: BTreeMap<u8, TcpStream>,
    last_label: String,
    /// An earlier step failed on I/O: later steps are not played.
    broken: bool,
    /// The client's call has returned ([`Replay::returned`]).
    returned: Arc<AtomicBool>,
}

/// Waits until `fd` is readable, at most [`io_timeout`], or until the
/// client's call has returned and nothing is there: what it sent before
/// returning is already in the socket (loopback).
fn ready(fd: std::os::fd::RawFd, returned: &AtomicBool) -> bool {
    let deadline = Instant::now() + io_timeout();
    loop {
        let done = returned.load(Ordering::SeqCst);
        let left = deadline.saturating_duration_since(Instant::now());
        let wait = if done {
            Duration::ZERO
        } else {
            left.min(Duration::from_millis(20))
        };
        if readable(fd, wait) {
            return true;
        }
        if done || left.is_zero() {
            return false;
        }
    }
}

/// Waits until `fd` is readable (a pending connection or data), at most `t`.
fn readable(fd: std::os::fd::RawFd, t: Duration) -> bool {
    let mut p = libc::pollfd {
        fd,
        events: libc::POLLIN,
        revents: 0,
    };
    let deadline = Instant::now() + t;
    loop {
        let left = deadline.saturating_duration_since(Instant::now());
        let ms = left.as_millis().min(i32::MAX as u128) as i32;
        let r = unsafe { libc::poll(&mut p, 1, ms) };
        if r > 0 {
            return true;
        }
        if r == 0 || std::io::Error::last_os_error().kind() != ErrorKind::Interrupted {
            return false;
        }
    }
}

enum ReadEnd {
    Timeout,
    Eof,
}

fn is_eof(e: &std::io::Error) -> bool {
    matches!(
        e.kind(),
        ErrorKind::ConnectionReset
            | ErrorKind::ConnectionAborted
            | ErrorKind::BrokenPipe
            | ErrorKind::UnexpectedEof
    )
}

/// Reads exactly `buf.len()` bytes; on failure the number of bytes read.
fn read_full(
    s: &mut TcpStream,
    buf: &mut [u8],
    returned: &AtomicBool,
) -> Result<(), (usize, ReadEnd)> {
    use std::os::fd::AsRawFd;
    let mut got = 0;
    while got < buf.len() {
        if !ready(s.as_raw_fd(), returned) {
            return Err((got, ReadEnd::Timeout));
        }
        match s.read(&mut buf[got..]) {
            Ok(0) => return Err((got, ReadEnd::Eof)),
            Ok(n) => got += n,
            Err(e) if e.kind() == ErrorKind::Interrupted => {}
            Err(e) if is_eof(&e) => return Err((got, ReadEnd::Eof)),
            Err(_) => return Err((got, ReadEnd::Timeout)),
        }
    }
    Ok(())
}

/// Reads until end of file (bounded by the read timeout); what arrived, and
/// whether the end was reached.
fn read_to_eof(s: &mut TcpStream, returned: &AtomicBool) -> (Vec<u8>, bool) {
    use std::os::fd::AsRawFd;
    let mut all = Vec::new();
    let mut buf = [0u8; 4096];
    loop {
        if !ready(s.as_raw_fd(), returned) {
            return (all, false);
        }
        match s.read(&mut buf) {
            Ok(0) => return (all, true),
            Ok(n) => all.extend_from_slice(&buf[..n]),
            Err(e) if e.kind() == ErrorKind::Interrupted => {}
            Err(e) if is_eof(&e) => return (all, true),
            Err(_) => return (all, false),
        }
    }
}

impl Server {
    /// Plays the events of one step. An I/O failure ends the step and closes
    /// every connection, so the client can never wait forever on us.
    fn play(&mut self, label: &str, events: &[Event]) -> Vec<String> {
        let mut out = Vec::new();
        if self.broken {
            return out;
        }
        for (i, e) in events.iter().enumerate() {
            if let Err(msg) = self.one(label, e, &mut out) {
                out.push(format!("{label}: {msg}"));
                let rest: Vec<String> = events[i + 1..].iter().map(|e| e.to_string()).collect();
                if !rest.is_empty() {
                    out.push(format!("{label}: events not played: [{}]", rest.join(", ")));
                }
                self.close_all();
                self.broken = true;
                break;
            }
        }
        out
    }

    fn conn(&mut self, c: u8) -> Result<&mut TcpStream, String> {
        self.conns
            .get_mut(&c)
            .ok_or_else(|| format!("conn {c} is not open (never accepted, or already closed)"))
    }

    fn one(&mut self, label: &str, e: &Event, out: &mut Vec<String>) -> Result<(), String> {
        let c = e.conn;
        match &e.ev {
            Ev::Accept => {
                use std::os::fd::AsRawFd;
                if !ready(self.listener.as_raw_fd(), &self.returned) {
                    return Err(format!(
                        "expected a connection for conn {c}, none before the call returned (or within {:?})",
                        io_timeout()
                    ));
                }
                let (s, _) = self
                    .listener
                    .accept()
                    .map_err(|e| format!("accept conn {c}: {e}"))?;
                s.set_read_timeout(Some(io_timeout())).ok();
                s.set_write_timeout(Some(io_timeout())).ok();
                s.set_nodelay(true).ok();
                self.conns.insert(c, s);
            }
            Ev::Req(want) => {
                let returned = self.returned.clone();
                let s = self.conn(c)?;
                let mut head = [0u8; 10];
                if let Err((n, end)) = read_full(s, &mut head, &returned) {
                    return Err(format!(
                        "conn {c}: expected request {}, got {} after {}",
                        hex(want),
                        match end {
                            ReadEnd::Eof => "end of file",
                            ReadEnd::Timeout => "nothing more (the call returned, or a timeout)",
                        },
                        if n == 0 {
                            "no bytes".to_string()
                        } else {
                            hex(&head[..n])
                        }
                    ));
                }
                let len = u16::from_be_bytes([head[8], head[9]]) as usize;
                let mut got = head.to_vec();
                got.resize(10 + len, 0);
                if let Err((n, _)) = read_full(s, &mut got[10..], &returned) {
                    got.truncate(10 + n);
                    return Err(format!(
                        "conn {c}: expected request {}, got a truncated frame {}",
                        hex(want),
                        hex(&got)
                    ));
                }
                if &got != want {
                    out.push(format!(
                        "{label}: conn {c}: request differs\n    expected {}\n    got      {}",
                        hex(want),
                        hex(&got)
                    ));
                }
            }
            Ev::Resp(bytes) => {
                let s = self.conn(c)?;
                s.write_all(bytes)
                    .and_then(|_| s.flush())
                    .map_err(|e| format!("conn {c}: writing response {}: {e}", hex(bytes)))?;
            }
            Ev::Eof => {
                // Tolerated when the connection is already gone (closed by the client earlier).
                if let Some(mut s) = self.conns.remove(&c) {
                    let (extra, eof) = read_to_eof(&mut s, &self.returned);
                    if !extra.is_empty() {
                        out.push(format!(
                            "{label}: conn {c}: expected the client to close, got unexpected bytes {}",
                            hex(&extra)
                        ));
                    }
                    if !eof {
                        return Err(format!(
                            "conn {c}: the client did not close it (the call returned, or within {:?})",
                            io_timeout()
                        ));
                    }
                }
            }
            Ev::Drop => {
                if let Some(s) = self.conns.remove(&c) {
                    let _ = s.shutdown(Shutdown::Both);
                }
            }
            Ev::Delay(d) => std::thread::sleep(*d),
        }
        Ok(())
    }

    /// Before a step and at the end: nothing may be waiting from the
    /// previous call (an extra request, an extra connection).
    fn pending_check(&mut self) -> Vec<String> {
        use std::os::fd::AsRawFd;
        let mut out = Vec::new();
        let label = self.last_label.clone();
        if readable(self.listener.as_raw_fd(), Duration::ZERO)
            && let Ok((s, _)) = self.listener.accept()
        {
            out.push(format!("{label}: unexpected extra connection"));
            drop(s);
        }
        for (c, s) in self.conns.iter_mut() {
            if !readable(s.as_raw_fd(), Duration::ZERO) {
                continue;
            }
            let mut b = [0u8; 4096];
            match s.peek(&mut b) {
                Ok(0) | Err(_) => {} // closed by the client: judged by the next event
                Ok(_) => {
                    s.set_nonblocking(true).ok();
                    let mut extra = Vec::new();
                    while let Ok(n) = s.read(&mut b) {
                        if n == 0 {
                            break;
                        }
                        extra.extend_from_slice(&b[..n]);
                    }
                    s.set_nonblocking(false).ok();
                    out.push(format!(
                        "{label}: conn {c}: unexpected bytes {}",
                        hex(&extra)
                    ));
                }
            }
        }
        out
    }

    fn close_all(&mut self) {
        for (_, s) in std::mem::take(&mut self.conns) {
            let _ = s.shutdown(Shutdown::Both);
        }
    }

    fn finish(&mut self) -> Vec<String> {
        let mut out = self.pending_check();
        let label = self.last_label.clone();
        for (c, mut s) in std::mem::take(&mut self.conns) {
            let (extra, eof) = read_to_eof(&mut s, &self.returned);
            if !extra.is_empty() {
                out.push(format!(
                    "end of case (after {label}): conn {c}: unexpected bytes {}",
                    hex(&extra)
                ));
            }
            if !eof {
                out.push(format!(
                    "end of case (after {label}): conn {c} still open: the client did not close it"
                ));
            }
        }
        out
    }
}

/// The fake CNC of the replay tests (tests/ffi/exchanges.rs, tests/robust/transport.rs):
/// its open response (frame version 3, 32 axes, 8 spindles, one path,
/// spindle word 1), the start-up sysinfo exchange, the close exchange.
pub const OPEN_RESP: &str = "a0a0a0a000030102004800000000000300200008000100000000000000000001000000000001\
                             000000000000000000000000204d00000000000000000000000000000000000000000000000000\
                             0000000000";
pub const SYSINFO_REQ: &str =
    "a0a0a0a000012101001e0001001c0001000100180000000000000000000000000000000000000000";
pub const SYSINFO_RESP: &str =
    "a0a0a0a0000321020024000100220001000100180000000000000012040200203331204d4734323130382e302033";
pub const CLOSE_REQ: &str = "a0a0a0a0000102010000";
pub const CLOSE_RESP: &str = "a0a0a0a0000302020000";

/// Events from (connection, direction, hex) triples; the hex may be spaced.
pub fn ev(script: &[(u8, &str, &str)]) -> Vec<Event> {
    script
        .iter()
        .map(|(c, d, h)| Event::parse(*c, d, &h.split_whitespace().collect::<String>()))
        .collect()
}

/// `cnc_allclibhndl3` to the replay server with `timeout`, answered by the
/// fake CNC above: the handle.
pub fn replay_connect(server: &mut Replay, timeout: std::os::raw::c_long) -> u16 {
    let port = server.port;
    let mut h: u16 = 0;
    let (r, m) = server.step(
        "connect",
        ev(&[
            (1, "accept", ""),
            (1, "req", "a0a0a0a00001010100020001"),
            (1, "resp", OPEN_RESP),
            (2, "accept", ""),
            (2, "req", "a0a0a0a00001010100020002"),
            (2, "resp", OPEN_RESP),
            (2, "req", SYSINFO_REQ),
            (2, "resp", SYSINFO_RESP),
        ]),
        || {
            let ip = c"127.0.0.1";
            unsafe { fwlib32::cnc_allclibhndl3(ip.as_ptr(), port, timeout, &mut h) }
        },
    );
    assert!(m.is_empty(), "{}", m.join("\n"));
    assert_eq!(r, fwlib32::ew::EW_OK);
    h
}
