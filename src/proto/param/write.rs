//! cnc_wrparam: the attributes read first, then the write.

use super::data::{Elem, Num, Param16, Param30, WRITE_RECORDS_30, value_of_num};
use super::info::{INFO_AXIS, InfoList, PARAMTYPE_LEN, ParamType30};
use crate::error::{Error, Result};
use crate::ew::EW_NUMBER;
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::{PARAMTYPE, RDPARAINFO, WRPARAM, WRPARAM16};
use crate::proto::open::CncClass;
use crate::proto::packet::{ReqSub, RespSub};
use crate::proto::value::Value;
use crate::proto::wire::Wire;

/// What cnc_wrparam learns before writing: the element kind and whether
/// the parameter is an axis parameter. `elem` is `None` for a 30i type
/// word other than 0..4: FANUC's library then checks no length and writes
/// the type word with every value slot zero [fuzz, wrparam `s0Tw`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WriteInfo {
    pub ptype: u16,
    pub elem: Option<Elem>,
    pub axis: bool,
}

/// First step of cnc_wrparam: read the parameter's attributes.
/// 30i: 0x00a0 [number, 1], exactly 28 bytes (another size is EW_NUMBER,
/// as FANUC's library answers); a type word 0..4 names the element kind,
/// any other is kept as it is (the write carries it, with zero values);
/// 16i: 0x0010 [number, 1], exactly one entry (else EW_NUMBER).
#[derive(Debug, Clone, Copy)]
pub struct ParamInfo {
    pub number: i32,
}

impl Call for ParamInfo {
    type Output = WriteInfo;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let cmd = match cx.class {
            CncClass::Series30 => PARAMTYPE,
            CncClass::Series16 { .. } => RDPARAINFO,
        };
        vec![ReqSub::cnc(cmd, &[self.number, 1])]
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<WriteInfo> {
        let s = sub(resp, 0)?;
        let bad = || Error::local(EW_NUMBER, "parameter attributes not understood");
        match cx.class {
            CncClass::Series30 => {
                if s.payload.len() != PARAMTYPE_LEN {
                    return Err(bad());
                }
                let t = ParamType30::from_bytes(&s.payload)?;
                let elem = Elem::of_param(t.ptype).filter(|_| t.ptype <= 4);
                Ok(WriteInfo {
                    ptype: t.ptype,
                    elem,
                    axis: t.axis == 2,
                })
            }
            CncClass::Series16 { .. } => {
                // Exactly one entry's answer (16 bytes): a longer one,
                // ragged or not, is EW_NUMBER [fuzz, cnc_wrset].
                if s.payload.len() != 16 {
                    return Err(bad());
                }
                let l = InfoList::from_bytes(&s.payload).map_err(|_| bad())?;
                // FANUC's library wants exactly the one entry asked for (a
                // longer answer is EW_NUMBER, nothing written).
                if l.entries.len() != 1 {
                    return Err(bad());
                }
                let e = &l.entries[0];
                let ptype = (e.ptype & 3) as u16;
                Ok(WriteInfo {
                    ptype,
                    elem: Some(Elem::of_param(ptype).ok_or_else(bad)?),
                    axis: e.ptype & INFO_AXIS != 0,
                })
            }
        }
    }
}

/// Second step of cnc_wrparam: the write itself.
#[derive(Debug, Clone)]
pub struct WriteParam {
    pub number: i32,
    pub axis: i16,
    pub ptype: u16,
    pub values: Vec<Num>,
}

impl WriteParam {
    /// The write payload of the class. A 16i-class payload has one value
    /// word per axis of `max_axes` (the CNC's maximum: 8 + 4 · max_axes
    /// bytes, as FANUC's library sends it).
    pub fn payload(&self, class: CncClass, max_axes: usize) -> Vec<u8> {
        let real = Elem::of_param(self.ptype) == Some(Elem::Real);
        match class {
            CncClass::Series30 => {
                let mut values: Vec<Value> =
                    self.values.iter().map(|n| value_of_num(*n, real)).collect();
                values.resize(WRITE_RECORDS_30, Value::default());
                Param30 {
                    number: self.number,
                    axis: self.axis,
                    ptype: self.ptype,
                    values,
                }
                .to_bytes()
            }
            CncClass::Series16 { .. } => {
                let mut values: Vec<i32> = if real {
                    self.values
                        .iter()
                        .flat_map(|n| [n.value, n.dec & 0xffff])
                        .collect()
                } else {
                    self.values.iter().map(|n| n.value).collect()
                };
                values.resize(max_axes, 0);
                Param16 {
                    number: self.number,
                    axis: self.axis,
                    ptype: self.ptype,
                    values,
                }
                .to_bytes()
            }
        }
    }
}

impl Call for WriteParam {
    type Output = ();
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let cmd = match cx.class {
            CncClass::Series30 => WRPARAM,
            CncClass::Series16 { .. } => WRPARAM16,
        };
        vec![ReqSub::cnc(cmd, &[]).with_payload(self.payload(cx.class, cx.axes()))]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        sub(resp, 0).map(|_| ())
    }
}
