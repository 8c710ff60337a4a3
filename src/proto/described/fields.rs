//! Reading a layout's fields from a reply: the one decoder of the
//! integers every described reply, record and payload is made of.

use super::super::value::Value;
use super::super::wire::Reader;
use crate::error::Result;
use crate::spec::{Field, Int, LAST, ZERO};

pub(super) fn read_fields(
    r: &mut Reader<'_>,
    fields: &[Field],
    args: &[i32],
    out: &mut Vec<i64>,
) -> Result<()> {
    for field in fields {
        if field.wire == Int::Char && field.arg.is_none() {
            // A text: its characters up to the first NUL, zeros after.
            let b = r.bytes(usize::from(field.n))?;
            let end = b.iter().position(|&c| c == 0).unwrap_or(b.len());
            out.extend((0..b.len()).map(|i| if i < end { i64::from(b[i]) } else { 0 }));
            continue;
        }
        for _ in 0..field.n {
            if let Some(a) = field.arg {
                let v = match a {
                    ZERO => 0,
                    // Patched once the records are decoded (`decode`).
                    LAST => args.first().copied().unwrap_or(0).wrapping_sub(1),
                    a => args.get(usize::from(a)).copied().unwrap_or(0),
                };
                out.push(i64::from(v));
                continue;
            }
            let v = match field.wire {
                Int::I8 => i64::from(r.u8()? as i8),
                Int::U8 | Int::Char => i64::from(r.u8()?),
                // An unset character (0xff) reads as a NUL.
                Int::IdChar => match r.u8()? {
                    0xff => 0,
                    c => i64::from(c as i8),
                },
                Int::I16 => i64::from(r.i16()?),
                Int::U16 => i64::from(r.u16()?),
                Int::I32 => i64::from(r.i32()?),
                Int::U32 => i64::from(r.u32()?),
                // The double's bits, big-endian on the wire.
                Int::F64 => i64::from_be_bytes(r.array()?),
                Int::BaseExp => {
                    // The value read before it and this base and exponent
                    // are one record: its decimal digits and places (only
                    // the P-code reads have one: their conversion).
                    let (base, exp) = (r.u16()?, r.i16()?);
                    let value = out.pop().unwrap_or(0) as i32;
                    let (d, p) = Value { value, base, exp }.to_decimal_pcode();
                    out.push(i64::from(d));
                    i64::from(p)
                }
            };
            out.push(v);
        }
    }
    Ok(())
}
