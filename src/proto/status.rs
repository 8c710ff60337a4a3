//! Connection-group and status structures: sysinfo, statinfo, statinfo2, CNC id.

use super::call::{Call, Ctx, Single, payload, sub};
use super::cmd;
use super::packet::{ReqSub, RespSub};
use super::wire::{DecodeError, Reader, Wire, Writer};
use crate::error::Result;
use crate::wire_struct;

wire_struct! {
    /// Payload of 0x0018 (cnc_sysinfo), 18 bytes.
    pub struct SysInfo {
        pub addinfo: u16,
        pub max_axis: u16,
        pub cnc_type: [u8; 2],
        pub mt_type: [u8; 2],
        pub series: [u8; 4],
        pub version: [u8; 4],
        pub axes: [u8; 2],
    }
}

wire_struct! {
    /// Payload of 0x0019: the seven status words of cnc_statinfo.
    pub struct Status {
        pub aut: i16,
        pub run: i16,
        pub motion: i16,
        pub mstb: i16,
        pub emergency: i16,
        pub alarm: i16,
        pub edit: i16,
    }
}

wire_struct! {
    /// Payload of 0x00e2: the eleven status words of cnc_statinfo2.
    pub struct Status2 {
        pub aut: i16,
        pub run: i16,
        pub motion: i16,
        pub mstb: i16,
        pub emergency: i16,
        pub alarm: i16,
        pub edit: i16,
        pub warning: i16,
        pub o3dchk: i16,
        pub ext_opt: i16,
        pub restart: i16,
    }
}

impl From<Status2> for Status {
    /// The seven words both status forms share.
    fn from(s: Status2) -> Status {
        Status {
            aut: s.aut,
            run: s.run,
            motion: s.motion,
            mstb: s.mstb,
            emergency: s.emergency,
            alarm: s.alarm,
            edit: s.edit,
        }
    }
}

wire_struct! {
    /// Payload of 0x00e1 (handle retrace) and 0x0098 (T/M mode): one word used.
    pub struct Word {
        pub value: i16,
    }
}

/// Payload of 0x00e8 (cnc_rdcncid): up to four 32-bit words.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct CncId(pub Vec<u32>);

impl Wire for CncId {
    fn encode(&self, w: &mut Writer) {
        self.0.iter().for_each(|x| w.u32(*x));
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        if r.remaining() % 4 != 0 || r.remaining() > 16 {
            return Err(DecodeError::Invalid("CNC id payload is not 1 to 4 words"));
        }
        Ok(CncId(Vec::<u32>::decode(r)?))
    }
}

/// cnc_statinfo / cnc_statinfo2: the main status subpacket plus handle
/// retrace (0xe1) and T/M mode (0x98). Only the first subpacket's error
/// counts; a CNC without the other two answers them with an error and
/// they read as 0.
#[derive(Debug, Clone, Copy)]
pub struct StatInfo<T>(std::marker::PhantomData<T>);

pub trait StatusWords: Wire {
    const CMD: u16;
}
impl StatusWords for Status {
    const CMD: u16 = cmd::STATINFO;
}
impl StatusWords for Status2 {
    const CMD: u16 = cmd::STATINFO2;
}

impl<T> StatInfo<T> {
    pub const fn new() -> Self {
        StatInfo(std::marker::PhantomData)
    }
}

impl<T> Default for StatInfo<T> {
    fn default() -> Self {
        Self::new()
    }
}

/// Decoded statinfo: (hdck, tmmode, status words).
pub type StatReply<T> = (i16, i16, T);

impl<T: StatusWords> Call for StatInfo<T> {
    type Output = StatReply<T>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![
            ReqSub::cnc(T::CMD, &[]),
            ReqSub::cnc(cmd::HDCK, &[]),
            ReqSub::cnc(cmd::TMMODE, &[]),
        ]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Self::Output> {
        let words: T = payload(resp, 0)?;
        let optional = |i| {
            sub(resp, i)
                .ok()
                .and_then(|s| Word::from_bytes(&s.payload).ok())
                .map_or(0, |w| w.value)
        };
        Ok((optional(1), optional(2), words))
    }
}

pub fn sysinfo_at_connect(paths: &[u16]) -> Vec<ReqSub> {
    paths
        .iter()
        .map(|p| {
            let mut s = ReqSub::cnc(cmd::SYSINFO, &[]);
            s.path = *p;
            s
        })
        .collect()
}

pub fn rdcncid() -> Single<CncId> {
    Single::new(ReqSub::cnc(cmd::RDCNCID, &[]))
}
