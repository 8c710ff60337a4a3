//! cnc_acts2 / cnc_rdspload: 0xa4\[1\], 0x40[code, sp_no], 0xa4\[1\].

use super::read::{expect_subs, whole_records};
use crate::error::{Error, Result};
use crate::ew::{EW_NOOPT, EW_NUMBER};
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::{COUNT, SPINDLE};
use crate::proto::packet::{ReqSub, RespSub};
use crate::proto::value::Value;

/// A spindle-data frame bracketed by spindle counts.
#[derive(Debug, Clone, Copy)]
pub struct SpindleData {
    pub code: i32,
    pub sp_no: i16,
}

/// (spindle count from the first 0xa4, the records).
pub type SpindleReply = (u16, Vec<Value>);

impl Call for SpindleData {
    type Output = SpindleReply;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let data = ReqSub::cnc(SPINDLE, &[self.code, i32::from(self.sp_no)]);
        if cx.class.is_16i() {
            // 16i class: no 0xa4 spindle counts (recorded from FANUC's library).
            return vec![data];
        }
        vec![ReqSub::cnc(COUNT, &[1]), data, ReqSub::cnc(COUNT, &[1])]
    }
    /// 30i class, in FANUC's library's order: the first count's error, the
    /// last count's error; the first count must be readable (an empty or
    /// 1-byte payload: FANUC's library reads the next subpacket's header as
    /// the count; ours EW_PROTOCOL), the last one reads zeros where it ends;
    /// the count is the smaller of the two: 0 is EW_NOOPT, below sp_no
    /// EW_NUMBER, both before the data's own error; the data are the whole
    /// records.
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<SpindleReply> {
        if cx.class.is_16i() {
            return Ok((cx.max_spindles, whole_records(resp, 0)?));
        }
        expect_subs(resp, 3)?;
        let p = &sub(resp, 0)?.payload;
        let last = &sub(resp, 2)?.payload;
        let Some(n) = p.get(..2) else {
            return Err(Error::short("no spindle count"));
        };
        let first = u16::from_be_bytes([n[0], n[1]]);
        let mut b = [0u8; 2];
        for (d, s) in b.iter_mut().zip(last) {
            *d = *s;
        }
        let n = first.min(u16::from_be_bytes(b));
        if n == 0 {
            return Err(Error::local(EW_NOOPT, "the path has no spindle"));
        }
        if i32::from(self.sp_no) > i32::from(n) {
            return Err(Error::local(EW_NUMBER, "the CNC has fewer spindles"));
        }
        let v = whole_records(resp, 1)?;
        Ok((n, v))
    }
}
