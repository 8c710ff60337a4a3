//! Connection-group and status structures: sysinfo, statinfo, statinfo2, CNC id.

use super::call::{Call, Ctx, sub};
use super::cmd;
use super::packet::{ReqSub, RespSub};
use super::wire::Wire;
use crate::error::{Error, Result};
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

/// cnc_statinfo / cnc_statinfo2: the main status subpacket plus handle
/// retrace (0xe1) and T/M mode (0x98), read as FANUC's library reads them:
/// hdck and tmmode come first (0 from a subpacket answering an error); the
/// main subpacket's error is the call's, else its whole words are the
/// status words (fewer when the answer is short). An answer without all
/// three subpackets: hdck and tmmode 0, the status EW_PROTOCOL.
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

/// Decoded statinfo: hdck, tmmode, and the main subpacket's whole words or
/// its error.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StatReply {
    pub hdck: i16,
    pub tmmode: i16,
    pub words: Result<StatWords>,
}

/// The status words of an answer, at most [`StatWords::MAX`] (the most
/// any form has: ODBST2's 11), kept without allocating: cnc_statinfo is
/// the call pollers make most.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct StatWords {
    w: [i16; StatWords::MAX],
    n: usize,
}

impl StatWords {
    pub const MAX: usize = 11;
}

impl std::ops::Deref for StatWords {
    type Target = [i16];
    fn deref(&self) -> &[i16] {
        &self.w[..self.n]
    }
}

fn words(p: &[u8]) -> StatWords {
    let mut s = StatWords::default();
    for (w, b) in s.w.iter_mut().zip(p.chunks_exact(2)) {
        *w = i16::from_be_bytes([b[0], b[1]]);
        s.n += 1;
    }
    s
}

impl<T: StatusWords> Call for StatInfo<T> {
    type Output = StatReply;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let mut v = Vec::new();
        self.request_into(cx, &mut v);
        v
    }
    fn request_into(&self, _: &Ctx, out: &mut Vec<ReqSub>) {
        out.extend([T::CMD, cmd::HDCK, cmd::TMMODE].map(|c| ReqSub::cnc(c, &[])));
    }
    /// An hdck or tmmode subpacket answering without error but without its
    /// word (FANUC's library then reads the bytes after it: the next
    /// subpacket's, or its own request's) is EW_PROTOCOL — or the main
    /// subpacket's error — with nothing written.
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<StatReply> {
        if resp.len() < 3 {
            return Ok(StatReply {
                hdck: 0,
                tmmode: 0,
                words: sub(resp, 2).map(|_| StatWords::default()),
            });
        }
        let word = |i| match sub(resp, i) {
            Err(_) => Some(0),
            Ok(s) => Word::from_bytes(&s.payload).ok().map(|w| w.value),
        };
        let (Some(hdck), Some(tmmode)) = (word(1), word(2)) else {
            sub(resp, 0)?;
            return Err(Error::short(
                "statinfo: handle-retrace or T/M mode answer without its word",
            ));
        };
        Ok(StatReply {
            hdck,
            tmmode,
            words: sub(resp, 0).map(|s| words(&s.payload)),
        })
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
