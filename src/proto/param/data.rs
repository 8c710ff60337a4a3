//! The payload shape of parameters and diagnoses (number, axis, type,
//! values) and the codec between values and the caller's C buffer.

use crate::error::Result;
use crate::proto::value::{BASE_10, Value};
use crate::proto::wire::{DecodeError, Reader, Wire, Writer};

/// Records of a 30i write payload (and of an all-axes 30i answer at most).
pub const WRITE_RECORDS_30: usize = 32;

/// A value slot of a parameter payload: a 30i record or a 16i word.
pub trait Slot: Wire + Copy + Default + PartialEq + std::fmt::Debug {
    const SIZE: usize;
}
impl Slot for Value {
    const SIZE: usize = 8;
}
impl Slot for i32 {
    const SIZE: usize = 4;
}

/// Number, axis, type and values: the payload of 0x008d/0x000e/0x0093/0x0030
/// answers and of 0x008e/0x000f writes.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ParamData<V> {
    pub number: i32,
    pub axis: i16,
    pub ptype: u16,
    pub values: Vec<V>,
}

/// 16i-class payload (0x000e, 0x000f, 0x0030; 0x008d of a Series 15).
pub type Param16 = ParamData<i32>;
/// 30i-class payload (0x008d, 0x008e, 0x0093).
pub type Param30 = ParamData<Value>;

impl<V: Slot> Wire for ParamData<V> {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.number);
        w.i16(self.axis);
        w.u16(self.ptype);
        self.values.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let number = r.i32()?;
        let axis = r.i16()?;
        let ptype = r.u16()?;
        // Values are whole slots; a ragged tail is ignored as FANUC's library does.
        let n = r.remaining() / V::SIZE;
        let mut values = Vec::with_capacity(n);
        for _ in 0..n {
            values.push(V::decode(r)?);
        }
        Ok(ParamData {
            number,
            axis,
            ptype,
            values,
        })
    }
}

/// A value as the C structures hold it: integer types use `value` only,
/// real ones `value · 10^-dec`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Num {
    pub value: i32,
    pub dec: i32,
}

impl Num {
    pub const fn int(value: i32) -> Num {
        Num { value, dec: 0 }
    }
}

/// How one value sits in a C buffer (little-endian), by element size.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Elem {
    /// `char` (bit and byte parameters; bit/byte diagnosis data).
    Byte,
    /// `short`.
    Word,
    /// 4-byte `long`.
    Long,
    /// REALPRM / REALDGN: 4-byte value, 4-byte decimals.
    Real,
}

impl Elem {
    /// Parameter type codes (0 bit, 1 byte, 2 word, 3 2-word, 4 real);
    /// like FANUC's library only the low byte of the type word counts.
    pub fn of_param(ptype: u16) -> Option<Elem> {
        match ptype & 0xff {
            0 | 1 => Some(Elem::Byte),
            2 => Some(Elem::Word),
            3 => Some(Elem::Long),
            4 => Some(Elem::Real),
            _ => None,
        }
    }
    /// Diagnosis type codes (0 byte, 1 word, 2 2-word, 3 and 4 bit, 5 real).
    pub fn of_diag(dtype: u16) -> Option<Elem> {
        match dtype & 0xff {
            0 | 3 | 4 => Some(Elem::Byte),
            1 => Some(Elem::Word),
            2 => Some(Elem::Long),
            5 => Some(Elem::Real),
            _ => None,
        }
    }
    pub const fn size(self) -> usize {
        match self {
            Elem::Byte => 1,
            Elem::Word => 2,
            Elem::Long => 4,
            Elem::Real => 8,
        }
    }
    /// Writes `v` into `out[..size]` (integer types are truncated to their size).
    pub fn put(self, out: &mut [u8], v: Num) {
        match self {
            Elem::Byte => out[0] = v.value as u8,
            Elem::Word => out[..2].copy_from_slice(&(v.value as i16).to_le_bytes()),
            Elem::Long => out[..4].copy_from_slice(&v.value.to_le_bytes()),
            Elem::Real => {
                out[..4].copy_from_slice(&v.value.to_le_bytes());
                out[4..8].copy_from_slice(&v.dec.to_le_bytes());
            }
        }
    }
    /// Reads the value `put` wrote (bytes and words sign-extended, as the
    /// header's `char`/`short` are).
    pub fn get(self, inp: &[u8]) -> Num {
        let i = |n: usize| {
            let mut b = [0u8; 4];
            b.copy_from_slice(&inp[n..n + 4]);
            i32::from_le_bytes(b)
        };
        match self {
            Elem::Byte => Num::int(inp[0] as i8 as i32),
            Elem::Word => Num::int(i16::from_le_bytes([inp[0], inp[1]]) as i32),
            Elem::Long => Num::int(i(0)),
            Elem::Real => Num {
                value: i(0),
                dec: i(4),
            },
        }
    }
}

/// A 30i record as a C value. Real records carry their decimals (base 10);
/// base-2 records are converted to decimals.
pub fn num_of_value(v: Value, real: bool) -> Num {
    if !real {
        return Num::int(v.value);
    }
    if v.base == crate::proto::value::BASE_2 && v.exp > 0 {
        // value · 2^-exp = value · 5^exp · 10^-exp, as long as it fits.
        let five = 5i64.checked_pow(v.exp as u32).unwrap_or(i64::MAX);
        if let Some(x) = (v.value as i64).checked_mul(five)
            && let Ok(x) = i32::try_from(x)
        {
            return Num {
                value: x,
                dec: v.exp as i32,
            };
        }
    }
    Num {
        value: v.value,
        dec: v.exp as i32,
    }
}

/// A C value as the 30i write record: base 10 with decimals for reals,
/// base 0 and decimals -1 otherwise (as FANUC's library sends them).
pub fn value_of_num(n: Num, real: bool) -> Value {
    if real {
        Value {
            value: n.value,
            base: BASE_10,
            exp: n.dec as i16,
        }
    } else {
        Value {
            value: n.value,
            base: 0,
            exp: -1,
        }
    }
}
