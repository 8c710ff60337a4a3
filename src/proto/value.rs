//! The 30i-class value record: the 8-byte form of positions, feeds, speeds,
//! loads, macro variables, and real parameters/diagnostics (SPEC.md §4.3).

use crate::wire_struct;

/// Base word of a decimal record.
pub const BASE_10: u16 = 10;
/// Base word of a binary record (value · 2^-exp).
pub const BASE_2: u16 = 2;

wire_struct! {
    /// i32 value, u16 base (10, or 2), i16 exponent: the number is
    /// `value · base^-exp`; for base 10 `exp` is the count of decimals.
    pub struct Value {
        pub value: i32,
        pub base: u16,
        pub exp: i16,
    }
}

impl Value {
    /// A decimal record: `value · 10^-decimals`.
    pub const fn decimal(value: i32, decimals: i16) -> Value {
        Value {
            value,
            base: BASE_10,
            exp: decimals,
        }
    }
}
