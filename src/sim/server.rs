//! The simulator's network side (tokio): accepts connections, answers the
//! open/close handshake and data frames through a [`CncService`].

use super::service::{CncService, dispatch};
use crate::proto::frame::{Frame, ftype};
use crate::proto::packet::{decode_request, encode_response};
use parking_lot::Mutex;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::{TcpListener, TcpStream};

/// Shared by every connection of one simulated CNC.
pub struct Shared {
    pub cnc: Mutex<Box<dyn CncService>>,
    sessions: AtomicUsize,
    /// A frozen clock (tests): frames are answered as at this instant.
    clock: Mutex<Option<std::time::Instant>>,
}

impl Shared {
    pub fn new(cnc: Box<dyn CncService>) -> Arc<Shared> {
        Arc::new(Shared {
            cnc: Mutex::new(cnc),
            sessions: AtomicUsize::new(0),
            clock: Mutex::new(None),
        })
    }
    /// Freezes the clock data frames are answered at (None: real time again).
    pub fn set_clock(&self, at: Option<std::time::Instant>) {
        *self.clock.lock() = at;
    }
    /// The instant a data frame is answered at.
    pub fn now(&self) -> std::time::Instant {
        self.clock.lock().unwrap_or_else(std::time::Instant::now)
    }
    /// FOCAS sessions open now (connection-1 opens not yet closed).
    pub fn sessions(&self) -> usize {
        self.sessions.load(Ordering::Relaxed)
    }
}

/// Accepts connections until the task is dropped.
pub async fn serve(listener: TcpListener, shared: Arc<Shared>) {
    loop {
        match listener.accept().await {
            Ok((stream, _)) => {
                let _ = stream.set_nodelay(true);
                tokio::spawn(connection(stream, shared.clone()));
            }
            // Out of file descriptors and the like: back off briefly, keep serving.
            Err(_) => tokio::time::sleep(std::time::Duration::from_millis(10)).await,
        }
    }
}

struct SessionGuard<'a>(&'a Shared);
impl Drop for SessionGuard<'_> {
    fn drop(&mut self) {
        self.0.sessions.fetch_sub(1, Ordering::Relaxed);
    }
}

async fn connection(mut stream: TcpStream, shared: Arc<Shared>) {
    let mut buf: Vec<u8> = Vec::with_capacity(4096);
    let mut chunk = vec![0u8; 4096];
    let mut _session: Option<SessionGuard<'_>> = None;
    let version = shared.cnc.lock().open_body().frame_version();
    loop {
        let frame = loop {
            match Frame::decode(&buf) {
                Ok(Some((f, used))) => {
                    buf.drain(..used);
                    break f;
                }
                Ok(None) => {}
                // A peer that does not speak FOCAS2: drop it.
                Err(_) => return,
            }
            match stream.read(&mut chunk).await {
                Ok(0) | Err(_) => return,
                Ok(n) => buf.extend_from_slice(&chunk[..n]),
            }
        };
        let reply = match frame.ftype {
            ftype::OPEN_REQ => {
                let number = frame
                    .body
                    .get(..2)
                    .map_or(0, |b| u16::from_be_bytes([b[0], b[1]]));
                let limit = shared.cnc.lock().max_sessions();
                if number == 1 && _session.is_none() {
                    let admitted = shared
                        .sessions
                        .fetch_update(Ordering::AcqRel, Ordering::Acquire, |n| {
                            (limit == 0 || n < limit).then_some(n + 1)
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
                }
                .or_else(|| {
                    Some(Frame::new(
                        version,
                        ftype::OPEN_RESP,
                        shared.cnc.lock().open_body().to_bytes(),
                    ))
                })
            }
            ftype::CLOSE_REQ => {
                let _ = stream
                    .write_all(&Frame::new(version, ftype::CLOSE_RESP, Vec::new()).encode())
                    .await;
                return;
            }
            ftype::ID_REQ => Some(Frame::new(version, ftype::ID_RESP, frame.body.clone())),
            ftype::UPLOAD_START_REQ => {
                // --- upload ---
                // The answer, then the whole upload in one write, as the fake
                // CNC of the recordings did; the client's 0x1702 / 0x1804
                // need no answer (ignored below).
                let req = crate::proto::upload::StartReq::decode(&frame.body);
                let r = shared.cnc.lock().upload(&req);
                let mut out = Frame::new(version, ftype::UPLOAD_START_RESP, Vec::new()).encode();
                match r {
                    Ok(text) => {
                        let max = crate::proto::frame::max_body_len(version);
                        for chunk in text.chunks(max) {
                            out.extend(
                                Frame::new(version, ftype::UPLOAD_DATA, chunk.to_vec()).encode(),
                            );
                        }
                        out.extend(Frame::new(version, ftype::UPLOAD_END, Vec::new()).encode());
                    }
                    Err(e) => out.extend(
                        Frame::new(
                            version,
                            ftype::UPLOAD_ABORT,
                            crate::proto::upload::error_body(e.code, e.detail.0, e.detail.1),
                        )
                        .encode(),
                    ),
                }
                if stream.write_all(&out).await.is_err() {
                    return;
                }
                None
            }
            ftype::DATA_REQ => match decode_request(&frame.body) {
                Ok(subs) => {
                    let resp = {
                        let now = shared.now();
                        let mut cnc = shared.cnc.lock();
                        cnc.advance(now);
                        subs.iter()
                            .map(|s| dispatch(cnc.as_mut(), s))
                            .collect::<Vec<_>>()
                    };
                    Some(Frame::new(
                        version,
                        ftype::DATA_RESP,
                        encode_response(&resp),
                    ))
                }
                Err(_) => return,
            },
            // Frames this CNC does not serve are ignored, as a CNC ignores them.
            _ => None,
        };
        if let Some(r) = reply {
            if stream.write_all(&r.encode()).await.is_err() {
                return;
            }
        }
    }
}
