//! Simple calls: cnc_absolute & co. (0x26 per axis) and cnc_getfigure.

use super::payload::Figures;
use super::read::{whole, whole_records, zext};
use crate::error::Result;
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::{GETFIGURE, POSITION};
use crate::proto::packet::{ReqSub, RespSub};
use crate::proto::value::Value;

/// cnc_absolute & co.: 0x26[code, axis], value records.
#[derive(Debug, Clone, Copy)]
pub struct AxisPositions {
    pub code: i32,
    pub axis: i16,
}

impl Call for AxisPositions {
    type Output = Vec<Value>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(POSITION, &[self.code, i32::from(self.axis)])]
    }
    /// Every whole record (none from an empty or short payload): the
    /// function checks the count against `length`.
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Vec<Value>> {
        whole_records(resp, 0)
    }
}

pub fn position(code: i32, axis: i16) -> AxisPositions {
    AxisPositions { code, axis }
}

/// cnc_getfigure: FANUC's library sends type 3 as 5, others as given.
#[derive(Debug, Clone, Copy)]
pub struct GetFigure {
    pub data_type: i16,
}

impl Call for GetFigure {
    type Output = Figures;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        let t = match self.data_type {
            3 => 5,
            t => i32::from(t),
        };
        vec![ReqSub::cnc(GETFIGURE, &[t])]
    }
    /// The count zero-extended, then every whole 4-byte figure entry.
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Figures> {
        let p = &sub(resp, 0)?.payload;
        Ok(Figures {
            count: i32::from_be_bytes(zext(p)),
            axes: whole(p.get(4..).unwrap_or(&[]), 4)?,
        })
    }
}

pub fn getfigure(data_type: i16) -> GetFigure {
    GetFigure { data_type }
}
