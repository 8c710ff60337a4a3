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

impl Value {
    /// The record as decimal digits and decimal places (`digits · 10^-dec`),
    /// as FANUC's library writes it into `mcr_val` / `dec_val` (oracle
    /// finding cnc_rdmacro_base2, vector cnc_rdmacror `v3_base2_record`):
    ///
    /// * base 10: a plain copy;
    /// * any other base is binary, `x = value · 2^-exp`; value 0 gives
    ///   (0, exp) unchanged;
    /// * otherwise x is rounded to 9 decimal places (half away from zero,
    ///   when |x| ≥ 1e-9) and written with a 9-digit mantissa
    ///   (10^8 ≤ |digits| < 10^9, trailing zeros added): 5·2^-1 → 250000000
    ///   with 8 decimals; values of 10^9 and more keep 9 significant digits
    ///   with negative decimals. Below 1e-9, FANUC's last digit may differ by
    ///   one (its own floating-point rounding); beyond f64's range (exponents
    ///   below about -1000) it was not probed: we give ±999999999 · 10^300.
    pub fn to_decimal(&self) -> (i32, i16) {
        if self.base != BASE_10 {
            return binary_to_decimal(self.value, self.exp);
        }
        (self.value, self.exp)
    }
}

fn binary_to_decimal(value: i32, exp: i16) -> (i32, i16) {
    if value == 0 {
        return (0, exp);
    }
    let x = f64::from(value) * 2f64.powi(-i32::from(exp));
    if !x.is_finite() {
        return (999_999_999 * value.signum(), -300);
    }
    let x = if x.abs() >= 1e-9 && x.abs() < 1e9 {
        (x * 1e9).round() / 1e9
    } else {
        x
    };
    if x == 0.0 {
        // Underflow (a huge exponent): nothing left to show.
        return (0, 0);
    }
    let mut dec = 8 - x.abs().log10().floor() as i32;
    // 10^dec in two halves: a subnormal x needs dec up to ~332, past f64's range.
    let digits = |dec: i32| {
        let h = dec / 2;
        (x * 10f64.powi(h) * 10f64.powi(dec - h)).round()
    };
    let mut m = digits(dec);
    if m.abs() >= 1e9 {
        dec -= 1;
        m = digits(dec);
    } else if m.abs() < 1e8 {
        dec += 1;
        m = digits(dec);
    }
    (m as i32, dec as i16)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extreme_binary_exponents_neither_panic_nor_wrap() {
        for exp in [
            i16::MIN,
            -1100,
            -1075,
            -1000,
            -500,
            500,
            1000,
            1074,
            1075,
            1100,
            i16::MAX,
        ] {
            for value in [1, -1, 5, i32::MAX, i32::MIN] {
                let (m, dec) = Value {
                    value,
                    base: BASE_2,
                    exp,
                }
                .to_decimal();
                let x = f64::from(value) * 2f64.powi(-i32::from(exp));
                if x == 0.0 {
                    assert_eq!((m, dec), (0, 0), "{value}·2^-{exp}");
                } else if x.is_finite() {
                    let back = f64::from(m)
                        / 10f64.powi(i32::from(dec) / 2)
                        / 10f64.powi(i32::from(dec) - i32::from(dec) / 2);
                    assert!(
                        ((back - x) / x).abs() < 1e-8,
                        "{value}·2^-{exp}: {m}e-{dec}"
                    );
                }
            }
        }
    }
}
