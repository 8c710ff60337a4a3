//! One TCP connection to a CNC, blocking std::net, every wait bounded by a deadline.
//!
//! The per-call cost is kept at what the bytes need: a request is encoded
//! into a reused buffer and sent with one `send`; answers are read into a
//! reused buffer, as much as has arrived (one `recv` when the whole frame
//! is there), and frames are taken from it whole, leftovers kept for the
//! next one. The socket timeouts that bound each wait are set only when the
//! one already set does not fit the call's deadline (see `Armed`), not
//! before every `send` and `recv`.

use super::log;
use crate::error::{Error, Result, detail};
use crate::proto::frame::{CLIENT_VERSION, Frame, FrameHeader, HEADER_LEN, ftype, max_body_len};
use crate::proto::packet::{
    ReqSub, RespSub, decode_response_into, echo_mismatch, encode_request_into,
};
use crate::proto::wire::Writer;
use std::io::{ErrorKind, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::ops::Range;
use std::os::fd::AsRawFd;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// When a wait gives up. `None` waits forever (a timeout of 0 or less).
#[derive(Debug, Clone, Copy)]
pub struct Deadline(Option<Instant>);

impl Deadline {
    pub fn after_secs(timeout: i32) -> Deadline {
        Deadline((timeout > 0).then(|| Instant::now() + Duration::from_secs(timeout as u64)))
    }
    /// When it passes; None for no limit.
    pub fn at(&self) -> Option<Instant> {
        self.0
    }

    /// Locks `m`, waiting at most until the deadline (not at all once it
    /// passed): None when another holder kept it that long. Every wait for
    /// a lock around network I/O goes through here, so no call waits past
    /// its own timeout behind another's.
    pub fn lock<'a, T>(
        &self,
        m: &'a parking_lot::Mutex<T>,
    ) -> Option<parking_lot::MutexGuard<'a, T>> {
        match self.remaining() {
            Some(None) => Some(m.lock()),
            Some(Some(left)) => m.try_lock_for(left),
            None => m.try_lock(),
        }
    }

    /// None once passed; Some(None) for no limit; else the time left.
    fn remaining(&self) -> Option<Option<Duration>> {
        match self.0 {
            None => Some(None),
            Some(t) => {
                let left = t.saturating_duration_since(Instant::now());
                (!left.is_zero()).then_some(Some(left))
            }
        }
    }
}

/// A socket timeout (SO_RCVTIMEO or SO_SNDTIMEO) as last set.
///
/// A wait must end by the call's deadline, so the timeout set must not be
/// longer than the time left; it is set a sixteenth shorter than that, so
/// that the next calls, whose deadlines are as far, find it short enough
/// and need not set it again. A wait it cuts short before the deadline is
/// simply resumed (with a timeout that fits what is left then). One that
/// is less than half the time left is set again, so that a slow answer does
/// not mean many wake-ups.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Armed {
    /// No timeout (blocks until the peer acts): how a socket starts.
    Forever,
    After(Duration),
}

impl Armed {
    /// Whether this timeout bounds a wait that must end within `left`
    /// (None: no limit) and is not needlessly short.
    fn fits(self, left: Option<Duration>) -> bool {
        match (self, left) {
            (Armed::Forever, None) => true,
            // No limit: waking up once a second to wait again costs nothing.
            (Armed::After(d), None) => d >= Duration::from_secs(1),
            (Armed::Forever, Some(_)) => false,
            (Armed::After(d), Some(l)) => d <= l && d >= l / 2,
        }
    }

    /// The timeout to set for a wait that must end within `left`.
    fn for_wait(left: Option<Duration>) -> Armed {
        match left {
            None => Armed::Forever,
            Some(l) => Armed::After(l - l / 16),
        }
    }

    fn as_option(self) -> Option<Duration> {
        match self {
            Armed::Forever => None,
            Armed::After(d) => Some(d),
        }
    }
}

/// The largest frame any version may carry.
const MAX_FRAME: usize = HEADER_LEN + 4950;
/// The read buffer's first size, at the first read: room for the answers
/// most calls get (the open answer, status, a few values) and whatever
/// arrives with them. It grows to what a longer frame needs (a power of
/// two, at most [`RBUF`]) and keeps that size: memory per connection is
/// what its answers need, not the longest frame there could be.
const RBUF_FIRST: usize = 256;
/// The most the read buffer grows to: room for a whole frame.
const RBUF: usize = 8192;
const _: () = assert!(max_body_len(u16::MAX) + HEADER_LEN == MAX_FRAME && RBUF >= MAX_FRAME);

pub struct Conn {
    /// Shared with the pair's shutters ([`Conn::shutter`]), which shut it
    /// down without waiting for the call using it.
    stream: Arc<TcpStream>,
    /// 1 or 2, for logs.
    pub number: u8,
    peer: String,
    /// Bytes read and not yet taken: `rbuf[rstart..rend]`. Allocated at
    /// the first read.
    rbuf: Vec<u8>,
    rstart: usize,
    rend: usize,
    /// The frame being sent, reused.
    wbuf: Vec<u8>,
    read_timeout: Armed,
    write_timeout: Armed,
    /// The last data answer's subpackets, reused by the next.
    resp: Vec<RespSub>,
    /// The request list calls build their subpackets in, reused
    /// ([`Conn::take_request`]).
    req: Vec<ReqSub>,
}

/// A frame's length word is 16 bits: a longer body is refused before any
/// byte is sent (EW_LENGTH), never sent with its length wrapped.
fn fits_a_frame(body: usize) -> Result<()> {
    if body > u16::MAX as usize {
        return Err(Error::local(
            crate::ew::EW_LENGTH,
            "the request does not fit in a frame (65535 bytes)",
        ));
    }
    Ok(())
}

impl Conn {
    pub fn connect(addrs: &[SocketAddr], number: u8, deadline: Deadline) -> Result<Conn> {
        let mut last = None;
        for a in addrs {
            let r = match deadline.remaining() {
                Some(Some(left)) => TcpStream::connect_timeout(a, left),
                Some(None) => TcpStream::connect(a),
                None => Err(ErrorKind::TimedOut.into()),
            };
            match r {
                Ok(stream) => {
                    let _ = stream.set_nodelay(true);
                    return Ok(Conn {
                        stream: Arc::new(stream),
                        number,
                        peer: a.to_string(),
                        rbuf: Vec::new(),
                        rstart: 0,
                        rend: 0,
                        wbuf: Vec::new(),
                        read_timeout: Armed::Forever,
                        write_timeout: Armed::Forever,
                        resp: Vec::new(),
                        req: Vec::new(),
                    });
                }
                Err(e) => last = Some(e),
            }
        }
        Err(Error::socket(
            detail::CONNECT,
            format!(
                "connect: {}",
                last.map_or_else(|| "no address".to_string(), |e| e.to_string())
            ),
        ))
    }

    /// Sets SO_RCVTIMEO (`read`) or SO_SNDTIMEO unless the one set fits a
    /// wait that must end within `left`.
    fn arm(&mut self, read: bool, left: Option<Duration>) {
        let armed = if read {
            self.read_timeout
        } else {
            self.write_timeout
        };
        if armed.fits(left) {
            return;
        }
        let want = Armed::for_wait(left);
        let r = if read {
            self.stream.set_read_timeout(want.as_option())
        } else {
            self.stream.set_write_timeout(want.as_option())
        };
        // Should it fail, the next wait tries again.
        let now = if r.is_ok() {
            want
        } else {
            Armed::After(Duration::ZERO)
        };
        if read {
            self.read_timeout = now;
        } else {
            self.write_timeout = now;
        }
    }

    pub fn send(&mut self, frame: &Frame, deadline: Deadline) -> Result<()> {
        fits_a_frame(frame.body.len())?;
        let mut w = Writer {
            buf: std::mem::take(&mut self.wbuf),
        };
        w.buf.clear();
        FrameHeader {
            version: frame.version,
            ftype: frame.ftype,
            len: frame.body.len() as u16,
        }
        .encode(&mut w);
        w.bytes(&frame.body);
        self.wbuf = w.buf;
        self.send_wbuf(deadline)
    }

    /// Sends a data request (0x2101) of `subs`, encoded in place.
    pub fn send_data(&mut self, subs: &[ReqSub], deadline: Deadline) -> Result<()> {
        let mut w = Writer {
            buf: std::mem::take(&mut self.wbuf),
        };
        w.buf.clear();
        FrameHeader {
            version: CLIENT_VERSION,
            ftype: ftype::DATA_REQ,
            len: 0,
        }
        .encode(&mut w);
        encode_request_into(subs, &mut w);
        let len = w.len() - HEADER_LEN;
        w.patch_u16(HEADER_LEN - 2, len as u16);
        self.wbuf = w.buf;
        fits_a_frame(len)?;
        self.send_wbuf(deadline)
    }

    /// The connection's request list, empty, for a call to build its
    /// subpackets in; given back with [`Conn::give_request`].
    pub fn take_request(&mut self) -> Vec<ReqSub> {
        std::mem::take(&mut self.req)
    }

    /// Keeps `v`'s room, not its subpackets (nor their payloads).
    pub fn give_request(&mut self, mut v: Vec<ReqSub>) {
        v.clear();
        self.req = v;
    }

    /// One data request and its answer: `subs` sent as a 0x2101 frame, the
    /// 0x21xx answer's subpackets (valid until the next exchange).
    pub fn exchange(&mut self, subs: &[ReqSub], deadline: Deadline) -> Result<&[RespSub]> {
        self.send_data(subs, deadline)?;
        let mut resp = std::mem::take(&mut self.resp);
        let r = self.recv_kind_with(0x21, deadline, |_, body| {
            decode_response_into(body, &mut resp)
        });
        self.resp = resp;
        r??;
        if let Some(i) = echo_mismatch(subs, &self.resp) {
            let (q, a) = (&subs[i], &self.resp[i]);
            return Err(Error::protocol(
                detail::ECHO,
                format!(
                    "answer subpacket {} is class {} command {:#x}, the request's is class {} command {:#x}",
                    i + 1,
                    a.class,
                    a.cmd,
                    q.class,
                    q.cmd
                ),
            ));
        }
        Ok(&self.resp)
    }

    /// Writes `wbuf` whole before the deadline.
    fn send_wbuf(&mut self, deadline: Deadline) -> Result<()> {
        log::bytes("send", self.number, &self.peer, &self.wbuf);
        let mut sent = 0;
        while sent < self.wbuf.len() {
            let left = deadline
                .remaining()
                .ok_or_else(|| Error::socket(detail::SEND, "send: timed out"))?;
            self.arm(false, left);
            match (&*self.stream).write(&self.wbuf[sent..]) {
                Ok(0) => {
                    return Err(Error::socket(
                        detail::SEND,
                        "send: the connection accepts no more bytes",
                    ));
                }
                Ok(n) => sent += n,
                // Cut short by a socket timeout before the deadline: go on.
                Err(e)
                    if matches!(
                        e.kind(),
                        ErrorKind::WouldBlock | ErrorKind::TimedOut | ErrorKind::Interrupted
                    ) => {}
                Err(e) => return Err(Error::socket(detail::SEND, format!("send: {e}"))),
            }
        }
        Ok(())
    }

    /// Reads at least one more byte into the read buffer, as many as have
    /// arrived (up to the room left), before the deadline; first makes
    /// room for the `need` bytes of the frame begun at `rstart`.
    fn fill(&mut self, deadline: Deadline, on_timeout: (i16, i16), need: usize) -> Result<()> {
        if self.rstart == self.rend {
            (self.rstart, self.rend) = (0, 0);
        } else if self.rbuf.len() - self.rstart < need {
            // Make room for the rest of the frame begun at rstart.
            self.rbuf.copy_within(self.rstart..self.rend, 0);
            (self.rstart, self.rend) = (0, self.rend - self.rstart);
        }
        if self.rbuf.len() - self.rstart < need {
            let size = need.next_power_of_two().clamp(RBUF_FIRST, RBUF);
            self.rbuf.resize(size.max(need), 0);
        }
        loop {
            let left = deadline
                .remaining()
                .ok_or_else(|| Error::socket(on_timeout, "receive: timed out"))?;
            self.arm(true, left);
            match (&*self.stream).read(&mut self.rbuf[self.rend..]) {
                Ok(0) => {
                    return Err(Error::socket(
                        detail::EOF,
                        "receive: connection closed by the CNC",
                    ));
                }
                Ok(n) => {
                    self.rend += n;
                    return Ok(());
                }
                // Cut short by a socket timeout before the deadline: go on.
                Err(e)
                    if matches!(
                        e.kind(),
                        ErrorKind::WouldBlock | ErrorKind::TimedOut | ErrorKind::Interrupted
                    ) => {}
                Err(e) => return Err(Error::socket(detail::EOF, format!("receive: {e}"))),
            }
        }
    }

    /// The next whole frame, read as needed: its header and where its body
    /// is in the read buffer (valid until the next read). A bad header is a
    /// protocol error after which the stream is out of step (the caller
    /// tears the connection down).
    fn next_frame(&mut self, deadline: Deadline) -> Result<(FrameHeader, Range<usize>)> {
        loop {
            let have = self.rend - self.rstart;
            if have < HEADER_LEN {
                self.fill(deadline, detail::RECV_TIMEOUT_HEADER, HEADER_LEN)?;
                continue;
            }
            let at = self.rstart;
            let h = match FrameHeader::decode(&self.rbuf[at..at + HEADER_LEN]) {
                Ok(h) => h,
                Err(e) => {
                    let head = &self.rbuf[at..at + HEADER_LEN];
                    log::bytes("recv-bad", self.number, &self.peer, head);
                    return Err(e.into());
                }
            };
            let total = HEADER_LEN + h.len as usize;
            if have < total {
                self.fill(deadline, detail::RECV_TIMEOUT_BODY, total)?;
                continue;
            }
            self.rstart += total;
            log::bytes("recv", self.number, &self.peer, &self.rbuf[at..at + total]);
            return Ok((h, at + HEADER_LEN..at + total));
        }
    }

    /// Reads one whole frame.
    pub fn recv(&mut self, deadline: Deadline) -> Result<Frame> {
        let (h, body) = self.next_frame(deadline)?;
        Ok(Frame::new(h.version, h.ftype, self.rbuf[body].to_vec()))
    }

    /// Reads frames until one of the kind `kind` (high type byte) arrives,
    /// and hands its body to `f`; frames of other kinds are logged and
    /// discarded, as FANUC's library does.
    pub fn recv_kind_with<T>(
        &mut self,
        kind: u8,
        deadline: Deadline,
        f: impl FnOnce(&FrameHeader, &[u8]) -> T,
    ) -> Result<T> {
        loop {
            let (h, body) = self.next_frame(deadline)?;
            if h.kind() == kind {
                return Ok(f(&h, &self.rbuf[body]));
            }
            crate::log_at!(
                log::ERRORS,
                "conn{} discarded a frame of type {:04x} while waiting for {:02x}xx",
                self.number,
                h.ftype,
                kind
            );
        }
    }

    /// As [`Conn::recv_kind_with`], the frame returned whole.
    pub fn recv_kind(&mut self, kind: u8, deadline: Deadline) -> Result<Frame> {
        self.recv_kind_with(kind, deadline, |h, body| {
            Frame::new(h.version, h.ftype, body.to_vec())
        })
    }

    /// Takes the bytes read and not yet taken as frames, and frees the
    /// read buffer (connection 1 hands them to its own buffer when it takes
    /// over the connection).
    pub fn take_buffered(&mut self) -> Vec<u8> {
        let v = self.rbuf[self.rstart..self.rend].to_vec();
        (self.rstart, self.rend) = (0, 0);
        self.rbuf = Vec::new();
        v
    }

    /// Appends bytes from the socket to `buf` and returns how many: with
    /// `wait` None only what has already arrived (possibly none), else at
    /// least one byte before the deadline. End of file is an error.
    pub fn read_some(&mut self, buf: &mut Vec<u8>, wait: Option<Deadline>) -> Result<usize> {
        let mut tmp = [0u8; 8192];
        let r = match wait {
            None => {
                let n = unsafe {
                    libc::recv(
                        self.stream.as_raw_fd(),
                        tmp.as_mut_ptr().cast(),
                        tmp.len(),
                        libc::MSG_DONTWAIT,
                    )
                };
                if n < 0 {
                    match std::io::Error::last_os_error() {
                        e if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::Interrupted) => {
                            return Ok(0);
                        }
                        e => Err(e),
                    }
                } else {
                    Ok(n as usize)
                }
            }
            Some(deadline) => loop {
                let left = deadline.remaining().ok_or_else(|| {
                    Error::socket(detail::RECV_TIMEOUT_HEADER, "receive: timed out")
                })?;
                self.arm(true, left);
                match (&*self.stream).read(&mut tmp) {
                    Err(e)
                        if matches!(
                            e.kind(),
                            ErrorKind::WouldBlock | ErrorKind::TimedOut | ErrorKind::Interrupted
                        ) => {}
                    r => break r,
                }
            },
        };
        match r {
            Ok(0) => Err(Error::socket(
                detail::EOF,
                "receive: connection closed by the CNC",
            )),
            Ok(n) => {
                log::bytes("recv", self.number, &self.peer, &tmp[..n]);
                buf.extend_from_slice(&tmp[..n]);
                Ok(n)
            }
            Err(e) => Err(Error::socket(detail::EOF, format!("receive: {e}"))),
        }
    }

    /// The socket, to shut down from another thread while a call waits on
    /// it (the descriptor stays open until the last of them is dropped, so
    /// a shutdown never reaches a descriptor number used again).
    pub fn shutter(&self) -> Arc<TcpStream> {
        self.stream.clone()
    }

    pub fn shutdown(&self) {
        let _ = self.stream.shutdown(std::net::Shutdown::Both);
    }
}

/// The close handshake on one connection (0x0201, then its 0x02xx answer).
pub(crate) fn close_conn(conn: &mut Conn, deadline: Deadline) -> Result<()> {
    conn.send(
        &Frame::new(CLIENT_VERSION, ftype::CLOSE_REQ, Vec::new()),
        deadline,
    )?;
    conn.recv_kind_with(0x02, deadline, |_, _| ())
}

#[cfg(test)]
mod tests {
    use super::*;

    const S: Duration = Duration::from_secs(1);

    #[test]
    fn a_timeout_set_fits_while_it_is_no_longer_than_what_is_left() {
        let armed = Armed::for_wait(Some(10 * S));
        assert_eq!(armed, Armed::After(10 * S - 10 * S / 16));
        // The next calls' deadlines are as far: nothing to set.
        assert!(armed.fits(Some(10 * S)));
        assert!(armed.fits(Some(10 * S - Duration::from_millis(1))));
        // Less time left than the timeout: set again.
        assert!(!armed.fits(Some(9 * S)));
        // Far shorter than the time left (another handle's timeout): set again.
        assert!(!armed.fits(Some(60 * S)));
        // No limit: a timeout of a second or more only means wake-ups.
        assert!(armed.fits(None));
        assert!(!Armed::After(Duration::from_millis(10)).fits(None));
        assert!(Armed::Forever.fits(None));
        assert!(!Armed::Forever.fits(Some(S)));
    }

    #[test]
    fn a_request_longer_than_a_frame_is_refused_before_any_byte() {
        use std::net::TcpListener;
        let l = TcpListener::bind("127.0.0.1:0").unwrap();
        let mut conn =
            Conn::connect(&[l.local_addr().unwrap()], 0, Deadline::after_secs(2)).unwrap();
        let (mut peer, _) = l.accept().unwrap();
        let sub = |n: usize| ReqSub {
            class: 1,
            path: 1,
            cmd: crate::proto::cmd::STATINFO,
            args: [0; 5],
            payload: vec![7; n],
        };
        // 2 (count) + 28 (the subpacket's fixed part) + payload: one byte too many.
        let err = conn
            .send_data(&[sub(u16::MAX as usize - 29)], Deadline::after_secs(2))
            .unwrap_err();
        assert_eq!(err.ew(), crate::ew::EW_LENGTH);
        let frame = Frame::new(CLIENT_VERSION, 0x2101, vec![0; u16::MAX as usize + 1]);
        assert_eq!(
            conn.send(&frame, Deadline::after_secs(2)).unwrap_err().ew(),
            crate::ew::EW_LENGTH
        );
        // The longest that fits goes out whole, its length word exact.
        conn.send_data(&[sub(u16::MAX as usize - 30)], Deadline::after_secs(2))
            .unwrap();
        let mut head = [0u8; HEADER_LEN];
        peer.read_exact(&mut head).unwrap();
        assert_eq!(u16::from_be_bytes([head[8], head[9]]), u16::MAX);
    }

    #[test]
    fn the_timeout_for_a_tiny_wait_is_not_zero() {
        for ns in [1, 2, 15, 16, 17, 1000] {
            let left = Duration::from_nanos(ns);
            let Armed::After(d) = Armed::for_wait(Some(left)) else {
                panic!("finite");
            };
            assert!(!d.is_zero() && d <= left, "{ns} ns");
        }
    }
}
