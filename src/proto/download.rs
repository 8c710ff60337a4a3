//! Program download and DNC operation over connection 1: the frames the
//! client sends, sans-IO, shared by the client (src/client/download.rs)
//! and the simulator (src/sim/session.rs). Learnt from FANUC's library
//! against a fake CNC \[oracle\]:
//!
//! * Start: kind 0x11 (download) or 0x19 (DNC), request `01` with the
//!   upload's 516-byte start body ([`super::upload::StartReq`]: data type,
//!   path, "N:`<name>`" for cnc_dwnstart4, else empty); any answer of the
//!   same kind is accepted, its body is ignored.
//! * Data: kind 0x12 / 0x1a, sub-type `04` (no answer), the caller's bytes
//!   as they are, split into bodies of [`Outgoing::chunk`] bytes.
//! * End: kind 0x13 / 0x1b, request `01` with an empty body; the CNC
//!   answers with the same kind (body ignored) or with its error frame.
//! * The CNC's error frame: kind 0x14 / 0x1c, sub-type `04`, the body of
//!   [`super::upload::error_body`]: code 0 ends the transfer (the client's
//!   next data call returns EW_RESET), another code refuses it (the next
//!   call returns that code). The client aborts a DNC operation with the
//!   same frame carrying its own code (cnc_dncend2).

/// The frame kinds (high byte of the type word) and chunk size of one
/// transfer the client sends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Outgoing {
    pub start: u8,
    pub data: u8,
    pub end: u8,
    pub error: u8,
    /// The largest data body FANUC's library sends (every class).
    pub chunk: usize,
}

/// cnc_dwnstart ... cnc_dwnend4.
pub const DOWNLOAD: Outgoing = Outgoing {
    start: 0x11,
    data: 0x12,
    end: 0x13,
    error: 0x14,
    chunk: 1280,
};

/// cnc_dncstart ... cnc_dncend2.
pub const DNC: Outgoing = Outgoing {
    start: 0x19,
    data: 0x1a,
    end: 0x1b,
    error: 0x1c,
    chunk: 1450,
};

impl Outgoing {
    /// The transfer a frame of kind `kind` belongs to.
    pub fn of_kind(kind: u8) -> Option<Outgoing> {
        [DOWNLOAD, DNC]
            .into_iter()
            .find(|o| [o.start, o.data, o.end, o.error].contains(&kind))
    }
    pub const fn start_req(&self) -> u16 {
        (self.start as u16) << 8 | 0x01
    }
    pub const fn start_resp(&self) -> u16 {
        (self.start as u16) << 8 | 0x02
    }
    pub const fn data_frame(&self) -> u16 {
        (self.data as u16) << 8 | 0x04
    }
    pub const fn end_req(&self) -> u16 {
        (self.end as u16) << 8 | 0x01
    }
    pub const fn end_resp(&self) -> u16 {
        (self.end as u16) << 8 | 0x02
    }
    pub const fn error_frame(&self) -> u16 {
        (self.error as u16) << 8 | 0x04
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_types_are_the_recorded_ones() {
        assert_eq!(
            [
                DOWNLOAD.start_req(),
                DOWNLOAD.data_frame(),
                DOWNLOAD.end_req(),
                DOWNLOAD.error_frame()
            ],
            [0x1101, 0x1204, 0x1301, 0x1404]
        );
        assert_eq!(
            [
                DNC.start_req(),
                DNC.data_frame(),
                DNC.end_req(),
                DNC.error_frame()
            ],
            [0x1901, 0x1a04, 0x1b01, 0x1c04]
        );
        assert_eq!(Outgoing::of_kind(0x1a), Some(DNC));
        assert_eq!(Outgoing::of_kind(0x15), None);
    }
}
