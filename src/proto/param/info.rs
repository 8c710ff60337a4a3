//! Attributes and info lists: the 30i attribute record, cnc_rdparainfo3,
//! cnc_rdparainfo / cnc_rddiaginfo.

use super::read::Table;
use crate::error::Result;
use crate::proto::call::{Call, Ctx, payload_padded, sub};
use crate::proto::cmd::PARAMTYPE;
use crate::proto::packet::{ReqSub, RespSub};
use crate::proto::wire::{DecodeError, Reader, Wire, Writer};
use crate::wire_struct;

/// Entries one cnc_rdparainfo / cnc_rddiaginfo request asks for at most.
pub const INFO_MAX: i32 = 178;

wire_struct! {
    /// 30i attribute record of one parameter (0x00a0) or diagnosis item
    /// (0x00a2), 28 bytes. cnc_wrparam uses `ptype` (0..4) and `axis`
    /// (2 = axis parameter); cnc_rdparam_ext / cnc_rddiag_ext check `number`
    /// and derive IODBPRM axis/info/unit from `axis`, `unit_lo`, `unit_hi`,
    /// `kind` and `flags` (oracle findings; what a real CNC puts in the
    /// words is not known, our simulator sends 0 there).
    pub struct ParamType30 {
        pub w0: i32,
        pub w4: i32,
        pub number: i32,
        pub ptype: u16,
        pub axis: u16,
        pub unit_lo: u16,
        pub unit_hi: u16,
        pub kind: u16,
        pub w22: u16,
        pub flags: u16,
        pub w26: u16,
    }
}

impl ParamType30 {
    /// IODBPRM.axis: 0, or (2v - 2) | 1 for an axis attribute v.
    pub fn ext_axis(&self) -> i16 {
        if self.axis == 0 {
            0
        } else {
            ((2 * self.axis as i32 - 2) | 1) as i16
        }
    }
    /// IODBPRM.info of a parameter.
    pub fn ext_info_param(&self) -> i16 {
        let w = self.flags;
        ((w & 1)
            | if w & 2 != 0 { 8 } else { 0 }
            | if w & 4 != 0 { 16 } else { 0 }
            | if self.kind == 1 { 2 } else { 0 }
            | if self.kind == 2 { 4 } else { 0 }) as i16
    }
    /// IODBPRM.unit of a parameter.
    pub fn ext_unit_param(&self) -> i16 {
        (self.unit_lo | (self.unit_hi << 2)) as i16
    }
}

/// The fifth word of cnc_rdparainfo3's 0x00a0 request (a short 1 in its
/// first half): the answer is the previous and next numbers (i32 each), then
/// a 20-byte record a parameter (ParamType30 from `number` on).
pub const INFO3_FLAG: i32 = 0x0001_0000;
/// Bytes of one cnc_rdparainfo3 record.
pub const INFO3_REC: usize = 20;

/// cnc_rdparainfo3: (1,0x00a0)[s, n, 0, 0, flag].
pub fn rdparainfo3(s: i16, n: i16) -> crate::proto::history::Records {
    crate::proto::history::Records {
        sub: ReqSub::cnc(PARAMTYPE, &[i32::from(s), i32::from(n), 0, 0, INFO3_FLAG]),
        skip: 0,
        size: 1,
    }
}

/// Size of the 0x00a0 payload FANUC's cnc_wrparam accepts.
pub const PARAMTYPE_LEN: usize = 28;

wire_struct! {
    /// One entry of a 0x0010 / 0x0031 answer.
    pub struct InfoEntry {
        pub number: i32,
        pub ptype: i32,
    }
}

/// Payload of 0x0010 / 0x0031: previous and next numbers, then entries.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct InfoList {
    pub prev: i32,
    pub next: i32,
    pub entries: Vec<InfoEntry>,
}

impl Wire for InfoList {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.prev);
        w.i32(self.next);
        self.entries.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let prev = r.i32()?;
        let next = r.i32()?;
        // Whole entries only; a ragged tail is not an entry.
        let mut entries = Vec::with_capacity(r.remaining() / 8);
        while r.remaining() >= 8 {
            entries.push(InfoEntry::decode(r)?);
        }
        Ok(InfoList {
            prev,
            next,
            entries,
        })
    }
}

/// Bit 8 of a 16i / rdparainfo type word: an axis parameter.
pub const INFO_AXIS: i32 = 0x100;

/// cnc_rdparainfo / cnc_rddiaginfo: [s, n].
#[derive(Debug, Clone, Copy)]
pub struct ReadInfo {
    pub table: Table,
    pub start: i32,
    pub count: i32,
}

impl Call for ReadInfo {
    /// The list, and whether the answer was empty (FANUC's library then
    /// writes info_no -1: it counts (length - 8) / 8 entries).
    type Output = (InfoList, bool);
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(
            self.table.info_cmd(cx.class),
            &[self.start, self.count.min(INFO_MAX)],
        )]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<(InfoList, bool)> {
        // An answer under 8 bytes: prev and next read as zeros where it
        // ends, as FANUC's library reads them.
        let empty = sub(resp, 0)?.payload.is_empty();
        Ok((payload_padded(resp, 0, 8)?, empty))
    }
}
