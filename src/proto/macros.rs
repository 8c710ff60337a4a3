//! Custom macro variables (SPEC.md §5.2): read and write 8-byte value
//! records ([`Value`]) with command 0x0015 / 0x0016.

use super::call::{Call, Ctx, records, sub};
use super::open::CncClass;
use super::packet::{ReqSub, RespSub};
use super::value::{BASE_2, BASE_10, Value};
use super::wire::Wire;
use crate::error::Result;
use crate::wire_struct;

/// Read custom macro variables s..e: args (s, e); payload: one record each.
pub const RDMACRO: u16 = 0x0015;
/// Write custom macro variables: args (s, e, 0, 0, payload length) + records.
pub const WRMACRO: u16 = 0x0016;

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

    /// The records sent to a CNC of `cx`'s class.
    pub fn records(&self, cx: &Ctx) -> Vec<Value> {
        // A Series 15 (kind 2) gets base-10 records as the 30i class.
        let base = match cx.class {
            CncClass::Series16 { kind: 2 } | CncClass::Series30 => BASE_10,
            CncClass::Series16 { .. } => BASE_2,
        };
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
/// m · 2^-e with m normalised to [2^30, 2^31) (negative: [-2^31, -2^30)),
/// truncated toward zero; 0 → (0, 0). Recorded from FANUC's library with
/// our fake CNC: 12345/3 → (0x62c28f5c, 27), 1/0 → (2^30, 30),
/// -1/0 → (-2^31, 31), 1/9 → (0x44b82fa0, 60), i32::MAX/0 → (i32::MAX, 0).
pub fn to_base2(value: i32, dec: i16) -> (i32, i16) {
    if value == 0 {
        return (0, 0);
    }
    let mut m = f64::from(value) / 10f64.powi(i32::from(dec));
    let (lo, hi) = (2f64.powi(30), 2f64.powi(31));
    let mut e: i32 = 0;
    if m > 0.0 {
        while m >= hi {
            m /= 2.0;
            e -= 1;
        }
        while m < lo {
            m *= 2.0;
            e += 1;
        }
    } else {
        while m < -hi {
            m /= 2.0;
            e -= 1;
        }
        while m >= -lo {
            m *= 2.0;
            e += 1;
        }
    }
    (m.trunc() as i32, e as i16)
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

/// cnc_rdmacror2: (1,0x00a7)[s, n], payload n IEEE doubles big-endian.
pub const RDMACROR2: u16 = 0x00a7;
/// cnc_wrmacror2: (1,0x00a8)[s, 0, 0, 0, 8n] + n doubles; reply i32 count.
pub const WRMACROR2: u16 = 0x00a8;
/// Most doubles FANUC's library asks for in one cnc_rdmacror2 request.
pub const RDMACROR2_CHUNK: u32 = 179;
/// Most doubles FANUC's library sends in one cnc_wrmacror2 request.
pub const WRMACROR2_CHUNK: u32 = 177;

wire_struct! {
    /// Payload of 0x0017: variable counts (only the low 16 bits reach ODBMVINF).
    pub struct MacroInfo {
        pub use_no1: i32,
        pub use_no2: i32,
    }
}

/// A big-endian IEEE double: the element of the rdmacror2/wrmacror2
/// payloads (bit-exact both ways, NaN included).
#[derive(Debug, Clone, Copy, Default)]
pub struct Double(pub f64);

impl PartialEq for Double {
    fn eq(&self, o: &Double) -> bool {
        self.0.to_bits() == o.0.to_bits()
    }
}

impl Wire for Double {
    fn encode(&self, w: &mut super::wire::Writer) {
        w.bytes(&self.0.to_bits().to_be_bytes());
    }
    fn decode(r: &mut super::wire::Reader<'_>) -> Result<Self, super::wire::DecodeError> {
        Ok(Double(f64::from_bits(u64::from_be_bytes(r.array()?))))
    }
}

/// One cnc_rdmacror2 request: `n` variables from `s`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ReadMacrosDouble {
    pub s: u32,
    pub n: u32,
}

impl Call for ReadMacrosDouble {
    type Output = Vec<Double>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(RDMACROR2, &[self.s as i32, self.n as i32])]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<Vec<Double>> {
        records(resp, 0)
    }
}

/// One cnc_wrmacror2 request: variables from `s`; the reply is the count
/// written. The payload is exactly what [`ReadMacrosDouble`] decodes.
#[derive(Debug, Clone, PartialEq)]
pub struct WriteMacrosDouble {
    pub s: u32,
    pub values: Vec<Double>,
}

impl Call for WriteMacrosDouble {
    type Output = i32;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(WRMACROR2, &[self.s as i32]).with_payload(self.values.to_bytes())]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<i32> {
        // FANUC's library reads a count cut short as 0 (zeros follow it).
        super::call::payload_padded(resp, 0, 4)
    }
}
