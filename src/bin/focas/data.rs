//! param, diag, macro, pmc.

use crate::out::{Fail, Table, json_line, num, print, to_json};
use fwlib32::native::{Cnc, Decimal, Kind, PmcArea, Value};
use serde_json::{Value as Json, json};

/// `focas param N [--axis A]` / `focas diag N [--axis A]`: the item with
/// the names of the axes its values belong to, in one batch.
pub fn param(
    cnc: &Cnc,
    diag: bool,
    number: u32,
    axis: Option<u16>,
    json: bool,
) -> Result<(), Fail> {
    let mut b = cnc.batch();
    let item = if diag {
        b.diag_values(number, axis)
    } else {
        b.param_values(number, axis)
    };
    let names = b.axis_names();
    let mut r = b.send()?;
    let p = r.take(item)?;
    let names = r.take(names).unwrap_or_default();
    let axis_names: Vec<String> = match (p.per_axis, axis) {
        (false, _) => Vec::new(),
        (true, Some(a)) => vec![axis_name(&names, usize::from(a))],
        (true, None) => (1..=p.values.len()).map(|i| axis_name(&names, i)).collect(),
    };
    if json {
        let mut o = to_json(&p);
        o["axis"] = json!(axis);
        o["axes"] = json!(axis_names);
        return json_line(&o);
    }
    let mut t = Table::new(if axis_names.is_empty() {
        &[true, false, true]
    } else {
        &[true, false, false, true]
    });
    let head = [number.to_string(), p.kind.to_string()];
    for (i, v) in p.values.iter().enumerate() {
        let [n, k] = if i == 0 {
            head.clone()
        } else {
            Default::default()
        };
        let shown = match (p.kind, v) {
            (Kind::Bit, Value::Bits(b)) => format!("{b:08b}"),
            _ => v.to_string(),
        };
        match axis_names.get(i) {
            Some(a) => t.row([n, k, a.clone(), shown]),
            None => t.row([n, k, shown]),
        }
    }
    print(&t.render())
}

/// Axis `i`'s name (1-based), or its number.
fn axis_name(names: &[String], i: usize) -> String {
    names
        .get(i.wrapping_sub(1))
        .filter(|n| !n.is_empty())
        .cloned()
        .unwrap_or_else(|| format!("axis {i}"))
}

/// A `focas macro` argument: the variable, and the value to write first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MacroSpec {
    pub number: u32,
    /// `Some(None)`: make it vacant.
    pub write: Option<Option<Decimal>>,
}

/// `N`, `#N`, `N=V` (V a number, or "vacant").
pub fn parse_macro(spec: &str) -> Result<MacroSpec, String> {
    let bad = || format!("{spec:?} is not N or N=VALUE (500, 500=1.25, 500=vacant)");
    let (n, write) = match spec.split_once('=') {
        Some((n, v)) => (n, Some(v.trim())),
        None => (spec, None),
    };
    let number: u32 = n
        .trim()
        .trim_start_matches('#')
        .parse()
        .map_err(|_| bad())?;
    let write = match write {
        None => None,
        Some("vacant" | "null" | "<null>") => Some(None),
        Some(v) => Some(Some(
            v.parse::<Decimal>().map_err(|e| format!("{spec:?}: {e}"))?,
        )),
    };
    Ok(MacroSpec { number, write })
}

/// `focas macro N` or `focas macro N=V`.
pub fn macro_var(cnc: &Cnc, spec: MacroSpec, json: bool) -> Result<(), Fail> {
    let number = spec.number;
    if let Some(value) = spec.write {
        cnc.set_macro_var(number, value)?;
    }
    let v = cnc.macro_var(number)?;
    if json {
        return json_line(&json!({
            "number": number,
            "value": v.map(num),
            "decimals": v.map(|d| d.decimals),
        }));
    }
    let shown = v.map_or("vacant".to_string(), |d| d.to_string());
    print(&format!("#{number}  {shown}\n"))
}

/// The element types `focas pmc --type` reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum PmcKind {
    /// Unsigned bytes
    Byte,
    /// Signed 16-bit words
    Word,
    /// Signed 32-bit longs
    Long,
    /// 32-bit reals
    Float,
    /// 64-bit reals
    Double,
}

/// What a PMC address argument names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PmcSpec {
    Range(PmcArea, u16, u16),
    Bit(PmcArea, u16, u8),
}

/// `D100`, `D100..D120`, `D100..120`, `R0.3`.
pub fn parse_pmc(s: &str) -> Result<PmcSpec, String> {
    let bad = || format!("{s:?} is not an address (D100, D100..D120, R0.3)");
    let split = |t: &str| -> Result<(PmcArea, String), String> {
        let t = t.trim();
        let letter = t.get(..1).ok_or_else(bad)?;
        let area = letter
            .parse::<PmcArea>()
            .map_err(|e| format!("{s:?}: {e}"))?;
        Ok((area, t[1..].to_string()))
    };
    let (area, first) = split(s.split("..").next().unwrap_or(""))?;
    if let Some((a, bit)) = first.split_once('.') {
        if s.contains("..") {
            return Err(bad());
        }
        let a = a.parse().map_err(|_| bad())?;
        let bit = bit.parse().ok().filter(|b| *b <= 7).ok_or_else(bad)?;
        return Ok(PmcSpec::Bit(area, a, bit));
    }
    let start: u16 = first.parse().map_err(|_| bad())?;
    let end = match s.split_once("..") {
        None => start,
        Some((_, e)) => {
            let e = e.trim();
            let digits = match e.get(..1) {
                Some(l) if l.chars().all(|c| c.is_ascii_alphabetic()) => {
                    let (a, rest) = split(e)?;
                    if a != area {
                        return Err(format!("{s:?} spans two areas"));
                    }
                    rest
                }
                _ => e.to_string(),
            };
            digits.parse().map_err(|_| bad())?
        }
    };
    if end < start {
        return Err(format!("{s:?} ends before it starts"));
    }
    Ok(PmcSpec::Range(area, start, end))
}

/// `focas pmc ADDR[..END] [--type T]`.
pub fn pmc(cnc: &Cnc, spec: PmcSpec, kind: PmcKind, json: bool) -> Result<(), Fail> {
    let (area, s, e) = match spec {
        PmcSpec::Bit(area, a, bit) => {
            let v = cnc.pmc_bit(area, a, bit)?;
            if json {
                return json_line(&json!({
                    "area": area.to_string(), "address": a, "bit": bit, "value": v,
                }));
            }
            return print(&format!("{area}{a}.{bit}  {}\n", u8::from(v)));
        }
        PmcSpec::Range(area, s, e) => (area, s, e),
    };
    let r = s..=e;
    let (size, values): (u16, Vec<Json>) = match kind {
        PmcKind::Byte => (
            1,
            cnc.pmc::<u8>(area, r)?
                .into_iter()
                .map(Json::from)
                .collect(),
        ),
        PmcKind::Word => (
            2,
            cnc.pmc::<i16>(area, r)?
                .into_iter()
                .map(Json::from)
                .collect(),
        ),
        PmcKind::Long => (
            4,
            cnc.pmc::<i32>(area, r)?
                .into_iter()
                .map(Json::from)
                .collect(),
        ),
        PmcKind::Float => (
            4,
            cnc.pmc::<f32>(area, r)?
                .into_iter()
                .map(Json::from)
                .collect(),
        ),
        PmcKind::Double => (
            8,
            cnc.pmc::<f64>(area, r)?
                .into_iter()
                .map(Json::from)
                .collect(),
        ),
    };
    let addr = |i: usize| s as usize + i * usize::from(size);
    if json {
        let list: Vec<Json> = values
            .iter()
            .enumerate()
            .map(|(i, v)| json!({ "address": addr(i), "value": v }))
            .collect();
        let kind = format!("{kind:?}").to_lowercase();
        return json_line(&json!({ "area": area.to_string(), "type": kind, "values": list }));
    }
    let mut t = Table::new(&[false, true]);
    for (i, v) in values.iter().enumerate() {
        t.row([format!("{area}{}", addr(i)), v.to_string()]);
    }
    print(&t.render())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pmc_addresses() {
        use PmcSpec::*;
        assert_eq!(parse_pmc("D100"), Ok(Range(PmcArea::D, 100, 100)));
        assert_eq!(parse_pmc("D100..D120"), Ok(Range(PmcArea::D, 100, 120)));
        assert_eq!(parse_pmc("d100..120"), Ok(Range(PmcArea::D, 100, 120)));
        assert_eq!(parse_pmc("R0.3"), Ok(Bit(PmcArea::R, 0, 3)));
        for bad in [
            "", "Q1", "D", "R0.8", "D1..R2", "D5..D1", "R0.3..R1", "D1..x",
        ] {
            assert!(parse_pmc(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn macro_specs() {
        let m = |n, w| {
            Ok(MacroSpec {
                number: n,
                write: w,
            })
        };
        assert_eq!(parse_macro("#500"), m(500, None));
        assert_eq!(parse_macro("150=vacant"), m(150, Some(None)));
        assert_eq!(
            parse_macro("150=-2.50"),
            m(150, Some(Some(Decimal::new(-250, 2))))
        );
        for bad in ["", "x", "1=", "1=abc", "-1"] {
            assert!(parse_macro(bad).is_err(), "{bad}");
        }
    }
}
