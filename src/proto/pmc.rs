//! PMC areas (SPEC.md §5.3): ranges of PMC addresses read and written as
//! raw big-endian bytes, class 2 subpackets.

use super::call::{Call, Ctx, payload, sub};
pub use super::cmd::{
    GET_TIMER_TYPE, PMC_RDALMMSG, RDPMCINFO, RDPMCRNG, RDPMCTITLE, SELECT_UNIT, SET_TIMER_TYPE,
    UNIT_TYPES, WRPMCRNG,
};
use super::packet::{ReqSub, RespSub};
use crate::error::Result;
use crate::wire_struct;

/// PMC data types (IODBPMC `type_d`).
pub mod dtype {
    pub const BYTE: i16 = 0;
    pub const WORD: i16 = 1;
    pub const LONG: i16 = 2;
    pub const FLOAT: i16 = 4;
    pub const DOUBLE: i16 = 5;
}

/// Bytes per element of a data type; `None` for types we do not know.
pub fn elem_size(data_type: i16) -> Option<usize> {
    match data_type {
        dtype::BYTE => Some(1),
        dtype::WORD => Some(2),
        dtype::LONG | dtype::FLOAT => Some(4),
        dtype::DOUBLE => Some(8),
        _ => None,
    }
}

/// Converts between the wire (big-endian) and the C buffer (little-endian)
/// element by element; its own inverse, so reads and writes share it. A
/// ragged tail shorter than an element is left as it is.
pub fn swap_elements(data_type: i16, bytes: &mut [u8]) {
    let n = elem_size(data_type).unwrap_or(1);
    for c in bytes.chunks_exact_mut(n) {
        c.reverse();
    }
}

/// A PMC range: address type, data type and first/last byte address.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct PmcRange {
    pub adr_type: i16,
    pub data_type: i16,
    pub s: u16,
    pub e: u16,
}

impl PmcRange {
    /// The args words shared by read and write requests.
    fn args(&self) -> [i32; 4] {
        [
            i32::from(self.s),
            i32::from(self.e),
            i32::from(self.adr_type),
            i32::from(self.data_type),
        ]
    }

    /// The range a request's args name (the simulator's side).
    pub fn from_args(a: &[i32; 5]) -> PmcRange {
        PmcRange {
            s: a[0] as u16,
            e: a[1] as u16,
            adr_type: a[2] as i16,
            data_type: a[3] as i16,
        }
    }

    /// Bytes the range spans (addresses are byte addresses); 0 when e < s.
    pub fn span(&self) -> usize {
        (usize::from(self.e) + 1).saturating_sub(usize::from(self.s))
    }
}

/// pmc_rdpmcrng: the range's bytes as the CNC sent them (big-endian).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReadPmc(pub PmcRange);

impl Call for ReadPmc {
    type Output = Vec<u8>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::pmc(RDPMCRNG, &self.0.args())]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Vec<u8>> {
        payload(resp, 0)
    }
}

/// pmc_wrpmcrng: the range's bytes, big-endian. The request payload is
/// exactly what [`ReadPmc`] returns for the same range.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WritePmc {
    pub range: PmcRange,
    pub data: Vec<u8>,
}

impl Call for WritePmc {
    type Output = ();
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::pmc(WRPMCRNG, &self.range.args()).with_payload(self.data.clone())]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        sub(resp, 0).map(|_| ())
    }
}

/// Records ODBPMCINF holds.
pub const PMCINFO_MAX: usize = 64;

wire_struct! {
    /// One area of the 0x8003 reply (only the low byte of `adr` / `attr`
    /// and the low 16 bits of `top` / `last` reach ODBPMCINF).
    pub struct PmcAreaInfo {
        pub adr: u16,
        pub attr: u16,
        pub top: i32,
        pub last: i32,
    }
}

/// Payload of 0x8003. The count word is kept as sent; the decoder takes
/// no more records than are present (FANUC's library trusts the count
/// and read past its buffer).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct PmcInfo {
    pub count: i32,
    pub areas: Vec<PmcAreaInfo>,
}

impl super::wire::Wire for PmcInfo {
    fn encode(&self, w: &mut super::wire::Writer) {
        w.i32(self.count);
        self.areas.encode(w);
    }
    fn decode(r: &mut super::wire::Reader<'_>) -> Result<Self, super::wire::DecodeError> {
        let count = r.i32()?;
        // FANUC's library counts with the word's low 16 bits (ODBPMCINF's
        // short `datano`) [fuzz, pmc_rdpmcinfo `s0Twwwwwmore`].
        let n = ((count as i16).max(0) as usize).min(r.remaining() / 12);
        let mut areas = Vec::with_capacity(n);
        for _ in 0..n {
            areas.push(PmcAreaInfo::decode(r)?);
        }
        Ok(PmcInfo { count, areas })
    }
}

pub fn rdpmcinfo(adr_type: i16) -> super::call::Single<PmcInfo> {
    super::call::Single::new(ReqSub::pmc(RDPMCINFO, &[i32::from(adr_type)]))
}

// ---------------------------------------------------------------------------
// PMC units (pmc_get_number_of_pmc is described in src/spec/table/)
// ---------------------------------------------------------------------------

/// pmc_get_pmc_unit_types: up to `most` unit types, as many whole i32 as
/// the answer holds.
#[derive(Debug, Clone, Copy)]
pub struct UnitTypes {
    pub most: i32,
}

impl Call for UnitTypes {
    type Output = Vec<i32>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::pmc(UNIT_TYPES, &[self.most])]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Vec<i32>> {
        Ok(sub(resp, 0)?
            .payload
            .chunks_exact(4)
            .map(|c| i32::from_be_bytes([c[0], c[1], c[2], c[3]]))
            .collect())
    }
}

/// pmc_select_pmc_unit: the CNC's answer is its error code alone.
#[derive(Debug, Clone, Copy)]
pub struct SelectUnit {
    pub unit: i32,
}

impl Call for SelectUnit {
    type Output = ();
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::pmc(SELECT_UNIT, &[self.unit])]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        sub(resp, 0).map(|_| ())
    }
}

/// Bytes of one pmc_rdalmmsg message (ODBPMCALM).
pub const ALMMSG_LEN: usize = 128;
/// Most messages FANUC's library asks for in one 0x8010 request.
pub const ALMMSG_MAX: i32 = 11;

/// pmc_rdalmmsg: one exchange, messages `s`.. (at most `n`).
#[derive(Debug, Clone, Copy)]
pub struct AlarmMsgs {
    pub s: i32,
    pub n: i32,
}

/// One 0x8010 answer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AlarmMsgAnswer {
    /// The answer's count word, as sent.
    pub count: i32,
    /// -1 no alarm, 0 all read, else more exist.
    pub exist: i32,
    /// The messages: min(count, n) records of 128 bytes (a short answer's
    /// missing bytes read as zeros, as FANUC's library reads them).
    pub text: Vec<u8>,
}

impl AlarmMsgAnswer {
    /// The messages the answer holds.
    pub fn records(&self) -> usize {
        self.text.len() / ALMMSG_LEN
    }
}

impl Call for AlarmMsgs {
    type Output = AlarmMsgAnswer;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::pmc(PMC_RDALMMSG, &[self.s, self.n])]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<AlarmMsgAnswer> {
        let mut p = sub(resp, 0)?.payload.clone();
        if p.len() < 8 {
            p.resize(8, 0);
        }
        let word = |i: usize| i32::from_be_bytes([p[i], p[i + 1], p[i + 2], p[i + 3]]);
        let (count, exist) = (word(0), word(4));
        let n = count.clamp(0, self.n.max(0)) as usize;
        let mut text = p[8..].to_vec();
        text.resize(n * ALMMSG_LEN, 0);
        Ok(AlarmMsgAnswer { count, exist, text })
    }
}
