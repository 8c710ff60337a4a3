//! Machine data (issue 11): the program restart information
//! (cnc_rdprstrinfo). Learnt with the oracle (docs/protocol/machine.md).

use super::call::{Call, Ctx, sub};
pub use super::cmd::RDPRSTR;
use super::packet::{ReqSub, RespSub};
use crate::error::Result;

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
