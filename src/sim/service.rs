//! A simulated CNC as the server sees it ([`CncService`]): its open body,
//! its clock, the connection-1 transfers, and the one entry that answers a
//! request subpacket. The simulator's machine answers requests through its
//! routes (src/sim/dispatch.rs); an error goes back as the CNC's code.

use crate::ew;
use crate::proto::open::OpenBody;
use crate::proto::packet::{ReqSub, RespSub};

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

/// A CNC as the wire sees it: what is not a request (open, sessions,
/// clock, transfers), and [`CncService::answer`] for every request.
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
    /// The answer to one request subpacket (an error answer for a command
    /// the CNC does not know: EW_FUNC).
    fn answer(&mut self, sub: &ReqSub) -> RespSub;
    /// Program upload on connection 1 (0x1501): the text to push in 0x1604
    /// frames, or the error for the CNC's error frame.
    fn upload(&mut self, req: &crate::proto::upload::StartReq) -> Reply<Vec<u8>> {
        unsupported()
    }
    /// A download or DNC operation on connection 1: `text` is what its data
    /// frames carried so far; called after each data frame, and with `done`
    /// at the client's end frame. An error goes back in the CNC's error
    /// frame (and ends the transfer); Ok at the end is the end's answer.
    fn receive(
        &mut self,
        how: crate::proto::download::Outgoing,
        req: &crate::proto::upload::StartReq,
        text: &[u8],
        done: bool,
    ) -> Reply<()> {
        unsupported()
    }
}

/// The response subpacket of an answer.
pub fn respond(sub: &ReqSub, r: Reply<Vec<u8>>) -> RespSub {
    match r {
        Ok(payload) => RespSub::ok(sub, payload),
        Err(e) => RespSub::err(sub, e.code, e.detail.0, e.detail.1),
    }
}
