//! Shared by tests/robust/hostile.rs and tests/robust/wire_faults.rs: an output buffer
//! followed by a guard the library must not touch, and their fake CNCs'
//! plumbing (a listener on a free port, frames read off a connection).

#![allow(dead_code)]

use fwlib32::proto::frame::Frame;
use std::io::Read;
use std::net::{TcpListener, TcpStream};

pub const GUARD: usize = 64;
pub const FILL: u8 = 0xA5;

/// An output of `n` bytes followed by a guard the library must not touch.
pub struct Out(pub Vec<u8>, pub usize);

impl Out {
    pub fn new(n: usize) -> Out {
        Out(vec![FILL; n + GUARD], n)
    }
    pub fn p<T>(&mut self) -> *mut T {
        self.0.as_mut_ptr().cast()
    }
    pub fn intact(&self) -> bool {
        self.0[self.1..].iter().all(|b| *b == FILL)
    }
}

/// A fake CNC on a free port of 127.0.0.1 (returned): a thread hands each
/// connection to `accept` with its number (0, 1 ...), and stops accepting,
/// closing the listener, when `accept` returns false or accepting fails.
pub fn listen(mut accept: impl FnMut(usize, TcpStream) -> bool + Send + 'static) -> u16 {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    std::thread::spawn(move || {
        for (i, s) in listener.incoming().enumerate() {
            let Ok(s) = s else { return };
            if !accept(i, s) {
                return;
            }
        }
    });
    port
}

/// The FOCAS frames a fake CNC reads off one connection.
pub struct Frames {
    buf: Vec<u8>,
    chunk: [u8; 4096],
}

impl Frames {
    pub fn new() -> Frames {
        Frames {
            buf: Vec::new(),
            chunk: [0; 4096],
        }
    }

    /// The next whole frame from `s`: None at the end of the stream, on a
    /// read error, or on bytes that are not a frame.
    pub fn read(&mut self, s: &mut impl Read) -> Option<Frame> {
        loop {
            match Frame::decode(&self.buf) {
                Ok(Some((f, used))) => {
                    self.buf.drain(..used);
                    return Some(f);
                }
                Ok(None) => {}
                Err(_) => return None,
            }
            match s.read(&mut self.chunk) {
                Ok(0) | Err(_) => return None,
                Ok(n) => self.buf.extend_from_slice(&self.chunk[..n]),
            }
        }
    }
}

/// What a [`Hostile`] CNC does wrong. The open and the start-up exchange of
/// each connection pair are answered as the simulator answers them (unless
/// the mode is [`Mode::SilentOpen`]); the mode breaks what comes after.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Nothing: the simulator's answers.
    Plain,
    /// Each data subpacket is answered with the simulator's answer to
    /// another command (cnc_statinfo's 0x19; 0x18 for 0x19 itself).
    OtherCommand,
    /// A data answer's subpackets in reverse order.
    Reversed,
    /// An upload's text frames typed 0x2102 (a data answer) instead of
    /// 0x1604, then the normal end frame.
    UploadWrongType,
    /// A download or DNC operation: after its first data frame, a frame of
    /// a kind connection 1 never carries (0x2102); the rest as usual.
    DownloadWrongType,
    /// Data requests after the start-up are never answered (the
    /// connections stay open).
    SilentData,
    /// Opens are never answered (the connections stay open).
    SilentOpen,
    /// Data answers after the start-up, one byte every 100 ms.
    Drip,
    /// Data answers after the start-up cut to half, then nothing.
    Truncated,
}

/// A fake CNC on a free port of 127.0.0.1 answering from a simulated
/// machine, broken as its [`Mode`] says; stops accepting when dropped.
/// Each connection's thread ends when the client closes it.
pub struct Hostile {
    pub port: u16,
    /// Data frames received after the start-up, all connections.
    pub data: std::sync::Arc<std::sync::atomic::AtomicUsize>,
    /// Connections accepted.
    pub accepted: std::sync::Arc<std::sync::atomic::AtomicUsize>,
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    /// Every connection accepted, for [`Hostile::close_all`].
    conns: std::sync::Arc<std::sync::Mutex<Vec<TcpStream>>>,
}

impl Hostile {
    pub fn start(mode: Mode) -> Hostile {
        use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
        use std::sync::{Arc, Mutex};
        let machine = Arc::new(Mutex::new(fwlib32::sim::Machine::new(
            fwlib32::sim::Profile::default(),
        )));
        let data = Arc::new(AtomicUsize::new(0));
        let accepted = Arc::new(AtomicUsize::new(0));
        let stop = Arc::new(AtomicBool::new(false));
        let conns = Arc::new(Mutex::new(Vec::new()));
        let (d, a, st, cs) = (data.clone(), accepted.clone(), stop.clone(), conns.clone());
        let port = listen(move |_, s| {
            if st.load(Ordering::SeqCst) {
                return false;
            }
            if let Ok(c) = s.try_clone() {
                cs.lock().unwrap().push(c);
            }
            a.fetch_add(1, Ordering::SeqCst);
            let (m, d) = (machine.clone(), d.clone());
            std::thread::spawn(move || serve_hostile(mode, &m, &d, s));
            true
        });
        Hostile {
            port,
            data,
            accepted,
            stop,
            conns,
        }
    }

    /// Closes every connection accepted so far (the client sees the end of
    /// the stream): what ends a client call that waits forever.
    pub fn close_all(&self) {
        for c in self.conns.lock().unwrap().drain(..) {
            let _ = c.shutdown(std::net::Shutdown::Both);
        }
    }
}

impl Drop for Hostile {
    fn drop(&mut self) {
        self.close_all();
        self.stop.store(true, std::sync::atomic::Ordering::SeqCst);
        // Wakes the accepting thread, which then stops.
        let _ = TcpStream::connect(("127.0.0.1", self.port));
    }
}

fn serve_hostile(
    mode: Mode,
    machine: &std::sync::Mutex<fwlib32::sim::Machine>,
    data: &std::sync::atomic::AtomicUsize,
    mut s: TcpStream,
) {
    use fwlib32::proto::frame::ftype;
    use fwlib32::proto::packet::{ReqSub, RespSub, decode_request, encode_response};
    use fwlib32::sim::service::CncService;
    use std::io::Write;
    let _ = s.set_nodelay(true);
    let lock = || machine.lock().unwrap_or_else(|e| e.into_inner());
    let version = lock().open_body().frame_version();
    let mut frames = Frames::new();
    let mut started = false;
    let mut sent_stray = false;
    while let Some(f) = frames.read(&mut s) {
        let out: Vec<u8> = match f.ftype {
            ftype::OPEN_REQ if mode == Mode::SilentOpen => continue,
            ftype::OPEN_REQ => {
                Frame::new(version, ftype::OPEN_RESP, lock().open_body().to_bytes()).encode()
            }
            ftype::CLOSE_REQ => {
                let _ = s.write_all(&Frame::new(version, ftype::CLOSE_RESP, vec![]).encode());
                return;
            }
            ftype::DATA_REQ => {
                let Ok(subs) = decode_request(&f.body) else {
                    return;
                };
                let first = !std::mem::replace(&mut started, true);
                if !first {
                    data.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
                }
                let mut m = lock();
                let answer = |q: &ReqSub| m.answer(q);
                let mut r: Vec<RespSub> = if !first && mode == Mode::OtherCommand {
                    subs.iter()
                        .map(|q| {
                            let other = if q.cmd == 0x19 { 0x18 } else { 0x19 };
                            let mut o = ReqSub::cnc(other, &[]);
                            o.path = 1;
                            o
                        })
                        .map(|o| m.answer(&o))
                        .collect()
                } else {
                    subs.iter().map(answer).collect()
                };
                drop(m);
                if !first && mode == Mode::Reversed {
                    r.reverse();
                }
                let b = Frame::new(version, ftype::DATA_RESP, encode_response(&r)).encode();
                match mode {
                    _ if first => b,
                    Mode::SilentData => continue,
                    Mode::Truncated => b[..b.len() / 2].to_vec(),
                    Mode::Drip => {
                        for c in b.chunks(1) {
                            if s.write_all(c).is_err() {
                                return;
                            }
                            // The fault itself (a line slower than the timeout).
                            std::thread::sleep(std::time::Duration::from_millis(100));
                        }
                        continue;
                    }
                    _ => b,
                }
            }
            ftype::UPLOAD_START_REQ => {
                let (_, mut fs) = fwlib32::sim::session::upload(&mut *lock(), version, &f);
                if mode == Mode::UploadWrongType {
                    for x in &mut fs {
                        if x.ftype == ftype::UPLOAD_DATA {
                            x.ftype = ftype::DATA_RESP;
                        }
                    }
                }
                fs.iter().flat_map(Frame::encode).collect()
            }
            // Download (0x11) and DNC (0x19): the start and the end answered,
            // the data taken.
            t if t == 0x1101 || t == 0x1901 || t == 0x1301 || t == 0x1b01 => {
                if t == 0x1101 || t == 0x1901 {
                    // A new transfer: its own stray frame.
                    sent_stray = false;
                }
                Frame::new(version, t + 1, vec![]).encode()
            }
            t if t == 0x1204 || t == 0x1a04 => {
                if mode != Mode::DownloadWrongType || std::mem::replace(&mut sent_stray, true) {
                    continue;
                }
                Frame::new(version, ftype::DATA_RESP, vec![0, 0]).encode()
            }
            _ => continue,
        };
        if s.write_all(&out).is_err() {
            return;
        }
    }
}
