//! What a simulated CNC answers, one method per function. Every method has
//! a default that answers EW_FUNC (1), as a CNC lacking the function does,
//! so the simulator grows one function at a time.

use crate::ew;
use crate::proto::cmd;
use crate::proto::open::OpenBody;
use crate::proto::packet::{CLASS_CNC, ReqSub, RespSub};
use crate::proto::param::Param16;
use crate::proto::status::{CncId, Status, Status2, SysInfo, Word};
use crate::proto::wire::Wire;

/// An error code a CNC puts in a response subpacket.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CncError {
    pub code: i16,
    pub detail: (u16, u16),
}

impl CncError {
    pub const fn new(code: i16) -> CncError {
        CncError {
            code,
            detail: (0, 0),
        }
    }
    pub const FUNC: CncError = CncError::new(ew::EW_FUNC);
    pub const NUMBER: CncError = CncError::new(ew::EW_NUMBER);
    pub const PATH: CncError = CncError::new(ew::EW_PATH);
}

pub type Reply<T> = Result<T, CncError>;

fn unsupported<T>() -> Reply<T> {
    Err(CncError::FUNC)
}

/// A CNC as the wire sees it. `path` is the 1-based path of the subpacket.
#[allow(unused_variables)]
pub trait CncService: Send {
    /// The open-response body (SPEC.md §3.2).
    fn open_body(&self) -> OpenBody;
    fn max_sessions(&self) -> usize {
        0
    }
    /// Brings the machine's running state (program cycle, scheduled events)
    /// up to `now`. Called once per data frame, before its subpackets are
    /// answered, so one frame sees one consistent snapshot.
    fn advance(&mut self, now: std::time::Instant) {}
    fn sysinfo(&mut self, path: u16) -> Reply<SysInfo> {
        unsupported()
    }
    fn statinfo(&mut self, path: u16) -> Reply<Status> {
        unsupported()
    }
    fn statinfo2(&mut self, path: u16) -> Reply<Status2> {
        unsupported()
    }
    fn hdck(&mut self, path: u16) -> Reply<Word> {
        unsupported()
    }
    fn tmmode(&mut self, path: u16) -> Reply<Word> {
        unsupported()
    }
    fn cnc_id(&mut self) -> Reply<CncId> {
        unsupported()
    }
    /// 16i-class parameter read (0x000e).
    fn param16(&mut self, path: u16, number: i32, axis: i16) -> Reply<Param16> {
        unsupported()
    }

    // --- position ---

    // --- program ---

    // --- alarm ---

    // --- param ---

    // --- macros ---

    // --- pmc ---

    // --- offset ---

    // --- tool ---

    // --- upload ---
    /// Program upload on connection 1 (0x1501): the text to push in 0x1604
    /// frames, or the error for the CNC's error frame.
    fn upload(&mut self, req: &crate::proto::upload::StartReq) -> Reply<Vec<u8>> {
        unsupported()
    }
}

fn enc<T: Wire>(r: Reply<T>) -> Reply<Vec<u8>> {
    r.map(|v| v.to_bytes())
}

/// Answers one request subpacket.
pub fn dispatch(svc: &mut dyn CncService, sub: &ReqSub) -> RespSub {
    let p = sub.path;
    let a = sub.args;
    let paths = svc.open_body().path_count() as u16;
    let r = if sub.class == CLASS_CNC && (p == 0 || p > paths) {
        Err(CncError::PATH)
    } else {
        match (sub.class, sub.cmd) {
            (CLASS_CNC, cmd::SYSINFO) => enc(svc.sysinfo(p)),
            (CLASS_CNC, cmd::STATINFO) => enc(svc.statinfo(p)),
            (CLASS_CNC, cmd::STATINFO2) => enc(svc.statinfo2(p)),
            (CLASS_CNC, cmd::HDCK) => enc(svc.hdck(p)),
            (CLASS_CNC, cmd::TMMODE) => enc(svc.tmmode(p)),
            (CLASS_CNC, cmd::RDCNCID) => enc(svc.cnc_id()),
            (CLASS_CNC, cmd::RDPARAM16) => enc(svc.param16(p, a[0], a[2] as i16)),

            // --- position ---

            // --- program ---

            // --- alarm ---

            // --- param ---

            // --- macros ---

            // --- pmc ---

            // --- offset ---

            // --- tool ---
            _ => Err(CncError::FUNC),
        }
    };
    match r {
        Ok(payload) => RespSub::ok(sub, payload),
        Err(e) => RespSub::err(sub, e.code, e.detail.0, e.detail.1),
    }
}
