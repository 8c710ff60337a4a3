//! Connection 1 (program transfer) with its read buffer and the state of
//! the upload running on it. The upload itself is src/client/upload.rs;
//! the pair (src/client/pair.rs) only opens and closes connection 1.

use super::conn::{Conn, Deadline, close_conn};
use super::log;
use crate::error::{Error, Result, detail};
use crate::ew::EW_BUSY;
use crate::proto::download::Outgoing;
use crate::proto::frame::{CLIENT_VERSION, Frame, ftype};
use crate::proto::upload::ABORT_BODY;
use std::time::Instant;

/// Connection 1 with its read buffer (frames are taken from it whole, so
/// a frame half-read by a non-blocking upload call is completed later).
pub struct Conn1 {
    pub(super) conn: Conn,
    rbuf: Vec<u8>,
    /// The upload running on it (src/client/upload.rs).
    pub(super) upload: Option<Upload>,
    /// The download or DNC operation running on it (src/client/download.rs);
    /// never together with an upload.
    pub(super) outgoing: Option<Sending>,
}

pub(super) struct Sending {
    /// The handle that started it.
    pub(super) owner: u16,
    pub(super) how: Outgoing,
    /// The start request, until it is sent: cnc_dncstart leaves it to the
    /// first cnc_dnc, as FANUC's library does.
    pub(super) pending: Option<Vec<u8>>,
    /// The CNC's end or refusal (its error frame), returned by the next call.
    pub(super) ended: Option<Error>,
}

pub(super) struct Upload {
    /// The handle that started it.
    pub(super) owner: u16,
    /// Text of the current 0x1604 frame not yet handed out, from `pos`.
    pub(super) text: Vec<u8>,
    pub(super) pos: usize,
    /// How it ended: EW_RESET after the CNC's end frame, or the CNC's
    /// error; every later upload call returns it.
    pub(super) ended: Option<Error>,
    /// Since when upload calls have found nothing (the timeout runs from there).
    pub(super) empty_since: Option<Instant>,
}

impl Conn1 {
    pub fn new(mut conn: Conn) -> Conn1 {
        // Whatever arrived after the open answer is the start of the next frame.
        let rbuf = conn.take_buffered();
        Conn1 {
            conn,
            rbuf,
            upload: None,
            outgoing: None,
        }
    }

    /// The next whole frame: with `wait` None only if it has fully arrived.
    pub(super) fn next_frame(&mut self, wait: Option<Deadline>) -> Result<Option<Frame>> {
        loop {
            if let Some((f, used)) = Frame::decode(&self.rbuf).map_err(Error::from)? {
                self.rbuf.drain(..used);
                return Ok(Some(f));
            }
            if self.conn.read_some(&mut self.rbuf, wait)? == 0 {
                return Ok(None);
            }
        }
    }

    /// Waits until a whole frame has arrived (not taking it), or the deadline.
    pub(super) fn wait_frame(&mut self, deadline: Deadline) -> Result<()> {
        while Frame::decode(&self.rbuf).map_err(Error::from)?.is_none() {
            self.conn.read_some(&mut self.rbuf, Some(deadline))?;
        }
        Ok(())
    }

    /// Waits for a frame of kind `kind` (a transfer's start answer). A
    /// frame of another program-transfer kind (0x11 to 0x1c) is what an
    /// aborted transfer still sent before the CNC took the abort: dropped.
    /// A frame of any other kind is no answer connection 1 can carry:
    /// EW_PROTOCOL, never dropped in silence.
    pub(super) fn recv_kind(&mut self, kind: u8, deadline: Deadline) -> Result<Frame> {
        loop {
            let f = self.next_frame(Some(deadline))?.expect("waited");
            let k = (f.ftype >> 8) as u8;
            if k == kind {
                return Ok(f);
            }
            if !stale(k) {
                return Err(unexpected(f.ftype, "waiting for a transfer's answer"));
            }
            crate::log_at!(
                log::ERRORS,
                "conn1 discarded a frame of type {:04x} while waiting for {kind:02x}xx",
                f.ftype
            );
        }
    }

    pub(super) fn send(&mut self, ftype: u16, body: Vec<u8>, deadline: Deadline) -> Result<()> {
        self.conn
            .send(&Frame::new(CLIENT_VERSION, ftype, body), deadline)
    }

    /// Makes way for handle `h`: a transfer whose handle was freed is
    /// aborted and dropped; one of another live handle (`live` says which
    /// handles of the pair exist) is EW_BUSY. Afterwards any transfer left
    /// is `h`'s own.
    pub(super) fn settle(
        &mut self,
        h: u16,
        live: impl Fn(u16) -> bool,
        deadline: Deadline,
    ) -> Result<()> {
        let owner = match (&self.upload, &self.outgoing) {
            (Some(u), _) => u.owner,
            (_, Some(s)) => s.owner,
            _ => return Ok(()),
        };
        if owner == h {
            Ok(())
        } else if live(owner) {
            Err(Error::local(
                EW_BUSY,
                "another transfer is running on this connection",
            ))
        } else {
            self.abort(deadline)
        }
    }

    /// Aborts and drops the running transfer: an unfinished upload with
    /// 0x1804, a download or DNC operation with its error frame (8 zero
    /// bytes); no answer is awaited.
    pub(super) fn abort(&mut self, deadline: Deadline) -> Result<()> {
        if let Some(u) = self.upload.take()
            && u.ended.is_none()
        {
            return self.send(ftype::UPLOAD_ABORT, ABORT_BODY.to_vec(), deadline);
        }
        if let Some(s) = self.outgoing.take()
            && s.ended.is_none()
        {
            return self.send(s.how.error_frame(), ABORT_BODY.to_vec(), deadline);
        }
        Ok(())
    }

    /// The close handshake, through the read buffer: whatever arrives
    /// before the close answer is dropped (the pair is closing).
    pub(super) fn close(&mut self, deadline: Deadline) -> Result<()> {
        if self.rbuf.is_empty() {
            return close_conn(&mut self.conn, deadline);
        }
        self.send(ftype::CLOSE_REQ, Vec::new(), deadline)?;
        while (self.next_frame(Some(deadline))?.expect("waited").ftype >> 8) != 0x02 {}
        Ok(())
    }
}

/// A program-transfer frame kind (upload 0x15 to 0x18, download 0x11 to
/// 0x14, DNC 0x19 to 0x1c): one an aborted transfer may still send.
pub(super) fn stale(kind: u8) -> bool {
    (0x11..=0x1c).contains(&kind)
}

/// A frame of type `ftype` where connection 1 expects none of its kind:
/// EW_PROTOCOL (FANUC's library's code for it during an upload).
pub(super) fn unexpected(ftype: u16, during: &str) -> Error {
    Error::protocol(
        detail::FRAME_KIND,
        format!("connection 1: a frame of type {ftype:04x} {during}"),
    )
}
