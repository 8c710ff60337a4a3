//! The range reads: one request, its answer cut into fixed-size records.

use crate::error::Result;
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::{RDALMHISTRY5, RDOMHISTRY, RDOMHISTRY2, RDOPHISTRY, RDPITCHR};
use crate::proto::packet::{ReqSub, RespSub, answer_records};

/// Bytes of one record on the wire.
pub const OP_REC: usize = 16;
pub const OM_REC: usize = 276;
pub const OM2_REC: usize = 272;
pub const ALM5_REC: usize = 528;

/// The message bytes of an operator message record.
pub const OM_TEXT: usize = 256;
/// The message bytes of an alarm history 5 record.
pub const ALM5_TEXT: usize = 64;

/// One request and the records of its answer (payload bytes after `skip`,
/// cut into `size`-byte records).
pub struct Records {
    pub sub: ReqSub,
    pub skip: usize,
    pub size: usize,
}

impl Call for Records {
    type Output = Vec<Vec<u8>>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![self.sub.clone()]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Vec<Vec<u8>>> {
        // FANUC's library counts the records as the whole payload's
        // length over the record size (a header included), and reads a
        // record the payload cuts short as zeros.
        let p = &sub(resp, 0)?.payload;
        Ok((0..p.len() / self.size)
            .map(|i| {
                let at = self.skip + i * self.size;
                let mut r = p.get(at..).unwrap_or(&[]).to_vec();
                r.resize(self.size, 0);
                r
            })
            .collect())
    }
}

/// The last entry asked for: `e` cut so that the answer holds at most `most`
/// records.
fn end(s: u16, e: u16, most: i32) -> i32 {
    let (s, e) = (i32::from(s), i32::from(e));
    s + (e - s + 1).min(most) - 1
}

/// cnc_rdophistry: (1,0x006a)[s, e], e cut to one answer (89 records).
pub fn rdophistry(s: u16, e: u16) -> Records {
    let e = end(s, e, answer_records(i32::MAX, OP_REC));
    Records {
        sub: ReqSub::cnc(RDOPHISTRY, &[i32::from(s), e]),
        skip: 0,
        size: OP_REC,
    }
}

/// cnc_rdomhistry: (1,0x0073)[s + 1, s + n] (the CNC numbers from 1), n
/// the entries asked for, at most 5.
pub fn rdomhistry(s: u16, n: u16) -> Records {
    let s = i32::from(s) + 1;
    Records {
        sub: ReqSub::cnc(RDOMHISTRY, &[s, s + i32::from(n.min(5)) - 1]),
        skip: 0,
        size: OM_REC,
    }
}

/// cnc_rdomhistry2: (1,0x01b5)[s, e, n, 1], at most 5 entries.
pub fn rdomhistry2(s: u16, e: u16) -> Records {
    let e = end(s, e, 5);
    let s = i32::from(s);
    Records {
        sub: ReqSub::cnc(RDOMHISTRY2, &[s, e, e - s + 1, 1]),
        skip: 4,
        size: OM2_REC,
    }
}

/// cnc_rdalmhistry5: (1,0x01d1)[s, e, n, 1], two entries an exchange.
pub fn rdalmhistry5(s: u16, e: u16) -> Records {
    let e = end(s, e, 2);
    let s = i32::from(s);
    Records {
        sub: ReqSub::cnc(RDALMHISTRY5, &[s, e, e - s + 1, 1]),
        skip: 0,
        size: ALM5_REC,
    }
}

/// Pitch error points asked for in one exchange.
pub const PITCH_CHUNK: i32 = 716;

/// cnc_rdpitchr: (1,0x0012)[s, e], one i16 a point, at most 716 points.
pub fn rdpitchr(s: i32, e: i32) -> Records {
    let e = s + (e - s + 1).min(PITCH_CHUNK) - 1;
    Records {
        sub: ReqSub::cnc(RDPITCHR, &[s, e]),
        skip: 0,
        size: 2,
    }
}

/// A big-endian i16 at `at` of a record.
pub fn be16(r: &[u8], at: usize) -> i16 {
    i16::from_be_bytes([r[at], r[at + 1]])
}

/// A big-endian i32 at `at` of a record.
pub fn be32(r: &[u8], at: usize) -> i32 {
    i32::from_be_bytes([r[at], r[at + 1], r[at + 2], r[at + 3]])
}
