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

/// Most decimals a binary record is converted to (FANUC's library turns
/// `5 · 2^-1` into 250000000 with 8 decimals, vector cnc_rdmacror
/// `v3_base2_record`).
pub const BASE_2_DECIMALS: i16 = 8;

impl Value {
    /// The record as decimal digits and decimal places (`digits · 10^-dec`),
    /// as FANUC's library writes it into `mcr_val` / `dec_val`.
    ///
    /// Base 10 (and any base other than 2) is a plain copy. A base-2 record
    /// `value · 2^-exp` becomes the value with [`BASE_2_DECIMALS`] decimals,
    /// or fewer while the digits would not fit in 32 bits (the one recorded
    /// case is 5·2^-1 → 250000000, 8; how FANUC's library treats larger
    /// values is not recorded: this rule keeps the most precision that fits).
    pub fn to_decimal(&self) -> (i32, i16) {
        if self.base != BASE_2 {
            return (self.value, self.exp);
        }
        let x = f64::from(self.value) * 2f64.powi(-i32::from(self.exp));
        for dec in (0..=BASE_2_DECIMALS).rev() {
            let m = (x * 10f64.powi(i32::from(dec))).round();
            if m.abs() <= f64::from(i32::MAX) {
                return (m as i32, dec);
            }
        }
        // Beyond 32 bits even without decimals: saturate.
        (if x < 0.0 { i32::MIN } else { i32::MAX }, 0)
    }
}
