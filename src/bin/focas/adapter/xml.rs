//! `focas adapter --devices-xml`: an MTConnect Devices.xml (1.3 schema) for
//! the discovered machines, naming the same data items the adapter sends.

use super::model::{Category, Item, Layout, Place};
use std::fmt::Write as _;

/// `&`, `<`, `>` and `"` escaped for an attribute.
fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// An id safe for XML (`[A-Za-z0-9_]`) from a device and item name.
fn id(device: &str, name: &str) -> String {
    format!("{device}_{name}")
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}

fn data_item(out: &mut String, device: &str, it: &Item, indent: usize) {
    let cat = match it.category {
        Category::Sample => "SAMPLE",
        Category::Event => "EVENT",
        Category::Condition => "CONDITION",
    };
    let pad = " ".repeat(indent);
    let _ = write!(
        out,
        "{pad}<DataItem category=\"{cat}\" id=\"{}\" name=\"{}\" type=\"{}\"",
        id(device, &it.name),
        esc(&it.name),
        it.kind
    );
    if let Some(s) = it.sub {
        let _ = write!(out, " subType=\"{s}\"");
    }
    if let Some(u) = it.units {
        let _ = write!(out, " units=\"{u}\"");
    }
    if let Some(u) = it.native_units {
        let _ = write!(out, " nativeUnits=\"{u}\"");
    }
    if let Some(r) = it.series_rate {
        let _ = write!(out, " representation=\"TIME_SERIES\" sampleRate=\"{r}\"");
    }
    out.push_str("/>\n");
}

fn items_of(out: &mut String, device: &str, items: &[Item], place: &Place, indent: usize) {
    let pad = " ".repeat(indent);
    let _ = writeln!(out, "{pad}<DataItems>");
    for it in items.iter().filter(|i| &i.place == place) {
        data_item(out, device, it, indent + 2);
    }
    let _ = writeln!(out, "{pad}</DataItems>");
}

/// The document for `devices`: each a name and its layout.
pub fn devices_xml(devices: &[(String, Layout)]) -> String {
    let mut o = String::new();
    o.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    o.push_str(
        "<MTConnectDevices xmlns=\"urn:mtconnect.org:MTConnectDevices:1.3\" \
         xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" \
         xmlns:x=\"urn:fwlib32-rs:focas-adapter\" \
         xsi:schemaLocation=\"urn:mtconnect.org:MTConnectDevices:1.3 \
         http://schemas.mtconnect.org/schemas/MTConnectDevices_1.3.xsd\">\n",
    );
    let _ = writeln!(
        o,
        "  <Header creationTime=\"{}\" sender=\"focas adapter\" instanceId=\"1\" bufferSize=\"131072\" version=\"1.3\"/>",
        jiff::Timestamp::now().strftime("%Y-%m-%dT%H:%M:%SZ")
    );
    o.push_str("  <Devices>\n");
    for (name, layout) in devices {
        let items = layout.items();
        let d = id(name, "");
        let d = d.trim_end_matches('_');
        let _ = writeln!(
            o,
            "    <Device id=\"{d}\" name=\"{}\" uuid=\"{d}\">",
            esc(name)
        );
        let _ = writeln!(
            o,
            "      <Description manufacturer=\"FANUC\">read by focas adapter</Description>"
        );
        items_of(&mut o, d, &items, &Place::Device, 6);
        o.push_str("      <Components>\n");
        o.push_str("        <Axes id=\"");
        o.push_str(&id(d, "axes"));
        o.push_str("\" name=\"Axes\">\n          <Components>\n");
        for p in &layout.paths {
            for (a, rotary) in p.axes.iter().zip(&p.rotary) {
                let tag = if *rotary { "Rotary" } else { "Linear" };
                let _ = writeln!(
                    o,
                    "            <{tag} id=\"{}\" name=\"{}\">",
                    id(d, &format!("axis_{a}")),
                    esc(a)
                );
                items_of(&mut o, d, &items, &Place::Axis(a.clone(), *rotary), 14);
                let _ = writeln!(o, "            </{tag}>");
            }
            for s in &p.spindles {
                let _ = writeln!(
                    o,
                    "            <Rotary id=\"{}\" name=\"{}\">",
                    id(d, &format!("spindle_{s}")),
                    esc(s)
                );
                items_of(&mut o, d, &items, &Place::Spindle(s.clone()), 14);
                let _ = writeln!(o, "            </Rotary>");
            }
        }
        o.push_str("          </Components>\n        </Axes>\n");
        let _ = writeln!(
            o,
            "        <Controller id=\"{}\" name=\"controller\">",
            id(d, "controller")
        );
        items_of(&mut o, d, &items, &Place::Controller, 10);
        o.push_str("          <Components>\n");
        for p in &layout.paths {
            let _ = writeln!(
                o,
                "            <Path id=\"{}\" name=\"path{}\">",
                id(d, &format!("path{}", p.number)),
                p.suffix
            );
            items_of(&mut o, d, &items, &Place::Path(p.number), 14);
            o.push_str("            </Path>\n");
        }
        o.push_str("          </Components>\n        </Controller>\n");
        if !layout.systems.is_empty() {
            let _ = writeln!(
                o,
                "        <Systems id=\"{}\" name=\"systems\">\n          <Components>",
                id(d, "systems")
            );
            for s in &layout.systems {
                let place = Place::System(s.component, s.name.clone());
                let _ = writeln!(
                    o,
                    "            <{} id=\"{}\" name=\"{}\">",
                    s.component,
                    id(d, &format!("system_{}", s.name)),
                    esc(&s.name)
                );
                items_of(&mut o, d, &items, &place, 14);
                let _ = writeln!(o, "            </{}>", s.component);
            }
            o.push_str("          </Components>\n        </Systems>\n");
        }
        o.push_str("      </Components>\n    </Device>\n");
    }
    o.push_str("  </Devices>\n</MTConnectDevices>\n");
    o
}
