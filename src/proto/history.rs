//! Records read by number range: the operation history (cnc_rdophistry),
//! the operator message histories (cnc_rdomhistry, cnc_rdomhistry2), alarm
//! history 5 (cnc_rdalmhistry5) and the pitch error table (cnc_rdpitchr).
//! Learnt with the oracle (src/proto/NOTES.md).
//!
//! Each answer is fixed-size records (cnc_rdomhistry2: after a 4-byte
//! count).

use super::call::{Call, Ctx, sub};
use super::packet::{ReqSub, RespSub, answer_records};
use crate::error::Result;

pub const RDOPHISTRY: u16 = 0x006a;
pub const RDOMHISTRY: u16 = 0x0073;
pub const RDOMHISTRY2: u16 = 0x01b5;
pub const RDALMHISTRY5: u16 = 0x01d1;
pub const RDPITCHR: u16 = 0x0012;

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
