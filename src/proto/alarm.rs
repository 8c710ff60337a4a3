//! Alarms, alarm messages, operator messages and the alarm history.

use super::call::Single;
pub use super::cmd::{RDALMHISNO, RDALMHISTRY, RDALMMSG, RDOPMSG, RDOPMSG3};
use super::packet::{ReqSub, answer_records};
use super::wire::{DecodeError, Reader, Wire, Writer};
use crate::wire_struct;

// --- alarm ---

/// One 0x0023 record: i32 number, type, axis, message length, then an
/// N-byte message (N = the request's arg 4: 32 or 64).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AlmMsg<const N: usize> {
    pub alm_no: i32,
    pub kind: i32,
    pub axis: i32,
    pub msg_len: i32,
    pub msg: [u8; N],
}

impl<const N: usize> Default for AlmMsg<N> {
    fn default() -> Self {
        AlmMsg {
            alm_no: 0,
            kind: 0,
            axis: 0,
            msg_len: 0,
            msg: [0; N],
        }
    }
}

impl<const N: usize> Wire for AlmMsg<N> {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.alm_no);
        w.i32(self.kind);
        w.i32(self.axis);
        w.i32(self.msg_len);
        w.bytes(&self.msg);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        Ok(AlmMsg {
            alm_no: r.i32()?,
            kind: r.i32()?,
            axis: r.i32()?,
            msg_len: r.i32()?,
            msg: r.array()?,
        })
    }
}

impl<const N: usize> AlmMsg<N> {
    /// A record with `text` (truncated to N bytes, zero-padded).
    pub fn new(alm_no: i32, kind: i32, axis: i32, text: &str) -> Self {
        let mut msg = [0u8; N];
        let b = text.as_bytes();
        let n = b.len().min(N);
        msg[..n].copy_from_slice(&b[..n]);
        AlmMsg {
            alm_no,
            kind,
            axis,
            msg_len: n as i32,
            msg,
        }
    }
}

/// Payload of 0x0034 (cnc_rdopmsg): number, type, character count, text.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct OpMsg {
    pub datano: i32,
    pub kind: i32,
    pub char_num: i32,
    pub text: Vec<u8>,
}

impl Wire for OpMsg {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.datano);
        w.i32(self.kind);
        w.i32(self.char_num);
        w.bytes(&self.text);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let (datano, kind, char_num) = (r.i32()?, r.i32()?, r.i32()?);
        let text = r.rest().to_vec();
        r.bytes(text.len())?;
        Ok(OpMsg {
            datano,
            kind,
            char_num,
            text,
        })
    }
}

/// Payload of 0x0023: whole records of 16 + N bytes; a ragged tail is
/// ignored, as FANUC's library ignores it.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct AlmMsgs<const N: usize>(pub Vec<AlmMsg<N>>);

impl<const N: usize> Wire for AlmMsgs<N> {
    fn encode(&self, w: &mut Writer) {
        self.0.encode(w)
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let n = r.remaining() / (16 + N);
        (0..n)
            .map(|_| AlmMsg::decode(r))
            .collect::<Result<_, _>>()
            .map(AlmMsgs)
    }
}

/// cnc_rdalmmsg (N = 32) / cnc_rdalmmsg2 (N = 64): (1,0x23)[type, num, 2,
/// N], num cut to the records that fit in one answer.
pub fn rdalmmsg<const N: usize>(kind: i16, num: i16) -> Single<AlmMsgs<N>> {
    Single::new(ReqSub::cnc(
        RDALMMSG,
        &[
            i32::from(kind),
            answer_records(i32::from(num), 16 + N),
            2,
            N as i32,
        ],
    ))
}

/// cnc_rdalminfo: (1,0x23)[alm_type, n, type, 32], 48-byte records, n cut
/// to the records that fit in one answer.
pub fn rdalminfo(kind: i16, alm_type: i16, n: i32) -> Single<AlmMsgs<32>> {
    Single::new(ReqSub::cnc(
        RDALMMSG,
        &[
            i32::from(alm_type),
            answer_records(n, 48),
            i32::from(kind),
            32,
        ],
    ))
}

/// (1,0x34)\[type\]; a short answer reads as zeros (FANUC's library).
pub fn rdopmsg(kind: i16) -> Single<OpMsg> {
    Single::padded(ReqSub::cnc(RDOPMSG, &[i32::from(kind)]))
}

// --- alarm history ---

/// Characters of a history record's message.
pub const HIS_MSG_LEN: usize = 32;

wire_struct! {
    /// One 60-byte alarm history record (SPEC.md §5.2).
    pub struct AlmHisRecord {
        pub alm_no: i32,
        /// Not used by FANUC's library; 0 from our simulator.
        pub reserved: i16,
        pub alm_grp: i16,
        pub axis: i32,
        pub year: u16,
        pub month: u16,
        pub day: u16,
        pub hour: u16,
        pub minute: u16,
        pub second: u16,
        pub msg_len: i32,
        pub msg: [u8; HIS_MSG_LEN],
    }
}

impl AlmHisRecord {
    /// A possible time stamp: month 1..12, day 1..31, hour 0..23,
    /// minute and second 0..59.
    pub fn time_ok(&self) -> bool {
        (1..=12).contains(&self.month)
            && (1..=31).contains(&self.day)
            && self.hour <= 23
            && self.minute <= 59
            && self.second <= 59
    }

    /// The message length stays inside the record's text field.
    pub fn msg_ok(&self) -> bool {
        (0..=HIS_MSG_LEN as i32).contains(&self.msg_len)
    }

    /// ODBAHIS year: the year mod 100, as FANUC's library writes it.
    pub fn year_his(&self) -> i8 {
        (self.year % 100) as i8
    }

    /// ODBAHIS2 year: FANUC's library writes the low byte sign-extended
    /// (2024 → -24); reproduced.
    pub fn year_his2(&self) -> i16 {
        i16::from(self.year as u8 as i8)
    }
}

/// Payload of 0x006c: whole 60-byte records. A ragged tail (part of a
/// record) is ignored, as FANUC's library ignores it.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct AlmHistory(pub Vec<AlmHisRecord>);

impl Wire for AlmHistory {
    fn encode(&self, w: &mut Writer) {
        Wire::encode(&self.0, w)
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let mut v = Vec::new();
        while r.remaining() >= 60 {
            v.push(<AlmHisRecord as Wire>::decode(r)?);
        }
        Ok(AlmHistory(v))
    }
}

impl AlmHistory {
    /// The entries our library hands to the caller: an entry with an
    /// impossible time stamp is skipped and the rest kept; an entry whose
    /// message length runs past its text field ends the list there (the
    /// entry and everything after it are dropped).
    pub fn valid(&self) -> Vec<AlmHisRecord> {
        let mut out = Vec::new();
        for r in &self.0 {
            if !r.msg_ok() {
                break;
            }
            if r.time_ok() {
                out.push(*r);
            }
        }
        out
    }
}

/// (1,0x6c)[s, e, 1], `e` cut to the entries that fit in one answer (23
/// from `s` on), as FANUC's library asks.
pub fn rdalmhistry(s: u16, e: u16) -> Single<AlmHistory> {
    let (s, e) = (i32::from(s), i32::from(e));
    let e = s + answer_records(e - s + 1, 60) - 1;
    Single::new(ReqSub::cnc(RDALMHISTRY, &[s, e, 1]))
}

/// Bytes of one cnc_rdopmsg3 record: i32 number, type, characters, then
/// 256 text bytes.
pub const OPMSG3_REC: usize = 268;
/// Messages one 0x00d0 exchange asks for.
pub const OPMSG3_CHUNK: i32 = 5;

/// cnc_rdopmsg3: on the 30i class (1,0x00d0)[start, type, n] (n at most
/// 5), on the 16i class (1,0x0034)\[type\]; the answer whole 268-byte
/// records.
pub fn rdopmsg3(class30: bool, start: i32, kind: i16, n: i32) -> crate::proto::history::Records {
    let sub = if class30 {
        ReqSub::cnc(RDOPMSG3, &[start, i32::from(kind), n])
    } else {
        ReqSub::cnc(RDOPMSG, &[i32::from(kind)])
    };
    crate::proto::history::Records {
        sub,
        skip: 0,
        size: OPMSG3_REC,
    }
}
