//! One client connection: frames read, answered through the machine's
//! [`CncService`], traced, and misbehaving as the machine's faults say.

use super::faults::Cut;
use super::service::CncService;
use super::shared::Shared;
use super::trace::Namer;
use crate::proto::download::Outgoing;
use crate::proto::frame::{Frame, ftype};
use crate::proto::packet::{RespSub, decode_request, encode_response};
use crate::proto::upload::{StartReq, error_body};
use std::os::fd::AsRawFd;
use std::sync::Arc;
use std::sync::atomic::Ordering;
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::TcpStream;

struct SessionGuard<'a>(&'a Shared);
impl Drop for SessionGuard<'_> {
    fn drop(&mut self) {
        self.0.sessions.fetch_sub(1, Ordering::Relaxed);
    }
}

/// Drops the connection with a reset (RST) instead of a close (FIN).
fn reset(stream: TcpStream) {
    let linger = libc::linger {
        l_onoff: 1,
        l_linger: 0,
    };
    // SAFETY: a valid option struct on a socket the stream owns.
    unsafe {
        libc::setsockopt(
            stream.as_raw_fd(),
            libc::SOL_SOCKET,
            libc::SO_LINGER,
            (&linger as *const libc::linger).cast(),
            std::mem::size_of::<libc::linger>() as libc::socklen_t,
        );
    }
    drop(stream);
}

/// Reads the next whole frame into `buf`; None when the peer is gone or
/// does not speak FOCAS2.
async fn next_frame(stream: &mut TcpStream, buf: &mut Vec<u8>) -> Option<Frame> {
    loop {
        match Frame::decode(buf) {
            Ok(Some((f, used))) => {
                buf.drain(..used);
                return Some(f);
            }
            Ok(None) => {}
            Err(_) => return None,
        }
        // Requests are small: 1 KB to start with, more only for a large one.
        if buf.capacity() - buf.len() < 256 {
            buf.reserve(1024);
        }
        match stream.read_buf(buf).await {
            Ok(0) | Err(_) => return None,
            Ok(_) => {}
        }
    }
}

pub(crate) async fn connection(mut stream: TcpStream, shared: Arc<Shared>, id: u64) {
    let faults = &shared.net.faults;
    let mut buf: Vec<u8> = Vec::new();
    let mut _session: Option<SessionGuard<'_>> = None;
    let (version, namer) = {
        let open = shared.cnc.lock().open_body();
        (open.frame_version(), Namer::new(open.class()))
    };
    let epoch = shared.epoch();
    // A download or DNC operation this connection is receiving.
    let mut incoming: Option<Incoming> = None;
    let mut last = shared.fault_time(shared.now());
    if faults.refusing(last) {
        // Accepted just before the listener stopped: refused all the same.
        shared.trace(id, || "!! connection refused (reset)".into());
        return reset(stream);
    }
    loop {
        let Some(frame) = next_frame(&mut stream, &mut buf).await else {
            return;
        };
        let now = shared.now();
        let t = shared.fault_time(now);
        if !faults.is_empty() {
            if faults.off_between(last, t) || shared.epoch() != epoch {
                shared.trace(id, || {
                    "!! the CNC was off the network: connection reset".into()
                });
                return reset(stream);
            }
            last = t;
            if faults.silent(t) {
                shared.trace(id, || {
                    // What the CNC ignored, named (a test counts the writes).
                    let subs = match frame.ftype {
                        ftype::DATA_REQ => decode_request(&frame.body).unwrap_or_default(),
                        _ => Vec::new(),
                    };
                    namer.request(&frame, &subs) + " (silent: no answer)"
                });
                continue;
            }
        }
        let delay = faults.delay(t);
        let reply = match frame.ftype {
            ftype::OPEN_REQ => {
                shared.trace(id, || namer.request(&frame, &[]));
                let number = frame
                    .body
                    .get(..2)
                    .map_or(0, |b| u16::from_be_bytes([b[0], b[1]]));
                // The profile's limit (0: none), and a fault's while it holds.
                let profile = Some(shared.cnc.lock().max_sessions()).filter(|&n| n > 0);
                let limit = match (profile, faults.session_cap(t)) {
                    (Some(a), Some(b)) => Some(a.min(b)),
                    (a, b) => a.or(b),
                };
                let reply = if number == 1 && _session.is_none() {
                    let admitted = shared
                        .sessions
                        .fetch_update(Ordering::AcqRel, Ordering::Acquire, |n| {
                            limit.is_none_or(|l| n < l).then_some(n + 1)
                        })
                        .is_ok();
                    if admitted {
                        _session = Some(SessionGuard(&shared));
                        None
                    } else {
                        Some(Frame::new(version, ftype::OPEN_REJECT, Vec::new()))
                    }
                } else {
                    None
                };
                reply.unwrap_or_else(|| {
                    Frame::new(
                        version,
                        ftype::OPEN_RESP,
                        shared.cnc.lock().open_body().to_bytes(),
                    )
                })
            }
            ftype::CLOSE_REQ => {
                shared.trace(id, || namer.request(&frame, &[]));
                // The session ends before the answer: a client that has it
                // may open another at once.
                _session = None;
                pause(delay).await;
                let r = Frame::new(version, ftype::CLOSE_RESP, Vec::new());
                shared.trace(id, || namer.answer(&r, &[], &[]));
                let _ = stream.write_all(&r.encode()).await;
                return;
            }
            ftype::ID_REQ => {
                shared.trace(id, || namer.request(&frame, &[]));
                Frame::new(version, ftype::ID_RESP, frame.body.clone())
            }
            ftype::UPLOAD_START_REQ => {
                shared.trace(id, || namer.request(&frame, &[]));
                pause(delay).await;
                let (out, frames) = upload(&mut **shared.cnc.lock(), version, &frame);
                if faults.upload_drop(t) {
                    // Off the network part-way: this connection is cut
                    // mid-frame, the others are gone at their next frame.
                    let start = frames.first().map_or(0, |f| f.encode().len());
                    let half = (out.len() / 2).max(start + 1).min(out.len());
                    let _ = stream.write_all(&out[..half]).await;
                    shared.drop_off();
                    shared.trace(id, || {
                        format!(
                            "!! off the network during the upload: reset after {half} of {} bytes",
                            out.len()
                        )
                    });
                    return reset(stream);
                }
                if delay.is_zero() {
                    for f in &frames {
                        shared.trace(id, || namer.answer(f, &[], &[]));
                    }
                    if stream.write_all(&out).await.is_err() {
                        return;
                    }
                    continue;
                }
                // A slow CNC: each frame of the program the delay late.
                for (i, f) in frames.iter().enumerate() {
                    if i > 0 {
                        pause(delay).await;
                    }
                    shared.trace(id, || namer.answer(f, &[], &[]));
                    if stream.write_all(&f.encode()).await.is_err() {
                        return;
                    }
                }
                continue;
            }
            ftype::DATA_REQ => {
                let Ok(subs) = decode_request(&frame.body) else {
                    return;
                };
                shared.trace(id, || namer.request(&frame, &subs));
                shared.data_frames.fetch_add(1, Ordering::Relaxed);
                let resp: Vec<RespSub> = {
                    let mut cnc = shared.cnc.lock();
                    cnc.advance(now);
                    subs.iter()
                        .map(|s| match faults.error_for(s.class, s.cmd, t) {
                            Some(code) => RespSub::err(s, code, 0, 0),
                            None => cnc.answer(s),
                        })
                        .collect()
                };
                let r = Frame::new(version, ftype::DATA_RESP, encode_response(&resp));
                pause(delay).await;
                if let Some(cut) = faults.cut(t) {
                    let bytes = r.encode();
                    let half = bytes.len() / 2;
                    let _ = stream.write_all(&bytes[..half]).await;
                    let how = match cut {
                        Cut::Reset => "reset",
                        Cut::Close => "closed",
                    };
                    shared.trace(id, || {
                        format!(
                            "!! answer cut after {half} of {} bytes, connection {how}",
                            bytes.len()
                        )
                    });
                    match cut {
                        Cut::Reset => reset(stream),
                        Cut::Close => {
                            let _ = stream.shutdown().await;
                        }
                    }
                    return;
                }
                shared.trace(id, || namer.answer(&r, &subs, &resp));
                if stream.write_all(&r.encode()).await.is_err() {
                    return;
                }
                continue;
            }
            t if Outgoing::of_kind((t >> 8) as u8).is_some() => {
                shared.trace(id, || namer.request(&frame, &[]));
                // Every frame of a download the delay late, answered or
                // not (a slow CNC slows the sender through TCP).
                pause(delay).await;
                let Some(r) = receive(&shared, &mut incoming, version, &frame) else {
                    continue;
                };
                shared.trace(id, || namer.answer(&r, &[], &[]));
                if stream.write_all(&r.encode()).await.is_err() {
                    return;
                }
                continue;
            }
            // Frames this CNC does not serve are ignored, as a CNC ignores them.
            _ => {
                shared.trace(id, || namer.request(&frame, &[]) + " (ignored)");
                continue;
            }
        };
        pause(delay).await;
        shared.trace(id, || namer.answer(&reply, &[], &[]));
        if stream.write_all(&reply.encode()).await.is_err() {
            return;
        }
    }
}

async fn pause(d: std::time::Duration) {
    if !d.is_zero() {
        tokio::time::sleep(d).await;
    }
}

/// A download or DNC operation being received on connection 1.
struct Incoming {
    how: Outgoing,
    req: StartReq,
    text: Vec<u8>,
    /// Refused part-way (memory full, a DNC block it cannot run): data is
    /// dropped until the end, which is answered with the same error.
    refused: Option<super::service::CncError>,
}

/// Most a transfer may bring before the CNC refuses it (memory full).
const MAX_INCOMING: usize = 64 << 20;

/// One frame of a download or DNC operation: its answer, if any. Data
/// frames are kept until the end frame; then the machine takes the text
/// and the answer is the end's, or the CNC's error frame.
fn receive(
    shared: &Shared,
    incoming: &mut Option<Incoming>,
    version: u16,
    f: &Frame,
) -> Option<Frame> {
    let how = Outgoing::of_kind((f.ftype >> 8) as u8)?;
    let error = |code: i16, d: (u16, u16)| {
        Frame::new(version, how.error_frame(), error_body(code, d.0, d.1))
    };
    match f.ftype {
        t if t == how.start_req() => {
            *incoming = Some(Incoming {
                how,
                req: StartReq::decode(&f.body),
                text: Vec::new(),
                refused: None,
            });
            Some(Frame::new(version, how.start_resp(), Vec::new()))
        }
        t if t == how.data_frame() => {
            let i = incoming
                .as_mut()
                .filter(|i| i.how == how && i.refused.is_none())?;
            if i.text.len() + f.body.len() > MAX_INCOMING {
                let e = super::service::CncError::new(crate::ew::EW_OVRFLOW);
                i.refused = Some(e);
                i.text = Vec::new();
                return Some(error(e.code, e.detail));
            }
            i.text.extend_from_slice(&f.body);
            let mut cnc = shared.cnc.lock();
            cnc.advance(shared.now());
            match cnc.receive(how, &i.req, &i.text, false) {
                Ok(()) => None,
                Err(e) => {
                    i.refused = Some(e);
                    Some(error(e.code, e.detail))
                }
            }
        }
        t if t == how.end_req() => {
            let i = incoming.take().filter(|i| i.how == how)?;
            if let Some(e) = i.refused {
                return Some(error(e.code, e.detail));
            }
            let mut cnc = shared.cnc.lock();
            cnc.advance(shared.now());
            match cnc.receive(how, &i.req, &i.text, true) {
                Ok(()) => Some(Frame::new(version, how.end_resp(), Vec::new())),
                Err(e) => Some(error(e.code, e.detail)),
            }
        }
        // The client's abort (or an unknown frame of the kind): dropped.
        _ => {
            *incoming = None;
            None
        }
    }
}

/// The answer to an upload start, then the whole upload, as one write (as
/// the fake CNC of the recordings did; the client's 0x1702 / 0x1804 need no
/// answer): the bytes, and the frames for the trace.
pub fn upload(cnc: &mut dyn CncService, version: u16, req: &Frame) -> (Vec<u8>, Vec<Frame>) {
    let req = crate::proto::upload::StartReq::decode(&req.body);
    let r = cnc.upload(&req);
    let mut frames = vec![Frame::new(version, ftype::UPLOAD_START_RESP, Vec::new())];
    match r {
        Ok(text) => {
            for chunk in text.chunks(crate::proto::upload::DATA_CHUNK) {
                frames.push(Frame::new(version, ftype::UPLOAD_DATA, chunk.to_vec()));
            }
            frames.push(Frame::new(version, ftype::UPLOAD_END, Vec::new()));
        }
        Err(e) => frames.push(Frame::new(
            version,
            ftype::UPLOAD_ABORT,
            crate::proto::upload::error_body(e.code, e.detail.0, e.detail.1),
        )),
    }
    let out = frames.iter().flat_map(Frame::encode).collect();
    (out, frames)
}
