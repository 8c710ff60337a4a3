//! Simple calls: cnc_getfigure.

use super::payload::Figures;
use super::read::{whole, zext};
use crate::error::Result;
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::GETFIGURE;
use crate::proto::packet::{ReqSub, RespSub};

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
