//! Machine data (issue 11): the spindle control signals (cnc_rdctrldi,
//! cnc_rdctrldo). Learnt with the oracle (src/proto/NOTES.md).

use super::call::{Call, Ctx, sub};
use super::packet::{ReqSub, RespSub};
use crate::error::Result;

/// cnc_rdctrldi / cnc_rdctrldo: (1,0x005b)[0] input signals, [1] output.
pub const RDCTRLSIG: u16 = 0x005b;

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
