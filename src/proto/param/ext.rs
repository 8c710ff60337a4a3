//! cnc_rdparam_ext / cnc_rddiag_ext: attributes and all-axes values of
//! several numbers per frame.

use super::info::ParamType30;
use super::read::Table;
use crate::error::{Error, Result};
use crate::ew::EW_NUMBER;
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::{
    DIAGNOSS, DIAGNOSS16, DIAGTYPE, PARAMTYPE, RDDIAGINFO, RDDIAGINFO15, RDPARAINFO, RDPARAINFO15,
    RDPARAM, RDPARAM16,
};
use crate::proto::open::CncClass;
use crate::proto::packet::{ReqSub, RespSub, encode_request};
use std::borrow::Cow;

/// One IODBPRM record of cnc_rdparam_ext / cnc_rddiag_ext.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ExtRecord {
    /// The CNC does not know the number: only datano and type = -1 are written.
    Missing,
    Found {
        ptype: i16,
        axis: i16,
        info: i16,
        unit: i16,
        /// max-axes (at most 32) {value, decimals}; base ignored, as FANUC's library does.
        data: Vec<(i32, i32)>,
    },
}

/// The attribute and value commands of cnc_rdparam_ext / cnc_rddiag_ext
/// by class: 30i 0xa0 + 0x8d (diag 0xa2 + 0x93); 16i 0x10 + 0x0e (0x31 +
/// 0x30); Series 15 0x8f + 0x8d (0x94 + 0x93).
fn ext_cmds(table: Table, class: CncClass) -> (u16, u16) {
    match (class, table) {
        (CncClass::Series30, Table::Param) => (PARAMTYPE, RDPARAM),
        (CncClass::Series30, Table::Diag) => (DIAGTYPE, DIAGNOSS),
        (CncClass::Series16 { kind: 2 }, Table::Param) => (RDPARAINFO15, RDPARAM),
        (CncClass::Series16 { kind: 2 }, Table::Diag) => (RDDIAGINFO15, DIAGNOSS),
        (CncClass::Series16 { .. }, Table::Param) => (RDPARAINFO, RDPARAM16),
        (CncClass::Series16 { .. }, Table::Diag) => (RDDIAGINFO, DIAGNOSS16),
    }
}

/// Numbers per frame of cnc_rdparam_ext / cnc_rddiag_ext: as many as their
/// answers fit in FANUC's budget (oracle: 8 on a 30i with 32 axes, 38 with
/// one; 7 on a 16i with 32 axes, 24 with one; 4 on a Series 15 with 32).
/// One number's answer: its two subpacket headers (16 bytes each), the
/// attribute payload (30i 28 bytes, else one 16-byte info list) and the
/// value block (8 bytes, then 8 (30i, Series 15) or 4 (16i) per axis).
pub fn ext_per_frame(cx: &Ctx) -> usize {
    let axes = cx.max_axes as usize;
    let (budget, per) = match cx.class {
        CncClass::Series30 => (2904, 68 + 8 * axes),
        CncClass::Series16 { kind: 2 } => (1444, 56 + 8 * axes),
        CncClass::Series16 { .. } => (1444, 56 + 4 * axes),
    };
    (budget / per).max(1)
}

/// IODBPRM axis, info and unit from an attribute answer (oracle, bit by
/// bit). `attr` is the payload, at least [`ext_attr_len`] bytes.
fn ext_fields(table: Table, class: CncClass, attr: &[u8]) -> (i16, i16, i16) {
    let w16 = |at: usize| u16::from_be_bytes([attr[at], attr[at + 1]]);
    match class {
        CncClass::Series30 => {
            let t = ParamType30 {
                number: 0,
                ptype: w16(12),
                axis: w16(14),
                unit_lo: w16(16),
                unit_hi: w16(18),
                kind: w16(20),
                w22: w16(22),
                flags: w16(24),
                ..ParamType30::default()
            };
            match table {
                Table::Param => (t.ext_axis(), t.ext_info_param(), t.ext_unit_param()),
                Table::Diag => (t.ext_axis(), (t.flags & 1) as i16, t.unit_hi as i16),
            }
        }
        // The info list's first entry: {number, attribute word}.
        CncClass::Series16 { kind } => {
            let a = i32::from_be_bytes([attr[12], attr[13], attr[14], attr[15]]);
            let bit = |n: u32| (a >> n) & 1;
            let v = match (kind, table) {
                // Series 15: bits 3, 9, 10 axis; 4-8 info; 11-15 unit.
                (2, Table::Param) => (bit(3) | (a >> 8) & 6, (a >> 4) & 0x1f, (a >> 11) & 0x1f),
                // Series 15 diagnosis: bits 8-11 an axis code (0 none, 1..3
                // → 2c - 1, more → 1); bit 4 info; bits 12-15 unit.
                (2, Table::Diag) => {
                    let c = (a >> 8) & 0xf;
                    let axis = match c {
                        0 => 0,
                        1..=3 => 2 * c - 1,
                        _ => 1,
                    };
                    (axis, bit(4), (a >> 12) & 0xf)
                }
                // 16i: bit 2 and bit 8 axis; bits 3-7 info; no unit.
                (_, Table::Param) => (bit(2) | bit(8) << 1, (a >> 3) & 0x1f, 0),
                (_, Table::Diag) => (bit(2), 0, 0),
            };
            (v.0 as i16, v.1 as i16, v.2 as i16)
        }
    }
}

/// Attribute bytes cnc_rdparam_ext uses: the 30i record up to its flags
/// word (@24), else the info list's first entry.
fn ext_attr_len(class: CncClass) -> usize {
    match class {
        CncClass::Series30 => 26,
        CncClass::Series16 { .. } => 16,
    }
}

/// The first `need` bytes FANUC's library reads from subpacket `k`'s
/// payload on. Its receive buffer holds the frame as received over the
/// request it sent, so a payload shorter than its fields goes on into the
/// next subpackets' headers (length, class, path, command, error, two
/// details, payload length: 16 bytes, big-endian) and payloads, past the
/// answer's end into the bytes of the request (`req`: its body, built
/// only then), and past both into zeros [fuzz, seeds 0x21b01128 and
/// 0x21b11128: every recorded 30i, 16i and Series 15 case of both
/// functions, short, cut, empty and error answers in any place;
/// docs/protocol/param.md]. `k` must be a subpacket of `resp`.
fn read_on<'a>(
    resp: &'a [RespSub],
    k: usize,
    need: usize,
    req: impl FnOnce() -> Vec<u8>,
) -> Cow<'a, [u8]> {
    let p = &resp[k].payload;
    if p.len() >= need {
        return Cow::Borrowed(p);
    }
    let mut v = Vec::with_capacity(need + 16);
    v.extend_from_slice(p);
    for s in &resp[k + 1..] {
        if v.len() >= need {
            break;
        }
        // The header as the frame carried it (packet.rs checks that a
        // frame's subpacket lengths add up).
        let len = (16 + s.payload.len()) as u16;
        for w in [
            len,
            s.class,
            s.path,
            s.cmd,
            s.error as u16,
            s.detail1,
            s.detail2,
        ] {
            v.extend_from_slice(&w.to_be_bytes());
        }
        v.extend_from_slice(&(s.payload.len() as u16).to_be_bytes());
        v.extend_from_slice(&s.payload);
    }
    if v.len() < need {
        // The answer's body: its count word, then every subpacket.
        let body = 2 + resp.iter().map(|s| 16 + s.payload.len()).sum::<usize>();
        if let Some(rest) = req().get(body..) {
            v.extend_from_slice(rest);
        }
    }
    v.resize(need.max(v.len()), 0);
    Cow::Owned(v)
}

/// Up to [`ext_per_frame`] numbers: per number its attributes and its
/// all-axes values (`ext_cmds`: [no, 1] and [no, no, -1]).
#[derive(Debug, Clone)]
pub struct ReadExt {
    pub table: Table,
    pub numbers: Vec<i32>,
}

impl Call for ReadExt {
    /// The records decoded, and the error that stopped decoding (if any):
    /// records before it are still written, as FANUC's library does.
    type Output = (Vec<ExtRecord>, Option<Error>);
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let (info, read) = ext_cmds(self.table, cx.class);
        self.numbers
            .iter()
            .flat_map(|n| {
                [
                    ReqSub::cnc(info, &[*n, 1]),
                    ReqSub::cnc(read, &[*n, *n, -1]),
                ]
            })
            .collect()
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Self::Output> {
        let count = cx.axes();
        let number3 = |r: &Result<&RespSub>| {
            matches!(
                r,
                Err(Error::Cnc {
                    code: EW_NUMBER,
                    ..
                })
            )
        };
        // A value block: 8 bytes, then per axis a 30i / Series 15 record
        // {i32 value, i16 base, i16 decimals} or a 16i word.
        let rec = match cx.class {
            CncClass::Series16 { kind } if kind != 2 => 4,
            _ => 8,
        };
        // The request as sent (the session stamps the handle's path).
        let req = || {
            let mut subs = self.request(cx);
            for s in subs.iter_mut().filter(|s| s.path == 0) {
                s.path = cx.path;
            }
            encode_request(&subs)
        };
        let mut out = Vec::with_capacity(self.numbers.len());
        for (k, n) in self.numbers.iter().enumerate() {
            let one = || -> Result<ExtRecord> {
                let (a, v) = (sub(resp, 2 * k), sub(resp, 2 * k + 1));
                // Error 3 (unknown number) in either subpacket: type -1;
                // any other error is returned, the attributes' first.
                if number3(&a) || number3(&v) {
                    return Ok(ExtRecord::Missing);
                }
                a?;
                v?;
                // Both read at their fixed offsets, a short payload going on
                // into what follows it in the frame (`read_on`).
                let a = read_on(resp, 2 * k, ext_attr_len(cx.class), req);
                let v = read_on(resp, 2 * k + 1, 8 + rec * count, req);
                // The number asked must be the one answered.
                if i32::from_be_bytes([a[8], a[9], a[10], a[11]]) != *n {
                    return Ok(ExtRecord::Missing);
                }
                let ptype = i16::from_be_bytes([v[6], v[7]]);
                let (axis, info, unit) = ext_fields(self.table, cx.class, &a);
                // Values of every axis from the block's byte 8: a 30i or
                // Series 15 record (base ignored), a 16i word (decimals 0).
                let vals = &v[8..];
                let data = (0..count)
                    .map(|i| {
                        let b = &vals[rec * i..rec * (i + 1)];
                        let value = i32::from_be_bytes([b[0], b[1], b[2], b[3]]);
                        match rec {
                            4 => (value, 0),
                            _ => (value, i16::from_be_bytes([b[6], b[7]]) as i32),
                        }
                    })
                    .collect();
                Ok(ExtRecord::Found {
                    ptype,
                    axis,
                    info,
                    unit,
                    data,
                })
            };
            match one() {
                Ok(r) => out.push(r),
                Err(e) => return Ok((out, Some(e))),
            }
        }
        Ok((out, None))
    }
}
