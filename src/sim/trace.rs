//! `focas-sim --trace`: every frame in both directions, one line each,
//! decoded: the FOCAS function a subpacket stands for (src/proto/names.rs),
//! its command, path and argument words, and the result code of each
//! answer. Lines go to stderr or a file, whole, as they happen:
//!
//! ```text
//!   0.004512 m1 c2 <- data cnc_statinfo 0x0019 p1 (0, 0, 0, 0, 0)
//!   0.004533 m1 c2 -> data cnc_statinfo 0x0019 p1 rc 0 EW_OK, 14 bytes
//! ```
//!
//! (seconds since the simulator started, machine, connection, direction:
//! `<-` from the client, `->` to it, `!!` a fault acting.)

use crate::proto::frame::{Frame, ftype};
use crate::proto::names;
use crate::proto::open::CncClass;
use crate::proto::packet::{ReqSub, RespSub};
use parking_lot::Mutex;
use std::fmt::Write as _;
use std::io::Write;
use std::sync::Arc;
use std::time::Instant;

/// Where trace lines go.
pub struct Trace {
    out: Mutex<Box<dyn Write + Send>>,
    start: Instant,
}

impl Trace {
    /// Lines to `out`, each written whole and flushed.
    pub fn to(out: Box<dyn Write + Send>, start: Instant) -> Arc<Trace> {
        Arc::new(Trace {
            out: Mutex::new(out),
            start,
        })
    }

    pub fn stderr(start: Instant) -> Arc<Trace> {
        Trace::to(Box::new(std::io::stderr()), start)
    }

    /// Lines to the file `path` (created, or truncated).
    pub fn file(path: &std::path::Path, start: Instant) -> std::io::Result<Arc<Trace>> {
        Ok(Trace::to(Box::new(std::fs::File::create(path)?), start))
    }

    /// One line: `machine` and connection `conn` say whose.
    pub fn line(&self, machine: &str, conn: u64, text: &str) {
        let t = self.start.elapsed().as_secs_f64();
        let line = format!("{t:11.6} {machine} c{conn} {text}\n");
        let mut out = self.out.lock();
        let _ = out.write_all(line.as_bytes());
        let _ = out.flush();
    }
}

/// What names a subpacket: the CNC's class.
#[derive(Debug, Clone, Copy)]
pub struct Namer {
    s16: bool,
    s15: bool,
}

impl Namer {
    pub fn new(class: CncClass) -> Namer {
        match class {
            CncClass::Series30 => Namer {
                s16: false,
                s15: false,
            },
            CncClass::Series16 { kind } => Namer {
                s16: true,
                s15: kind == 2,
            },
        }
    }

    fn name(&self, sub: &ReqSub) -> &'static str {
        names::request_name(sub, self.s16, self.s15).unwrap_or("?")
    }

    /// A request from the client (`subs`: a data frame's subpackets).
    pub fn request(&self, f: &Frame, subs: &[ReqSub]) -> String {
        let word = |i: usize| {
            f.body
                .get(i..i + 2)
                .map_or(0, |b| u16::from_be_bytes([b[0], b[1]]))
        };
        match f.ftype {
            ftype::OPEN_REQ => format!("<- open conn {}", word(0)),
            ftype::CLOSE_REQ => "<- close".into(),
            ftype::ID_REQ => format!("<- id {:02x?}", f.body),
            ftype::UPLOAD_START_REQ => {
                let r = crate::proto::upload::StartReq::decode(&f.body);
                format!(
                    "<- upload start {:?} type {} p{}",
                    r.start_text(),
                    r.dtype,
                    r.path
                )
            }
            ftype::UPLOAD_END_ACK => "<- upload end acknowledged".into(),
            ftype::UPLOAD_ABORT => "<- upload abort".into(),
            ftype::DATA_REQ => {
                let mut s = String::from("<- data");
                for (i, sub) in subs.iter().enumerate() {
                    let a = sub.args;
                    let _ = write!(
                        s,
                        "{} {} {:#06x} p{} ({}, {}, {}, {}, {})",
                        if i == 0 { "" } else { " |" },
                        self.name(sub),
                        sub.cmd,
                        sub.path,
                        a[0],
                        a[1],
                        a[2],
                        a[3],
                        a[4]
                    );
                    if !sub.payload.is_empty() {
                        let _ = write!(s, " +{} bytes", sub.payload.len());
                    }
                }
                s
            }
            t => format!("<- frame type {t:#06x}, {} bytes", f.body.len()),
        }
    }

    /// An answer to the client (`reqs`/`resps`: a data frame's subpackets).
    pub fn answer(&self, f: &Frame, reqs: &[ReqSub], resps: &[RespSub]) -> String {
        match f.ftype {
            ftype::OPEN_RESP => format!("-> open ok, {} bytes", f.body.len()),
            ftype::OPEN_REJECT => "-> open refused (session limit)".into(),
            ftype::CLOSE_RESP => "-> close ok".into(),
            ftype::ID_RESP => "-> id ok".into(),
            ftype::UPLOAD_START_RESP => "-> upload start ok".into(),
            ftype::UPLOAD_DATA => format!("-> upload data, {} bytes", f.body.len()),
            ftype::UPLOAD_END => "-> upload end".into(),
            ftype::UPLOAD_ABORT => {
                let (code, d1, d2) = crate::proto::upload::decode_error(&f.body);
                format!("-> upload error rc {}{}", rc(code), detail(d1, d2))
            }
            ftype::DATA_RESP => {
                let mut s = String::from("-> data");
                for (i, r) in resps.iter().enumerate() {
                    let name = match reqs.get(i) {
                        Some(q) => self.name(q),
                        None => {
                            names::command_name(r.class, r.cmd, self.s16, self.s15).unwrap_or("?")
                        }
                    };
                    let _ = write!(
                        s,
                        "{} {name} {:#06x} p{} rc {}{}, {} bytes",
                        if i == 0 { "" } else { " |" },
                        r.cmd,
                        r.path,
                        rc(r.error),
                        detail(r.detail1, r.detail2),
                        r.payload.len()
                    );
                }
                s
            }
            t => format!("-> frame type {t:#06x}, {} bytes", f.body.len()),
        }
    }
}

fn rc(code: i16) -> String {
    match names::ew_name(code) {
        Some(n) => format!("{code} {n}"),
        None => code.to_string(),
    }
}

fn detail(d1: u16, d2: u16) -> String {
    if (d1, d2) == (0, 0) {
        String::new()
    } else {
        format!(" detail {d1}/{d2}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::proto::frame::CLIENT_VERSION;

    #[test]
    fn data_frames_name_their_functions() {
        let n = Namer::new(CncClass::Series30);
        let mut q = ReqSub::cnc(crate::proto::cmd::RDPARAM, &[6711, 6711, 0]);
        q.path = 1;
        let f = Frame::new(CLIENT_VERSION, ftype::DATA_REQ, Vec::new());
        assert_eq!(
            n.request(&f, std::slice::from_ref(&q)),
            "<- data cnc_rdparam 0x008d p1 (6711, 6711, 0, 0, 0)"
        );
        let r = RespSub::err(&q, 6, 0, 0);
        let f = Frame::new(CLIENT_VERSION, ftype::DATA_RESP, Vec::new());
        assert_eq!(
            n.answer(&f, &[q], &[r]),
            "-> data cnc_rdparam 0x008d p1 rc 6 EW_NOOPT, 0 bytes"
        );
    }
}
