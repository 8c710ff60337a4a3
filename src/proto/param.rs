//! Parameters and diagnostics (SPEC.md §5.2, §5.3).
//!
//! One payload shape serves reads and writes of both classes: number, axis,
//! type, then values (30i: 8-byte [`Value`] records; 16i: 4-byte i32).
//! [`Elem`] is the one codec between a value and the bytes of the caller's
//! C buffer (IODBPSD / ODBDGN / the write input): `get` is `put` reversed.

use super::call::{Call, Ctx, payload, sub};
use super::open::CncClass;
use super::packet::{ReqSub, RespSub};
use super::value::{BASE_10, Value};
use super::wire::{DecodeError, Reader, Wire, Writer};
use crate::error::{Error, Result};
use crate::ew::{EW_LENGTH, EW_NUMBER};
use crate::wire_struct;

/// 30i: read parameters [s, e, axis] (also rdparar's range form).
pub const RDPARAM: u16 = super::cmd::RDPARAM;
/// 16i: read parameters [s, e, axis] (also the FOCAS option probe).
pub const RDPARAM16: u16 = super::cmd::RDPARAM16;
/// 30i: write one parameter, 264-byte payload.
pub const WRPARAM: u16 = 0x008e;
/// 16i: write one parameter, 40-byte payload.
pub const WRPARAM16: u16 = 0x000f;
/// 30i: the attribute record of one parameter [number, 1] (28 bytes).
pub const PARAMTYPE: u16 = 0x00a0;
/// Both classes: parameter numbers and attributes [s, n] (cnc_rdparainfo;
/// the 16i cnc_wrparam reads one entry of it first).
pub const RDPARAINFO: u16 = 0x0010;
/// 30i: read diagnosis data [s, e, axis].
pub const DIAGNOSS: u16 = 0x0093;
/// 16i: read diagnosis data [s, e, axis].
pub const DIAGNOSS16: u16 = 0x0030;
/// Both classes: diagnosis numbers and attributes [s, n].
pub const RDDIAGINFO: u16 = 0x0031;
/// 30i: the attribute record of one diagnosis item [number, 1] (28 bytes).
pub const DIAGTYPE: u16 = 0x00a2;
/// Series 15: parameter numbers and attributes [s, n] (cnc_rdparainfo).
pub const RDPARAINFO15: u16 = 0x008f;
/// Series 15: diagnosis numbers and attributes [s, n] (cnc_rddiaginfo).
pub const RDDIAGINFO15: u16 = 0x0094;
/// Entries one cnc_rdparainfo / cnc_rddiaginfo request asks for at most.
pub const INFO_MAX: i32 = 178;
/// cnc_rdparanum: smallest, largest and count of parameter numbers.
pub const RDPARANUM: u16 = 0x0011;
/// cnc_rddiagnum: the same for diagnosis data.
pub const RDDIAGNUM: u16 = 0x0032;
/// Items per frame of cnc_rdparam_ext / cnc_rddiag_ext.
pub const EXT_PER_FRAME: usize = 8;

/// Records of a 30i write payload (and of an all-axes 30i answer at most).
pub const WRITE_RECORDS_30: usize = 32;

/// A value slot of a parameter payload: a 30i record or a 16i word.
pub trait Slot: Wire + Copy + Default + PartialEq + std::fmt::Debug {
    const SIZE: usize;
}
impl Slot for Value {
    const SIZE: usize = 8;
}
impl Slot for i32 {
    const SIZE: usize = 4;
}

/// Number, axis, type and values: the payload of 0x008d/0x000e/0x0093/0x0030
/// answers and of 0x008e/0x000f writes.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ParamData<V> {
    pub number: i32,
    pub axis: i16,
    pub ptype: u16,
    pub values: Vec<V>,
}

/// 16i-class payload (0x000e, 0x000f, 0x0030; 0x008d of a Series 15).
pub type Param16 = ParamData<i32>;
/// 30i-class payload (0x008d, 0x008e, 0x0093).
pub type Param30 = ParamData<Value>;

impl<V: Slot> Wire for ParamData<V> {
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
        // Values are whole slots; a ragged tail is ignored as FANUC's library does.
        let n = r.remaining() / V::SIZE;
        let mut values = Vec::with_capacity(n);
        for _ in 0..n {
            values.push(V::decode(r)?);
        }
        Ok(ParamData {
            number,
            axis,
            ptype,
            values,
        })
    }
}

/// A value as the C structures hold it: integer types use `value` only,
/// real ones `value · 10^-dec`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Num {
    pub value: i32,
    pub dec: i32,
}

impl Num {
    pub const fn int(value: i32) -> Num {
        Num { value, dec: 0 }
    }
}

/// How one value sits in a C buffer (little-endian), by element size.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Elem {
    /// `char` (bit and byte parameters; bit/byte diagnosis data).
    Byte,
    /// `short`.
    Word,
    /// 4-byte `long`.
    Long,
    /// REALPRM / REALDGN: 4-byte value, 4-byte decimals.
    Real,
}

impl Elem {
    /// Parameter type codes (0 bit, 1 byte, 2 word, 3 2-word, 4 real);
    /// like FANUC's library only the low byte of the type word counts.
    pub fn of_param(ptype: u16) -> Option<Elem> {
        match ptype & 0xff {
            0 | 1 => Some(Elem::Byte),
            2 => Some(Elem::Word),
            3 => Some(Elem::Long),
            4 => Some(Elem::Real),
            _ => None,
        }
    }
    /// Diagnosis type codes (0 byte, 1 word, 2 2-word, 3 and 4 bit, 5 real).
    pub fn of_diag(dtype: u16) -> Option<Elem> {
        match dtype & 0xff {
            0 | 3 | 4 => Some(Elem::Byte),
            1 => Some(Elem::Word),
            2 => Some(Elem::Long),
            5 => Some(Elem::Real),
            _ => None,
        }
    }
    pub const fn size(self) -> usize {
        match self {
            Elem::Byte => 1,
            Elem::Word => 2,
            Elem::Long => 4,
            Elem::Real => 8,
        }
    }
    /// Writes `v` into `out[..size]` (integer types are truncated to their size).
    pub fn put(self, out: &mut [u8], v: Num) {
        match self {
            Elem::Byte => out[0] = v.value as u8,
            Elem::Word => out[..2].copy_from_slice(&(v.value as i16).to_le_bytes()),
            Elem::Long => out[..4].copy_from_slice(&v.value.to_le_bytes()),
            Elem::Real => {
                out[..4].copy_from_slice(&v.value.to_le_bytes());
                out[4..8].copy_from_slice(&v.dec.to_le_bytes());
            }
        }
    }
    /// Reads the value `put` wrote (bytes and words sign-extended, as the
    /// header's `char`/`short` are).
    pub fn get(self, inp: &[u8]) -> Num {
        let i = |n: usize| {
            let mut b = [0u8; 4];
            b.copy_from_slice(&inp[n..n + 4]);
            i32::from_le_bytes(b)
        };
        match self {
            Elem::Byte => Num::int(inp[0] as i8 as i32),
            Elem::Word => Num::int(i16::from_le_bytes([inp[0], inp[1]]) as i32),
            Elem::Long => Num::int(i(0)),
            Elem::Real => Num {
                value: i(0),
                dec: i(4),
            },
        }
    }
}

/// A 30i record as a C value. Real records carry their decimals (base 10);
/// base-2 records are converted to decimals.
pub fn num_of_value(v: Value, real: bool) -> Num {
    if !real {
        return Num::int(v.value);
    }
    if v.base == super::value::BASE_2 && v.exp > 0 {
        // value · 2^-exp = value · 5^exp · 10^-exp, as long as it fits.
        let five = 5i64.checked_pow(v.exp as u32).unwrap_or(i64::MAX);
        if let Some(x) = (v.value as i64).checked_mul(five)
            && let Ok(x) = i32::try_from(x)
        {
            return Num {
                value: x,
                dec: v.exp as i32,
            };
        }
    }
    Num {
        value: v.value,
        dec: v.exp as i32,
    }
}

/// A C value as the 30i write record: base 10 with decimals for reals,
/// base 0 and decimals -1 otherwise (as FANUC's library sends them).
pub fn value_of_num(n: Num, real: bool) -> Value {
    if real {
        Value {
            value: n.value,
            base: BASE_10,
            exp: n.dec as i16,
        }
    } else {
        Value {
            value: n.value,
            base: 0,
            exp: -1,
        }
    }
}

/// Parameter or diagnosis: the two read families differ only in command
/// words and type codes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Table {
    Param,
    Diag,
}

impl Table {
    pub fn read_cmd(self, class: CncClass) -> u16 {
        match (self, class) {
            // A Series 15 (kind 2) is asked with the 30i commands and
            // answers in the 16i value form.
            (Table::Param, CncClass::Series30 | CncClass::Series16 { kind: 2 }) => RDPARAM,
            (Table::Param, CncClass::Series16 { .. }) => RDPARAM16,
            (Table::Diag, CncClass::Series30 | CncClass::Series16 { kind: 2 }) => DIAGNOSS,
            (Table::Diag, CncClass::Series16 { .. }) => DIAGNOSS16,
        }
    }
    pub fn elem(self, t: u16) -> Option<Elem> {
        match self {
            Table::Param => Elem::of_param(t),
            Table::Diag => Elem::of_diag(t),
        }
    }
    /// The info-list command; a Series 15 (kind 2) has its own.
    pub fn info_cmd(self, class: CncClass) -> u16 {
        match (self, class) {
            (Table::Param, CncClass::Series16 { kind: 2 }) => RDPARAINFO15,
            (Table::Diag, CncClass::Series16 { kind: 2 }) => RDDIAGINFO15,
            (Table::Param, _) => RDPARAINFO,
            (Table::Diag, _) => RDDIAGINFO,
        }
    }
}

/// One parameter/diagnosis item as read: its number, the axis word of the
/// answer, its element kind and its values (one, or max-axes for axis -1).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Item {
    pub number: i32,
    pub axis: i16,
    /// The answer's type word.
    pub ptype: u16,
    /// None: a type code the library writes no value for.
    pub elem: Option<Elem>,
    pub values: Vec<Num>,
}

impl Item {
    /// Bytes of the C structure from offset 4 on (`length` already checked).
    pub fn data_bytes(&self) -> Vec<u8> {
        let Some(e) = self.elem else {
            return Vec::new();
        };
        let mut out = vec![0u8; e.size() * self.values.len()];
        for (i, v) in self.values.iter().enumerate() {
            e.put(&mut out[i * e.size()..], *v);
        }
        out
    }
}

/// cnc_rdparam / cnc_diagnoss: [number, number, axis] → one [`Item`].
#[derive(Debug, Clone, Copy)]
pub struct ReadOne {
    pub table: Table,
    pub number: i32,
    pub axis: i16,
}

/// How many values an answer block carries, by its axis word (FANUC's
/// library): a negative axis word (all axes) max-axes values, any other one
/// value — whatever axis was asked, so a non-axis parameter asked with
/// axis -1 and answered with axis word 0 is one value.
fn count_for(cx: &Ctx, axis_word: i16) -> usize {
    if axis_word < 0 { cx.axes() } else { 1 }
}

impl Call for ReadOne {
    type Output = Item;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let n = self.number;
        vec![ReqSub::cnc(
            self.table.read_cmd(cx.class),
            &[n, n, self.axis as i32],
        )]
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Item> {
        let short = || Error::short("parameter answer carries fewer values than the axis count");
        match cx.class {
            CncClass::Series30 => {
                let p: Param30 = payload(resp, 0)?;
                let count = count_for(cx, p.axis);
                let elem = self.table.elem(p.ptype);
                let real = elem == Some(Elem::Real);
                if p.values.len() < count {
                    return Err(short());
                }
                Ok(Item {
                    number: p.number,
                    axis: p.axis,
                    ptype: p.ptype,
                    elem,
                    values: p.values[..count]
                        .iter()
                        .map(|v| num_of_value(*v, real))
                        .collect(),
                })
            }
            CncClass::Series16 { .. } => {
                let p: Param16 = payload(resp, 0)?;
                let count = count_for(cx, p.axis);
                let elem = self.table.elem(p.ptype);
                // A 16i real takes two words: value, then decimals in the
                // low half of the second (SPEC.md §5.2).
                let values: Vec<Num> = if elem == Some(Elem::Real) {
                    p.values
                        .chunks_exact(2)
                        .map(|c| Num {
                            value: c[0],
                            dec: c[1] as i16 as i32,
                        })
                        .collect()
                } else {
                    p.values.iter().map(|v| Num::int(*v)).collect()
                };
                if values.len() < count {
                    return Err(short());
                }
                Ok(Item {
                    number: p.number,
                    axis: p.axis,
                    ptype: p.ptype,
                    elem,
                    values: values[..count].to_vec(),
                })
            }
        }
    }
}

wire_struct! {
    /// 30i attribute record of one parameter (0x00a0) or diagnosis item
    /// (0x00a2), 28 bytes. cnc_wrparam uses `ptype` (0..4) and `axis`
    /// (2 = axis parameter); cnc_rdparam_ext / cnc_rddiag_ext check `number`
    /// and derive IODBPRM axis/info/unit from `axis`, `unit_lo`, `unit_hi`,
    /// `kind` and `flags` (oracle findings; what a real CNC puts in the
    /// words is not known, our simulator sends 0 there).
    pub struct ParamType30 {
        pub w0: i32,
        pub w4: i32,
        pub number: i32,
        pub ptype: u16,
        pub axis: u16,
        pub unit_lo: u16,
        pub unit_hi: u16,
        pub kind: u16,
        pub w22: u16,
        pub flags: u16,
        pub w26: u16,
    }
}

impl ParamType30 {
    /// IODBPRM.axis: 0, or (2v - 2) | 1 for an axis attribute v.
    pub fn ext_axis(&self) -> i16 {
        if self.axis == 0 {
            0
        } else {
            ((2 * self.axis as i32 - 2) | 1) as i16
        }
    }
    /// IODBPRM.info of a parameter.
    pub fn ext_info_param(&self) -> i16 {
        let w = self.flags;
        ((w & 1)
            | if w & 2 != 0 { 8 } else { 0 }
            | if w & 4 != 0 { 16 } else { 0 }
            | if self.kind == 1 { 2 } else { 0 }
            | if self.kind == 2 { 4 } else { 0 }) as i16
    }
    /// IODBPRM.unit of a parameter.
    pub fn ext_unit_param(&self) -> i16 {
        (self.unit_lo | (self.unit_hi << 2)) as i16
    }
}

/// Size of the 0x00a0 payload FANUC's cnc_wrparam accepts.
pub const PARAMTYPE_LEN: usize = 28;

wire_struct! {
    /// One entry of a 0x0010 / 0x0031 answer.
    pub struct InfoEntry {
        pub number: i32,
        pub ptype: i32,
    }
}

/// Payload of 0x0010 / 0x0031: previous and next numbers, then entries.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct InfoList {
    pub prev: i32,
    pub next: i32,
    pub entries: Vec<InfoEntry>,
}

impl Wire for InfoList {
    fn encode(&self, w: &mut Writer) {
        w.i32(self.prev);
        w.i32(self.next);
        self.entries.encode(w);
    }
    fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        let prev = r.i32()?;
        let next = r.i32()?;
        // Whole entries only; a ragged tail is not an entry.
        let mut entries = Vec::with_capacity(r.remaining() / 8);
        while r.remaining() >= 8 {
            entries.push(InfoEntry::decode(r)?);
        }
        Ok(InfoList {
            prev,
            next,
            entries,
        })
    }
}

/// Bit 8 of a 16i / rdparainfo type word: an axis parameter.
pub const INFO_AXIS: i32 = 0x100;

/// cnc_rdparainfo / cnc_rddiaginfo: [s, n].
#[derive(Debug, Clone, Copy)]
pub struct ReadInfo {
    pub table: Table,
    pub start: i32,
    pub count: i32,
}

impl Call for ReadInfo {
    type Output = InfoList;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(
            self.table.info_cmd(cx.class),
            &[self.start, self.count.min(INFO_MAX)],
        )]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<InfoList> {
        payload(resp, 0)
    }
}

/// What cnc_wrparam learns before writing: the element kind and whether
/// the parameter is an axis parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WriteInfo {
    pub ptype: u16,
    pub elem: Elem,
    pub axis: bool,
}

/// First step of cnc_wrparam: read the parameter's attributes.
/// 30i: 0x00a0 [number, 1], exactly 28 bytes; 16i: 0x0010 [number, 1].
/// Anything else (wrong size, unknown type) is EW_NUMBER, as FANUC's library answers.
#[derive(Debug, Clone, Copy)]
pub struct ParamInfo {
    pub number: i32,
}

impl Call for ParamInfo {
    type Output = WriteInfo;
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let cmd = match cx.class {
            CncClass::Series30 => PARAMTYPE,
            CncClass::Series16 { .. } => RDPARAINFO,
        };
        vec![ReqSub::cnc(cmd, &[self.number, 1])]
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<WriteInfo> {
        let s = sub(resp, 0)?;
        let bad = || Error::local(EW_NUMBER, "parameter attributes not understood");
        match cx.class {
            CncClass::Series30 => {
                if s.payload.len() != PARAMTYPE_LEN {
                    return Err(bad());
                }
                let t = ParamType30::from_bytes(&s.payload)?;
                let elem = Elem::of_param(t.ptype)
                    .filter(|_| t.ptype <= 4)
                    .ok_or_else(bad)?;
                Ok(WriteInfo {
                    ptype: t.ptype,
                    elem,
                    axis: t.axis == 2,
                })
            }
            CncClass::Series16 { .. } => {
                let l = InfoList::from_bytes(&s.payload).map_err(|_| bad())?;
                // FANUC's library wants exactly the one entry asked for (a
                // longer answer is EW_NUMBER, nothing written).
                if l.entries.len() != 1 {
                    return Err(bad());
                }
                let e = &l.entries[0];
                let ptype = (e.ptype & 3) as u16;
                Ok(WriteInfo {
                    ptype,
                    elem: Elem::of_param(ptype).ok_or_else(bad)?,
                    axis: e.ptype & INFO_AXIS != 0,
                })
            }
        }
    }
}

/// Second step of cnc_wrparam: the write itself.
#[derive(Debug, Clone)]
pub struct WriteParam {
    pub number: i32,
    pub axis: i16,
    pub ptype: u16,
    pub values: Vec<Num>,
}

impl WriteParam {
    /// The write payload of the class. A 16i-class payload has one value
    /// word per axis of `max_axes` (the CNC's maximum: 8 + 4 · max_axes
    /// bytes, as FANUC's library sends it).
    pub fn payload(&self, class: CncClass, max_axes: usize) -> Vec<u8> {
        let real = Elem::of_param(self.ptype) == Some(Elem::Real);
        match class {
            CncClass::Series30 => {
                let mut values: Vec<Value> =
                    self.values.iter().map(|n| value_of_num(*n, real)).collect();
                values.resize(WRITE_RECORDS_30, Value::default());
                Param30 {
                    number: self.number,
                    axis: self.axis,
                    ptype: self.ptype,
                    values,
                }
                .to_bytes()
            }
            CncClass::Series16 { .. } => {
                let mut values: Vec<i32> = if real {
                    self.values
                        .iter()
                        .flat_map(|n| [n.value, n.dec & 0xffff])
                        .collect()
                } else {
                    self.values.iter().map(|n| n.value).collect()
                };
                values.resize(max_axes, 0);
                Param16 {
                    number: self.number,
                    axis: self.axis,
                    ptype: self.ptype,
                    values,
                }
                .to_bytes()
            }
        }
    }
}

impl Call for WriteParam {
    type Output = ();
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let cmd = match cx.class {
            CncClass::Series30 => WRPARAM,
            CncClass::Series16 { .. } => WRPARAM16,
        };
        vec![ReqSub::cnc(cmd, &[]).with_payload(self.payload(cx.class, cx.axes()))]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        sub(resp, 0).map(|_| ())
    }
}

/// The `length` cnc_rdparam / cnc_diagnoss need for one value of `elem`
/// (FANUC checks it after the exchange).
/// cnc_rdparam / cnc_diagnoss after the exchange (FANUC's library):
/// `length` must hold 4 + the size of every value answered (one, or
/// max-axes for an answer with a negative axis word).
pub fn check_length(length: i16, item: &Item) -> Result<()> {
    let need = 4 + item.elem.map_or(0, Elem::size) * item.values.len();
    if (length as i32) < need as i32 {
        return Err(Error::local(
            EW_LENGTH,
            "length below 4 + the size of the values answered",
        ));
    }
    Ok(())
}

wire_struct! {
    /// Payload of 0x0011 / 0x0032: three i32, of which the library keeps the low 16 bits.
    pub struct NumRange {
        pub min: i32,
        pub max: i32,
        pub total: i32,
    }
}

pub fn rdnum(table: Table) -> super::call::Single<NumRange> {
    super::call::Single::new(ReqSub::cnc(
        match table {
            Table::Param => RDPARANUM,
            Table::Diag => RDDIAGNUM,
        },
        &[],
    ))
}

/// One IODBPRM record of cnc_rdparam_ext / cnc_rddiag_ext.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ExtRecord {
    /// The CNC does not know the number: only datano and type = -1 are written.
    Missing,
    Found {
        ptype: i16,
        axis: i16,
        info: i16,
        unit: i16,
        /// max-axes (at most 32) {value, decimals}; base ignored, as FANUC's library does.
        data: Vec<(i32, i32)>,
    },
}

/// Up to [`EXT_PER_FRAME`] numbers: per number its attribute record
/// (0x00a0 / 0x00a2 [no, 1]) and its all-axes values (0x008d / 0x0093 [no, no, -1]).
#[derive(Debug, Clone)]
pub struct ReadExt {
    pub table: Table,
    pub numbers: Vec<i32>,
}

impl Call for ReadExt {
    /// The records decoded, and the error that stopped decoding (if any):
    /// records before it are still written, as FANUC's library does.
    type Output = (Vec<ExtRecord>, Option<Error>);
    fn request(&self, cx: &Ctx) -> Vec<ReqSub> {
        let (info, read) = match self.table {
            Table::Param => (PARAMTYPE, RDPARAM),
            Table::Diag => (DIAGTYPE, DIAGNOSS),
        };
        let _ = cx;
        self.numbers
            .iter()
            .flat_map(|n| {
                [
                    ReqSub::cnc(info, &[*n, 1]),
                    ReqSub::cnc(read, &[*n, *n, -1]),
                ]
            })
            .collect()
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Self::Output> {
        let count = cx.axes();
        let mut out = Vec::with_capacity(self.numbers.len());
        for (k, n) in self.numbers.iter().enumerate() {
            let one = || -> Result<ExtRecord> {
                // An unknown number: error 3 in the value subpacket (FANUC's
                // library) or, as our simulator answers, already in the attributes.
                let t: ParamType30 = match payload(resp, 2 * k) {
                    Err(Error::Cnc {
                        code: EW_NUMBER, ..
                    }) => return Ok(ExtRecord::Missing),
                    r => r?,
                };
                let v = match sub(resp, 2 * k + 1) {
                    Err(Error::Cnc {
                        code: EW_NUMBER, ..
                    }) => return Ok(ExtRecord::Missing),
                    r => r?,
                };
                if t.number != *n {
                    return Ok(ExtRecord::Missing);
                }
                let p = Param30::from_bytes(&v.payload)?;
                if p.values.len() < count {
                    return Err(Error::short("fewer value records than the CNC's axes"));
                }
                let (info, unit) = match self.table {
                    Table::Param => (t.ext_info_param(), t.ext_unit_param()),
                    Table::Diag => ((t.flags & 1) as i16, t.unit_hi as i16),
                };
                Ok(ExtRecord::Found {
                    ptype: p.ptype as i16,
                    axis: t.ext_axis(),
                    info,
                    unit,
                    data: p.values[..count]
                        .iter()
                        .map(|r| (r.value, r.exp as i32))
                        .collect(),
                })
            };
            match one() {
                Ok(r) => out.push(r),
                Err(e) => return Ok((out, Some(e))),
            }
        }
        Ok((out, None))
    }
}

// --- rdparar / wrparas ---
//
// cnc_rdparar and cnc_wrparas move parameters in one packed C format
// ([`Packed`]): per parameter i16 number, i16 type word
// `(type << 8) | (axis & 0xff)`, then one value (or max-axes values for
// axis -1) of the type's size (bit/byte 1, word 2, 2-word 4, real 8 =
// value + decimals), each record padded to a multiple of 4 (padding bytes
// are never written). On the wire both use the 30i block of cnc_rdparam /
// cnc_wrparam ([`Param30`], 8 + 8 · max-axes bytes). Only the 30i class is
// known (oracle findings); a 16i-class CNC gets EW_FUNC without traffic.

/// Blocks per 0x008e frame of cnc_wrparas (FANUC's library sends 5).
pub const WRPARAS_PER_FRAME: usize = 5;

/// One parameter of the packed cnc_rdparar / cnc_wrparas buffer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Packed {
    pub number: i16,
    /// Axis byte of the type word as a signed value (-1 all axes, 0, 1..).
    pub axis: i8,
    /// Type (high byte of the type word): 0 bit, 1 byte, 2 word, 3 2-word, 4 real.
    pub ptype: u8,
    /// One value, or `axes` values when `axis` is -1.
    pub values: Vec<Num>,
}

impl Packed {
    /// Values a record with this axis byte carries.
    pub fn count(axis: i8, axes: usize) -> usize {
        if axis < 0 { axes } else { 1 }
    }
    fn elem(ptype: u8) -> Option<Elem> {
        Elem::of_param(ptype as u16).filter(|_| ptype <= 4)
    }
    /// Bytes the record takes in the buffer, padding included.
    pub fn padded_len(&self) -> usize {
        (self.to_c().len() + 3) & !3
    }
    /// The record's bytes without the padding (a type we do not know
    /// carries no value).
    pub fn to_c(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(4 + 8 * self.values.len());
        out.extend_from_slice(&self.number.to_le_bytes());
        out.push(self.axis as u8);
        out.push(self.ptype);
        if let Some(e) = Self::elem(self.ptype) {
            for v in &self.values {
                let at = out.len();
                out.resize(at + e.size(), 0);
                e.put(&mut out[at..], *v);
            }
        }
        out
    }
    /// Reads one record from the start of `inp` (what `to_c` wrote) and
    /// returns it with the bytes it takes, padding included (the padding
    /// of the last record may be missing). EW_ATTRIB for a type other than
    /// 0..4, EW_LENGTH if the record does not fit in `inp`.
    pub fn from_c(inp: &[u8], axes: usize) -> Result<(Packed, usize)> {
        if inp.len() < 4 {
            return Err(Error::local(EW_LENGTH, "a record does not fit in length"));
        }
        let number = i16::from_le_bytes([inp[0], inp[1]]);
        let axis = inp[2] as i8;
        let ptype = inp[3];
        let e = Self::elem(ptype).ok_or(Error::local(
            crate::ew::EW_ATTRIB,
            "parameter type not 0..4",
        ))?;
        let n = Self::count(axis, axes);
        let end = 4 + n * e.size();
        if inp.len() < end {
            return Err(Error::local(EW_LENGTH, "a record does not fit in length"));
        }
        let values = (0..n).map(|i| e.get(&inp[4 + i * e.size()..])).collect();
        Ok((
            Packed {
                number,
                axis,
                ptype,
                values,
            },
            ((end + 3) & !3).min(inp.len()),
        ))
    }
    /// The record of a 0x008d answer block: the first value, or `axes`
    /// values for a block with axis < 0.
    pub fn of_block(b: &Param30, axes: usize) -> Result<Packed> {
        let ptype = b.ptype as u8;
        let real = Self::elem(ptype) == Some(Elem::Real);
        let n = Self::count(b.axis as i8, axes);
        if b.values.len() < n {
            return Err(Error::short(
                "parameter block carries fewer values than its axis word needs",
            ));
        }
        Ok(Packed {
            number: b.number as i16,
            axis: if b.axis < 0 { -1 } else { b.axis as i8 },
            ptype,
            values: b.values[..n]
                .iter()
                .map(|v| num_of_value(*v, real))
                .collect(),
        })
    }
    /// The 0x008e write block of the record (cnc_wrparam's payload).
    pub fn to_block(&self) -> Vec<u8> {
        WriteParam {
            number: self.number as i32,
            axis: self.axis as i16,
            ptype: self.ptype as u16,
            values: self.values.clone(),
        }
        .payload(CncClass::Series30, WRITE_RECORDS_30)
    }
}

/// Size of one block of a 30i 0x008d answer / 0x008e write.
pub fn block_len(max_axes: usize) -> usize {
    8 + 8 * max_axes
}

/// One exchange of cnc_rdparar: [s, e, axis] → the records of the answer's
/// whole blocks (8 + 8 · max-axes bytes each; a ragged tail is ignored).
#[derive(Debug, Clone, Copy)]
pub struct ReadRange {
    pub start: i32,
    pub end: i32,
    pub axis: i16,
}

impl Call for ReadRange {
    type Output = Vec<Packed>;
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        vec![ReqSub::cnc(
            RDPARAM,
            &[self.start, self.end, self.axis as i32],
        )]
    }
    fn decode(&self, cx: &Ctx, resp: &[RespSub]) -> Result<Vec<Packed>> {
        let s = sub(resp, 0)?;
        let axes = cx.axes();
        let size = block_len(cx.max_axes as usize);
        if s.payload.len() < size {
            // FANUC's library then loops on a garbage number; we stop.
            return Err(Error::short(
                "parameter range answer shorter than one block",
            ));
        }
        s.payload
            .chunks_exact(size)
            .map(|c| Packed::of_block(&Param30::from_bytes(c)?, axes))
            .collect()
    }
}

/// One frame of cnc_wrparas: up to [`WRPARAS_PER_FRAME`] records as
/// consecutive 0x008e blocks in one subpacket.
#[derive(Debug, Clone)]
pub struct WriteSeveral {
    pub records: Vec<Packed>,
}

impl Call for WriteSeveral {
    type Output = ();
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        let payload = self.records.iter().flat_map(Packed::to_block).collect();
        vec![ReqSub::cnc(WRPARAM, &[]).with_payload(payload)]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        sub(resp, 0).map(|_| ())
    }
}
