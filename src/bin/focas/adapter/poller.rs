//! A device's poller thread: connecting (discovery, the tool table),
//! polling every interval with the time series sampled between polls, and
//! reconnecting after an outage.

use super::config::Extras;
use super::model::{Category, Layout, Series};
use super::poll::{self, PathMemo};
use super::server::Hub;
use super::{assets, shdr};
use fwlib32::native::{Cnc, Error};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A connection and its layout: one `Cnc` per path.
pub(super) struct Link {
    paths: Vec<Cnc>,
    pub(super) layout: Layout,
}

pub(super) fn connect(addr: &str, timeout: Duration, extras: &Extras) -> Result<Link, Error> {
    let cnc = Cnc::connect(addr, timeout)?;
    let mut layout = Layout::discover(&cnc)?;
    layout.systems = extras.systems.clone();
    layout.series = extras.series.clone();
    layout.custom = extras.custom.clone();
    let mut paths = Vec::new();
    for p in &layout.paths {
        let c = cnc.try_clone()?;
        c.set_path(p.number)?;
        paths.push(c);
    }
    Ok(Link { paths, layout })
}

/// Item and condition names of a layout (time series included: they go
/// UNAVAILABLE with the rest).
fn names(layout: &Layout) -> (Vec<String>, Vec<String>) {
    let (mut items, mut conds) = (Vec::new(), Vec::new());
    for i in layout.items() {
        if i.category == Category::Condition {
            conds.push(i.name);
        } else {
            items.push(i.name);
        }
    }
    (items, conds)
}

/// A poller's settings.
pub(super) struct Polling {
    pub(super) addr: String,
    pub(super) timeout: Duration,
    pub(super) interval: Duration,
    pub(super) polls: Option<u64>,
    pub(super) extras: Extras,
}

/// Samples of the time series since the last poll: per item, its values;
/// and when the last was taken.
#[derive(Default)]
struct Samples {
    values: Vec<(String, Vec<String>)>,
    last: Option<String>,
}

impl Samples {
    fn push(&mut self, name: String, v: String) {
        match self.values.iter_mut().find(|(n, _)| *n == name) {
            Some((_, vs)) => vs.push(v),
            None => self.values.push((name, vec![v])),
        }
    }

    /// The series' values (count, rate, samples), emptied.
    fn take(&mut self, rate: u32) -> Option<(String, Vec<(String, String)>)> {
        let ts = self.last.take()?;
        let sep = shdr::SEP;
        let out = (self.values.drain(..))
            .map(|(n, vs)| (n, format!("{}{sep}{rate}{sep}{}", vs.len(), vs.join(" "))))
            .collect();
        Some((ts, out))
    }
}

/// One sample of every path's series.
fn sample(l: &Link, s: &Series, into: &mut Samples) -> Result<(), Error> {
    for (cnc, p) in l.paths.iter().zip(&l.layout.paths) {
        let (loads, speeds) = poll::sample_path(cnc, s)?;
        for (a, v) in p.axes.iter().zip(loads) {
            into.push(format!("{a}load_ts"), v);
        }
        for (sp, v) in p.spindles.iter().zip(speeds) {
            into.push(format!("{sp}speed_ts"), v);
        }
    }
    into.last = Some(shdr::now());
    Ok(())
}

/// Reads the tool table of path 1 and hands its CuttingTool assets to the
/// hub (a CNC without tool life management: none, logged).
fn read_assets(hub: &Hub, l: &Link) -> Result<(), Error> {
    let Some(cnc) = l.paths.first() else {
        return Ok(());
    };
    // The offsets' decimals: the first axis's.
    let decimals = cnc.positions()?.first().map_or(3, |a| a.absolute.decimals);
    match assets::read(cnc, &hub.name, decimals) {
        Ok(a) => hub.assets(&shdr::now(), a),
        // No tool life management: no assets.
        Err(e @ Error::Cnc { .. }) => eprintln!("focas adapter: {}: no tool table: {e}", hub.name),
        Err(e) => return Err(e),
    }
    Ok(())
}

/// Polls one CNC every `interval` until `polls` (for ever without).
pub(super) fn poller(hub: Arc<Hub>, cfg: Polling) {
    let Polling {
        addr,
        timeout,
        interval,
        polls,
        extras,
    } = cfg;
    let mut link: Option<Link> = None;
    let mut memos: Vec<PathMemo> = Vec::new();
    let mut samples = Samples::default();
    let (mut done, mut frames, mut most) = (0u64, 0usize, 0usize);
    let mut assets_at: Option<Instant> = None;
    let mut down: Option<String> = None;
    while polls.is_none_or(|n| done < n) {
        let start = Instant::now();
        done += 1;
        if link.is_none() {
            match connect(&addr, timeout, &extras) {
                Ok(l) => {
                    let (items, conds) = names(&l.layout);
                    hub.declare(&items, &conds);
                    eprintln!(
                        "focas adapter: {}: {addr} connected: {} path(s), axes {}",
                        hub.name,
                        l.layout.paths.len(),
                        l.layout
                            .paths
                            .iter()
                            .flat_map(|p| p.axes.iter().cloned())
                            .collect::<Vec<_>>()
                            .join(" ")
                    );
                    down = None;
                    memos = l.layout.paths.iter().map(|_| PathMemo::default()).collect();
                    samples = Samples::default();
                    assets_at = None;
                    link = Some(l);
                }
                Err(e) => {
                    let why = e.to_string();
                    if down.as_ref() != Some(&why) {
                        eprintln!("focas adapter: {}: {addr}: {why}", hub.name);
                    }
                    down = Some(why);
                    hub.unavailable(&shdr::now());
                }
            }
        }
        if let Some(l) = &link {
            let mut values = vec![("avail".to_string(), "AVAILABLE".to_string())];
            let mut conds = Some(Vec::new());
            let mut failed = None;
            let mut this = 0;
            for ((cnc, p), memo) in l.paths.iter().zip(&l.layout.paths).zip(&mut memos) {
                match poll::poll_path(cnc, p, &l.layout.systems, &l.layout.custom, memo) {
                    Ok(r) => {
                        this += r.frames;
                        values.extend(r.values);
                        if r.alarms_unknown {
                            conds = None;
                        }
                        if let Some(c) = conds.as_mut() {
                            c.extend(r.conditions);
                        }
                    }
                    Err(e) => {
                        failed = Some(e);
                        break;
                    }
                }
            }
            frames += this;
            most = most.max(this);
            // The tool table: on connecting, then every `assets` seconds.
            let due = match assets_at {
                None => true,
                Some(t) => extras.assets > 0 && t.elapsed().as_secs() >= extras.assets,
            };
            if failed.is_none() && due {
                assets_at = Some(Instant::now());
                if let Err(e) = read_assets(&hub, l) {
                    failed = Some(e);
                }
            }
            let ts = shdr::now();
            match failed {
                None => {
                    hub.update(&ts, values, conds);
                    if let Some((ts, v)) = extras.series.as_ref().and_then(|s| samples.take(s.rate))
                    {
                        hub.series(&ts, v);
                    }
                }
                Some(e) => {
                    eprintln!("focas adapter: {}: {addr}: lost: {e}", hub.name);
                    down = Some(e.to_string());
                    link = None;
                    hub.unavailable(&ts);
                }
            }
        }
        if polls.is_some_and(|n| done >= n) {
            break;
        }
        // After an outage, try again at least every half second.
        let wait = if link.is_none() {
            interval.min(Duration::from_millis(500))
        } else {
            interval
        };
        // Until the next poll: the time series' samples, if any.
        if let (Some(l), Some(s)) = (&link, &extras.series) {
            let every = Duration::from_secs_f64(1.0 / f64::from(s.rate));
            let mut next = Instant::now();
            while next + every <= start + wait {
                next += every;
                if let Some(rest) = next.checked_duration_since(Instant::now()) {
                    std::thread::sleep(rest);
                }
                if let Err(e) = sample(l, s, &mut samples) {
                    eprintln!("focas adapter: {}: {addr}: lost: {e}", hub.name);
                    down = Some(e.to_string());
                    link = None;
                    hub.unavailable(&shdr::now());
                    break;
                }
            }
        }
        if let Some(rest) = wait.checked_sub(start.elapsed()) {
            std::thread::sleep(rest);
        }
    }
    eprintln!(
        "focas adapter: {}: {done} polls, {frames} request frames, at most {most} in one",
        hub.name
    );
}
