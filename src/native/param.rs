//! Parameters (cnc_rdparam) and diagnosis data (cnc_diagnoss), typed.

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::decimal::Decimal;
use super::error::{Error, Ew, Result};
use super::part::{Failed, Part, Then, via};
use crate::proto::param::{Item, ReadOne, Table};
use std::fmt;

/// How the CNC stores a parameter or diagnosis item.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kind {
    /// Eight bits (#7..#0).
    Bit,
    Byte,
    Word,
    /// Two words (32 bits).
    Long,
    /// A value with decimal places.
    Real,
}

impl fmt::Display for Kind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(match self {
            Kind::Bit => "bit",
            Kind::Byte => "byte",
            Kind::Word => "word",
            Kind::Long => "2word",
            Kind::Real => "real",
        })
    }
}

impl Kind {
    /// The type word of an answer: parameters 0 bit, 1 byte, 2 word, 3
    /// 2-word, 4 real; diagnosis 0 byte, 1 word, 2 2-word, 3 and 4 bit, 5
    /// real (only the low byte counts, as in FANUC's library).
    fn of(table: Table, t: u16) -> Option<Kind> {
        Some(match (table, t & 0xff) {
            (Table::Param, 0) | (Table::Diag, 3 | 4) => Kind::Bit,
            (Table::Param, 1) | (Table::Diag, 0) => Kind::Byte,
            (Table::Param, 2) | (Table::Diag, 1) => Kind::Word,
            (Table::Param, 3) | (Table::Diag, 2) => Kind::Long,
            (Table::Param, 4) | (Table::Diag, 5) => Kind::Real,
            _ => return None,
        })
    }
}

/// One value of a parameter or diagnosis item.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Value {
    /// The eight bits of a bit type (bit n is `1 << n`).
    Bits(u8),
    /// A byte, word or 2-word value, as the CNC sent it.
    Int(i32),
    Real(Decimal),
}

impl fmt::Display for Value {
    /// Bits as `#7..#0` ("00000010"), numbers as the CNC shows them.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Bits(b) => f.pad(&format!("{b:08b}")),
            Value::Int(v) => f.pad(&v.to_string()),
            Value::Real(d) => d.fmt(f),
        }
    }
}

/// A Rust type a [`Value`] reads as: `i8`/`u8` (bits, bytes), `i16`,
/// `i32`, `i64`, `f64` (any value), [`Decimal`] (any value, exact) or
/// [`Value`] itself. A value that does not fit (a real read as `i32`, 300
/// read as `i8`) is an `EW_ATTRIB` error naming the item.
pub trait FromValue: Sized {
    /// `None` when the value does not fit the type.
    fn from_value(v: Value) -> Option<Self>;
}

impl FromValue for Value {
    fn from_value(v: Value) -> Option<Value> {
        Some(v)
    }
}

macro_rules! from_int {
    ($($t:ty),*) => {$(
        impl FromValue for $t {
            fn from_value(v: Value) -> Option<$t> {
                match v {
                    Value::Bits(b) => <$t>::try_from(b).ok(),
                    Value::Int(i) => <$t>::try_from(i).ok(),
                    Value::Real(_) => None,
                }
            }
        }
    )*};
}
from_int!(u8, i16, i32, i64);

impl FromValue for i8 {
    /// Bits as the signed byte of the C structures' `char`.
    fn from_value(v: Value) -> Option<i8> {
        match v {
            Value::Bits(b) => Some(b as i8),
            Value::Int(i) => i8::try_from(i).ok(),
            Value::Real(_) => None,
        }
    }
}

impl FromValue for f64 {
    fn from_value(v: Value) -> Option<f64> {
        Some(match v {
            Value::Bits(b) => f64::from(b),
            Value::Int(i) => f64::from(i),
            Value::Real(d) => d.to_f64(),
        })
    }
}

impl FromValue for Decimal {
    fn from_value(v: Value) -> Option<Decimal> {
        Some(match v {
            Value::Bits(b) => Decimal::from(i32::from(b)),
            Value::Int(i) => Decimal::from(i),
            Value::Real(d) => d,
        })
    }
}

/// A parameter or diagnosis item as the CNC holds it.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Param {
    pub number: u32,
    pub kind: Kind,
    /// A value per axis (all of them, or the one asked for).
    pub per_axis: bool,
    /// One value, or one per axis (axis 1 first) when `per_axis`.
    pub values: Vec<Value>,
}

struct Names {
    call: &'static str,
    what: &'static str,
}

fn names(table: Table) -> Names {
    match table {
        Table::Param => Names {
            call: "cnc_rdparam",
            what: "parameter",
        },
        Table::Diag => Names {
            call: "cnc_diagnoss",
            what: "diagnosis",
        },
    }
}

/// The answer as a [`Param`]: at most `axes` values of a per-axis item.
fn param_of(table: Table, number: u32, item: Item, axes: usize) -> Result<Param> {
    let n = names(table);
    let kind = Kind::of(table, item.ptype).ok_or_else(|| {
        let msg = format!("{} {number} has type {}", n.what, item.ptype);
        Error::invalid(n.call, Ew::ATTRIB, msg)
    })?;
    // The answer's axis word: negative all axes, n one axis, 0 none.
    let per_axis = item.axis != 0;
    let take = if item.axis < 0 { axes } else { 1 };
    let values = item
        .values
        .iter()
        .take(take)
        .map(|v| match kind {
            Kind::Bit => Value::Bits(v.value as u8),
            Kind::Real => Value::Real(Decimal::new(v.value, v.dec as i16)),
            _ => Value::Int(v.value),
        })
        .collect();
    Ok(Param {
        number,
        kind,
        per_axis,
        values,
    })
}

/// One read of `number` with the axis word `axis` (0 none, -1 all, n).
fn read_part(
    table: Table,
    number: u32,
    axis: i16,
    axes: usize,
) -> impl Part<Out = Param> + Send + 'static {
    let n = names(table);
    let c = ReadOne {
        table,
        number: number.min(i32::MAX as u32) as i32,
        axis,
        flag: 0,
    };
    via(n.call, c, 8 + 8 * crate::types::MAX_AXIS, move |item| {
        param_of(table, number, item, axes)
    })
}

/// One value as `T`: EW_ATTRIB when the item is per axis and no axis was
/// given, or when the value does not fit `T`.
fn one<T: FromValue>(table: Table, p: Param) -> Result<T> {
    let n = names(table);
    let (number, kind) = (p.number, p.kind);
    let [v] = p.values[..] else {
        let msg = format!("{} {number} is per axis: give an axis", n.what);
        return Err(Error::invalid(n.call, Ew::ATTRIB, msg));
    };
    T::from_value(v).ok_or_else(|| {
        let t = std::any::type_name::<T>().rsplit("::").next().unwrap_or("");
        let msg = format!("{} {number} is {kind} ({v}), not readable as {t}", n.what);
        Error::invalid(n.call, Ew::ATTRIB, msg)
    })
}

/// The axis word for `axis` (None: 0, the whole item); `none` for None.
fn axis_word(table: Table, axis: Option<u16>, none: i16) -> Result<i16> {
    match axis.map(i16::try_from) {
        None => Ok(none),
        Some(Ok(a)) if a >= 1 => Ok(a),
        _ => {
            let n = names(table);
            Err(Error::invalid(n.call, Ew::ATTRIB, "axes are numbered 1.."))
        }
    }
}

fn typed_part<T: FromValue + Send + 'static>(
    cnc: &Cnc,
    table: Table,
    number: u32,
    axis: Option<u16>,
) -> Result<impl Part<Out = T> + Send + 'static> {
    let p = read_part(table, number, axis_word(table, axis, 0)?, path_axes(cnc));
    Ok(Then(p, move |p| one::<T>(table, p)))
}

/// The whole item (axis word -1) or one axis of it, as a [`Param`].
fn values_part(
    cnc: &Cnc,
    table: Table,
    number: u32,
    axis: Option<u16>,
) -> Result<impl Part<Out = Param> + Send + 'static> {
    let word = axis_word(table, axis, -1)?;
    Ok(read_part(table, number, word, path_axes(cnc)))
}

/// The controlled axes of the current path.
fn path_axes(cnc: &Cnc) -> usize {
    cnc.sysinfo()
        .map_or(cnc.ctx().axes(), |s| usize::from(s.axes))
}

impl Cnc {
    /// One value of parameter `number`: of the whole path (`axis` None) or
    /// of axis `axis` (1..), read as `T` (see [`FromValue`]).
    ///
    /// ```
    /// use fwlib32::native::{Cnc, Decimal, Ew, Value};
    /// use fwlib32::sim::{Profile, Simulator};
    /// use std::time::Duration;
    ///
    /// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
    /// assert_eq!(cnc.param::<i32>(6711, None)?, 1234); // parts count, 2-word
    /// assert_eq!(cnc.param::<Decimal>(1320, Some(2))?, Decimal::new(500000, 3));
    /// assert_eq!(cnc.param::<Value>(0, None)?.to_string(), "00000010"); // bits
    /// // A real does not read as an integer, and an absent number is the CNC's EW_NUMBER:
    /// assert_eq!(cnc.param::<i32>(1320, Some(1)).unwrap_err().code(), Ew::ATTRIB);
    /// assert_eq!(cnc.param::<i32>(9999, None).unwrap_err().code(), Ew::NUMBER);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn param<T: FromValue + Send + 'static>(
        &self,
        number: u32,
        axis: Option<u16>,
    ) -> Result<T> {
        self.run(typed_part(self, Table::Param, number, axis)?)
    }

    /// Parameter `number` with its kind: with `axis` None the whole
    /// parameter (its one value, or one per axis of the path), with
    /// `Some(n)` the value of axis `n` alone (`per_axis` stays true).
    ///
    /// ```
    /// # use fwlib32::native::{Cnc, Kind, Value};
    /// # use fwlib32::sim::{Profile, Simulator};
    /// # let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// # let cnc = Cnc::connect(&sim.addr().to_string(), std::time::Duration::from_secs(5))?;
    /// let p = cnc.param_values(1825, None)?; // servo loop gain, per axis
    /// assert_eq!((p.kind, p.per_axis, p.values.len()), (Kind::Word, true, 3));
    /// assert_eq!(cnc.param_values(1825, Some(3))?.values, [Value::Int(3000)]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn param_values(&self, number: u32, axis: Option<u16>) -> Result<Param> {
        self.run(values_part(self, Table::Param, number, axis)?)
    }

    /// One value of diagnosis item `number` (as [`Cnc::param`]).
    pub fn diag<T: FromValue + Send + 'static>(&self, number: u32, axis: Option<u16>) -> Result<T> {
        self.run(typed_part(self, Table::Diag, number, axis)?)
    }

    /// Diagnosis item `number` with its kind (as [`Cnc::param_values`]).
    pub fn diag_values(&self, number: u32, axis: Option<u16>) -> Result<Param> {
        self.run(values_part(self, Table::Diag, number, axis)?)
    }
}

impl Batch<'_> {
    /// [`Cnc::param`] in the batch; a bad axis number fails its ticket.
    pub fn param<T: FromValue + Send + 'static>(
        &mut self,
        number: u32,
        axis: Option<u16>,
    ) -> Ticket<T> {
        self.typed(Table::Param, number, axis)
    }

    /// [`Cnc::param_values`] in the batch.
    pub fn param_values(&mut self, number: u32, axis: Option<u16>) -> Ticket<Param> {
        match values_part(self.cnc(), Table::Param, number, axis) {
            Ok(p) => self.push(p),
            Err(e) => self.push(Failed::new(e)),
        }
    }

    /// [`Cnc::diag_values`] in the batch.
    pub fn diag_values(&mut self, number: u32, axis: Option<u16>) -> Ticket<Param> {
        match values_part(self.cnc(), Table::Diag, number, axis) {
            Ok(p) => self.push(p),
            Err(e) => self.push(Failed::new(e)),
        }
    }

    /// [`Cnc::diag`] in the batch.
    pub fn diag<T: FromValue + Send + 'static>(
        &mut self,
        number: u32,
        axis: Option<u16>,
    ) -> Ticket<T> {
        self.typed(Table::Diag, number, axis)
    }

    fn typed<T: FromValue + Send + 'static>(
        &mut self,
        table: Table,
        number: u32,
        axis: Option<u16>,
    ) -> Ticket<T> {
        match typed_part(self.cnc(), table, number, axis) {
            Ok(p) => self.push(p),
            Err(e) => self.push(Failed::new(e)),
        }
    }
}
