//! Big-endian primitives and the [`Wire`] trait: every wire structure has one
//! encoder and one decoder, and they are exact inverses.

use thiserror::Error;

/// Why a byte sequence could not be decoded. Never a panic.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Error)]
pub enum DecodeError {
    #[error("payload ends after {have} bytes, {need} needed")]
    Short { need: usize, have: usize },
    #[error("bad magic")]
    BadMagic,
    #[error("body of {len} bytes exceeds the {max}-byte limit of frame version {version}")]
    Oversize {
        len: usize,
        max: usize,
        version: u16,
    },
    #[error("subpacket count is zero")]
    CountZero,
    #[error("subpacket lengths exceed the body")]
    SubLenTooBig,
    #[error("subpacket lengths do not fill the body")]
    SubLenTooSmall,
    #[error("invalid value: {0}")]
    Invalid(&'static str),
}

/// A bounds-checked big-endian reader over a byte slice.
#[derive(Debug, Clone)]
pub struct Reader<'a> {
    buf: &'a [u8],
    pos: usize,
}

impl<'a> Reader<'a> {
    pub fn new(buf: &'a [u8]) -> Self {
        Reader { buf, pos: 0 }
    }
    pub fn remaining(&self) -> usize {
        self.buf.len() - self.pos
    }
    pub fn position(&self) -> usize {
        self.pos
    }
    pub fn rest(&self) -> &'a [u8] {
        &self.buf[self.pos..]
    }
    pub fn bytes(&mut self, n: usize) -> Result<&'a [u8], DecodeError> {
        if self.remaining() < n {
            return Err(DecodeError::Short {
                need: self.pos + n,
                have: self.buf.len(),
            });
        }
        let s = &self.buf[self.pos..self.pos + n];
        self.pos += n;
        Ok(s)
    }
    pub fn array<const N: usize>(&mut self) -> Result<[u8; N], DecodeError> {
        let mut a = [0u8; N];
        a.copy_from_slice(self.bytes(N)?);
        Ok(a)
    }
    pub fn u8(&mut self) -> Result<u8, DecodeError> {
        Ok(self.array::<1>()?[0])
    }
    pub fn u16(&mut self) -> Result<u16, DecodeError> {
        Ok(u16::from_be_bytes(self.array()?))
    }
    pub fn i16(&mut self) -> Result<i16, DecodeError> {
        Ok(i16::from_be_bytes(self.array()?))
    }
    pub fn u32(&mut self) -> Result<u32, DecodeError> {
        Ok(u32::from_be_bytes(self.array()?))
    }
    pub fn i32(&mut self) -> Result<i32, DecodeError> {
        Ok(i32::from_be_bytes(self.array()?))
    }
}

/// A growable big-endian writer.
#[derive(Debug, Default, Clone)]
pub struct Writer {
    pub buf: Vec<u8>,
}

impl Writer {
    pub fn new() -> Self {
        Writer { buf: Vec::new() }
    }
    pub fn with_capacity(n: usize) -> Self {
        Writer {
            buf: Vec::with_capacity(n),
        }
    }
    pub fn len(&self) -> usize {
        self.buf.len()
    }
    pub fn is_empty(&self) -> bool {
        self.buf.is_empty()
    }
    pub fn bytes(&mut self, b: &[u8]) {
        self.buf.extend_from_slice(b);
    }
    pub fn u8(&mut self, v: u8) {
        self.buf.push(v);
    }
    pub fn u16(&mut self, v: u16) {
        self.bytes(&v.to_be_bytes());
    }
    pub fn i16(&mut self, v: i16) {
        self.bytes(&v.to_be_bytes());
    }
    pub fn u32(&mut self, v: u32) {
        self.bytes(&v.to_be_bytes());
    }
    pub fn i32(&mut self, v: i32) {
        self.bytes(&v.to_be_bytes());
    }
    /// Overwrites a big-endian u16 at `at` (used for length fields written last).
    pub fn patch_u16(&mut self, at: usize, v: u16) {
        self.buf[at..at + 2].copy_from_slice(&v.to_be_bytes());
    }
    pub fn into_vec(self) -> Vec<u8> {
        self.buf
    }
}

/// A structure with a wire form. `decode(encode(x)) == x` for every value,
/// and `encode(decode(b)) == b` for every `b` that decodes with nothing left over.
pub trait Wire: Sized {
    fn encode(&self, w: &mut Writer);
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError>;

    fn to_bytes(&self) -> Vec<u8> {
        let mut w = Writer::new();
        self.encode(&mut w);
        w.into_vec()
    }
    /// Decodes from the front of `b`; trailing bytes are allowed (CNCs of
    /// later series append fields), missing bytes are an error.
    fn from_bytes(b: &[u8]) -> Result<Self, DecodeError> {
        Self::decode(&mut Reader::new(b))
    }
}

macro_rules! prim {
    ($($t:ident),*) => {$(
        impl Wire for $t {
            fn encode(&self, w: &mut Writer) { w.$t(*self) }
            fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> { r.$t() }
        }
    )*};
}
prim!(u8, u16, i16, u32, i32);

impl<const N: usize> Wire for [u8; N] {
    fn encode(&self, w: &mut Writer) {
        w.bytes(self)
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        r.array()
    }
}

/// Declares a struct whose wire form is its fields in order, big-endian.
/// The encoder and decoder are generated from the same field list, so they
/// cannot drift apart.
#[macro_export]
macro_rules! wire_struct {
    ($(#[$m:meta])* pub struct $name:ident { $($(#[$fm:meta])* pub $f:ident : $t:ty),* $(,)? }) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
        pub struct $name { $($(#[$fm])* pub $f: $t),* }
        impl $crate::proto::wire::Wire for $name {
            fn encode(&self, w: &mut $crate::proto::wire::Writer) {
                $( $crate::proto::wire::Wire::encode(&self.$f, w); )*
            }
            fn decode(r: &mut $crate::proto::wire::Reader<'_>) -> Result<Self, $crate::proto::wire::DecodeError> {
                Ok($name { $($f: <$t as $crate::proto::wire::Wire>::decode(r)?),* })
            }
        }
    };
}

/// A sequence of records that fills the rest of a payload.
/// Decoding requires the payload to be a whole number of records.
impl<T: Wire> Wire for Vec<T> {
    fn encode(&self, w: &mut Writer) {
        for x in self {
            x.encode(w);
        }
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let mut v = Vec::new();
        while r.remaining() > 0 {
            v.push(T::decode(r)?);
        }
        Ok(v)
    }
}
