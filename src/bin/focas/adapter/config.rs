//! The adapter's configuration: the `--config` file, its systems, series
//! and custom items, and the devices it and the command line name.

use super::Args;
use super::model::{Custom, Series, System};
use crate::out::Fail;
use fwlib32::native::PmcArea;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::net::SocketAddr;

/// The `--config` file.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Config {
    /// Milliseconds between polls (--interval's default).
    interval: Option<u64>,
    heartbeat: Option<u64>,
    /// Systems conditions, for every device.
    #[serde(default, rename = "system")]
    systems: Vec<SystemConfig>,
    /// Time series sampled between polls, for every device.
    series: Option<SeriesConfig>,
    /// Seconds between reads of the tool table (CuttingTool assets; 0: on
    /// connecting only; default 60).
    assets: Option<u64>,
    /// The C++ adapter's `adapter.ini` sections, item name to address.
    #[serde(default)]
    macros: BTreeMap<String, u32>,
    #[serde(default)]
    pmc: BTreeMap<String, PmcAddress>,
    #[serde(default)]
    parameters: BTreeMap<String, u32>,
    #[serde(default)]
    diagnostics: BTreeMap<String, u32>,
    #[serde(default)]
    alarms: BTreeMap<String, toml::Value>,
    #[serde(default)]
    critical: BTreeMap<String, toml::Value>,
    #[serde(default, rename = "device")]
    devices: Vec<DeviceConfig>,
}

/// A `[[system]]`: a condition FAULT while a PMC bit is at its active
/// level or one of some alarms is active.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SystemConfig {
    /// The condition's name (`coolant`).
    name: String,
    /// coolant, hydraulic, pneumatic, electric or lubrication (default:
    /// the name's).
    component: Option<String>,
    /// `R600.2`: area, byte, bit.
    pmc: Option<String>,
    /// The bit's level that means a fault (default 1).
    active: Option<u8>,
    /// Alarm numbers that mean a fault.
    #[serde(default)]
    alarms: Vec<i32>,
    /// The text of a PMC fault (default: the address).
    text: Option<String>,
}

/// `[series]`: time series of servo loads (`load`) and spindle speeds
/// (`speed`) sampled `rate` times a second between polls.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SeriesConfig {
    rate: u32,
    items: Vec<String>,
}

/// A `[pmc]` address: `R500`, or the C++ adapter's number (area type
/// times 10000 plus the byte, G 0, F 1, Y 2, X 3, A 4, R 5, T 6, K 7, C 8,
/// D 9; negative: a byte with its top bit set is sent inverted).
#[derive(Deserialize)]
#[serde(untagged)]
enum PmcAddress {
    Number(i64),
    Text(String),
}

fn pmc_address(name: &str, a: &PmcAddress) -> Result<(PmcArea, u16, bool), Fail> {
    const AREAS: [PmcArea; 10] = [
        PmcArea::G,
        PmcArea::F,
        PmcArea::Y,
        PmcArea::X,
        PmcArea::A,
        PmcArea::R,
        PmcArea::T,
        PmcArea::K,
        PmcArea::C,
        PmcArea::D,
    ];
    let bad = || Fail::Other(format!("[pmc] {name}: expected R500 or a number as 50500"));
    match a {
        PmcAddress::Number(n) => {
            let (inv, n) = (*n < 0, n.unsigned_abs());
            let area = usize::try_from(n / 10000).ok().and_then(|i| AREAS.get(i));
            let at = u16::try_from(n % 10000).map_err(|_| bad())?;
            Ok((*area.ok_or_else(bad)?, at, inv))
        }
        PmcAddress::Text(t) => {
            let split = t.find(|c: char| c.is_ascii_digit()).ok_or_else(bad)?;
            let (area, at) = t.split_at(split);
            let area: PmcArea = area.parse().map_err(|_| bad())?;
            Ok((area, at.parse().map_err(|_| bad())?, false))
        }
    }
}

/// What the configuration adds to every device.
#[derive(Clone, Default)]
pub(super) struct Extras {
    pub(super) systems: Vec<System>,
    pub(super) series: Option<Series>,
    /// Seconds between tool table reads (0: on connecting only).
    pub(super) assets: u64,
    pub(super) custom: Custom,
}

fn system(c: SystemConfig) -> Result<System, Fail> {
    let bad = |why: String| Fail::Other(format!("[[system]] {:?}: {why}", c.name));
    let comp = c
        .component
        .as_deref()
        .unwrap_or(&c.name)
        .to_ascii_lowercase();
    let component = match comp.trim_end_matches('s') {
        "coolant" => "Coolant",
        "hydraulic" => "Hydraulic",
        "pneumatic" => "Pneumatic",
        "electric" => "Electric",
        "lubrication" => "Lubrication",
        other => {
            return Err(bad(format!(
                "component {other:?}: coolant, hydraulic, pneumatic, electric or lubrication"
            )));
        }
    };
    let pmc = match &c.pmc {
        None => None,
        Some(a) => {
            let split = a.find(|ch: char| ch.is_ascii_digit()).unwrap_or(a.len());
            let (area, rest) = a.split_at(split);
            let (byte, bit) = rest.split_once('.').unwrap_or((rest, ""));
            let area = area
                .parse()
                .map_err(|_| bad(format!("pmc {a:?}: no PMC area {area:?}")))?;
            let (Ok(byte), Ok(bit @ 0..=7)) = (byte.parse::<u16>(), bit.parse::<u8>()) else {
                return Err(bad(format!("pmc {a:?}: expected AREA BYTE.BIT, as R600.2")));
            };
            let level = match c.active.unwrap_or(1) {
                0 => false,
                1 => true,
                _ => return Err(bad("active: 0 or 1".into())),
            };
            Some((area, byte, bit, level))
        }
    };
    if pmc.is_none() && c.alarms.is_empty() {
        return Err(bad("give pmc or alarms".into()));
    }
    Ok(System {
        text: c.text.unwrap_or_else(|| c.pmc.clone().unwrap_or_default()),
        name: c.name,
        component,
        pmc,
        alarms: c.alarms,
    })
}

fn series(c: SeriesConfig) -> Result<Series, Fail> {
    if !(1..=1000).contains(&c.rate) {
        return Err(Fail::Other("[series] rate: 1 to 1000 Hz".into()));
    }
    let mut s = Series {
        rate: c.rate,
        load: false,
        speed: false,
    };
    for i in &c.items {
        match i.as_str() {
            "load" => s.load = true,
            "speed" => s.speed = true,
            _ => return Err(Fail::Other(format!("[series] items: {i:?}: load or speed"))),
        }
    }
    Ok(s)
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct DeviceConfig {
    /// The device's name (Devices.xml, logs).
    name: Option<String>,
    /// `host[:port]`.
    cnc: String,
    /// Where its agents connect: default the previous device's port plus
    /// one (the first: --listen's).
    listen: Option<String>,
}

/// One device to serve.
pub(super) struct Device {
    pub(super) name: String,
    /// `host:port` of the CNC.
    pub(super) cnc: String,
    pub(super) listen: String,
}

/// `ip:port` with the port moved on by `n` (port 0 stays 0: each its own).
fn next_port(listen: &str, n: usize) -> Result<String, Fail> {
    let a: SocketAddr = listen
        .parse()
        .map_err(|_| Fail::Other(format!("--listen {listen:?}: expected IP:PORT")))?;
    if a.port() == 0 {
        return Ok(a.to_string());
    }
    let p = usize::from(a.port()) + n;
    let p = u16::try_from(p).map_err(|_| Fail::Other(format!("no port {p} after {listen}")))?;
    Ok(SocketAddr::new(a.ip(), p).to_string())
}

fn cnc_addr(s: &str, default_port: u16) -> Result<String, Fail> {
    let hp = crate::host_port(s).map_err(|e| Fail::Other(format!("--cnc: {e}")))?;
    Ok(hp.addr(default_port))
}

/// The devices the command line and the config file name, and what the
/// configuration adds to each ([`Extras`]).
pub(super) fn devices(
    a: &Args,
    host: Option<String>,
    port: u16,
) -> Result<(Vec<Device>, u64, u64, Extras), Fail> {
    let (mut interval, mut heartbeat) = (a.interval, a.heartbeat);
    let mut extras = Extras {
        assets: 60,
        ..Extras::default()
    };
    let mut specs: Vec<(Option<String>, String, Option<String>)> = Vec::new();
    if let Some(path) = &a.config {
        let text = std::fs::read_to_string(path)
            .map_err(|e| Fail::Other(format!("{}: {e}", path.display())))?;
        let c: Config =
            toml::from_str(&text).map_err(|e| Fail::Other(format!("{}: {e}", path.display())))?;
        interval = c.interval.unwrap_or(interval).max(10);
        heartbeat = c.heartbeat.unwrap_or(heartbeat).max(100);
        specs.extend(c.devices.into_iter().map(|d| (d.name, d.cnc, d.listen)));
        for sc in c.systems {
            extras.systems.push(system(sc)?);
        }
        extras.series = c.series.map(series).transpose()?;
        extras.assets = c.assets.unwrap_or(extras.assets);
        let cu = &mut extras.custom;
        cu.macros = c.macros.into_iter().collect();
        for (n, a) in &c.pmc {
            let (area, at, inv) = pmc_address(n, a)?;
            cu.pmc.push((n.clone(), area, at, inv));
        }
        cu.parameters = c.parameters.into_iter().collect();
        // As the C++ adapter: axis times 10000 plus the number.
        cu.diagnostics = (c.diagnostics.into_iter())
            .map(|(n, v)| {
                let axis = u16::try_from(v / 10000).ok().filter(|a| *a > 0);
                (n, v % 10000, axis)
            })
            .collect();
        cu.alarms = c.alarms.into_keys().collect();
        cu.critical = c.critical.into_keys().collect();
    }
    specs.extend(a.cnc.iter().map(|c| (None, c.clone(), None)));
    if specs.is_empty() {
        match host {
            Some(h) => specs.push((None, h, None)),
            None => {
                return Err(Fail::Other(
                    "adapter: no CNC: give --cnc HOST[:PORT], --host, or --config FILE".into(),
                ));
            }
        }
    }
    let many = specs.len() > 1;
    let mut out = Vec::new();
    let mut last = a.listen.clone();
    for (i, (name, cnc, listen)) in specs.into_iter().enumerate() {
        let listen = match listen {
            Some(l) => l,
            None if i == 0 => a.listen.clone(),
            None => next_port(&last, 1)?,
        };
        last = listen.clone();
        let name = name.unwrap_or_else(|| {
            if many {
                format!("device{}", i + 1)
            } else {
                "device".to_string()
            }
        });
        out.push(Device {
            name,
            cnc: cnc_addr(&cnc, port)?,
            listen,
        });
    }
    Ok((out, interval, heartbeat, extras))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pmc_addresses_and_systems() {
        let n = |v| pmc_address("x", &PmcAddress::Number(v)).ok();
        assert_eq!(n(50500), Some((PmcArea::R, 500, false)));
        assert_eq!(n(-12), Some((PmcArea::G, 12, true)));
        assert_eq!(n(90003), Some((PmcArea::D, 3, false)));
        assert_eq!(n(100001), None, "no area 10 in the C++ numbering");
        let t = |v: &str| pmc_address("x", &PmcAddress::Text(v.into())).ok();
        assert_eq!(t("R501"), Some((PmcArea::R, 501, false)));
        assert_eq!(t("Q1"), None);
        assert_eq!(t("R"), None);
        let sys = |toml: &str| {
            toml::from_str::<SystemConfig>(toml)
                .map_err(|_| ())
                .and_then(|c| system(c).map_err(|_| ()))
        };
        let s =
            sys("name = \"air\"\ncomponent = \"pneumatic\"\npmc = \"X8.4\"\nactive = 0").unwrap();
        assert_eq!(
            (s.component, s.pmc),
            ("Pneumatic", Some((PmcArea::X, 8, 4, false)))
        );
        assert_eq!(s.text, "X8.4");
        assert!(sys("name = \"coolant\"\npmc = \"R1.8\"").is_err(), "bit 8");
        assert!(sys("name = \"coolant\"").is_err(), "neither pmc nor alarms");
        assert!(
            sys("name = \"vacuum\"\nalarms = [1]").is_err(),
            "no such component"
        );
        assert_eq!(
            sys("name = \"hydraulics\"\nalarms = [1]")
                .unwrap()
                .component,
            "Hydraulic"
        );
    }

    #[test]
    fn devices_take_consecutive_ports() {
        assert_eq!(next_port("0.0.0.0:7878", 1).ok().unwrap(), "0.0.0.0:7879");
        assert_eq!(next_port("127.0.0.1:0", 1).ok().unwrap(), "127.0.0.1:0");
        assert!(next_port("0.0.0.0:65535", 1).is_err());
        assert!(next_port("cnc1:7878", 1).is_err());
        let args = |extra: &[&str]| {
            #[derive(clap::Parser)]
            struct T {
                #[command(flatten)]
                a: Args,
            }
            let mut v = vec!["t"];
            v.extend_from_slice(extra);
            <T as clap::Parser>::parse_from(v).a
        };
        let a = args(&["--cnc", "cnc1", "--cnc", "[::1]:9000", "--cnc", "cnc3"]);
        let (d, interval, heartbeat, _) = devices(&a, None, 8193).ok().unwrap();
        let got: Vec<(&str, &str, &str)> = d
            .iter()
            .map(|d| (d.name.as_str(), d.cnc.as_str(), d.listen.as_str()))
            .collect();
        assert_eq!(
            got,
            [
                ("device1", "cnc1:8193", "0.0.0.0:7878"),
                ("device2", "[::1]:9000", "0.0.0.0:7879"),
                ("device3", "cnc3:8193", "0.0.0.0:7880"),
            ]
        );
        assert_eq!((interval, heartbeat), (1000, 10000));
        let (d, ..) = devices(&args(&[]), Some("cnc9:8193".into()), 8193)
            .ok()
            .unwrap();
        assert_eq!(
            (d[0].name.as_str(), d[0].cnc.as_str()),
            ("device", "cnc9:8193")
        );
        assert!(devices(&args(&[]), None, 8193).is_err(), "no CNC");
    }
}
