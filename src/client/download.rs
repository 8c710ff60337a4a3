//! Program download and DNC operation on connection 1, client side
//! (frames: src/proto/download.rs).
//!
//! As the upload (src/client/upload.rs): one transfer per connection pair,
//! owned by the handle that started it, under connection 1's own lock, so
//! data requests of every handle go on meanwhile. Data calls send at once
//! and wait for nothing; a CNC error frame that has arrived is returned by
//! the next call, as FANUC's library does.

use super::conn::Deadline;
use super::conn1::{Conn1, Sending, stale, unexpected};
use super::pair::Pair;
use crate::error::{Error, Result};
use crate::ew::{EW_BUSY, EW_FUNC, EW_RESET};
use crate::proto::download::Outgoing;
use crate::proto::upload::{StartReq, decode_error, error_body};

fn not_started() -> Error {
    super::keep_detail();
    Error::local(EW_FUNC, "no download or DNC operation started")
}

/// The error a CNC error frame body means: code 0 ends the transfer
/// (EW_RESET), another code is the CNC's refusal.
fn cnc_end(body: &[u8]) -> Error {
    let (code, detail1, detail2) = decode_error(body);
    Error::Cnc {
        code: if code == 0 { EW_RESET } else { code },
        detail1,
        detail2,
    }
}

impl Conn1 {
    /// Sends the start request still pending, and waits for its answer;
    /// the transfer is dropped if the CNC does not take it.
    fn start_now(&mut self, deadline: Deadline) -> Result<()> {
        let Some(s) = self.outgoing.as_mut() else {
            return Err(not_started());
        };
        let (how, Some(body)) = (s.how, s.pending.take()) else {
            return Ok(());
        };
        let r = self.send(how.start_req(), body, deadline).and_then(|_| {
            let f = self.recv_kind(how.start, deadline)?;
            if f.ftype == how.start_resp() {
                Ok(())
            } else {
                Err(Error::local(EW_FUNC, "the CNC refused the transfer"))
            }
        });
        if r.is_err() {
            self.outgoing = None;
        }
        r
    }

    /// Ends `h`'s transfer of kind `how` on the client's side (it is
    /// dropped): Some(result) when the CNC already ended it, None when the
    /// client has to tell the CNC; EW_FUNC when its start was never sent
    /// (FANUC's library has nothing to end then).
    fn finishing(&mut self, how: Outgoing) -> Result<Option<Result<()>>> {
        let s = self.sending(how)?;
        let (ended, unsent) = (s.ended.clone(), s.pending.is_some());
        self.outgoing = None;
        if unsent {
            return Err(not_started());
        }
        Ok(ended.map(ok_at_end))
    }

    /// `h`'s running transfer of kind `how`, after taking in an error
    /// frame that has arrived. Before the start is sent a program-transfer
    /// frame is an earlier transfer's (dropped); any other frame is not one
    /// the CNC sends during a transfer: it ends the transfer with
    /// EW_PROTOCOL, so that its end call never reports success.
    fn sending(&mut self, how: Outgoing) -> Result<&mut Sending> {
        match &self.outgoing {
            Some(s) if s.how == how => {}
            _ => return Err(not_started()),
        }
        while self.outgoing.as_ref().is_some_and(|s| s.ended.is_none()) {
            let Some(f) = self.next_frame(None)? else {
                break;
            };
            let s = self.outgoing.as_mut().expect("checked");
            let k = (f.ftype >> 8) as u8;
            if k == how.error {
                s.ended = Some(cnc_end(&f.body));
            } else if s.pending.is_some() && stale(k) {
                // Before this transfer's start: what an earlier one (ended
                // or aborted) still sent.
                crate::log_at!(
                    super::log::ERRORS,
                    "conn1 discarded a frame of type {:04x} before a transfer's start",
                    f.ftype
                );
            } else {
                s.ended = Some(unexpected(f.ftype, "during a download or DNC operation"));
            }
        }
        Ok(self.outgoing.as_mut().expect("checked"))
    }
}

impl Pair {
    /// cnc_dwnstart* / cnc_dncstart*: the start frame, then its answer;
    /// with `defer`, both wait for the first data call (cnc_dncstart).
    pub fn send_start(
        &self,
        h: u16,
        how: Outgoing,
        req: &StartReq,
        defer: bool,
        timeout: i32,
        live: impl Fn(u16) -> bool,
    ) -> Result<()> {
        let deadline = Deadline::after_secs(timeout);
        self.with_c1(deadline, |c1| {
            c1.settle(h, live, deadline)?;
            if c1.upload.is_some() || c1.outgoing.is_some() {
                return Err(Error::local(EW_BUSY, "a transfer is already running"));
            }
            c1.outgoing = Some(Sending {
                owner: h,
                how,
                pending: Some(req.encode()),
                ended: None,
            });
            if defer {
                Ok(())
            } else {
                c1.start_now(deadline)
            }
        })
    }

    /// cnc_download* / cnc_dnc*: `data` in frames of `how.chunk` bytes. A
    /// CNC error frame that has arrived is returned instead (code 0:
    /// EW_RESET), by this call and every later one until the end call.
    pub fn send_data(
        &self,
        h: u16,
        how: Outgoing,
        data: &[u8],
        timeout: i32,
        live: impl Fn(u16) -> bool,
    ) -> Result<()> {
        let deadline = Deadline::after_secs(timeout);
        self.with_c1(deadline, |c1| {
            c1.settle(h, live, deadline)?;
            if let Some(e) = &c1.sending(how)?.ended {
                return Err(e.clone());
            }
            c1.start_now(deadline)?;
            for chunk in data.chunks(how.chunk) {
                c1.send(how.data_frame(), chunk.to_vec(), deadline)?;
            }
            Ok(())
        })
    }

    /// cnc_dwnend* / cnc_dncend*: after the CNC's error frame, its code
    /// (0: Ok) and nothing sent; else the end frame, then the CNC's answer
    /// or its error frame.
    pub fn send_end(
        &self,
        h: u16,
        how: Outgoing,
        timeout: i32,
        live: impl Fn(u16) -> bool,
    ) -> Result<()> {
        let deadline = Deadline::after_secs(timeout);
        self.with_c1(deadline, |c1| {
            c1.settle(h, live, deadline)?;
            if let Some(r) = c1.finishing(how)? {
                return r;
            }
            c1.send(how.end_req(), Vec::new(), deadline)?;
            // The end's answer or the CNC's error frame; any other frame
            // is no answer to it.
            let f = c1.next_frame(Some(deadline))?.expect("waited");
            match (f.ftype >> 8) as u8 {
                k if k == how.end => Ok(()),
                k if k == how.error => ok_at_end(cnc_end(&f.body)),
                _ => Err(unexpected(f.ftype, "waiting for the end's answer")),
            }
        })
    }

    /// cnc_dncend2 with an error result: the client's error frame carrying
    /// `code`, no answer awaited.
    pub fn send_abort(
        &self,
        h: u16,
        how: Outgoing,
        code: i16,
        timeout: i32,
        live: impl Fn(u16) -> bool,
    ) -> Result<()> {
        let deadline = Deadline::after_secs(timeout);
        self.with_c1(deadline, |c1| {
            c1.settle(h, live, deadline)?;
            match c1.finishing(how)? {
                Some(r) => r,
                None => c1.send(how.error_frame(), error_body(code, 0, 0), deadline),
            }
        })
    }
}

/// An end call's answer to the CNC's end of the transfer: code 0 is Ok.
fn ok_at_end(e: Error) -> Result<()> {
    match e {
        Error::Cnc { code: EW_RESET, .. } => Ok(()),
        e => Err(e),
    }
}
