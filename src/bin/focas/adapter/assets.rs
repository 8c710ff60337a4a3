//! The tool table as MTConnect CuttingTool assets: one per tool of the
//! CNC's tool life groups, with its group's life and counter, its T
//! number, and its length and diameter from the tool offsets its H and D
//! numbers point at (geometry as nominal, geometry plus wear as value).

use fwlib32::native::{Cnc, Decimal, Error, ToolLifeGroup};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// `&`, `<`, `>` and `"` escaped.
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// One offset number's values as (radius geometry, radius wear, length
/// geometry, length wear), by the offset memory's layout (values per
/// number: 4 memory C, 2 memory B: geometry and wear for both, 1 memory
/// A: one value).
fn offset(v: &[i32]) -> Option<(i32, i32, i32, i32)> {
    Some(match v.len() {
        4 => (v[1], v[0], v[3], v[2]),
        2 => (v[0], v[1], v[0], v[1]),
        1 => (v[0], 0, v[0], 0),
        _ => return None,
    })
}

/// Reads the tool table of `cnc`'s current path (three exchanges: groups,
/// their tools, the offsets they name) and builds the assets: (asset id,
/// document). `decimals`: the offsets' decimal places (the path's first
/// axis's).
pub fn read(cnc: &Cnc, device: &str, decimals: i16) -> Result<Vec<(String, String)>, Error> {
    let groups = cnc.tool_life_groups(1, 44)?;
    let mut numbers: Vec<i16> = (groups.iter().flat_map(|g| &g.tools))
        .flat_map(|t| [t.length_offset, t.radius_offset])
        .filter_map(|n| i16::try_from(n).ok().filter(|n| *n >= 1))
        .collect();
    numbers.sort_unstable();
    numbers.dedup();
    // Each number on its own: one the CNC lacks fails alone.
    let mut b = cnc.batch();
    let tickets: Vec<_> = numbers
        .iter()
        .map(|n| (*n, b.tool_offsets(*n, *n)))
        .collect();
    let mut r = b.send()?;
    let mut offsets = BTreeMap::new();
    for (n, t) in tickets {
        if let Some(o) = r.take(t).ok().as_deref().and_then(offset) {
            offsets.insert(i32::from(n), o);
        }
    }
    Ok(build(device, &groups, &offsets, decimals))
}

fn build(
    device: &str,
    groups: &[ToolLifeGroup],
    offsets: &BTreeMap<i32, (i32, i32, i32, i32)>,
    decimals: i16,
) -> Vec<(String, String)> {
    let mm = |v: i32| Decimal::new(v, decimals).to_string();
    let mut out = Vec::new();
    for g in groups {
        for t in &g.tools {
            let id = format!("{device}.T{}", t.number);
            let mut d = String::new();
            let _ = writeln!(
                d,
                "<CuttingTool serialNumber=\"{}\" toolId=\"{}\" assetId=\"{}\" deviceUuid=\"{}\">",
                t.number,
                t.number,
                esc(&id),
                esc(device)
            );
            let _ = writeln!(
                d,
                "  <Description>T{} of tool life group {}</Description>",
                t.number, g.number
            );
            d.push_str("  <CuttingToolLifeCycle>\n");
            let status = if g.life > 0 && g.count >= g.life {
                "EXPIRED"
            } else {
                "AVAILABLE"
            };
            let _ = writeln!(
                d,
                "    <CutterStatus><Status>{status}</Status></CutterStatus>"
            );
            let kind = if g.count_type == 1 {
                "MINUTES"
            } else {
                "PART_COUNT"
            };
            let _ = writeln!(
                d,
                "    <ToolLife type=\"{kind}\" countDirection=\"UP\" limit=\"{}\">{}</ToolLife>",
                g.life, g.count
            );
            let _ = writeln!(d, "    <ProgramToolGroup>{}</ProgramToolGroup>", g.number);
            let _ = writeln!(d, "    <ProgramToolNumber>{}</ProgramToolNumber>", t.number);
            let length = offsets.get(&t.length_offset).copied();
            let radius = offsets.get(&t.radius_offset).copied();
            if length.is_some() || radius.is_some() {
                d.push_str("    <Measurements>\n");
                if let Some((_, _, lg, lw)) = length {
                    let _ = writeln!(
                        d,
                        "      <FunctionalLength code=\"LF\" nominal=\"{}\" units=\"MILLIMETER\">{}</FunctionalLength>",
                        mm(lg),
                        mm(lg.saturating_add(lw))
                    );
                }
                if let Some((rg, rw, _, _)) = radius {
                    let _ = writeln!(
                        d,
                        "      <CuttingDiameterMax code=\"DC\" nominal=\"{}\" units=\"MILLIMETER\">{}</CuttingDiameterMax>",
                        mm(rg.saturating_mul(2)),
                        mm(rg.saturating_add(rw).saturating_mul(2))
                    );
                }
                d.push_str("    </Measurements>\n");
            }
            d.push_str("  </CuttingToolLifeCycle>\n</CuttingTool>\n");
            out.push((id, d));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use fwlib32::native::GroupTool;

    #[test]
    fn offsets_by_memory_layout() {
        assert_eq!(
            offset(&[-5, 8000, -20, 131250]),
            Some((8000, -5, 131250, -20))
        );
        assert_eq!(offset(&[100, -1]), Some((100, -1, 100, -1)));
        assert_eq!(offset(&[7]), Some((7, 0, 7, 0)));
        assert_eq!(offset(&[]), None);
    }

    #[test]
    fn a_tool_document() {
        let g = ToolLifeGroup {
            number: 2,
            life: 500,
            count: 500,
            count_type: 0,
            tools: vec![GroupTool {
                number: 5,
                length_offset: 1,
                radius_offset: 1,
                info: 0,
            }],
        };
        let o = BTreeMap::from([(1, offset(&[0, 4250, -8, 165000]).unwrap())]);
        let a = build("m1", &[g], &o, 3);
        assert_eq!(a.len(), 1);
        assert_eq!(a[0].0, "m1.T5");
        let d = &a[0].1;
        assert!(d.contains("<Status>EXPIRED</Status>"), "{d}");
        assert!(d.contains("type=\"PART_COUNT\" countDirection=\"UP\" limit=\"500\">500<"));
        assert!(
            d.contains("nominal=\"165.000\" units=\"MILLIMETER\">164.992<"),
            "{d}"
        );
        assert!(
            d.contains("nominal=\"8.500\" units=\"MILLIMETER\">8.500<"),
            "{d}"
        );
    }
}
