//! One TCP connection to a CNC, blocking std::net, every wait bounded by a deadline.

use super::log;
use crate::error::{Error, Result, detail};
use crate::proto::frame::{CLIENT_VERSION, Frame, FrameHeader, HEADER_LEN, ftype};
use std::io::{ErrorKind, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::time::{Duration, Instant};

/// When a wait gives up. `None` waits forever (a timeout of 0 or less).
#[derive(Debug, Clone, Copy)]
pub struct Deadline(Option<Instant>);

impl Deadline {
    pub fn after_secs(timeout: i32) -> Deadline {
        Deadline((timeout > 0).then(|| Instant::now() + Duration::from_secs(timeout as u64)))
    }
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

pub struct Conn {
    stream: TcpStream,
    /// 1 or 2, for logs.
    pub number: u8,
    peer: String,
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
                        stream,
                        number,
                        peer: a.to_string(),
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

    pub fn send(&mut self, frame: &Frame, deadline: Deadline) -> Result<()> {
        let bytes = frame.encode();
        log::bytes("send", self.number, &self.peer, &bytes);
        let t = match deadline.remaining() {
            Some(t) => t,
            None => return Err(Error::socket(detail::SEND, "send: timed out")),
        };
        let _ = self.stream.set_write_timeout(t);
        self.stream
            .write_all(&bytes)
            .map_err(|e| Error::socket(detail::SEND, format!("send: {e}")))
    }

    fn read_exact(
        &mut self,
        buf: &mut [u8],
        deadline: Deadline,
        on_timeout: (i16, i16),
    ) -> Result<()> {
        let mut got = 0;
        while got < buf.len() {
            let t = deadline
                .remaining()
                .ok_or_else(|| Error::socket(on_timeout, "receive: timed out"))?;
            let _ = self.stream.set_read_timeout(t);
            match self.stream.read(&mut buf[got..]) {
                Ok(0) => {
                    return Err(Error::socket(
                        detail::EOF,
                        "receive: connection closed by the CNC",
                    ));
                }
                Ok(n) => got += n,
                Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => {
                    return Err(Error::socket(on_timeout, "receive: timed out"));
                }
                Err(e) if e.kind() == ErrorKind::Interrupted => {}
                Err(e) => return Err(Error::socket(detail::EOF, format!("receive: {e}"))),
            }
        }
        Ok(())
    }

    /// Reads one whole frame. A bad header is a protocol error after which
    /// the stream is out of step (the caller tears the connection down).
    pub fn recv(&mut self, deadline: Deadline) -> Result<Frame> {
        let mut head = [0u8; HEADER_LEN];
        self.read_exact(&mut head, deadline, detail::RECV_TIMEOUT_HEADER)?;
        let h = match FrameHeader::decode(&head) {
            Ok(h) => h,
            Err(e) => {
                log::bytes("recv-bad", self.number, &self.peer, &head);
                return Err(e.into());
            }
        };
        let mut body = vec![0u8; h.len as usize];
        self.read_exact(&mut body, deadline, detail::RECV_TIMEOUT_BODY)?;
        if log::enabled(log::BYTES) {
            let mut all = head.to_vec();
            all.extend_from_slice(&body);
            log::bytes("recv", self.number, &self.peer, &all);
        }
        Ok(Frame::new(h.version, h.ftype, body))
    }

    /// Reads frames until one of the kind `kind` (high type byte) arrives;
    /// frames of other kinds are logged and discarded, as FANUC's library does.
    pub fn recv_kind(&mut self, kind: u8, deadline: Deadline) -> Result<Frame> {
        loop {
            let f = self.recv(deadline)?;
            if (f.ftype >> 8) as u8 == kind {
                return Ok(f);
            }
            crate::log_at!(
                log::ERRORS,
                "conn{} discarded a frame of type {:04x} while waiting for {:02x}xx",
                self.number,
                f.ftype,
                kind
            );
        }
    }

    /// Appends bytes from the socket to `buf` and returns how many: with
    /// `wait` None only what has already arrived (possibly none), else at
    /// least one byte before the deadline. End of file is an error.
    pub fn read_some(&mut self, buf: &mut Vec<u8>, wait: Option<Deadline>) -> Result<usize> {
        let mut tmp = [0u8; 8192];
        let r = match wait {
            None => {
                let _ = self.stream.set_nonblocking(true);
                let r = self.stream.read(&mut tmp);
                let _ = self.stream.set_nonblocking(false);
                match r {
                    Err(e) if e.kind() == ErrorKind::WouldBlock => return Ok(0),
                    r => r,
                }
            }
            Some(deadline) => loop {
                let t = deadline.remaining().ok_or_else(|| {
                    Error::socket(detail::RECV_TIMEOUT_HEADER, "receive: timed out")
                })?;
                let _ = self.stream.set_read_timeout(t);
                match self.stream.read(&mut tmp) {
                    Err(e) if e.kind() == ErrorKind::Interrupted => {}
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
            Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => Err(
                Error::socket(detail::RECV_TIMEOUT_HEADER, "receive: timed out"),
            ),
            Err(e) if e.kind() == ErrorKind::Interrupted => Ok(0),
            Err(e) => Err(Error::socket(detail::EOF, format!("receive: {e}"))),
        }
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
    conn.recv_kind(0x02, deadline)?;
    Ok(())
}
