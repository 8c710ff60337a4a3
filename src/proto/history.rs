//! Records read by number range: the operation history (cnc_rdophistry),
//! the operator message histories (cnc_rdomhistry, cnc_rdomhistry2), alarm
//! history 5 (cnc_rdalmhistry5) and the pitch error table (cnc_rdpitchr).
//! Learnt with the oracle (docs/protocol/history.md).
//!
//! Each answer is fixed-size records (cnc_rdomhistry2: after a 4-byte
//! count).

use super::call::{Call, Ctx, sub};
pub use super::cmd::{
    RDALMHISTRY5, RDOMHISTRY, RDOMHISTRY2, RDOPHISTRY, RDOPHISTRY4, RDPITCHR, WRHISSGNL3,
};
use super::packet::{ReqSub, RespSub, answer_records};
use crate::error::Result;

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

/// The kinds of operation history record FANUC's library decodes, by the
/// record type the CNC sends (other types: the type alone).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OpKind {
    Mdi,
    Signal,
    Alarm,
    Date,
    Time,
    Other,
}

impl OpKind {
    pub fn of(rec_type: i16) -> OpKind {
        match rec_type {
            0 | 5 | 10 => OpKind::Mdi,
            1 | 6 | 11 => OpKind::Signal,
            2 | 7 | 12 => OpKind::Alarm,
            3 => OpKind::Date,
            4 => OpKind::Time,
            _ => OpKind::Other,
        }
    }
}

/// One operation history record as the CNC sends it (simulator side):
/// type at 2, then six words from byte 4. MDI: key, power-on flag; signal:
/// i32 number, name, old << 8 | new; alarm: i32 number, 0, group, i32
/// axis; date: year, month, day, power-on flag; time: hour, minute,
/// second, power-on flag.
pub fn op_record(rec_type: i16, words: [i32; 4]) -> Vec<u8> {
    let mut b = vec![0u8; OP_REC];
    b[2..4].copy_from_slice(&rec_type.to_be_bytes());
    let w16 =
        |b: &mut [u8], at: usize, v: i32| b[at..at + 2].copy_from_slice(&(v as i16).to_be_bytes());
    let w32 = |b: &mut [u8], at: usize, v: i32| b[at..at + 4].copy_from_slice(&v.to_be_bytes());
    match OpKind::of(rec_type) {
        OpKind::Signal => {
            w32(&mut b, 4, words[0]);
            w16(&mut b, 8, words[1]);
            w16(&mut b, 10, words[2] << 8 | (words[3] & 0xff));
        }
        OpKind::Alarm => {
            w32(&mut b, 4, words[0]);
            w16(&mut b, 10, words[1]);
            w32(&mut b, 12, words[2]);
        }
        _ => {
            for (k, v) in words.iter().enumerate() {
                w16(&mut b, 4 + 2 * k, *v);
            }
        }
    }
    b
}

/// The time stamp of a history record: year, month, day, hour, minute, second.
pub type Stamp = [u16; 6];

fn text<const N: usize>(msg: &str) -> [u8; N] {
    let mut t = [0u8; N];
    let b = msg.as_bytes();
    let n = b.len().min(N);
    t[..n].copy_from_slice(&b[..n]);
    t
}

fn stamp_words(t: &Stamp) -> Vec<u8> {
    t.iter().flat_map(|v| v.to_be_bytes()).collect()
}

/// One cnc_rdomhistry record (simulator side): om_no at 2, the time stamp
/// from 4, the text from 20.
pub fn om_record(number: i16, t: &Stamp, msg: &str) -> Vec<u8> {
    let mut b = vec![0u8; 2];
    b.extend(number.to_be_bytes());
    b.extend(stamp_words(t));
    b.extend([0u8; 4]);
    b.extend(text::<OM_TEXT>(msg));
    b
}

/// One cnc_rdomhistry2 record (simulator side): display flag, number, the
/// time stamp, the text.
pub fn om2_record(shown: bool, number: i16, t: &Stamp, msg: &str) -> Vec<u8> {
    let mut b = i16::from(shown).to_be_bytes().to_vec();
    b.extend(number.to_be_bytes());
    b.extend(stamp_words(t));
    b.extend(text::<OM_TEXT>(msg));
    b
}

/// The fields of an alarm history 5 record.
#[derive(Debug, Clone, Default)]
pub struct Alm5 {
    pub number: i32,
    pub group: i32,
    pub axis: i32,
    pub time: Stamp,
    pub path: i16,
    pub axes: i16,
    pub message: String,
}

/// One cnc_rdalmhistry5 record (simulator side): i32 number, group, axis;
/// six i16 of time; i32 message length; i16 path, system alarm, display
/// flag, number of axes; 64 text bytes; then the modal and position blocks
/// (zeros here: the simulator keeps no snapshot); 528 bytes in all.
pub fn alm5_record(a: &Alm5) -> Vec<u8> {
    let mut b = Vec::with_capacity(ALM5_REC);
    for v in [a.number, a.group, a.axis] {
        b.extend(v.to_be_bytes());
    }
    b.extend(stamp_words(&a.time));
    b.extend((a.message.len().min(ALM5_TEXT) as i32).to_be_bytes());
    for v in [a.path, 0, 1, a.axes] {
        b.extend(v.to_be_bytes());
    }
    b.extend(text::<ALM5_TEXT>(&a.message));
    b.resize(ALM5_REC, 0);
    b
}

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

/// One entry of the signal table on the wire: i32 entry number, i32 PMC
/// number, i32 byte number, the address type an i16 at 12 (its low
/// byte 13 read), byte 14 the mask.
pub const SIG3_REC: usize = 16;

/// One entry of the operation history's signal table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Sig3 {
    pub ent_no: i16,
    pub pmc_no: i16,
    pub sig_no: i16,
    pub sig_name: u8,
    pub mask_pat: u8,
}

impl Sig3 {
    pub fn to_wire(&self) -> [u8; SIG3_REC] {
        let mut b = [0u8; SIG3_REC];
        b[0..4].copy_from_slice(&i32::from(self.ent_no).to_be_bytes());
        b[4..8].copy_from_slice(&i32::from(self.pmc_no).to_be_bytes());
        b[8..12].copy_from_slice(&i32::from(self.sig_no).to_be_bytes());
        // FANUC's library sends the char sign-extended to a short.
        b[12..14].copy_from_slice(&i16::from(self.sig_name as i8).to_be_bytes());
        b[14] = self.mask_pat;
        b
    }
    /// An entry of a request's payload (the simulator): the full i32
    /// words, which it checks.
    pub fn from_wire(b: &[u8]) -> (i32, i32, i32, u8, u8) {
        (be32(b, 0), be32(b, 4), be32(b, 8), b[13], b[14])
    }
}

/// cnc_wrhissgnl3's request: the entries, their number the argument word.
pub struct WriteSig3 {
    pub entries: Vec<Sig3>,
}

impl Call for WriteSig3 {
    type Output = ();
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        let n = self.entries.len() as i32;
        let sub = ReqSub::cnc(WRHISSGNL3, &[n]);
        if n == 0 {
            return vec![sub];
        }
        let data = self.entries.iter().flat_map(Sig3::to_wire).collect();
        vec![sub.with_payload(data)]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        sub(resp, 0).map(|_| ())
    }
}
