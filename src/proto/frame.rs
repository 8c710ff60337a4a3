//! The 10-byte frame header and whole frames (SPEC.md §2).

use super::wire::{DecodeError, Reader, Writer};

pub const MAGIC: [u8; 4] = [0xA0; 4];
pub const HEADER_LEN: usize = 10;

/// Frame type words: high byte = kind, low byte = direction (1 request, 2 response).
pub mod ftype {
    pub const OPEN_REQ: u16 = 0x0101;
    pub const OPEN_RESP: u16 = 0x0102;
    /// Our simulator's answer to an open beyond the CNC's session limit.
    pub const OPEN_REJECT: u16 = 0x0103;
    pub const CLOSE_REQ: u16 = 0x0201;
    pub const CLOSE_RESP: u16 = 0x0202;
    pub const DATA_REQ: u16 = 0x2101;
    pub const DATA_RESP: u16 = 0x2102;
    pub const UPLOAD_START_REQ: u16 = 0x1501;
    pub const UPLOAD_START_RESP: u16 = 0x1502;
    pub const UPLOAD_DATA: u16 = 0x1604;
    pub const UPLOAD_END: u16 = 0x1701;
    pub const UPLOAD_END_ACK: u16 = 0x1702;
    pub const UPLOAD_ABORT: u16 = 0x1804;
    pub const ID_REQ: u16 = 0xf501;
    pub const ID_RESP: u16 = 0xf502;
    pub const ID_REJECT: u16 = 0xf5ff;
}

/// The version our client writes in every frame, as FANUC's library does.
pub const CLIENT_VERSION: u16 = 1;

/// Largest body a frame of this version may carry (SPEC.md §2).
pub const fn max_body_len(version: u16) -> usize {
    match version {
        0..=2 => 1450,
        3 => 2910,
        4 => 3470,
        _ => 4950,
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FrameHeader {
    pub version: u16,
    pub ftype: u16,
    pub len: u16,
}

impl FrameHeader {
    pub fn encode(&self, w: &mut Writer) {
        w.bytes(&MAGIC);
        w.u16(self.version);
        w.u16(self.ftype);
        w.u16(self.len);
    }

    /// Decodes and validates a header: magic, and the body length against the
    /// version's maximum.
    pub fn decode(b: &[u8]) -> Result<FrameHeader, DecodeError> {
        let mut r = Reader::new(b);
        if r.array::<4>()? != MAGIC {
            return Err(DecodeError::BadMagic);
        }
        let h = FrameHeader {
            version: r.u16()?,
            ftype: r.u16()?,
            len: r.u16()?,
        };
        let max = max_body_len(h.version);
        if h.len as usize > max {
            return Err(DecodeError::Oversize {
                len: h.len as usize,
                max,
                version: h.version,
            });
        }
        Ok(h)
    }

    /// The kind byte (high byte of the type word) that pairs a response with its request.
    pub fn kind(&self) -> u8 {
        (self.ftype >> 8) as u8
    }
}

/// A whole frame: header fields and body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Frame {
    pub version: u16,
    pub ftype: u16,
    pub body: Vec<u8>,
}

impl Frame {
    pub fn new(version: u16, ftype: u16, body: Vec<u8>) -> Frame {
        Frame {
            version,
            ftype,
            body,
        }
    }

    pub fn encode(&self) -> Vec<u8> {
        let mut w = Writer::with_capacity(HEADER_LEN + self.body.len());
        FrameHeader {
            version: self.version,
            ftype: self.ftype,
            len: self.body.len() as u16,
        }
        .encode(&mut w);
        w.bytes(&self.body);
        w.into_vec()
    }

    /// Incremental decode from a stream buffer: `Ok(None)` while incomplete,
    /// `Ok(Some((frame, consumed)))` once a whole frame is there.
    pub fn decode(buf: &[u8]) -> Result<Option<(Frame, usize)>, DecodeError> {
        if buf.len() < HEADER_LEN {
            // Reject a bad magic as early as it can be seen.
            let n = buf.len().min(4);
            if buf[..n] != MAGIC[..n] {
                return Err(DecodeError::BadMagic);
            }
            return Ok(None);
        }
        let h = FrameHeader::decode(&buf[..HEADER_LEN])?;
        let total = HEADER_LEN + h.len as usize;
        if buf.len() < total {
            return Ok(None);
        }
        Ok(Some((
            Frame::new(h.version, h.ftype, buf[HEADER_LEN..total].to_vec()),
            total,
        )))
    }
}
