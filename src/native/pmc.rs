//! PMC areas (pmc_rdpmcrng) read as bytes, words, longs or reals.

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::error::{Error, Ew, Result};
use super::part::{Failed, Part, via};
use crate::proto::pmc::{PmcRange, ReadPmc, dtype};
use std::fmt;
use std::ops::RangeInclusive;
use std::str::FromStr;

const CALL: &str = "pmc_rdpmcrng";

/// Most bytes one read asks for (an answer fitting the smallest frame).
pub const PMC_CHUNK: usize = 1400;

/// A PMC address area, by its letter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PmcArea {
    /// Signals from the PMC to the CNC.
    G,
    /// Signals from the CNC to the PMC.
    F,
    /// Outputs to the machine.
    Y,
    /// Inputs from the machine.
    X,
    /// Message requests.
    A,
    /// Internal relays.
    R,
    /// Variable timers.
    T,
    /// Keep relays.
    K,
    /// Counters.
    C,
    /// Data tables.
    D,
    M,
    N,
    /// Extra relays.
    E,
    Z,
}

const AREAS: [(PmcArea, &str, i16); 14] = [
    (PmcArea::G, "G", 0),
    (PmcArea::F, "F", 1),
    (PmcArea::Y, "Y", 2),
    (PmcArea::X, "X", 3),
    (PmcArea::A, "A", 4),
    (PmcArea::R, "R", 5),
    (PmcArea::T, "T", 6),
    (PmcArea::K, "K", 7),
    (PmcArea::C, "C", 8),
    (PmcArea::D, "D", 9),
    (PmcArea::M, "M", 10),
    (PmcArea::N, "N", 11),
    (PmcArea::E, "E", 12),
    (PmcArea::Z, "Z", 13),
];

impl PmcArea {
    /// The area's `adr_type` number (G 0, F 1, ... D 9).
    pub fn code(self) -> i16 {
        AREAS.iter().find(|a| a.0 == self).map_or(0, |a| a.2)
    }
}

impl fmt::Display for PmcArea {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(AREAS.iter().find(|a| a.0 == *self).map_or("?", |a| a.1))
    }
}

/// A letter that names no PMC area.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("no PMC area {0:?} (G F Y X A R T K C D M N E Z)")]
pub struct ParsePmcAreaError(pub String);

impl FromStr for PmcArea {
    type Err = ParsePmcAreaError;
    fn from_str(s: &str) -> Result<PmcArea, ParsePmcAreaError> {
        AREAS
            .iter()
            .find(|a| a.1.eq_ignore_ascii_case(s))
            .map(|a| a.0)
            .ok_or_else(|| ParsePmcAreaError(s.to_string()))
    }
}

/// An element type of PMC data: `u8`/`i8` bytes, `u16`/`i16` words,
/// `u32`/`i32` longs, `f32`/`f64` reals (the PMC stores them high byte first).
pub trait PmcType: Sized + Copy + Send + 'static {
    /// pmc_rdpmcrng's data type (0 byte, 1 word, 2 long, 4 float, 5 double).
    const DATA_TYPE: i16;
    /// Bytes per element.
    const SIZE: usize;
    /// The element from its big-endian bytes (`SIZE` of them).
    fn from_be(b: &[u8]) -> Self;
}

macro_rules! pmc_type {
    ($($t:ty => $d:expr),*) => {$(
        impl PmcType for $t {
            const DATA_TYPE: i16 = $d;
            const SIZE: usize = std::mem::size_of::<$t>();
            fn from_be(b: &[u8]) -> $t {
                let mut a = [0u8; std::mem::size_of::<$t>()];
                a.copy_from_slice(&b[..Self::SIZE]);
                <$t>::from_be_bytes(a)
            }
        }
    )*};
}
pmc_type!(u8 => dtype::BYTE, i8 => dtype::BYTE, u16 => dtype::WORD, i16 => dtype::WORD,
    u32 => dtype::LONG, i32 => dtype::LONG, f32 => dtype::FLOAT, f64 => dtype::DOUBLE);

/// The byte range of the elements at `range`'s addresses (one every
/// `T::SIZE` bytes from its start, the last starting at or before its end).
fn span<T: PmcType>(range: &RangeInclusive<u16>) -> Result<(u16, u16, usize)> {
    let (s, e) = (*range.start(), *range.end());
    if e < s {
        return Err(Error::invalid(
            CALL,
            Ew::NUMBER,
            "the range ends before it starts",
        ));
    }
    let n = usize::from(e - s) / T::SIZE + 1;
    let last = usize::from(s) + n * T::SIZE - 1;
    let last = u16::try_from(last)
        .map_err(|_| Error::invalid(CALL, Ew::NUMBER, "the range runs past address 65535"))?;
    Ok((s, last, n))
}

fn read_part<T: PmcType>(
    area: PmcArea,
    s: u16,
    e: u16,
    n: usize,
) -> impl Part<Out = Vec<T>> + Send + 'static {
    let range = PmcRange {
        adr_type: area.code(),
        data_type: T::DATA_TYPE,
        s,
        e,
    };
    via(CALL, ReadPmc(range), n * T::SIZE, move |b: Vec<u8>| {
        if b.len() < n * T::SIZE {
            let msg = "the PMC answered fewer bytes than the range";
            return Err(Error::of(CALL, crate::error::Error::short(msg)));
        }
        Ok(b.chunks_exact(T::SIZE).take(n).map(T::from_be).collect())
    })
}

impl Cnc {
    /// The PMC data at `range` of `area`: one `T` at each address from the
    /// start, `T::SIZE` bytes apart, up to the one starting at the end
    /// (`D100..=D120` as `i16` is the 11 words D100, D102 ... D120). Large
    /// ranges take several exchanges of at most [`PMC_CHUNK`] bytes.
    ///
    /// ```
    /// use fwlib32::native::{Cnc, PmcArea};
    /// use fwlib32::sim::{Profile, Simulator};
    /// use std::time::Duration;
    ///
    /// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
    /// assert_eq!(cnc.pmc::<i32>(PmcArea::D, 0..=0)?, [1000]); // D0-D3, a long
    /// assert_eq!(cnc.pmc::<u8>(PmcArea::G, 30..=30)?, [100]); // spindle override %
    /// assert!(cnc.pmc_bit(PmcArea::F, 0, 5)?); // F0.5 STL
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn pmc<T: PmcType>(&self, area: PmcArea, range: RangeInclusive<u16>) -> Result<Vec<T>> {
        let (s, _, n) = span::<T>(&range)?;
        let per = PMC_CHUNK / T::SIZE;
        let mut out = Vec::with_capacity(n);
        while out.len() < n {
            let k = (n - out.len()).min(per);
            let from = usize::from(s) + out.len() * T::SIZE;
            let to = from + k * T::SIZE - 1;
            out.extend(self.run(read_part::<T>(area, from as u16, to as u16, k))?);
        }
        Ok(out)
    }

    /// Bit `bit` (0..=7) of the byte at `address` of `area` (`R0.3`).
    pub fn pmc_bit(&self, area: PmcArea, address: u16, bit: u8) -> Result<bool> {
        if bit > 7 {
            return Err(Error::invalid(CALL, Ew::NUMBER, "bits are numbered 0 to 7"));
        }
        let b = self.pmc::<u8>(area, address..=address)?;
        Ok(b.first().is_some_and(|b| b & (1 << bit) != 0))
    }
}

impl Batch<'_> {
    /// [`Cnc::pmc`] in the batch: at most [`PMC_CHUNK`] bytes.
    pub fn pmc<T: PmcType>(&mut self, area: PmcArea, range: RangeInclusive<u16>) -> Ticket<Vec<T>> {
        match span::<T>(&range) {
            Ok((_, _, n)) if n * T::SIZE > PMC_CHUNK => {
                let msg = format!("a batch reads at most {PMC_CHUNK} PMC bytes at once");
                self.push(Failed::new(Error::invalid(CALL, Ew::LENGTH, msg)))
            }
            Ok((s, e, n)) => self.push(read_part::<T>(area, s, e, n)),
            Err(e) => self.push(Failed::new(e)),
        }
    }
}
