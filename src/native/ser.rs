//! `serde::Serialize` for the API's types (the `serde` feature): the JSON
//! the `focas` command prints. Status words are `{"code": 1, "name":
//! "MEM"}`, decimals their nearest `f64` (an axis also gives its
//! `decimals`), units and kinds their names, CNC clock readings RFC 3339
//! with this computer's UTC offset ([`Timestamp::rfc3339`]).

use super::alarm::{Alarm, AlarmKind, HistoryEntry, Timestamp};
use super::decimal::Decimal;
use super::param::{Kind, Value};
use super::position::{AxisPosition, Unit};
use super::status::{AlarmState, Emergency, Mode, Motion, Run};
use serde::ser::{Serialize, SerializeStruct, Serializer};

macro_rules! word {
    ($($t:ty),*) => {$(
        impl Serialize for $t {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let mut o = s.serialize_struct(stringify!($t), 2)?;
                o.serialize_field("code", &self.code())?;
                o.serialize_field("name", &self.to_string())?;
                o.end()
            }
        }
    )*};
}
word!(Mode, Run, Motion, Emergency, AlarmState);

macro_rules! named {
    ($($t:ty),*) => {$(
        impl Serialize for $t {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.collect_str(self)
            }
        }
    )*};
}
named!(Unit, Kind);

impl Serialize for Decimal {
    /// The nearest `f64`: 125.0, -0.125.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_f64(self.to_f64())
    }
}

impl Serialize for Value {
    /// Bits as their byte, integers and decimals as numbers.
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Value::Bits(b) => s.serialize_u8(*b),
            Value::Int(i) => s.serialize_i32(*i),
            Value::Real(d) => d.serialize(s),
        }
    }
}

impl Serialize for Timestamp {
    /// RFC 3339 ("2024-05-17T13:45:30+02:00"); a reading that is no date
    /// as the CNC gave it ("2024-02-30 10:00:00").
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self.rfc3339() {
            Some(t) => s.serialize_str(&t),
            None => s.collect_str(self),
        }
    }
}

impl Serialize for AxisPosition {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut o = s.serialize_struct("AxisPosition", 7)?;
        o.serialize_field("name", &self.name)?;
        o.serialize_field("absolute", &self.absolute)?;
        o.serialize_field("machine", &self.machine)?;
        o.serialize_field("relative", &self.relative)?;
        o.serialize_field("distance", &self.distance)?;
        o.serialize_field("decimals", &self.absolute.decimals)?;
        o.serialize_field("unit", &self.unit)?;
        o.end()
    }
}

/// An alarm's `number`, `type`, `prefix` ("OT", or null), `code` as the
/// CNC shows it ("OT0500"), `axis`, `message`, and its `time`.
fn alarm<S: Serializer>(
    s: S,
    name: &'static str,
    (number, kind, axis, message): (i32, AlarmKind, i16, &str),
    time: Option<&Timestamp>,
) -> Result<S::Ok, S::Error> {
    let mut o = s.serialize_struct(name, 7)?;
    if let Some(t) = time {
        o.serialize_field("time", t)?;
    }
    o.serialize_field("number", &number)?;
    o.serialize_field("type", &kind.0)?;
    o.serialize_field("prefix", &kind.prefix())?;
    o.serialize_field("code", &super::alarm::shown(kind, number))?;
    o.serialize_field("axis", &axis)?;
    o.serialize_field("message", message)?;
    o.end()
}

impl Serialize for Alarm {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let a = (self.number, self.kind, self.axis, &*self.message);
        alarm(s, "Alarm", a, None)
    }
}

impl Serialize for HistoryEntry {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let a = (self.number, self.kind, self.axis, &*self.message);
        alarm(s, "HistoryEntry", a, Some(&self.time))
    }
}
