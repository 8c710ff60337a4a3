//! The area's payload structures: alarm bits, program and sequence numbers,
//! axis and spindle names, unit words, counts, figures.

use crate::error::Result;
use crate::proto::wire::{DecodeError, Reader, Wire, Writer};
use crate::wire_struct;

wire_struct! {
    /// Payload of 0x1a: one bit per active alarm type (bit n = type n).
    /// Shared with cnc_alarm / cnc_alarm2.
    pub struct AlarmBits {
        pub bits: u32,
    }
}

wire_struct! {
    /// Payload of 0x1c: running (`data`) and main (`mdata`) program numbers.
    /// Shared with cnc_rdprgnum.
    pub struct ProgNums {
        pub data: i32,
        pub mdata: i32,
    }
}

wire_struct! {
    /// Payload of 0x1d: the sequence number. Shared with cnc_rdseqnum.
    pub struct SeqNum {
        pub data: i32,
    }
}

wire_struct! {
    /// One 4-byte name entry of 0x89\[0\] / 0x8a: name, suffix(es), padding.
    pub struct Name {
        pub bytes: [u8; 4],
    }
}

wire_struct! {
    /// One axis of 0x89[-1]: the names shown for the absolute (also
    /// distance), machine and relative positions, and 4 bytes not used.
    pub struct PosNames {
        pub absolute: [u8; 4],
        pub machine: [u8; 4],
        pub relative: [u8; 4],
        pub other: [u8; 4],
    }
}

/// Payload of 0x89[-1]: i32 count, then 16 bytes per axis.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct AxisNames {
    pub count: i32,
    pub axes: Vec<PosNames>,
}

impl Wire for AxisNames {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.count);
        self.axes.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        // Whole entries (FANUC's library ignores a longer tail), and a last
        // one cut in its unused fourth word: FANUC's library reads the
        // three names alone [fuzz, seed 0x20271128, rdaxisdata `s1Twwcut`:
        // 51 bytes for 3 axes are 3 axes]; the cut word reads as zeros.
        let count = r.i32()?;
        let rest = r.bytes(r.remaining())?;
        let word = |c: &[u8], at: usize| -> [u8; 4] {
            let mut w = [0u8; 4];
            let b = c.get(at..).unwrap_or(&[]);
            let n = b.len().min(4);
            w[..n].copy_from_slice(&b[..n]);
            w
        };
        let axes = rest
            .chunks(16)
            .take_while(|c| c.len() >= 12)
            .map(|c| PosNames {
                absolute: word(c, 0),
                machine: word(c, 4),
                relative: word(c, 8),
                other: word(c, 12),
            })
            .collect();
        Ok(AxisNames { count, axes })
    }
}

wire_struct! {
    /// One axis of 0x88: two unit words (0x88\[1\]: word 0 = unit of the
    /// absolute/relative/distance positions; 0x88\[2\]: word 1 = unit of the
    /// machine position; ODBAXDT unit codes: 0 mm, 1 inch, 2 degree ...).
    pub struct UnitWords {
        pub w0: u16,
        pub w1: u16,
    }
}

wire_struct! {
    /// Payload of 0xa4: a count.
    pub struct Count {
        pub n: u16,
    }
}

wire_struct! {
    /// Input and output figures (decimal places) of one axis.
    pub struct Figure {
        pub input: i16,
        pub output: i16,
    }
}

/// Payload of 0x1b: i32 count, then one [`Figure`] per axis.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Figures {
    pub count: i32,
    pub axes: Vec<Figure>,
}

impl Wire for Figures {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.count);
        self.axes.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        Ok(Figures {
            count: r.i32()?,
            axes: Vec::decode(r)?,
        })
    }
}
