//! Program upload on connection 1 (SPEC.md §2, §5.3), client side.
//!
//! One upload at a time per connection pair, owned by the handle that
//! started it. Connection 1 has its own lock (`Pair::c1`), never held with
//! connection 2's, so data requests of every handle go on during an upload.
//! Upload calls never wait for data: what has arrived is handed out, and
//! nothing yet is EW_BUFFER, as FANUC's library does. A handle freed in the
//! middle of its upload leaves it to be aborted by the next upload call of
//! any handle of the pair (or closed with the pair by the last free).

use super::conn::Deadline;
use super::conn1::{Conn1, Upload, unexpected};
use super::log;
use super::pair::{Pair, busy, dead, stream_broken};
use crate::error::{Error, Result};
use crate::ew::{EW_BUFFER, EW_BUSY, EW_FUNC, EW_LENGTH, EW_RESET};
use crate::proto::frame::ftype;
use crate::proto::upload::{
    KIND_DATA, KIND_END, KIND_ERROR, KIND_START, MIN_READ, StartReq, decode_error,
};
use std::time::{Duration, Instant};

/// Detail words of the upload stall timeout (FANUC's, [dis]).
const STALL: (i16, i16) = (9, 4);

fn no_upload() -> Error {
    super::keep_detail();
    Error::local(EW_FUNC, "no upload started (cnc_upstart first)")
}

fn upload_busy() -> Error {
    Error::local(EW_BUSY, "another upload is running on this connection")
}

impl Pair {
    /// Runs `f` on connection 1; a broken stream tears the pair down.
    /// Waits for it at most until `deadline` (EW_BUSY, nothing sent, when
    /// another handle's call kept it that long).
    pub(super) fn with_c1<T>(
        &self,
        deadline: Deadline,
        f: impl FnOnce(&mut Conn1) -> Result<T>,
    ) -> Result<T> {
        let Some(mut g) = deadline.lock(&self.c1) else {
            return Err(busy());
        };
        let c1 = g.as_mut().ok_or_else(dead)?;
        let r = f(c1);
        if let Err(e) = &r
            && stream_broken(e)
        {
            drop(g);
            self.kill();
        }
        r
    }

    /// Makes way for `h` (see [`Conn1::settle`]): Ok(true) when `h` owns
    /// the running upload, Ok(false) when there is none.
    fn settle(
        c1: &mut Conn1,
        h: u16,
        live: impl Fn(u16) -> bool,
        deadline: Deadline,
    ) -> Result<bool> {
        c1.settle(h, live, deadline)?;
        Ok(c1.upload.is_some())
    }

    /// cnc_upstart and relatives: 0x1501, then any 0x15xx answer.
    pub fn upload_start(
        &self,
        h: u16,
        req: &StartReq,
        timeout: i32,
        live: impl Fn(u16) -> bool,
    ) -> Result<()> {
        let deadline = Deadline::after_secs(timeout);
        self.with_c1(deadline, |c1| {
            if Self::settle(c1, h, live, deadline)? || c1.outgoing.is_some() {
                return Err(upload_busy());
            }
            c1.send(ftype::UPLOAD_START_REQ, req.encode(), deadline)?;
            c1.recv_kind(KIND_START, deadline)?;
            c1.upload = Some(Upload {
                owner: h,
                text: Vec::new(),
                pos: 0,
                ended: None,
                empty_since: None,
            });
            Ok(())
        })
    }

    /// cnc_upload3: copies upload text into `out` and returns how much.
    /// As FANUC's library: the room is `out.len()` rounded down to whole
    /// 256 bytes; frames that have arrived are copied (one that does not
    /// fit is split, its rest comes next time) while 256 bytes or more of
    /// room are left. Nothing yet: EW_BUFFER; after the end: EW_RESET.
    pub fn upload_read(
        &self,
        h: u16,
        out: &mut [u8],
        timeout: i32,
        live: impl Fn(u16) -> bool,
    ) -> Result<usize> {
        let deadline = Deadline::after_secs(timeout);
        self.with_c1(deadline, |c1| {
            if !Self::settle(c1, h, live, deadline)? {
                return Err(no_upload());
            }
            if out.len() < MIN_READ {
                return Err(Error::local(EW_LENGTH, "length must be at least 256"));
            }
            // FANUC's library uses whole 256-byte units of the room given.
            let room = out.len() / MIN_READ * MIN_READ;
            let out = &mut out[..room];
            let mut total = 0;
            loop {
                let u = c1.upload.as_mut().expect("settled");
                if let Some(e) = &u.ended {
                    return Err(e.clone());
                }
                let n = (u.text.len() - u.pos).min(out.len() - total);
                if n > 0 {
                    out[total..total + n].copy_from_slice(&u.text[u.pos..u.pos + n]);
                    u.pos += n;
                    total += n;
                    if out.len() - total >= MIN_READ {
                        continue;
                    }
                    break;
                }
                let Some(f) = c1.next_frame(None)? else {
                    if total > 0 {
                        break;
                    }
                    let u = c1.upload.as_mut().expect("settled");
                    let since = *u.empty_since.get_or_insert_with(Instant::now);
                    if timeout > 0 && since.elapsed() > Duration::from_secs(timeout as u64) {
                        // As FANUC: abort, then the sockets are closed
                        // (a socket error tears the pair down).
                        let _ = c1.abort(Deadline::after_secs(1));
                        return Err(Error::socket(STALL, "upload: no data within the timeout"));
                    }
                    return Err(Error::local(EW_BUFFER, "no upload data yet"));
                };
                let u = c1.upload.as_mut().expect("settled");
                match (f.ftype >> 8) as u8 {
                    KIND_DATA => {
                        u.text = f.body;
                        u.pos = 0;
                    }
                    KIND_END => {
                        u.ended = Some(Error::Cnc {
                            code: EW_RESET,
                            detail1: 0,
                            detail2: 0,
                        });
                        c1.send(ftype::UPLOAD_END_ACK, Vec::new(), deadline)?;
                        if total > 0 {
                            break;
                        }
                    }
                    KIND_ERROR => {
                        let (code, detail1, detail2) = decode_error(&f.body);
                        let code = if code == 0 { EW_RESET } else { code };
                        u.ended = Some(Error::Cnc {
                            code,
                            detail1,
                            detail2,
                        });
                    }
                    // Any other frame is not the upload's: the upload
                    // ends with EW_PROTOCOL (as FANUC's library), never
                    // as complete with that frame's text lost.
                    _ => {
                        crate::log_at!(
                            log::ERRORS,
                            "conn1: a frame of type {:04x} during an upload: EW_PROTOCOL",
                            f.ftype
                        );
                        let e = unexpected(f.ftype, "during an upload");
                        u.ended = Some(e.clone());
                        if total > 0 {
                            break;
                        }
                        return Err(e);
                    }
                }
            }
            if let Some(u) = c1.upload.as_mut() {
                u.empty_since = None;
            }
            Ok(total)
        })
    }

    /// Waits until `h`'s upload has something for [`Pair::upload_read`]
    /// (text, its end or an error), at most `timeout` seconds: the Rust
    /// API's blocking read, where cnc_upload polls. A stall past the timeout
    /// is EW_SOCKET and tears the pair down, as a stalled cnc_upload does.
    pub fn upload_wait(&self, h: u16, timeout: i32) -> Result<()> {
        let deadline = Deadline::after_secs(timeout);
        self.with_c1(deadline, |c1| {
            match &c1.upload {
                Some(u) if u.owner == h => {
                    if u.ended.is_some() || u.pos < u.text.len() {
                        return Ok(());
                    }
                }
                _ => return Err(no_upload()),
            }
            c1.wait_frame(deadline)
        })
    }

    /// cnc_upend3: ends the handle's upload; before the CNC's end frame it
    /// sends the 0x1804 abort. After a CNC error frame, that error.
    pub fn upload_end(&self, h: u16, timeout: i32, live: impl Fn(u16) -> bool) -> Result<()> {
        let deadline = Deadline::after_secs(timeout);
        self.with_c1(deadline, |c1| {
            if !Self::settle(c1, h, live, deadline)? {
                return Err(no_upload());
            }
            let u = c1.upload.as_ref().expect("settled");
            if let Some(e) = &u.ended {
                let e = e.clone();
                c1.upload = None;
                return match e {
                    Error::Cnc { code: EW_RESET, .. } => Ok(()),
                    e => Err(e),
                };
            }
            // FANUC looks at one frame that has arrived: the end is
            // acknowledged, an error returned, anything else aborted.
            match c1.next_frame(None)? {
                Some(f) if (f.ftype >> 8) as u8 == KIND_END => {
                    c1.upload = None;
                    c1.send(ftype::UPLOAD_END_ACK, Vec::new(), deadline)
                }
                Some(f) if (f.ftype >> 8) as u8 == KIND_ERROR => {
                    c1.upload = None;
                    let (code, detail1, detail2) = decode_error(&f.body);
                    match code {
                        0 => Ok(()),
                        code => Err(Error::Cnc {
                            code,
                            detail1,
                            detail2,
                        }),
                    }
                }
                // Text or nothing yet: the caller ends the upload early.
                Some(f) if (f.ftype >> 8) as u8 != KIND_DATA => {
                    c1.abort(deadline)?;
                    Err(unexpected(f.ftype, "during an upload"))
                }
                _ => c1.abort(deadline),
            }
        })
    }
}
