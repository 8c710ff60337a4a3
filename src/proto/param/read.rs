//! One parameter or diagnosis item read (the typed parameter block of
//! cnc_rdparam / cnc_diagnoss, src/proto/described/block.rs), and the
//! number range answer (cnc_rdparanum / cnc_rddiagnum's, the simulator's).

use super::data::{Elem, Num, Param16, Param30, num_of_value};
use crate::error::{Error, Result};
use crate::proto::call::{Call, Ctx, payload};
use crate::proto::cmd::{
    DIAGNOSS, DIAGNOSS16, RDDIAGINFO, RDDIAGINFO15, RDPARAINFO, RDPARAINFO15, RDPARAM, RDPARAM16,
};
use crate::proto::open::CncClass;
use crate::proto::packet::{ReqSub, RespSub};
use crate::wire_struct;

/// Parameter or diagnosis: the two read families differ only in command
/// words and type codes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Table {
    Param,
    Diag,
}

impl Table {
    pub fn read_cmd(self, class: CncClass) -> u16 {
        match (self, class) {
            // A Series 15 (kind 2) is asked with the 30i commands and
            // answers in the 16i value form.
            (Table::Param, CncClass::Series30 | CncClass::Series16 { kind: 2 }) => RDPARAM,
            (Table::Param, CncClass::Series16 { .. }) => RDPARAM16,
            (Table::Diag, CncClass::Series30 | CncClass::Series16 { kind: 2 }) => DIAGNOSS,
            (Table::Diag, CncClass::Series16 { .. }) => DIAGNOSS16,
        }
    }
    pub fn elem(self, t: u16) -> Option<Elem> {
        match self {
            Table::Param => Elem::of_param(t),
            Table::Diag => Elem::of_diag(t),
        }
    }
    /// The info-list command; a Series 15 (kind 2) has its own.
    pub fn info_cmd(self, class: CncClass) -> u16 {
        match (self, class) {
            (Table::Param, CncClass::Series16 { kind: 2 }) => RDPARAINFO15,
            (Table::Diag, CncClass::Series16 { kind: 2 }) => RDDIAGINFO15,
            (Table::Param, _) => RDPARAINFO,
            (Table::Diag, _) => RDDIAGINFO,
        }
    }
}

/// One parameter/diagnosis item as read: its number, the axis word of the
/// answer, its element kind and its values (one, or max-axes for axis -1).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Item {
    pub number: i32,
    pub axis: i16,
    /// The answer's type word.
    pub ptype: u16,
    /// None: a type code the library writes no value for.
    pub elem: Option<Elem>,
    pub values: Vec<Num>,
}

impl Item {
    /// Bytes of the C structure from offset 4 on (`length` already checked).
    pub fn data_bytes(&self) -> Vec<u8> {
        let Some(e) = self.elem else {
            return Vec::new();
        };
        let mut out = vec![0u8; e.size() * self.values.len()];
        for (i, v) in self.values.iter().enumerate() {
            e.put(&mut out[i * e.size()..], *v);
        }
        out
    }
}

/// cnc_rdparam / cnc_diagnoss: [number, number, axis] → one [`Item`].
#[derive(Debug, Clone, Copy)]
pub struct ReadOne {
    pub table: Table,
    pub number: i32,
    pub axis: i16,
    /// The request's fifth word: cnc_rdparam3 sends 0x10000 (a short 1 in
    /// its first half) for a `type` other than 0; every other reader 0.
    pub flag: i32,
}

/// How many values an answer block carries, by its axis word (FANUC's
/// library): a negative axis word (all axes) max-axes values, any other one
/// value — whatever axis was asked, so a non-axis parameter asked with
/// axis -1 and answered with axis word 0 is one value.
fn count_for(cx: &Ctx, axis_word: i16) -> usize {
    if axis_word < 0 { cx.axes() } else { 1 }
}

impl Call for ReadOne {
    type Output = Item;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let n = self.number;
        vec![ReqSub::cnc(
            self.table.read_cmd(cx.class),
            &[n, n, self.axis as i32, 0, self.flag],
        )]
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Item> {
        let short = || Error::short("parameter answer carries fewer values than the axis count");
        match cx.class {
            CncClass::Series30 => {
                let p: Param30 = payload(resp, 0)?;
                let count = count_for(cx, p.axis);
                let elem = self.table.elem(p.ptype);
                let real = elem == Some(Elem::Real);
                if p.values.len() < count {
                    return Err(short());
                }
                Ok(Item {
                    number: p.number,
                    axis: p.axis,
                    ptype: p.ptype,
                    elem,
                    values: p.values[..count]
                        .iter()
                        .map(|v| num_of_value(*v, real))
                        .collect(),
                })
            }
            CncClass::Series16 { .. } => {
                let p: Param16 = payload(resp, 0)?;
                let count = count_for(cx, p.axis);
                let elem = self.table.elem(p.ptype);
                // A 16i real takes two words: value, then decimals in the
                // low half of the second (SPEC.md §5.2).
                let values: Vec<Num> = if elem == Some(Elem::Real) {
                    p.values
                        .chunks_exact(2)
                        .map(|c| Num {
                            value: c[0],
                            dec: c[1] as i16 as i32,
                        })
                        .collect()
                } else {
                    p.values.iter().map(|v| Num::int(*v)).collect()
                };
                if values.len() < count {
                    return Err(short());
                }
                Ok(Item {
                    number: p.number,
                    axis: p.axis,
                    ptype: p.ptype,
                    elem,
                    values: values[..count].to_vec(),
                })
            }
        }
    }
}

wire_struct! {
    /// Payload of 0x0011 / 0x0032: three i32, of which the library keeps the low 16 bits.
    pub struct NumRange {
        pub min: i32,
        pub max: i32,
        pub total: i32,
    }
}
