//! [`Decimal`]: a CNC number as the CNC keeps it, digits and decimal places.

use std::fmt;
use std::str::FromStr;

/// A number as the CNC holds it: `value · 10^-decimals` (125000 with 3
/// decimals is 125.000 mm). Positions, real parameters and macro variables
/// come as decimals; nothing is lost to binary floating point until you ask
/// for [`Decimal::to_f64`]. Negative `decimals` scale up (123 with -2 is 12300).
///
/// ```
/// use fwlib32::native::Decimal;
///
/// let d: Decimal = "-42.500".parse().unwrap();
/// assert_eq!(d, Decimal::new(-42500, 3));
/// assert_eq!(d.to_string(), "-42.500");
/// assert_eq!(d.to_f64(), -42.5);
/// assert_eq!(Decimal::from(7).to_string(), "7");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Decimal {
    /// The digits.
    pub value: i32,
    /// Decimal places.
    pub decimals: i16,
}

impl Decimal {
    pub const fn new(value: i32, decimals: i16) -> Decimal {
        Decimal { value, decimals }
    }

    /// The number as an `f64` (the nearest one).
    pub fn to_f64(self) -> f64 {
        // Dividing by an exact power of ten rounds once: 125000 / 1000 is 125.0 exactly.
        let v = f64::from(self.value);
        if self.decimals >= 0 {
            v / 10f64.powi(i32::from(self.decimals))
        } else {
            v * 10f64.powi(-i32::from(self.decimals))
        }
    }
}

impl From<i32> for Decimal {
    fn from(value: i32) -> Decimal {
        Decimal::new(value, 0)
    }
}

impl From<Decimal> for f64 {
    fn from(d: Decimal) -> f64 {
        d.to_f64()
    }
}

impl fmt::Display for Decimal {
    /// Every decimal place the CNC keeps: `125.000`, `-0.125`, `48000`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let digits = i64::from(self.value).unsigned_abs().to_string();
        let sign = if self.value < 0 { "-" } else { "" };
        let s = match usize::try_from(self.decimals) {
            Ok(0) => format!("{sign}{digits}"),
            Ok(dec) => {
                let padded = format!("{digits:0>width$}", width = dec + 1);
                let (int, frac) = padded.split_at(padded.len() - dec);
                format!("{sign}{int}.{frac}")
            }
            // Negative decimals: zeros appended (0 stays 0).
            Err(_) if self.value == 0 => "0".to_string(),
            Err(_) => format!(
                "{sign}{digits}{}",
                "0".repeat(usize::from(self.decimals.unsigned_abs()))
            ),
        };
        f.pad(&s)
    }
}

/// A text that is not a decimal number fitting 32-bit digits.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("not a decimal number of at most 9 digits: {0:?}")]
pub struct ParseDecimalError(pub String);

impl FromStr for Decimal {
    type Err = ParseDecimalError;

    /// `"12"`, `"-0.125"`, `"+3."`, `".5"`: the decimal places as written.
    fn from_str(s: &str) -> Result<Decimal, ParseDecimalError> {
        let bad = || ParseDecimalError(s.to_string());
        let t = s.trim();
        let (neg, t) = match t.as_bytes().first() {
            Some(b'-') => (true, &t[1..]),
            Some(b'+') => (false, &t[1..]),
            _ => (false, t),
        };
        let (int, frac) = t.split_once('.').unwrap_or((t, ""));
        let all_digits = |p: &str| p.bytes().all(|b| b.is_ascii_digit());
        if int.len() + frac.len() == 0 || !all_digits(int) || !all_digits(frac) {
            return Err(bad());
        }
        let digits: i64 = format!("{int}{frac}0").parse::<i64>().map_err(|_| bad())? / 10;
        let value = i32::try_from(if neg { -digits } else { digits }).map_err(|_| bad())?;
        let decimals = i16::try_from(frac.len()).map_err(|_| bad())?;
        Ok(Decimal::new(value, decimals))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_round_trips() {
        for s in ["0", "125.000", "-42.500", "-0.125", "0.5", "48000", "1.5"] {
            assert_eq!(s.parse::<Decimal>().unwrap().to_string(), s);
        }
        assert_eq!(".5".parse::<Decimal>().unwrap(), Decimal::new(5, 1));
        assert_eq!("+3.".parse::<Decimal>().unwrap(), Decimal::new(3, 0));
        assert_eq!(Decimal::new(123, -2).to_string(), "12300");
        assert_eq!(Decimal::new(-5, 4).to_string(), "-0.0005");
        assert_eq!(format!("{:>8}", Decimal::new(15, 1)), "     1.5");
        for bad in ["", "-", ".", "1.2.3", "x", "99999999999", "1e3"] {
            assert!(bad.parse::<Decimal>().is_err(), "{bad:?}");
        }
    }

    #[test]
    fn to_f64_is_exact_where_it_can_be() {
        assert_eq!(Decimal::new(125000, 3).to_f64(), 125.0);
        assert_eq!(Decimal::new(-125, 3).to_f64(), -0.125);
        assert_eq!(Decimal::new(12, -3).to_f64(), 12000.0);
    }
}
