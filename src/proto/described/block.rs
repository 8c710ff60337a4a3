//! The typed parameter block of a described function ([`Block`]): the
//! answer read into IODBPSD's bytes, the write block sent, and the
//! simulator's answer encoded, all through the parameter codec of
//! src/proto/param (cnc_rdparam's and cnc_wrparam's).
//!
//! The integers of a read (client side, [`read`]): `datano`, `type` as
//! the C struct gets them, then the values' C bytes, one integer each; of
//! a range read ([`range`]), packed records.
//! The integers of a write's payload ([`write_payload`]): number, axis,
//! type word, then each value's digits and decimals. The integers of the
//! simulator's answer ([`encode`], [`wire_values`]): the wire block's, in
//! the class's form: number, axis, type word, then per value record its
//! value, base and exponent (30i class) or per word its value (16i class
//! and Series 15).

use crate::error::Result;
use crate::proto::call::{Call, Ctx};
use crate::proto::open::CncClass;
use crate::proto::packet::RespSub;
use crate::proto::param::{Num, Param16, Param30, ReadOne, ReadRange, Table, WriteParam};
use crate::proto::value::Value;
use crate::proto::wire::{DecodeError, Wire};
use crate::spec::{Block, Short};

/// Whether the block is of 8-byte value records (else 4-byte words): a
/// read's answer on the 30i class, a write's payload on the 30i class and
/// Series 15 (FANUC's library sends a Series 15 the 30i write block, and
/// reads its answers in the 16i form).
pub fn records(class: CncClass, write: bool) -> bool {
    match class {
        CncClass::Series30 => true,
        CncClass::Series16 { kind: 2 } => write,
        CncClass::Series16 { .. } => false,
    }
}

/// A read's answer shorter than one block of the CNC's max axes, as
/// [`Short`] says: EW_PROTOCOL, zeros past its end, or (`Short::Request`,
/// FANUC's library reading the answer into the buffer that held its
/// request) payload byte k the request body's byte 18 + k, zeros past the
/// request (an empty answer to `[n, n, axis]` is number `axis`, then
/// zeros). One block of the CNC's max axes: 8 bytes a value, a 30i value
/// record or a 16i-form real's two words (value, decimals).
fn padded(cx: &Ctx, resp: &[RespSub], short: Short, request: &[u8]) -> Vec<RespSub> {
    let need = 8 + 8 * cx.axes();
    resp.iter()
        .enumerate()
        .map(|(i, s)| {
            let mut s = s.clone();
            if i == 0 && s.error == 0 && s.payload.len() < need && short != Short::Error {
                let have = s.payload.len();
                s.payload
                    .extend((have..need).map(|k| request.get(18 + k).copied().unwrap_or(0)));
            }
            s
        })
        .collect()
}

/// A read's answer as IODBPSD gets it: `datano` (the number's low 16
/// bits), `type` (the answer's axis word; from a Series 15 `(type << 8) |
/// (axis & 0xff)`, as FANUC's library writes it), then the values' bytes.
pub fn read(
    cx: &Ctx,
    resp: &[RespSub],
    short: Short,
    request: &[u8],
    diag: bool,
) -> Result<Vec<i64>> {
    let one = ReadOne {
        table: if diag { Table::Diag } else { Table::Param },
        number: 0,
        axis: 0,
        flag: 0,
    };
    let item = one.decode(cx, &padded(cx, resp, short, request))?;
    let type_field = match cx.class {
        CncClass::Series16 { kind: 2 } => ((item.ptype & 0xff) << 8) as i16 | (item.axis & 0xff),
        _ => item.axis,
    };
    let mut out = vec![i64::from(item.number as i16), i64::from(type_field)];
    out.extend(item.data_bytes().into_iter().map(i64::from));
    Ok(out)
}

/// A range read's answer (cnc_rdparar's, [`ReadRange`] decoding it) as
/// packed records: per record its (whole 32-bit) number, the bytes it takes with its
/// padding, how many bytes it has, then those bytes.
pub fn range(cx: &Ctx, resp: &[RespSub]) -> Result<Vec<i64>> {
    let one = ReadRange {
        start: 0,
        end: 0,
        axis: 0,
    };
    let mut out = Vec::new();
    for (whole, r) in one.decode(cx, resp)? {
        let bytes = r.to_c();
        out.extend([i64::from(whole), r.padded_len() as i64, bytes.len() as i64]);
        out.extend(bytes.into_iter().map(i64::from));
    }
    Ok(out)
}

/// The payload integers of a write: number, axis, type word, then each
/// value's digits and decimals.
pub fn write_values(number: i32, axis: i16, ptype: u16, values: &[Num]) -> Vec<i64> {
    let mut v = vec![i64::from(number), i64::from(axis), i64::from(ptype)];
    for n in values {
        v.extend([i64::from(n.value), i64::from(n.dec)]);
    }
    v
}

/// The write block of these payload integers ([`write_values`]) in the
/// class's form, as cnc_wrparam sends it (30i class and Series 15: 32 value
/// records; 16i class: one word per axis of the CNC's maximum).
pub fn write_payload(cx: &Ctx, v: &[i64]) -> Vec<u8> {
    let at = |i: usize| v.get(i).copied().unwrap_or(0);
    let values: Vec<Num> = v
        .get(3..)
        .unwrap_or_default()
        .chunks_exact(2)
        .map(|c| Num {
            value: c[0] as i32,
            dec: c[1] as i32,
        })
        .collect();
    WriteParam {
        number: at(0) as i32,
        axis: at(1) as i16,
        ptype: at(2) as u16,
        values,
    }
    .payload(
        if records(cx.class, true) {
            CncClass::Series30
        } else {
            cx.class
        },
        cx.axes(),
    )
}

/// The wire block of these integers (see the module's doc), in the class's
/// form: a read's answer (the simulator's), or a write's payload (`write`);
/// no integers, no bytes (a write's answer).
pub fn encode(
    class: CncClass,
    write: bool,
    v: &[i64],
) -> std::result::Result<Vec<u8>, DecodeError> {
    let bad = DecodeError::Invalid("a parameter block's integers");
    if v.is_empty() {
        return Ok(Vec::new());
    }
    let [number, axis, ptype, rest @ ..] = v else {
        return Err(bad);
    };
    let (number, axis, ptype) = (*number as i32, *axis as i16, *ptype as u16);
    if records(class, write) {
        if rest.len() % 3 != 0 {
            return Err(bad);
        }
        let values = rest
            .chunks_exact(3)
            .map(|c| Value {
                value: c[0] as i32,
                base: c[1] as u16,
                exp: c[2] as i16,
            })
            .collect();
        Ok(Param30 {
            number,
            axis,
            ptype,
            values,
        }
        .to_bytes())
    } else {
        let values = rest.iter().map(|x| *x as i32).collect();
        Ok(Param16 {
            number,
            axis,
            ptype,
            values,
        }
        .to_bytes())
    }
}

/// The integers of a wire block's bytes (simulator side, the inverse of
/// [`encode`]): a ragged tail is left out.
pub fn wire_values(
    class: CncClass,
    write: bool,
    bytes: &[u8],
) -> std::result::Result<Vec<i64>, DecodeError> {
    let mut out;
    if records(class, write) {
        let p = Param30::from_bytes(bytes)?;
        out = vec![i64::from(p.number), i64::from(p.axis), i64::from(p.ptype)];
        for r in p.values {
            out.extend([i64::from(r.value), i64::from(r.base), i64::from(r.exp)]);
        }
    } else {
        let p = Param16::from_bytes(bytes)?;
        out = vec![i64::from(p.number), i64::from(p.axis), i64::from(p.ptype)];
        out.extend(p.values.into_iter().map(i64::from));
    }
    Ok(out)
}

/// Whether a read's `length` (number parameter [`Block::length`]) holds
/// the block's values: 4 + their bytes.
pub fn fits(b: &Block, args: &[i32], values: &[i64]) -> bool {
    let length = args.get(usize::from(b.length)).copied().unwrap_or(0) as i16;
    i32::from(length) >= 4 + values.len().saturating_sub(2) as i32
}
