//! cnc_rdparar and cnc_wrparas move parameters in one packed C format
//! ([`Packed`]): per parameter i16 number, i16 type word
//! `(type << 8) | (axis & 0xff)`, then one value (or max-axes values for
//! axis -1) of the type's size (bit/byte 1, word 2, 2-word 4, real 8 =
//! value + decimals), each record padded to a multiple of 4 (padding bytes
//! are never written). On the wire (oracle) both use blocks of the CNC's
//! max axes: on the 30i class and a Series 15 the 8-byte record block of
//! cnc_rdparam (0x008d / 0x008e, 8 + 8 · max-axes bytes), on the 16i class
//! the word block (0x000e / 0x000f, 8 + 4 · max-axes bytes; a real takes
//! two words).

use super::data::{Elem, Num, Param16, Param30, num_of_value, value_of_num};
use crate::error::{Error, Result};
use crate::ew::EW_LENGTH;
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::{RDPARAM, RDPARAM16, WRPARAM, WRPARAM16};
use crate::proto::open::CncClass;
use crate::proto::packet::{ReqSub, RespSub};
use crate::proto::value::{BASE_10, Value};
use crate::proto::wire::Wire;

/// How many [`Packed`] write blocks of `block` bytes cnc_wrparas puts in
/// one frame (oracle: 5 of 264 bytes, 19 of 72, 10 of 136, 118 of 12).
pub fn wrparas_per_frame(block: usize) -> usize {
    (1416 / block.max(1)).max(1)
}

/// One parameter of the packed cnc_rdparar / cnc_wrparas buffer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Packed {
    pub number: i16,
    /// Axis byte of the type word as a signed value (-1 all axes, 0, 1..).
    pub axis: i8,
    /// Type (high byte of the type word): 0 bit, 1 byte, 2 word, 3 2-word, 4 real.
    pub ptype: u8,
    /// One value, or `axes` values when `axis` is -1.
    pub values: Vec<Num>,
}

impl Packed {
    /// Values a record with this axis byte carries.
    pub fn count(axis: i8, axes: usize) -> usize {
        if axis < 0 { axes } else { 1 }
    }
    fn elem(ptype: u8) -> Option<Elem> {
        Elem::of_param(ptype as u16).filter(|_| ptype <= 4)
    }
    /// Bytes the record takes in the buffer, padding included.
    pub fn padded_len(&self) -> usize {
        (self.to_c().len() + 3) & !3
    }
    /// The record's bytes without the padding (a type we do not know
    /// carries no value).
    pub fn to_c(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(4 + 8 * self.values.len());
        out.extend_from_slice(&self.number.to_le_bytes());
        out.push(self.axis as u8);
        out.push(self.ptype);
        if let Some(e) = Self::elem(self.ptype) {
            for v in &self.values {
                let at = out.len();
                out.resize(at + e.size(), 0);
                e.put(&mut out[at..], *v);
            }
        }
        out
    }
    /// Reads one record from the start of `inp` (what `to_c` wrote) and
    /// returns it with the bytes it takes, padding included (the padding
    /// of the last record may be missing). A type other than 0..4 is a
    /// record of its 4 header bytes, without values (as FANUC's library
    /// reads it). EW_LENGTH if the record does not fit in `inp`.
    pub fn from_c(inp: &[u8], axes: usize) -> Result<(Packed, usize)> {
        if inp.len() < 4 {
            return Err(Error::local(EW_LENGTH, "a record does not fit in length"));
        }
        let number = i16::from_le_bytes([inp[0], inp[1]]);
        let axis = inp[2] as i8;
        let ptype = inp[3];
        let Some(e) = Self::elem(ptype) else {
            let r = Packed {
                number,
                axis,
                ptype,
                values: Vec::new(),
            };
            return Ok((r, 4));
        };
        let n = Self::count(axis, axes);
        let end = 4 + n * e.size();
        if inp.len() < end {
            return Err(Error::local(EW_LENGTH, "a record does not fit in length"));
        }
        let values = (0..n).map(|i| e.get(&inp[4 + i * e.size()..])).collect();
        Ok((
            Packed {
                number,
                axis,
                ptype,
                values,
            },
            ((end + 3) & !3).min(inp.len()),
        ))
    }
    /// The record of a 0x008d answer block: the first value, or `axes`
    /// values for a block with axis < 0.
    pub fn of_block(b: &Param30, axes: usize) -> Result<Packed> {
        let ptype = b.ptype as u8;
        let real = Self::elem(ptype) == Some(Elem::Real);
        // The axis word's sign decides the count, its low byte is the
        // record's axis byte [fuzz + `oracle verify`: 0x0080 one value,
        // byte 0x80; 0x8000 every axis, byte 0x00].
        let n = if b.axis < 0 { axes } else { 1 };
        if b.values.len() < n {
            return Err(Error::short(
                "parameter block carries fewer values than its axis word needs",
            ));
        }
        Ok(Packed {
            number: b.number as i16,
            // The axis word's low byte, as FANUC's library copies it
            // (0x9a9d → 0x9d, not -1).
            axis: b.axis as i8,
            ptype,
            values: b.values[..n]
                .iter()
                .map(|v| num_of_value(*v, real))
                .collect(),
        })
    }
    /// The record of a 16i 0x000e answer block at the start of `inp`: its
    /// values are read from byte 8 on, one word each (a real two: value,
    /// decimals in the low half), past the block's end if the values need
    /// it, as FANUC's library reads them (a real for all axes takes two
    /// blocks' worth of words).
    pub fn of_block16(inp: &[u8], axes: usize) -> Result<Packed> {
        let short =
            || Error::short("parameter block carries fewer values than its axis word needs");
        if inp.len() < 8 {
            return Err(short());
        }
        let number = i32::from_be_bytes([inp[0], inp[1], inp[2], inp[3]]);
        let axis = i16::from_be_bytes([inp[4], inp[5]]);
        let ptype = u16::from_be_bytes([inp[6], inp[7]]) as u8;
        let real = Self::elem(ptype) == Some(Elem::Real);
        // All axes when the axis word is negative; the record keeps the
        // word's low byte [fuzz, rdparar 16i `s0Twwwww`: word 0x9877 is
        // axis byte 0x77 with max_axes values, EW_LENGTH in 8 bytes].
        let n = if axis < 0 { axes } else { 1 };
        let words = if real { 2 * n } else { n };
        let body = inp.get(8..8 + 4 * words).ok_or_else(short)?;
        let w = |i: usize| i32::from_be_bytes(body[4 * i..4 * i + 4].try_into().unwrap());
        Ok(Packed {
            number: number as i16,
            axis: axis as i8,
            ptype,
            values: (0..n)
                .map(|i| {
                    if real {
                        Num {
                            value: w(2 * i),
                            dec: w(2 * i + 1) as i16 as i32,
                        }
                    } else {
                        Num::int(w(i))
                    }
                })
                .collect(),
        })
    }
    /// The write block of the record: on the 30i class and a Series 15
    /// the 0x008e block of `max_axes` 8-byte records (non-real: value, base
    /// 0, decimals -1; real: value, base 10, decimals); on the 16i class
    /// the 0x000f block of `max_axes` words (a real: value, then base 10 in
    /// the high half and the decimals in the low half). Unused slots zero.
    pub fn to_block(&self, class: CncClass, max_axes: usize) -> Vec<u8> {
        let real = Self::elem(self.ptype) == Some(Elem::Real);
        match class {
            CncClass::Series16 { kind } if kind != 2 => {
                let mut values: Vec<i32> = if real {
                    self.values
                        .iter()
                        .flat_map(|n| [n.value, (BASE_10 as i32) << 16 | (n.dec & 0xffff)])
                        .collect()
                } else {
                    self.values.iter().map(|n| n.value).collect()
                };
                values.resize(max_axes, 0);
                Param16 {
                    number: self.number as i32,
                    axis: self.axis as i16,
                    ptype: self.ptype as u16,
                    values,
                }
                .to_bytes()
            }
            _ => {
                let mut values: Vec<Value> =
                    self.values.iter().map(|n| value_of_num(*n, real)).collect();
                values.resize(max_axes, Value::default());
                Param30 {
                    number: self.number as i32,
                    axis: self.axis as i16,
                    ptype: self.ptype as u16,
                    values,
                }
                .to_bytes()
            }
        }
    }
}

/// Size of one block of a cnc_rdparar answer / cnc_wrparas write: 8 + 8 ·
/// max-axes bytes on the 30i class and a Series 15, 8 + 4 · max-axes on
/// the 16i class.
pub fn block_len(class: CncClass, max_axes: usize) -> usize {
    match class {
        CncClass::Series16 { kind } if kind != 2 => 8 + 4 * max_axes,
        _ => 8 + 8 * max_axes,
    }
}

/// One exchange of cnc_rdparar: [s, e, axis] → per whole block of the
/// answer ([`block_len`] each; a ragged tail is ignored) its i32 number
/// and its record. A CNC error 2 is read as an answer (its blocks are
/// used), as FANUC's library reads it; an answer without a whole block
/// gives none (the caller asks again, as FANUC's library does).
#[derive(Debug, Clone, Copy)]
pub struct ReadRange {
    pub start: i32,
    pub end: i32,
    pub axis: i16,
}

impl Call for ReadRange {
    /// (the block's i32 number, its record); the record keeps the
    /// number's low 16 bits.
    type Output = Vec<(i32, Packed)>;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let cmd = match cx.class {
            CncClass::Series16 { kind } if kind != 2 => RDPARAM16,
            _ => RDPARAM,
        };
        vec![ReqSub::cnc(cmd, &[self.start, self.end, self.axis as i32])]
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Self::Output> {
        let s = match sub(resp, 0) {
            Err(Error::Cnc { code: 2, .. }) => &resp[0],
            r => r?,
        };
        let axes = cx.axes();
        let size = block_len(cx.class, cx.max_axes as usize);
        let n = s.payload.len() / size;
        (0..n)
            .map(|i| {
                let b = &s.payload[i * size..];
                let number = i32::from_be_bytes([b[0], b[1], b[2], b[3]]);
                let rec = match cx.class {
                    CncClass::Series16 { kind } if kind != 2 => Packed::of_block16(b, axes),
                    _ => Packed::of_block(&Param30::from_bytes(&b[..size])?, axes),
                };
                Ok((number, rec?))
            })
            .collect()
    }
}

/// One frame of cnc_wrparas: up to [`wrparas_per_frame`] records as
/// consecutive write blocks in one subpacket (0x008e on the 30i class and
/// a Series 15, 0x000f on the 16i class).
#[derive(Debug, Clone)]
pub struct WriteSeveral {
    pub records: Vec<Packed>,
}

impl Call for WriteSeveral {
    type Output = ();
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let max = cx.max_axes as usize;
        let payload = self
            .records
            .iter()
            .flat_map(|r| r.to_block(cx.class, max))
            .collect();
        let cmd = match cx.class {
            CncClass::Series16 { kind } if kind != 2 => WRPARAM16,
            _ => WRPARAM,
        };
        vec![ReqSub::cnc(cmd, &[]).with_payload(payload)]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        sub(resp, 0).map(|_| ())
    }
}
