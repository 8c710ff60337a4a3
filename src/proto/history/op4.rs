//! cnc_rdophistry4: the answer, and the moves of each record kind from
//! the wire into the caller's record.

use super::records::{be16, be32};
use crate::error::Result;
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::RDOPHISTRY4;
use crate::proto::packet::{ReqSub, RespSub};

/// cnc_rdophistry4: (1,0x01b0)[s, e]. The answer: i32 "more" (non-zero:
/// the CNC holds more of the range than it sent), i32 record count, then
/// the records, each as long as its type says ([`op4_kind`]).
pub struct OpHis4 {
    pub s: i32,
    pub e: i32,
}

/// The decoded answer of 0x01b0: the more flag, the record count, and the
/// record bytes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OpHis4Answer {
    pub more: i32,
    pub count: i32,
    pub records: Vec<u8>,
}

impl Call for OpHis4 {
    type Output = OpHis4Answer;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(RDOPHISTRY4, &[self.s, self.e])]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<OpHis4Answer> {
        // A header cut short reads as zeros (what FANUC's library reads
        // past a one-subpacket answer).
        let p = &sub(resp, 0)?.payload;
        let mut h = [0u8; 8];
        let n = p.len().min(8);
        h[..n].copy_from_slice(&p[..n]);
        Ok(OpHis4Answer {
            more: be32(&h, 0),
            count: be32(&h, 4),
            records: p.get(8..).unwrap_or(&[]).to_vec(),
        })
    }
}

/// One move of an operation history 4 record from the wire (big-endian)
/// into the caller's record (native), by byte offsets.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Move {
    /// `n` i16 from `wire` to `c` on.
    Shorts { wire: usize, c: usize, n: usize },
    /// `n` i32 from `wire` to `c` on.
    Longs { wire: usize, c: usize, n: usize },
    /// The low 16 bits of the i32 at `wire` to the short at `c`.
    Low16 { wire: usize, c: usize },
    /// The low byte of the i16 at `wire` to the char at `c`.
    Low8 { wire: usize, c: usize },
    /// `n` bytes as they are.
    Bytes { wire: usize, c: usize, n: usize },
}

/// How FANUC's library reads one operation history 4 record type: its
/// bytes on the wire, its bytes in the caller's buffer (`rec_len`, the
/// 4-byte head included) and the moves from one to the other.
#[derive(Debug, Clone, Copy)]
pub struct Op4Kind {
    pub wire: usize,
    pub size: usize,
    pub moves: &'static [Move],
}

const fn sh(wire: usize, c: usize, n: usize) -> Move {
    Move::Shorts { wire, c, n }
}
const fn lg(wire: usize, c: usize, n: usize) -> Move {
    Move::Longs { wire, c, n }
}
const fn by(wire: usize, c: usize, n: usize) -> Move {
    Move::Bytes { wire, c, n }
}

/// The modal and position snapshot of the alarm records 9 and 10, at the
/// same offsets on the wire and in the record from `b` on: 10 G-code
/// modal longs and 10 flag bytes, 10 other modal longs and flags, 32
/// absolute positions and digits, 32 machine positions and digits.
macro_rules! snapshot {
    ($b:expr) => {
        [
            lg($b, $b, 10),
            by($b + 0x28, $b + 0x28, 10),
            lg($b + 0x34, $b + 0x34, 10),
            by($b + 0x5c, $b + 0x5c, 10),
            lg($b + 0x68, $b + 0x68, 32),
            by($b + 0xe8, $b + 0xe8, 32),
            lg($b + 0x108, $b + 0x108, 32),
            by($b + 0x188, $b + 0x188, 32),
        ]
    };
}

const IAL: [Move; 11] = {
    let s = snapshot!(0x20);
    [
        low16(4, 6),
        sh(8, 4, 1),
        sh(0xa, 8, 11),
        s[0],
        s[1],
        s[2],
        s[3],
        s[4],
        s[5],
        s[6],
        s[7],
    ]
};

const MAL: [Move; 12] = {
    let s = snapshot!(0x60);
    [
        low16(4, 6),
        sh(8, 4, 1),
        sh(0xa, 8, 11),
        by(0x20, 0x1e, 64),
        s[0],
        s[1],
        s[2],
        s[3],
        s[4],
        s[5],
        s[6],
        s[7],
    ]
};

/// The record type that makes FANUC's library continue its record loop
/// at index 9 (it reuses the record index for the 8 bytes it copies).
pub const OP4_RESTART_TYPE: u16 = 13;

/// The record types FANUC's library reads (learnt from it, docs/protocol/history.md:
/// 0 MDI key, 1 signal, 2 alarm, 3 date, 4 macro variable, 5 parameter,
/// 6 operator message, 7 tool offset, 8 work offset, 9 alarm with
/// snapshot, 10 alarm with message and snapshot, 11 macro variable with a
/// 32-bit number, 12 screen, 13 (a record of 8 raw bytes), 0xffff an empty
/// record); any other type: EW_VERSION.
pub fn op4_kind(rec_type: u16) -> Option<Op4Kind> {
    OP4_KINDS
        .iter()
        .find(|(t, _)| *t == rec_type)
        .map(|(_, k)| *k)
}

const fn k(wire: usize, size: usize, moves: &'static [Move]) -> Op4Kind {
    Op4Kind { wire, size, moves }
}

const fn low16(wire: usize, c: usize) -> Move {
    Move::Low16 { wire, c }
}

const fn low8(wire: usize, c: usize) -> Move {
    Move::Low8 { wire, c }
}

/// [`op4_kind`]'s table.
pub const OP4_KINDS: &[(u16, Op4Kind)] = &[
    (0, k(20, 16, &[low8(4, 4), low8(6, 5), sh(8, 6, 5)])),
    (
        1,
        k(
            40,
            20,
            &[
                sh(8, 4, 1),
                low16(4, 6),
                by(0xc, 8, 2),
                sh(0xa, 0xa, 1),
                sh(0xe, 0xc, 3),
            ],
        ),
    ),
    (2, k(36, 24, &[low16(4, 6), sh(8, 4, 1), sh(0xa, 8, 8)])),
    (3, k(32, 20, &[sh(4, 4, 7)])),
    (
        4,
        k(28, 28, &[sh(4, 4, 5), lg(0x10, 0x10, 2), sh(0x18, 0x18, 2)]),
    ),
    (
        5,
        k(32, 32, &[sh(4, 4, 6), lg(0x10, 0x10, 3), sh(0x1c, 0x1c, 2)]),
    ),
    (6, k(276, 276, &[sh(4, 4, 8), by(0x14, 0x14, 256)])),
    (
        7,
        k(
            40,
            28,
            &[
                sh(8, 4, 1),
                low16(4, 6),
                sh(0xa, 8, 4),
                lg(0x14, 0x10, 2),
                sh(0x1c, 0x18, 2),
            ],
        ),
    ),
    (
        8,
        k(
            36,
            32,
            &[
                sh(8, 4, 1),
                low16(4, 6),
                sh(0xa, 8, 5),
                lg(0x18, 0x14, 2),
                sh(0x20, 0x1c, 2),
            ],
        ),
    ),
    (9, k(456, 456, &IAL)),
    (10, k(520, 520, &MAL)),
    (
        11,
        k(
            28,
            28,
            &[
                lg(4, 4, 1),
                sh(8, 8, 4),
                lg(0x10, 0x10, 2),
                sh(0x18, 0x18, 2),
            ],
        ),
    ),
    (12, k(16, 16, &[sh(4, 4, 6)])),
    (
        13,
        k(28, 28, &[sh(4, 4, 2), by(8, 8, 8), sh(0x10, 0x10, 6)]),
    ),
    (0xffff, k(4, 4, &[])),
];

/// Fills the caller's record `out` (`kind.size` bytes) from the wire
/// record `r` (`kind.wire` bytes): `rec_len` = the size, `rec_type`, then
/// the moves. Bytes no move names stay as they were.
pub fn op4_put(kind: &Op4Kind, rec_type: u16, r: &[u8], out: &mut [u8]) {
    out[0..2].copy_from_slice(&(kind.size as i16).to_ne_bytes());
    out[2..4].copy_from_slice(&rec_type.to_ne_bytes());
    for m in kind.moves {
        match *m {
            Move::Shorts { wire, c, n } => {
                for k in 0..n {
                    let v = be16(r, wire + 2 * k);
                    out[c + 2 * k..c + 2 * k + 2].copy_from_slice(&v.to_ne_bytes());
                }
            }
            Move::Longs { wire, c, n } => {
                for k in 0..n {
                    let v = be32(r, wire + 4 * k);
                    out[c + 4 * k..c + 4 * k + 4].copy_from_slice(&v.to_ne_bytes());
                }
            }
            Move::Low16 { wire, c } => {
                out[c..c + 2].copy_from_slice(&be16(r, wire + 2).to_ne_bytes());
            }
            Move::Low8 { wire, c } => out[c] = r[wire + 1],
            Move::Bytes { wire, c, n } => out[c..c + n].copy_from_slice(&r[wire..wire + n]),
        }
    }
}

/// One operation history 4 record as the CNC sends it (simulator side):
/// its length and type, then `fill` writes its fields (big-endian) into
/// the rest, the record zeros otherwise.
pub fn op4_record(rec_type: u16, fill: impl FnOnce(&mut [u8])) -> Vec<u8> {
    let wire = op4_kind(rec_type).map_or(4, |k| k.wire);
    let mut b = vec![0u8; wire];
    b[0..2].copy_from_slice(&(wire as u16).to_be_bytes());
    b[2..4].copy_from_slice(&rec_type.to_be_bytes());
    fill(&mut b);
    b
}

/// Writes the big-endian i16 `v` at `at` of a wire record.
pub fn put16(b: &mut [u8], at: usize, v: i32) {
    b[at..at + 2].copy_from_slice(&(v as i16).to_be_bytes());
}

/// Writes the big-endian i32 `v` at `at` of a wire record.
pub fn put32(b: &mut [u8], at: usize, v: i32) {
    b[at..at + 4].copy_from_slice(&v.to_be_bytes());
}

/// Why [`op4_walk`] stopped before the answer's count.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Op4Stop {
    /// The next record does not fit in the room left.
    Full,
    /// A record type FANUC's library does not know (EW_VERSION).
    Unknown,
}

/// One record of a 0x01b0 answer: its kind, type and wire bytes.
pub type Op4Record = (Op4Kind, u16, Vec<u8>);

/// The records of one 0x01b0 answer, as FANUC's library walks them: up to
/// the answer's count (after a type-13 record from index 9 on), each as
/// long as its type says (bytes past the payload read as zeros), while
/// each fits in `room` bytes. Returns each record's kind, type and wire
/// bytes, and why the walk stopped early, if it did.
pub fn op4_walk(ans: &OpHis4Answer, mut room: i32) -> (Vec<Op4Record>, Option<Op4Stop>) {
    let (mut out, mut i, mut at) = (Vec::new(), 0i32, 0usize);
    while i < ans.count {
        let head = |k: usize| ans.records.get(at + k).copied().unwrap_or(0);
        let t = u16::from_be_bytes([head(2), head(3)]);
        let Some(kind) = op4_kind(t) else {
            return (out, Some(Op4Stop::Unknown));
        };
        if room < kind.size as i32 {
            return (out, Some(Op4Stop::Full));
        }
        let mut r = ans.records.get(at..).unwrap_or(&[]).to_vec();
        r.resize(kind.wire, 0);
        out.push((kind, t, r));
        room -= kind.size as i32;
        at += kind.wire;
        i = if t == OP4_RESTART_TYPE { 9 } else { i + 1 };
    }
    (out, None)
}
