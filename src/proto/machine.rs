//! Machine data (issue 11): the spindle control signals (cnc_rdctrldi,
//! cnc_rdctrldo). Learnt with the oracle (docs/protocol/machine.md).

use super::call::{Call, Ctx, sub};
pub use super::cmd::{RDCTRLSIG, RDPRSTR};
use super::packet::{ReqSub, RespSub};
use crate::error::Result;

/// cnc_rdctrldi (`output` false) / cnc_rdctrldo (true): the signal words
/// FANUC's library takes from the answer: one per two payload bytes, at
/// most the CNC's maximum spindles, each the big-endian i32 at 4 × its
/// index (bytes past the payload read as zeros).
pub struct CtrlSignals {
    pub output: bool,
}

impl Call for CtrlSignals {
    type Output = Vec<i32>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(RDCTRLSIG, &[i32::from(self.output)])]
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Vec<i32>> {
        let p = &sub(resp, 0)?.payload;
        let n = (p.len() / 2).min(usize::from(cx.max_spindles));
        Ok((0..n)
            .map(|i| {
                let b = |k: usize| p.get(4 * i + k).copied().unwrap_or(0);
                i32::from_be_bytes([b(0), b(1), b(2), b(3)])
            })
            .collect())
    }
}

/// The position codes of the restart position and distance.
pub const PRSTR_DEST: i32 = 13;
pub const PRSTR_DIST: i32 = 14;

/// cnc_rdprstrinfo's request.
pub struct PrstrInfo;

/// What FANUC's library takes from the answer, subpacket by subpacket:
/// the i32 words of each 0x0043 answer (payload length / 4), and the
/// values of the two position answers (payload length / 8 records, at most
/// the path's maximum axes, the i32 at the start of each 8 bytes), up to
/// the first subpacket answered by an error (then `error`).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct PrstrAnswer {
    pub words: Vec<Vec<i32>>,
    pub positions: Vec<Vec<i32>>,
    pub error: Option<crate::error::Error>,
}

impl Call for PrstrInfo {
    type Output = PrstrAnswer;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        let mut v: Vec<ReqSub> = (0..5).map(|k| ReqSub::cnc(RDPRSTR, &[k])).collect();
        for code in [PRSTR_DEST, PRSTR_DIST] {
            v.push(ReqSub::cnc(super::position::POSITION, &[code, -1]));
        }
        v
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<PrstrAnswer> {
        let mut a = PrstrAnswer::default();
        for i in 0..7 {
            let p = match sub(resp, i) {
                Ok(s) => &s.payload,
                Err(e) => {
                    a.error = Some(e);
                    break;
                }
            };
            let be = |at: usize| i32::from_be_bytes([p[at], p[at + 1], p[at + 2], p[at + 3]]);
            if i < 5 {
                a.words.push((0..p.len() / 4).map(|k| be(4 * k)).collect());
            } else {
                let n = (p.len() / 8).min(usize::from(cx.max_axes));
                a.positions.push((0..n).map(|k| be(8 * k)).collect());
            }
        }
        Ok(a)
    }
}
