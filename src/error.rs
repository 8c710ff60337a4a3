//! Internal errors and the one place they become `EW_*` codes.

use crate::ew::*;
use crate::proto::wire::DecodeError;
use std::os::raw::c_short;
use thiserror::Error;

/// Detail words reported by `cnc_getdtailerr` for library-side failures
/// (FANUC's location codes, SPEC.md §6.2).
pub mod detail {
    pub const RECV_TIMEOUT_HEADER: (i16, i16) = (9, 1);
    pub const RECV_TIMEOUT_BODY: (i16, i16) = (9, 2);
    pub const EOF: (i16, i16) = (11, 2);
    pub const BAD_MAGIC: (i16, i16) = (4, 0);
    pub const OVERSIZE: (i16, i16) = (7, 1);
    pub const SUBLEN_TOO_BIG: (i16, i16) = (7, 4);
    pub const SUBLEN_TOO_SMALL: (i16, i16) = (7, 5);
    pub const COUNT_ZERO: (i16, i16) = (3, 0);
    /// An answer with fewer subpackets than the request (FANUC's library's
    /// detail for it, as for a zero count).
    pub const SUB_MISSING: (i16, i16) = (3, 0);
    /// An answer whose subpackets do not echo the request's class and
    /// command (ours alone checks): FANUC's detail for an answer that does
    /// not fit the request's subpackets, as for a missing one.
    pub const ECHO: (i16, i16) = (3, 0);
    pub const CONNECT: (i16, i16) = (1, 0);
    pub const SEND: (i16, i16) = (2, 0);
    pub const SHORT_PAYLOAD: (i16, i16) = (8, 0);
    pub const DEAD: (i16, i16) = (11, 2);
    pub const REJECTED: (i16, i16) = (12, 0);
    /// A frame on connection 1 of a kind its transfer never has (ours:
    /// FANUC's library's detail for it is not known).
    pub const FRAME_KIND: (i16, i16) = (5, 0);
}

#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum Error {
    /// The connection failed: refused, closed, timed out, or already torn down.
    #[error("socket error ({}/{}): {msg}", .detail.0, .detail.1)]
    Socket { detail: (i16, i16), msg: String },
    /// The peer sent something that is not a valid FOCAS2 frame or payload.
    #[error("protocol error ({}/{}): {msg}", .detail.0, .detail.1)]
    Protocol { detail: (i16, i16), msg: String },
    /// The CNC answered with a non-zero error code in a subpacket.
    #[error("CNC error {code} (detail {detail1}/{detail2})")]
    Cnc {
        code: i16,
        detail1: u16,
        detail2: u16,
    },
    /// A check made before any traffic (handle, pointer, length, number ...).
    #[error("{msg} (EW {code})")]
    Local { code: c_short, msg: &'static str },
    /// The call was queued in its handle's batch (src/client/batch.rs):
    /// EW_OK now, its own result at fwlib_batch_end.
    #[error("queued in a batch")]
    Queued,
}

impl Error {
    /// The `EW_*` code a C caller sees.
    pub fn ew(&self) -> c_short {
        match self {
            Error::Socket { .. } => EW_SOCKET,
            Error::Protocol { .. } => EW_PROTOCOL,
            Error::Cnc { code, .. } => *code,
            Error::Local { code, .. } => *code,
            Error::Queued => crate::ew::EW_OK,
        }
    }

    pub fn socket(detail: (i16, i16), msg: impl Into<String>) -> Error {
        Error::Socket {
            detail,
            msg: msg.into(),
        }
    }
    pub fn protocol(detail: (i16, i16), msg: impl Into<String>) -> Error {
        Error::Protocol {
            detail,
            msg: msg.into(),
        }
    }
    /// A payload shorter than the decoder needs: EW_PROTOCOL, never garbage.
    pub fn short(msg: impl Into<String>) -> Error {
        Error::protocol(detail::SHORT_PAYLOAD, msg)
    }
    pub const fn local(code: c_short, msg: &'static str) -> Error {
        Error::Local { code, msg }
    }
    pub const fn handle() -> Error {
        Error::local(EW_HANDLE, "unknown or freed handle")
    }
    pub const fn null() -> Error {
        Error::local(EW_DATA, "NULL pointer argument")
    }
    pub const fn length() -> Error {
        Error::local(EW_LENGTH, "length argument too small")
    }
    /// True for errors after which the connection pair can no longer be used.
    pub fn kills_connection(&self) -> bool {
        matches!(self, Error::Socket { .. })
    }
}

impl From<DecodeError> for Error {
    /// A payload or frame that does not decode. Which framing errors leave
    /// the stream usable is decided by the transport, not here.
    fn from(e: DecodeError) -> Error {
        let detail = match e {
            DecodeError::BadMagic => detail::BAD_MAGIC,
            DecodeError::Oversize { .. } => detail::OVERSIZE,
            DecodeError::CountZero => detail::COUNT_ZERO,
            DecodeError::SubLenTooBig | DecodeError::Invalid(_) => detail::SUBLEN_TOO_BIG,
            DecodeError::SubLenTooSmall => detail::SUBLEN_TOO_SMALL,
            DecodeError::Short { .. } => detail::SHORT_PAYLOAD,
        };
        Error::protocol(detail, e.to_string())
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_maps_to_its_code() {
        assert_eq!(Error::socket(detail::EOF, "x").ew(), EW_SOCKET);
        assert_eq!(Error::protocol(detail::BAD_MAGIC, "x").ew(), EW_PROTOCOL);
        let cnc = Error::Cnc {
            code: 5,
            detail1: 1,
            detail2: 2,
        };
        assert_eq!(cnc.ew(), EW_DATA);
        assert_eq!(Error::handle().ew(), EW_HANDLE);
        assert_eq!(Error::null().ew(), EW_DATA);
        assert_eq!(Error::length().ew(), EW_LENGTH);
        assert_eq!(Error::from(DecodeError::CountZero).ew(), EW_PROTOCOL);
    }

    #[test]
    fn header_values_match_fanuc() {
        assert_eq!((EW_PASSWD, EW_PATH, EW_HANDLE), (17, 11, -8));
        assert_eq!((EW_SOCKET, EW_PROTOCOL), (-16, -17));
    }
}
