//! Custom macro variables (SPEC.md §5.2): read and write 8-byte value
//! records ([`Value`]) with command 0x0015 / 0x0016.

use super::call::{Call, Ctx, records, sub};
pub use super::cmd::{RDMACRO, WRMACRO};
use super::open::CncClass;
use super::packet::{ReqSub, RespSub};
use super::value::{BASE_2, BASE_10, Float, Value};
use super::wire::Wire;
use crate::error::Result;
use crate::wire_struct;

/// Decimal places of a vacant (`<null>`) variable, as CNCs report it.
pub const VACANT_DEC: i16 = -1;
/// `dec_val` FANUC's library refuses locally with EW_DATA.
pub const DEC_FORBIDDEN: i16 = 32767;
/// The lowest number cnc_wrmacro sends: #1..#33 are local variables.
pub const FIRST_WRITABLE: i16 = 100;

/// cnc_rdmacro / cnc_rdmacror: variables `s..=e` as records.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReadMacros {
    pub s: i32,
    pub e: i32,
}

impl Call for ReadMacros {
    type Output = Vec<Value>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(RDMACRO, &[self.s, self.e])]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Vec<Value>> {
        records(resp, 0)
    }
}

/// cnc_wrmacro / cnc_wrmacror: variables `s..` = `mcr_val · 10^-dec_val`,
/// one subpacket. The records are the exact inverse of [`ReadMacros`]'
/// reply: a 30i-class CNC gets base-10 records; FANUC's library sends the
/// 16i class the same digits and decimals with base word 2 (SPEC.md §5.2).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WriteMacros {
    pub s: i32,
    /// (mcr_val, dec_val) per variable.
    pub values: Vec<(i32, i16)>,
}

impl WriteMacros {
    pub fn e(&self) -> i32 {
        self.s + self.values.len().max(1) as i32 - 1
    }

    /// The records sent to a CNC of `cx`'s class. FANUC's library converts
    /// to binary records (16i class, not the Series 15) when the first
    /// number is at most 999, or on a wire-cut machine 13000..=13999;
    /// other variables get base-10 records as on the 30i class.
    pub fn records(&self, cx: &Ctx) -> Vec<Value> {
        let binary = match cx.class {
            CncClass::Series16 { kind: 2 } | CncClass::Series30 => false,
            CncClass::Series16 { .. } => {
                self.s <= 999 || (cx.wire_cut() && (13000..=13999).contains(&self.s))
            }
        };
        let base = if binary { BASE_2 } else { BASE_10 };
        self.values
            .iter()
            .map(|&(value, exp)| {
                if base == BASE_2 {
                    let (value, exp) = to_base2(value, exp);
                    Value { value, base, exp }
                } else {
                    Value { value, base, exp }
                }
            })
            .collect()
    }
}

/// 16i class: FANUC's library sends `value · 10^-dec` as a binary record
/// m · 2^-e, computed with its own 32-bit floating point (learnt from its
/// code, checked against 750 recorded conversions): m normalised to
/// [2^30, 2^31) (negative: [-2^31, -2^30)); dec 1..9 is one division by
/// 10^dec, dec -9..-1 one multiplication; larger |dec| multiply by 10^9
/// (10^-9) first, as often as needed, then by 10^rest, each product
/// truncated (so 1 with dec 10 is 0x6df37f63, 4 units below the exact
/// 0x6df37f67). A value 0 is sent as (0, dec).
pub fn to_base2(value: i32, dec: i16) -> (i32, i16) {
    if value == 0 {
        return (0, dec);
    }
    let f = Float::from_int(value);
    let pow10 = |k: i32| Float::from_int(10i32.pow(k as u32));
    let r = match i32::from(dec) {
        0 => f,
        d @ 1..=9 => f.div(pow10(d)),
        d if d < -9 => {
            // ×10^9 until at most 9 are left, then ×10^rest.
            let mut f = f;
            let mut d = d;
            while d < -9 {
                d += 9;
                f = f.mul(Float::E9);
            }
            f.mul(pow10(-d))
        }
        d if d < 0 => f.mul(pow10(-d)),
        d => {
            // ×10^-9 while 9 or more are left, then ×10^(9 - rest).
            let mut f = f;
            let mut d = d;
            loop {
                f = f.mul(Float::E_9);
                d -= 9;
                if d < 0 {
                    break;
                }
            }
            f.mul(pow10(-d))
        }
    };
    (r.m, r.e as i16)
}

impl Call for WriteMacros {
    type Output = ();
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(WRMACRO, &[self.s, self.e()]).with_payload(self.records(cx).to_bytes())]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        sub(resp, 0).map(|_| ())
    }
}

wire_struct! {
    /// Payload of 0x0017: variable counts (only the low 16 bits reach ODBMVINF).
    pub struct MacroInfo {
        pub use_no1: i32,
        pub use_no2: i32,
    }
}
