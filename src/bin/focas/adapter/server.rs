//! One device's SHDR service: the current state of its items, the agents
//! connected to it (each sent every change, and the full state when it
//! connects), and their heartbeats.

use super::condition::Conditions;
use super::shdr::{self, Cond};
use std::collections::HashMap;
use std::io::{BufRead, BufReader, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Duration;

/// A device's state and its agents.
pub struct Hub {
    state: Mutex<State>,
    /// The heartbeat `* PONG` announces, ms.
    heartbeat: u64,
    /// The device's name (in logs).
    pub name: String,
}

#[derive(Default)]
struct State {
    /// Items in order, their current values.
    values: Vec<(String, String)>,
    index: HashMap<String, usize>,
    conditions: Conditions,
    agents: Vec<(u64, TcpStream)>,
    next: u64,
    /// CuttingTool assets: id and document.
    assets: Vec<(String, String)>,
}

/// How long a write to an agent may block before it is dropped.
const WRITE_TIMEOUT: Duration = Duration::from_secs(5);

impl Hub {
    pub fn new(name: &str, heartbeat: u64) -> Arc<Hub> {
        let mut s = State::default();
        s.set("avail", "UNAVAILABLE");
        Arc::new(Hub {
            state: Mutex::new(s),
            heartbeat,
            name: name.to_string(),
        })
    }

    fn lock(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Adds items (names of a newly discovered layout), unavailable until
    /// polled, and conditions.
    pub fn declare(&self, items: &[String], conditions: &[String]) {
        let mut s = self.lock();
        for i in items {
            if !s.index.contains_key(i) {
                s.set(i, "UNAVAILABLE");
            }
        }
        for c in conditions {
            s.conditions.add(c);
        }
    }

    /// One poll's values and, unless `None`, every active condition:
    /// the changes go to every agent, stamped `ts`.
    pub fn update(&self, ts: &str, values: Vec<(String, String)>, conds: Option<Vec<Cond>>) {
        let mut s = self.lock();
        let changed: Vec<(String, String)> =
            values.into_iter().filter(|(n, v)| s.set(n, v)).collect();
        let conds = conds.map(|c| s.conditions.sweep(c)).unwrap_or_default();
        s.broadcast(ts, &changed, &conds);
    }

    /// The CNC is gone: every item UNAVAILABLE.
    /// Time series sampled up to `ts`: sent every time, even when equal to
    /// the last.
    pub fn series(&self, ts: &str, values: Vec<(String, String)>) {
        let mut s = self.lock();
        for (n, v) in &values {
            s.set(n, v);
        }
        s.broadcast(ts, &values, &[]);
    }

    /// The assets now: those new or changed are sent to every agent (and
    /// all of them to each new agent).
    pub fn assets(&self, ts: &str, assets: Vec<(String, String)>) {
        let mut s = self.lock();
        let mut text = String::new();
        for (id, doc) in &assets {
            if !s.assets.iter().any(|(i, d)| i == id && d == doc) {
                text.push_str(&shdr::asset(ts, id, doc));
            }
        }
        s.assets = assets;
        s.send(&text);
    }

    pub fn unavailable(&self, ts: &str) {
        let mut s = self.lock();
        let names: Vec<String> = s.values.iter().map(|(n, _)| n.clone()).collect();
        let changed: Vec<(String, String)> = names
            .into_iter()
            .filter(|n| s.set(n, "UNAVAILABLE"))
            .map(|n| (n, "UNAVAILABLE".to_string()))
            .collect();
        let conds = s.conditions.unavailable();
        s.broadcast(ts, &changed, &conds);
    }

    /// Serves agents connecting to `listener`, a thread each, until the
    /// process ends.
    pub fn serve(self: &Arc<Hub>, listener: TcpListener) {
        for conn in listener.incoming() {
            let stream = match conn {
                Ok(s) => s,
                Err(e) => {
                    // Out of descriptors, say: not a busy loop meanwhile.
                    eprintln!("focas adapter: {}: accept: {e}", self.name);
                    std::thread::sleep(Duration::from_millis(100));
                    continue;
                }
            };
            let hub = self.clone();
            let spawned = std::thread::Builder::new()
                .name("agent".into())
                .stack_size(64 * 1024)
                .spawn(move || hub.agent(stream));
            if let Err(e) = spawned {
                eprintln!("focas adapter: {}: no thread for an agent: {e}", self.name);
            }
        }
    }

    /// One agent: the full state, then every change; `* PING` answered;
    /// dropped when it closes, when a write fails, or when it pinged once
    /// and then stays silent twice the heartbeat.
    fn agent(&self, stream: TcpStream) {
        let peer = stream
            .peer_addr()
            .map_or_else(|_| "?".to_string(), |a| a.to_string());
        let writer = match stream.try_clone() {
            Ok(w) => w,
            Err(_) => return,
        };
        let _ = writer.set_write_timeout(Some(WRITE_TIMEOUT));
        let _ = writer.set_nodelay(true);
        let id = {
            let mut s = self.lock();
            let id = s.next;
            s.next += 1;
            let mut w = writer;
            if w.write_all(s.full(&shdr::now()).as_bytes()).is_err() {
                return;
            }
            s.agents.push((id, w));
            id
        };
        eprintln!("focas adapter: {}: agent {peer} connected", self.name);
        let mut lines = BufReader::new(&stream);
        let mut line = String::new();
        loop {
            line.clear();
            match lines.read_line(&mut line) {
                Ok(0) | Err(_) => break,
                Ok(_) => {}
            }
            if line.trim() == "* PING" {
                let _ = stream.set_read_timeout(Some(Duration::from_millis(2 * self.heartbeat)));
                let mut s = self.lock();
                let ok = match s.agents.iter_mut().find(|(i, _)| *i == id) {
                    Some((_, w)) => w.write_all(shdr::pong(self.heartbeat).as_bytes()).is_ok(),
                    None => false,
                };
                if !ok {
                    break;
                }
            }
        }
        self.lock().agents.retain(|(i, _)| *i != id);
        let _ = stream.shutdown(Shutdown::Both);
        eprintln!("focas adapter: {}: agent {peer} gone", self.name);
    }
}

impl State {
    /// Sets an item; whether it changed.
    fn set(&mut self, name: &str, value: &str) -> bool {
        match self.index.get(name) {
            Some(&i) if self.values[i].1 == value => false,
            Some(&i) => {
                self.values[i].1 = value.to_string();
                true
            }
            None => {
                self.index.insert(name.to_string(), self.values.len());
                self.values.push((name.to_string(), value.to_string()));
                true
            }
        }
    }

    /// Every item and condition as lines stamped `ts`.
    fn full(&self, ts: &str) -> String {
        // A time series is sent as sampled, not again (unless unavailable).
        let values: Vec<(String, String)> = (self.values.iter())
            .filter(|(n, v)| !n.ends_with("_ts") || v == "UNAVAILABLE")
            .cloned()
            .collect();
        let mut out = shdr::sample_line(ts, &values).unwrap_or_default();
        for (id, doc) in &self.assets {
            out.push_str(&shdr::asset(ts, id, doc));
        }
        for c in self.conditions.current() {
            out.push_str(&c.line(ts));
        }
        out
    }

    /// Sends changes to every agent; drops those that cannot take them.
    fn broadcast(&mut self, ts: &str, changed: &[(String, String)], conds: &[Cond]) {
        let mut text = shdr::sample_line(ts, changed).unwrap_or_default();
        for c in conds {
            text.push_str(&c.line(ts));
        }
        self.send(&text);
    }

    fn send(&mut self, text: &str) {
        if text.is_empty() {
            return;
        }
        self.agents.retain_mut(|(_, w)| {
            let ok = w.write_all(text.as_bytes()).is_ok();
            if !ok {
                let _ = w.shutdown(Shutdown::Both);
            }
            ok
        });
    }
}
