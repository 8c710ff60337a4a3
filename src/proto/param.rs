//! Parameter payloads.

use super::wire::{DecodeError, Reader, Wire, Writer};

/// 16i-class parameter payload (0x000e, and 0x008d of a Series 15): number,
/// axis, type, then 4-byte values (one, or eight for an axis array).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Param16 {
    pub number: i32,
    pub axis: i16,
    pub ptype: u16,
    pub values: Vec<i32>,
}

impl Wire for Param16 {
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
        // Values are whole 4-byte words; a ragged tail is ignored as FANUC's library does.
        let n = r.remaining() / 4;
        let mut values = Vec::with_capacity(n);
        for _ in 0..n {
            values.push(r.i32()?);
        }
        Ok(Param16 {
            number,
            axis,
            ptype,
            values,
        })
    }
}
