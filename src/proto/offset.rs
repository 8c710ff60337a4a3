//! Tool and work offsets (SPEC.md §5.3 for cnc_rdtofs / cnc_rdzofs). The
//! other functions' requests, local checks and the payload bytes FANUC's
//! library reads were recorded by running FANUC's library against the fake
//! CNC (/tmp/orc/fake.py); what a real CNC answers (the decimals it sends,
//! the 0x000a/0x000d words) is not verified.
//!
//! Every value travels as the 30i 8-byte value record ([`Value`]). Reads
//! answer records with base 10 and the decimals of the offset; writes send
//! base 0 and decimals -1 (FANUC's library: "integer, no decimals").

use super::call::{Call, Ctx, Single, records};
pub use super::cmd::{RDTOFS, RDZOFS, WRTOFS, WRWKCDSHFT, WRZOFS};
use super::packet::{ReqSub, RespSub};
use super::value::Value;
use super::wire::{DecodeError, Reader, Wire, Writer};
use crate::wire_struct;

/// cnc_rdtofs adds this to the type word (cnc_rdtofsr sends the type as is).
pub const TOFS_SINGLE: i32 = 1000;

/// The record a write sends: FANUC's library marks it base 0, decimals -1.
pub const fn write_record(value: i32) -> Value {
    Value {
        value,
        base: 0,
        exp: -1,
    }
}

/// Offset values: whole 8-byte records filling the payload.
pub type Values = Vec<Value>;

/// cnc_rdtofs: the first whole record; bytes after it are ignored, as
/// FANUC's library ignores them.
pub fn rdtofs(number: i16, kind: i16) -> Single<WholeValues> {
    let n = i32::from(number);
    Single::new(ReqSub::cnc(RDTOFS, &[n, n, TOFS_SINGLE + i32::from(kind)]))
}

/// The whole 8-byte value records of an answer; a partial record after
/// them is ignored (cnc_rdtofsr: FANUC's library reads whole records only).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct WholeValues(pub Values);

impl Wire for WholeValues {
    fn encode(&self, w: &mut Writer) {
        self.0.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let n = r.remaining() / 8;
        let mut whole = Reader::new(r.bytes(n * 8)?);
        let v = Values::decode(&mut whole)?;
        r.bytes(r.remaining())?;
        Ok(WholeValues(v))
    }
}

pub fn rdtofsr(s: i16, kind: i16, e: i16) -> Single<WholeValues> {
    Single::new(ReqSub::cnc(
        RDTOFS,
        &[i32::from(s), i32::from(e), i32::from(kind)],
    ))
}

/// An empty answer (the write's acknowledgement).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Ack;

impl Wire for Ack {
    fn encode(&self, _: &mut Writer) {}
    fn decode(_: &mut Reader<'_>) -> Result<Self, DecodeError> {
        Ok(Ack)
    }
}

pub fn wrtofs(number: i16, kind: i16, value: i32) -> Single<Ack> {
    let n = i32::from(number);
    Single::new(
        ReqSub::cnc(WRTOFS, &[n, n, TOFS_SINGLE + i32::from(kind)])
            .with_payload(write_record(value).to_bytes()),
    )
}

wire_struct! {
    /// Payload of 0x000a (cnc_rdtofsinfo, cnc_rdtofsinfo2). FANUC's library
    /// reads `use_no` from bytes 2..4, `ofs_type` from bytes 4..6 and
    /// (cnc_rdtofsinfo2) `ofs_enable` from bytes 6..8; what a real CNC puts
    /// in bytes 0..2 is unknown (not recorded from a real CNC).
    pub struct TofsInfo {
        pub reserved: i16,
        pub use_no: i16,
        pub ofs_type: i16,
        pub enable: i16,
    }
}

/// cnc_rdzofs: the whole records; a partial record after them is ignored,
/// as FANUC's library ignores it (it reads the records it needs).
pub fn rdzofs(number: i16, axis: i16) -> Single<WholeValues> {
    let n = i32::from(number);
    Single::new(ReqSub::cnc(RDZOFS, &[n, n, i32::from(axis)]))
}

/// Most value records one cnc_rdzofsr request asks for: FANUC's library
/// asks for 179 / (records per number) numbers at a time (5 numbers of 32
/// axes, 179 of one axis; 25 of 7 axes with max_axes 7).
pub const RDZOFSR_RECORDS: usize = 179;

/// One cnc_rdzofsr request: `(1,0x000b)[s, e, axis]`. The answer is its
/// whole value records (a ragged tail is ignored, as FANUC's library
/// ignores it); how many numbers they make is the caller's business.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReadZofsRange {
    pub s: i32,
    pub e: i32,
    pub axis: i16,
}

impl Call for ReadZofsRange {
    type Output = Values;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(RDZOFS, &[self.s, self.e, i32::from(self.axis)])]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> crate::error::Result<Values> {
        records(resp, 0)
    }
}

/// cnc_wrwkcdshft: 0x0064 \[axis\] with one record (axis ≥ 0) or one per
/// axis (axis -1).
pub fn wrwkcdshft(axis: i16, values: &[i32]) -> Single<Ack> {
    let records: Values = values.iter().map(|v| write_record(*v)).collect();
    Single::new(ReqSub::cnc(WRWKCDSHFT, &[i32::from(axis)]).with_payload(records.to_bytes()))
}

/// cnc_wrzofs: one record (axis ≥ 0) or one per axis (axis -1).
pub fn wrzofs(number: i16, axis: i16, values: &[i32]) -> Single<Ack> {
    let n = i32::from(number);
    let records: Values = values.iter().map(|v| write_record(*v)).collect();
    Single::new(ReqSub::cnc(WRZOFS, &[n, n, i32::from(axis)]).with_payload(records.to_bytes()))
}

wire_struct! {
    /// Payload of 0x000d (cnc_rdzofsinfo) and 0x006b (cnc_rdalmhisno): one
    /// i32 of which FANUC's library keeps the low 16 bits.
    pub struct Count {
        pub value: i32,
    }
}
