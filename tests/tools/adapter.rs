//! `focas adapter` against in-process simulators, through real TCP clients
//! of its SHDR port (an agent's side): the line grammar, values that follow
//! the running program (the simulator's clock stopped where a test needs
//! it, each value checked against the Rust API reading the same machine),
//! an alarm as a condition FAULT then NORMAL, PING/PONG and a silent peer
//! dropped, a CNC stopped and restarted, a second agent's full state, the
//! round trips per poll, Devices.xml, and a fleet from one process.
//! Every wait on the adapter is for a line (a read timeout only turns a
//! hang into a failure).

use crate::toolchain;
use fwlib32::native::{Cnc, Decimal};
use fwlib32::sim::{Fleet, FleetOptions, Profile, Simulator};
use std::collections::BTreeMap;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, ChildStdout, Stdio};
use std::time::Duration;

/// How long a line may take before the test fails.
const PATIENCE: Duration = Duration::from_secs(60);

/// The adapter process, killed when dropped.
struct Adapter {
    child: Child,
    ports: Vec<u16>,
    _stdout: BufReader<ChildStdout>,
}

impl Drop for Adapter {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn focas() -> std::process::Command {
    let mut c = toolchain::target_command(env!("CARGO_BIN_EXE_focas"));
    c.env_remove("FOCAS_HOST").env_remove("FOCAS_PORT");
    c
}

/// Starts `focas adapter ARGS` and reads its `listening on` lines, one per
/// device.
fn adapter(devices: usize, args: &[&str]) -> Adapter {
    let mut child = focas()
        .arg("adapter")
        .args(["--listen", "127.0.0.1:0", "--timeout", "5"])
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("start focas adapter");
    let mut out = BufReader::new(child.stdout.take().expect("stdout"));
    let mut ports = Vec::new();
    for _ in 0..devices {
        let mut line = String::new();
        out.read_line(&mut line).expect("a listening line");
        let addr = line
            .trim()
            .strip_prefix("listening on ")
            .unwrap_or_else(|| panic!("not a listening line: {line:?}"));
        let port = addr.rsplit(':').next().unwrap().parse().expect("a port");
        ports.push(port);
    }
    Adapter {
        child,
        ports,
        _stdout: out,
    }
}

fn cnc_arg(port: u16) -> String {
    format!("127.0.0.1:{port}")
}

/// An agent's connection: the lines, and every item's last value.
struct Agent {
    r: BufReader<TcpStream>,
    w: TcpStream,
    values: BTreeMap<String, String>,
    /// Condition name to its last line's fields after the name.
    conds: BTreeMap<String, Vec<String>>,
    /// The device's condition names (to tell their lines).
    names: Vec<String>,
    /// Asset id to its type and document.
    assets: BTreeMap<String, (String, String)>,
}

/// A checked SHDR line: data items, a condition, or a heartbeat answer.
#[derive(Debug)]
enum Line {
    Data(Vec<(String, String)>),
    Cond(String, Vec<String>),
    Pong(u64),
    /// An asset's id, type and document.
    Asset(String, String, String),
}

/// The mark around an asset's document.
const MULTILINE: &str = "--multiline--";

const LEVELS: [&str; 4] = ["NORMAL", "WARNING", "FAULT", "UNAVAILABLE"];

/// Parses one line, failing the test on anything outside the grammar.
fn parse(line: &str, conditions: &[String]) -> Line {
    let line = line
        .strip_suffix('\n')
        .unwrap_or_else(|| panic!("unterminated {line:?}"));
    if let Some(ms) = line.strip_prefix("* PONG ") {
        return Line::Pong(ms.parse().expect("PONG ms"));
    }
    let f: Vec<&str> = line.split('|').collect();
    let ts = f[0];
    // YYYY-MM-DDTHH:MM:SS.FFFZ, UTC, milliseconds.
    assert_eq!(ts.len(), 24, "timestamp {ts:?} in {line:?}");
    assert!(ts.ends_with('Z') && ts.as_bytes()[19] == b'.', "{ts:?}");
    let t: jiff::Timestamp = ts.parse().unwrap_or_else(|e| panic!("{ts:?}: {e}"));
    let age = jiff::Timestamp::now().duration_since(t);
    assert!(age.as_secs().abs() < 3600, "{ts:?} is now, in UTC");
    if f.len() == 5 && f[1] == "@ASSET@" {
        assert!(f[4].starts_with(MULTILINE), "{line:?}");
        return Line::Asset(f[2].to_string(), f[3].to_string(), f[4].to_string());
    }
    // Items of several fields, each on its own line: a message (native
    // code, text) and a time series (count, rate, values).
    if f.len() == 4 && f[1] == "message" {
        return Line::Data(vec![(f[1].to_string(), f[2..].join("|"))]);
    }
    if f.len() == 5 && f[1].ends_with("_ts") {
        return Line::Data(vec![(f[1].to_string(), f[2..].join("|"))]);
    }
    if f.len() >= 2 && conditions.iter().any(|c| c == f[1]) {
        assert_eq!(f.len(), 7, "a condition has 7 fields: {line:?}");
        assert!(LEVELS.contains(&f[2]), "{line:?}");
        return Line::Cond(
            f[1].to_string(),
            f[2..].iter().map(|s| s.to_string()).collect(),
        );
    }
    assert!(
        f.len() >= 3 && f.len() % 2 == 1,
        "name|value pairs: {line:?}"
    );
    Line::Data(
        f[1..]
            .chunks(2)
            .map(|p| {
                assert!(!p[0].is_empty(), "an item name: {line:?}");
                (p[0].to_string(), p[1].to_string())
            })
            .collect(),
    )
}

/// The condition names of the built-in profile's one path (3 axes, 1 spindle).
fn condition_names() -> Vec<String> {
    let mut v: Vec<String> = ["servo", "comms", "logic", "motion", "system", "S1servo"]
        .map(String::from)
        .to_vec();
    for a in ["X", "Y", "Z"] {
        for c in ["travel", "overheat", "servo"] {
            v.push(format!("{a}{c}"));
        }
    }
    v
}

impl Agent {
    fn connect(port: u16) -> Agent {
        Agent::with(port, condition_names())
    }

    fn with(port: u16, names: Vec<String>) -> Agent {
        let s = TcpStream::connect(("127.0.0.1", port)).expect("connect to the adapter");
        s.set_read_timeout(Some(PATIENCE)).unwrap();
        Agent {
            w: s.try_clone().unwrap(),
            r: BufReader::new(s),
            values: BTreeMap::new(),
            conds: BTreeMap::new(),
            names,
            assets: BTreeMap::new(),
        }
    }

    /// Reads one line and records it (an asset: its document's lines too).
    fn line(&mut self) -> Line {
        let mut s = String::new();
        let n = self.r.read_line(&mut s).expect("a line from the adapter");
        assert!(n > 0, "the adapter closed the connection");
        let mut l = parse(&s, &self.names);
        if let Line::Asset(_, _, mark) = &mut l {
            let mut doc = String::new();
            loop {
                let mut s = String::new();
                let n = self.r.read_line(&mut s).expect("an asset's line");
                assert!(n > 0, "the adapter closed the connection in an asset");
                if s.trim_end() == mark.as_str() {
                    break;
                }
                doc.push_str(&s);
            }
            *mark = doc;
        }
        match &l {
            Line::Asset(id, kind, doc) => {
                self.assets.insert(id.clone(), (kind.clone(), doc.clone()));
            }
            Line::Data(p) => {
                for (k, v) in p {
                    self.values.insert(k.clone(), v.clone());
                }
            }
            Line::Cond(n, f) => {
                self.conds.insert(n.clone(), f.clone());
            }
            Line::Pong(_) => {}
        }
        l
    }

    /// Reads until `done` holds for the state so far.
    fn until(&mut self, what: &str, done: impl Fn(&Agent) -> bool) {
        while !done(self) {
            let _ = what;
            self.line();
        }
    }

    /// Reads the full state sent on connecting: every item and condition.
    fn full_state(&mut self) {
        let conds = self.names.clone();
        self.until("the full state", |a| {
            a.values.contains_key("avail") && conds.iter().all(|c| a.conds.contains_key(c))
        });
    }

    fn value(&self, name: &str) -> &str {
        self.values.get(name).map_or("", |s| s.as_str())
    }

    fn wait_value(&mut self, name: &str, v: &str) {
        let (n, v2) = (name.to_string(), v.to_string());
        self.until(name, move |a| a.value(&n) == v2);
    }

    fn level(&self, cond: &str) -> Option<(&str, &str)> {
        self.conds.get(cond).map(|f| (f[0].as_str(), f[1].as_str()))
    }
}

/// The built-in profile's program, as cnc_exeprgname2 names it.
const PROGRAM: &str = "//CNC_MEM/USER/PATH1/O1234";

fn sim_at(secs: f64) -> Simulator {
    let s = Simulator::start(Profile::default(), "127.0.0.1:0").expect("simulator");
    s.set_elapsed(Duration::from_secs_f64(secs));
    s
}

/// What the Rust API reads from `sim` now: X's machine position, the
/// sequence number, the feed.
fn api(sim: &Simulator) -> (Decimal, i32, i32) {
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5)).expect("connect");
    let x = cnc.positions().expect("positions")[0].machine;
    let e = cnc.execution().expect("execution");
    (x, e.sequence, e.feed)
}

#[test]
fn grammar_and_values_of_the_full_state() {
    let sim = sim_at(1.0);
    let (x, seq, feed) = api(&sim);
    let a = adapter(1, &["--cnc", &cnc_arg(sim.port()), "--interval", "100"]);
    let mut agent = Agent::connect(a.ports[0]);
    agent.full_state();
    agent.wait_value("avail", "AVAILABLE");
    for (k, v) in [
        ("mode", "AUTOMATIC"),
        ("execution", "ACTIVE"),
        ("program", PROGRAM),
        ("estop", "ARMED"),
        ("active_axes", "X Y Z"),
        ("Fovr", "100"),
        ("Sovr", "100"),
        ("S1speed", "12000"),
        ("S1load", "40"),
        ("part_count", "1234"),
    ] {
        agent.wait_value(k, v);
    }
    assert_eq!(agent.value("Xact"), x.to_string());
    assert_eq!(agent.value("line"), seq.to_string());
    assert_eq!(agent.value("path_feedrate"), feed.to_string());
    for item in ["Xload", "Yact", "Yload", "Zact", "Zload", "path_position"] {
        assert!(!agent.value(item).is_empty(), "{item}");
        assert_ne!(agent.value(item), "UNAVAILABLE", "{item}");
    }
    assert_eq!(agent.value("path_position").split(' ').count(), 3);
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5)).unwrap();
    let (t, f) = (cnc.modal_code(108).unwrap(), cnc.modal_code(103).unwrap());
    // Read in a poll's later frames: they may follow the first values.
    agent.wait_value("tool_id", &t.to_string());
    agent.wait_value("f_command", &f.to_string());
    let n = format!("N{seq} ");
    agent.until("the block", |a| a.value("block").starts_with(&n));
    for c in condition_names() {
        agent.until("the conditions", |a| {
            a.level(&c).is_some_and(|l| l.0 != "UNAVAILABLE")
        });
        assert_eq!(agent.level(&c), Some(("NORMAL", "")), "{c}");
    }
}

#[test]
fn values_follow_the_running_program() {
    let sim = sim_at(0.0);
    let a = adapter(1, &["--cnc", &cnc_arg(sim.port()), "--interval", "50"]);
    let mut agent = Agent::connect(a.ports[0]);
    agent.full_state();
    let mut seen = Vec::new();
    for t in [0.0, 0.7, 1.2, 2.6, 3.1] {
        sim.set_elapsed(Duration::from_secs_f64(t));
        let (x, seq, feed) = api(&sim);
        let (xs, ss, fs) = (x.to_string(), seq.to_string(), feed.to_string());
        agent.until("the program's state", |a| {
            a.value("Xact") == xs && a.value("line") == ss && a.value("path_feedrate") == fs
        });
        seen.push((xs, ss));
    }
    seen.dedup();
    assert!(seen.len() >= 3, "the program moved: {seen:?}");
}

#[test]
fn an_alarm_is_a_fault_then_normal() {
    // The built-in profile raises OT0500 on X from 30 s to 40 s.
    let sim = sim_at(20.0);
    let a = adapter(1, &["--cnc", &cnc_arg(sim.port()), "--interval", "50"]);
    let mut agent = Agent::connect(a.ports[0]);
    agent.full_state();
    agent.wait_value("avail", "AVAILABLE");
    agent.until("NORMAL", |a| a.level("Xtravel") == Some(("NORMAL", "")));
    sim.set_elapsed(Duration::from_secs(35));
    agent.until("FAULT", |a| {
        a.level("Xtravel").is_some_and(|l| l.0 == "FAULT")
    });
    let f = &agent.conds["Xtravel"];
    assert_eq!(f[..3], ["FAULT", "OT0500", "4"]);
    assert_eq!(f[4], "OVER TRAVEL ( SOFT 1 ) +X");
    assert_eq!(
        agent.level("system"),
        Some(("NORMAL", "")),
        "only X's travel"
    );
    sim.set_elapsed(Duration::from_secs(45));
    agent.until("NORMAL again", |a| {
        a.level("Xtravel") == Some(("NORMAL", ""))
    });
    assert_eq!(
        agent.conds["Xtravel"],
        ["NORMAL", "", "", "", ""],
        "a bare NORMAL"
    );
}

#[test]
fn ping_is_answered_and_a_silent_peer_dropped() {
    let sim = sim_at(1.0);
    let a = adapter(
        1,
        &[
            "--cnc",
            &cnc_arg(sim.port()),
            "--heartbeat",
            "300",
            "--interval",
            "1000",
        ],
    );
    let mut agent = Agent::connect(a.ports[0]);
    agent.full_state();
    agent.w.write_all(b"* PING\n").unwrap();
    loop {
        if let Line::Pong(ms) = agent.line() {
            assert_eq!(ms, 300);
            break;
        }
    }
    // Silent now: dropped after twice the heartbeat (the read ends).
    let mut rest = Vec::new();
    agent
        .r
        .read_to_end(&mut rest)
        .expect("the adapter closes, not a read timeout");
}

#[test]
fn a_cnc_stopped_and_restarted() {
    let sim = sim_at(1.0);
    let port = sim.port();
    let a = adapter(1, &["--cnc", &cnc_arg(port), "--interval", "50"]);
    let mut agent = Agent::connect(a.ports[0]);
    agent.full_state();
    agent.wait_value("avail", "AVAILABLE");
    agent.wait_value("mode", "AUTOMATIC");
    drop(sim);
    agent.wait_value("avail", "UNAVAILABLE");
    for item in [
        "Xact",
        "mode",
        "execution",
        "program",
        "S1speed",
        "part_count",
    ] {
        agent.wait_value(item, "UNAVAILABLE");
    }
    agent.until("conditions unavailable", |a| {
        condition_names()
            .iter()
            .all(|c| a.level(c).is_some_and(|l| l.0 == "UNAVAILABLE"))
    });
    let sim = Simulator::start(Profile::default(), &format!("127.0.0.1:{port}")).expect("again");
    sim.set_elapsed(Duration::from_secs(1));
    let (x, _, _) = api(&sim);
    agent.wait_value("avail", "AVAILABLE");
    agent.wait_value("Xact", &x.to_string());
    agent.wait_value("mode", "AUTOMATIC");
    agent.until("conditions back", |a| {
        a.level("Xtravel") == Some(("NORMAL", ""))
    });
}

#[test]
fn a_second_agent_gets_the_full_current_state() {
    let sim = sim_at(35.0); // X's overtravel alarm active
    let a = adapter(1, &["--cnc", &cnc_arg(sim.port()), "--interval", "50"]);
    let mut first = Agent::connect(a.ports[0]);
    first.full_state();
    first.until("the alarm", |a| {
        a.level("Xtravel").is_some_and(|l| l.0 == "FAULT")
    });
    first.wait_value("avail", "AVAILABLE");
    first.wait_value("program", PROGRAM);
    // The clock is stopped: nothing changes any more.
    let mut second = Agent::connect(a.ports[0]);
    second.full_state();
    // What the first agent was sent up to then (items read late in a poll,
    // such as the program's comment, may still be in its socket) is what
    // the second got at once; a difference that never resolves times out
    // in `line`.
    let (values, conds) = (second.values.clone(), second.conds.clone());
    first.until("the second agent's state", |a| {
        a.values == values && a.conds == conds
    });
    assert_eq!(second.values, first.values);
    assert_eq!(second.conds, first.conds);
}

/// The adapter's own count of one run: (polls, request frames, most in
/// one poll).
fn poll_count(stderr: &[u8]) -> (u64, u64, u64) {
    let err = String::from_utf8_lossy(stderr);
    let l = err
        .lines()
        .find(|l| l.contains(" polls, "))
        .unwrap_or_else(|| panic!("no count in {err}"));
    let n: Vec<u64> = l
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|w| w.parse().ok())
        .collect();
    let k = n.len();
    assert!(k >= 3, "{l}");
    (n[k - 3], n[k - 2], n[k - 1])
}

#[test]
fn a_poll_is_at_most_three_round_trips() {
    let sim = sim_at(1.0);
    let cnc = cnc_arg(sim.port());
    // One poll, then eleven: connecting, discovery and the tool table are
    // the same in both; the difference is ten polls.
    let run = |polls: u64| {
        let before = sim.data_frames();
        let out = focas()
            .args(["adapter", "--cnc", &cnc, "--listen", "127.0.0.1:0"])
            .args(["--interval", "10", "--polls", &polls.to_string()])
            .output()
            .expect("adapter");
        assert!(out.status.success());
        let (n, frames, most) = poll_count(&out.stderr);
        assert_eq!(n, polls);
        // The first poll reads the program's comment too: still <= 3.
        assert!(most <= 3, "{most} frames in one poll");
        (sim.data_frames() - before, frames)
    };
    let (one, one_said) = run(1);
    let (eleven, eleven_said) = run(11);
    let polled = eleven - one;
    assert_eq!(
        polled,
        eleven_said - one_said,
        "the adapter counts them all"
    );
    assert!(polled > 0);
    assert!(polled <= 3 * 10, "{polled} frames in 10 polls");
}

/// What the Rust API reads for the items FANUC's C++ adapter sends and
/// the last session lacked.
#[test]
fn every_item_of_fanucs_adapter() {
    let sim = sim_at(1.0);
    let a = adapter(1, &["--cnc", &cnc_arg(sim.port()), "--interval", "100"]);
    let mut agent = Agent::connect(a.ports[0]);
    agent.full_state();
    agent.wait_value("avail", "AVAILABLE");
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5)).unwrap();
    let name = cnc.program_name().unwrap();
    assert_eq!(name, PROGRAM);
    agent.wait_value("program", &name);
    let comment = cnc.program_entry(1234).unwrap().unwrap().comment;
    assert_eq!(comment, "POCKET DEMO");
    agent.wait_value("program_comment", &comment);
    let (group, tools) = cnc.tool_group_tools(0).unwrap();
    // The built-in profile's first tool life group: 1, with T1 and T11.
    assert_eq!((group, tools), (1, 2));
    agent.wait_value("tool_group", &group.to_string());
    let m = cnc
        .operator_message()
        .unwrap()
        .expect("a message on display");
    agent.wait_value("message", &format!("{}|{}", m.number, m.text));
    assert_eq!(agent.value("message"), "2001|CHECK COOLANT NOZZLE");
    let speeds = cnc.spindle_speeds().unwrap();
    agent.wait_value("S1speed", &speeds[0].to_string());
    // Every item FANUC's adapter sends for this machine (fanuc_adapter.cpp,
    // fanuc_path.cpp, fanuc_axis.cpp), by the same name.
    let mut theirs: Vec<String> = [
        "avail",
        "message",
        "part_count",
        "tool_id",
        "tool_group",
        "program",
        "program_comment",
        "line",
        "block",
        "path_feedrate",
        "path_position",
        "active_axes",
        "mode",
        "execution",
        "f_command",
        "estop",
        "S1speed",
        "S1load",
    ]
    .map(String::from)
    .to_vec();
    for ax in ["X", "Y", "Z"] {
        theirs.push(format!("{ax}act"));
        theirs.push(format!("{ax}load"));
    }
    for item in &theirs {
        let v = agent.value(item);
        assert!(!v.is_empty() && v != "UNAVAILABLE", "{item}: {v:?}");
    }
    for c in [
        "servo",
        "comms",
        "logic",
        "motion",
        "system",
        "S1servo",
        "Xtravel",
        "Xoverheat",
        "Xservo",
    ] {
        assert!(agent.conds.contains_key(c), "{c}");
    }
}

#[test]
fn systems_are_conditions_from_pmc_bits_and_alarms() {
    // R500.2 set (R500 = 0x04); OT0500 raised from 30 s to 40 s.
    let text = fwlib32::sim::profile::DEFAULT_PROFILE.replace(
        "data = { 500 = [0x00, 0x2a] }",
        "data = { 500 = [0x04, 0x2a] }",
    );
    assert_ne!(text, fwlib32::sim::profile::DEFAULT_PROFILE);
    let sim = Simulator::start(Profile::parse(&text).unwrap(), "127.0.0.1:0").unwrap();
    sim.set_elapsed(Duration::from_secs(20));
    assert!(
        Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))
            .unwrap()
            .pmc_bit(fwlib32::native::PmcArea::R, 500, 2)
            .unwrap()
    );
    let dir = toolchain::scratch("adapter_systems");
    let cfg = dir.join("systems.toml");
    std::fs::write(
        &cfg,
        format!(
            "interval = 50\n\n\
             [[system]]\nname = \"coolant\"\npmc = \"R500.2\"\ntext = \"COOLANT LEVEL LOW\"\n\n\
             [[system]]\nname = \"hydraulic\"\npmc = \"R500.3\"\n\n\
             [[system]]\nname = \"air\"\ncomponent = \"pneumatic\"\npmc = \"R500.3\"\nactive = 0\n\n\
             [[system]]\nname = \"electric\"\nalarms = [500]\n\n\
             [[device]]\ncnc = \"127.0.0.1:{}\"\n",
            sim.port()
        ),
    )
    .unwrap();
    let a = adapter(1, &["--config", cfg.to_str().unwrap()]);
    let mut names = condition_names();
    names.extend(["coolant", "hydraulic", "air", "electric"].map(String::from));
    let mut agent = Agent::with(a.ports[0], names);
    agent.full_state();
    agent.wait_value("avail", "AVAILABLE");
    agent.until("coolant FAULT", |a| {
        a.level("coolant").is_some_and(|l| l.0 == "FAULT")
    });
    assert_eq!(
        agent.conds["coolant"],
        ["FAULT", "R500.2", "", "", "COOLANT LEVEL LOW"]
    );
    agent.until("air FAULT (active low)", |a| {
        a.level("air").is_some_and(|l| l.0 == "FAULT")
    });
    // The same bit, active high: NORMAL (its line may follow air's).
    agent.until("hydraulic NORMAL", |a| {
        a.level("hydraulic") == Some(("NORMAL", ""))
    });
    agent.until("electric NORMAL", |a| {
        a.level("electric") == Some(("NORMAL", ""))
    });
    sim.set_elapsed(Duration::from_secs(35));
    agent.until("electric FAULT", |a| {
        a.level("electric").is_some_and(|l| l.0 == "FAULT")
    });
    assert_eq!(agent.conds["electric"][..2], ["FAULT", "OT0500"]);
    sim.set_elapsed(Duration::from_secs(45));
    agent.until("electric NORMAL again", |a| {
        a.level("electric") == Some(("NORMAL", ""))
    });
    let xml = focas()
        .args(["adapter", "--devices-xml", "--config"])
        .arg(&cfg)
        .output()
        .expect("devices-xml");
    let xml = String::from_utf8(xml.stdout).unwrap();
    assert!(xml.contains("<Systems ") && xml.contains("<Coolant ") && xml.contains("<Pneumatic "));
    assert!(xml.contains(" name=\"coolant\" type=\"SYSTEM\""), "{xml}");
}

#[test]
fn time_series_sampled_between_polls() {
    let sim = sim_at(1.0);
    let dir = toolchain::scratch("adapter_series");
    let cfg = dir.join("series.toml");
    std::fs::write(
        &cfg,
        format!(
            "interval = 300\n\n[series]\nrate = 50\nitems = [\"load\", \"speed\"]\n\n\
             [[device]]\ncnc = \"127.0.0.1:{}\"\n",
            sim.port()
        ),
    )
    .unwrap();
    let a = adapter(1, &["--config", cfg.to_str().unwrap()]);
    let mut agent = Agent::connect(a.ports[0]);
    agent.full_state();
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5)).unwrap();
    let load = cnc.servo_loads().unwrap()[1].load.to_string();
    let speed = cnc.spindle_speeds().unwrap()[0].to_string();
    for (item, v) in [("Yload_ts", load), ("S1speed_ts", speed)] {
        // The full state may say UNAVAILABLE before the first series.
        agent.until(item, |a| {
            a.values.get(item).is_some_and(|v| v.contains('|'))
        });
        let f: Vec<String> = agent.value(item).split('|').map(String::from).collect();
        assert_eq!(f.len(), 3, "count|rate|values: {f:?}");
        let n: usize = f[0].parse().unwrap();
        assert_eq!(f[1], "50");
        let vs: Vec<&str> = f[2].split(' ').collect();
        // The clock is stopped: every sample the same.
        assert!(n >= 2, "sampled faster than the poll: {f:?}");
        assert_eq!(vs, vec![v.as_str(); n], "{item}");
    }
    let xml = focas()
        .args(["adapter", "--devices-xml", "--config"])
        .arg(&cfg)
        .output()
        .expect("devices-xml");
    let xml = String::from_utf8(xml.stdout).unwrap();
    assert!(
        xml.contains(" name=\"Xload_ts\" type=\"LOAD\" subType=\"ACTUAL\" units=\"PERCENT\" nativeUnits=\"PERCENT\" representation=\"TIME_SERIES\" sampleRate=\"50\""),
        "{xml}"
    );
}

#[test]
fn the_tool_table_as_cutting_tool_assets() {
    let sim = sim_at(1.0);
    let a = adapter(1, &["--cnc", &cnc_arg(sim.port()), "--interval", "100"]);
    let mut agent = Agent::connect(a.ports[0]);
    agent.full_state();
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5)).unwrap();
    let groups = cnc.tool_life_groups(1, 44).unwrap();
    let tools: Vec<_> = groups.iter().flat_map(|g| &g.tools).collect();
    assert!(tools.len() >= 2);
    // The tool table is read apart from the polls, just after connecting:
    // the full state may come before it.
    agent.until("every tool's asset", |a| a.assets.len() >= tools.len());
    assert_eq!(agent.assets.len(), tools.len(), "{:?}", agent.assets.keys());
    for g in &groups {
        for t in &g.tools {
            let (kind, doc) = &agent.assets[&format!("device.T{}", t.number)];
            assert_eq!(kind, "CuttingTool");
            assert!(doc.starts_with("<CuttingTool ") && doc.trim_end().ends_with("</CuttingTool>"));
            assert!(doc.contains(&format!("toolId=\"{}\"", t.number)), "{doc}");
            assert!(
                doc.contains(&format!("limit=\"{}\">{}</ToolLife>", g.life, g.count)),
                "{doc}"
            );
            assert!(doc.contains(&format!(
                "<ProgramToolGroup>{}</ProgramToolGroup>",
                g.number
            )));
            // Length: geometry + wear of offset H (memory C: radius wear,
            // radius geometry, length wear, length geometry).
            if let Ok(o) = cnc.tool_offsets(t.length_offset as i16, t.length_offset as i16) {
                let d = |v: i32| Decimal::new(v, 3).to_string();
                let want = format!(
                    "nominal=\"{}\" units=\"MILLIMETER\">{}</FunctionalLength>",
                    d(o[3]),
                    d(o[3] + o[2])
                );
                assert!(doc.contains(&want), "{want} in {doc}");
            }
        }
    }
    // The built-in profile's T1: H1 152.340 worn 0.012, D1 radius 5.000,
    // group 1: 37 of 120 minutes.
    let t1 = &agent.assets["device.T1"].1;
    assert!(
        t1.contains("nominal=\"152.340\" units=\"MILLIMETER\">152.328</FunctionalLength>"),
        "{t1}"
    );
    assert!(
        t1.contains("nominal=\"10.000\" units=\"MILLIMETER\">10.000</CuttingDiameterMax>"),
        "{t1}"
    );
    assert!(
        t1.contains("<ToolLife type=\"MINUTES\" countDirection=\"UP\" limit=\"120\">37</ToolLife>"),
        "{t1}"
    );
    // A second agent gets them too.
    let mut second = Agent::connect(a.ports[0]);
    second.full_state();
    assert_eq!(second.assets, agent.assets);
}

#[test]
fn devices_xml_names_every_item_sent() {
    let (s1, s2) = (sim_at(1.0), sim_at(1.0));
    let dir = toolchain::scratch("adapter_devices_xml");
    let cfg = dir.join("shop.toml");
    std::fs::write(
        &cfg,
        format!(
            "interval = 100\n\n[[device]]\nname = \"mill-1\"\ncnc = \"127.0.0.1:{}\"\n\n\
             [[device]]\nname = \"mill-2\"\ncnc = \"127.0.0.1:{}\"\n",
            s1.port(),
            s2.port()
        ),
    )
    .unwrap();
    let out = focas()
        .args(["adapter", "--devices-xml", "--config"])
        .arg(&cfg)
        .output()
        .expect("devices-xml");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let xml = String::from_utf8(out.stdout).unwrap();
    assert!(xml.starts_with("<?xml"));
    assert_eq!(xml.matches("<Device ").count(), 2);
    assert!(xml.contains("name=\"mill-1\"") && xml.contains("name=\"mill-2\""));
    assert_eq!(xml.matches("<Linear ").count(), 6);
    let a = adapter(2, &["--config", cfg.to_str().unwrap()]);
    let mut agent = Agent::connect(a.ports[1]);
    agent.full_state();
    for name in agent.values.keys().chain(agent.conds.keys()) {
        assert!(
            xml.contains(&format!(" name=\"{name}\" ")),
            "{name} in Devices.xml"
        );
    }
    assert_eq!(
        xml.matches("<DataItem ").count(),
        2 * (agent.values.len() + agent.conds.len())
    );
}

#[test]
fn one_adapter_serves_a_fleet() {
    // 100 CNCs, one adapter process, a port each from a config file.
    const N: usize = 100;
    let fleet = Fleet::start(
        &[Profile::default()],
        "127.0.0.1:0",
        FleetOptions {
            machines: Some(N),
            worker_threads: Some(2),
            ..FleetOptions::default()
        },
    )
    .expect("fleet");
    fleet.set_elapsed(Duration::from_secs(1));
    let dir = toolchain::scratch("adapter_fleet");
    let cfg = dir.join("fleet.toml");
    let mut text = String::from("interval = 1000\n");
    for i in 0..N {
        text.push_str(&format!(
            "\n[[device]]\nname = \"m{i}\"\ncnc = \"127.0.0.1:{}\"\nlisten = \"127.0.0.1:0\"\n",
            fleet.port(i)
        ));
    }
    std::fs::write(&cfg, text).unwrap();
    let a = adapter(N, &["--config", cfg.to_str().unwrap()]);
    assert_eq!(a.ports.len(), N);
    for (i, port) in a.ports.iter().enumerate() {
        let mut agent = Agent::connect(*port);
        agent.full_state();
        agent.wait_value("avail", "AVAILABLE");
        agent.until("values", |a| {
            a.value("Xact") != "UNAVAILABLE" && a.value("mode") == "AUTOMATIC"
        });
        assert_eq!(agent.value("program"), PROGRAM, "machine {i}");
    }
}

#[test]
fn a_second_path_is_named_with_its_number() {
    // The built-in profile with its path twice: X Y Z and S1 on both.
    let text = fwlib32::sim::profile::DEFAULT_PROFILE;
    let start = text.find("\n[[path]]").unwrap();
    let end = text.find("\n[[program]]").unwrap();
    let end = text[..end].rfind("# -----").unwrap();
    let two = format!("{}{}{}", &text[..end], &text[start..end], &text[end..]);
    let profile = Profile::parse(&two).expect("a two-path profile");
    let sim = Simulator::start(profile, "127.0.0.1:0").expect("simulator");
    sim.set_elapsed(Duration::from_secs(1));
    let a = adapter(1, &["--cnc", &cnc_arg(sim.port()), "--interval", "50"]);
    let mut names = condition_names();
    for c in ["servo", "comms", "logic", "motion", "system"] {
        names.push(format!("{c}2"));
    }
    for a in ["X2", "Y2", "Z2"] {
        for c in ["travel", "overheat", "servo"] {
            names.push(format!("{a}{c}"));
        }
    }
    names.push("S12servo".into());
    let mut agent = Agent::with(a.ports[0], names);
    agent.full_state();
    agent.wait_value("avail", "AVAILABLE");
    agent.wait_value("mode2", "AUTOMATIC");
    agent.wait_value("active_axes2", "X Y Z");
    agent.wait_value("program2", "//CNC_MEM/USER/PATH2/O1234");
    for item in [
        "X2act",
        "Y2load",
        "S12speed",
        "S12load",
        "line2",
        "path_position2",
    ] {
        agent.until(item, |a| {
            !a.value(item).is_empty() && a.value(item) != "UNAVAILABLE"
        });
    }
    assert!(!agent.values.contains_key("estop2"), "one emergency stop");
    let xml = focas()
        .args(["adapter", "--devices-xml", "--cnc", &cnc_arg(sim.port())])
        .output()
        .expect("devices-xml");
    let xml = String::from_utf8(xml.stdout).unwrap();
    assert_eq!(xml.matches("<Path ").count(), 2);
    assert!(xml.contains(" name=\"X2act\" ") && xml.contains(" name=\"S12servo\" "));
}

#[test]
fn items_configured_as_in_the_cpp_adapters_ini() {
    // The built-in profile raises OT0500 (type 4, overtravel) on X from
    // 30 s to 40 s.
    let sim = sim_at(35.0);
    let dir = toolchain::scratch("adapter_custom");
    let cfg = dir.join("custom.toml");
    std::fs::write(
        &cfg,
        format!(
            "interval = 50\n\n\
             [macros]\ngauge1 = 500\n\n\
             [pmc]\nFovr_pmc = -12\nr500 = 50500\nr501 = \"R501\"\n\n\
             [parameters]\ncuttime = 6754\npowerontime = 6750\n\n\
             [diagnostics]\nXposError = 15202\nDCLink = 10752\nspload = 4901\n\n\
             [alarms]\nalarm1 = 1\nalarm2 = 2\n\n\
             [critical]\ncritical1 = 1\n\n\
             [[device]]\ncnc = \"127.0.0.1:{}\"\n",
            sim.port()
        ),
    )
    .unwrap();
    let a = adapter(1, &["--config", cfg.to_str().unwrap()]);
    let mut agent = Agent::connect(a.ports[0]);
    agent.full_state();
    agent.wait_value("avail", "AVAILABLE");
    let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5)).unwrap();
    let gauge = cnc.macro_var(500).unwrap().unwrap().to_string();
    let cut = cnc.param::<i32>(6754, None).unwrap().to_string();
    let on = cnc.param::<i32>(6750, None).unwrap().to_string();
    let pos_err = cnc.diag_values(5202, Some(1)).unwrap().values[0].to_string();
    let dc = cnc.diag_values(752, Some(1)).unwrap().values[0].to_string();
    let spload = cnc.diag_values(4901, None).unwrap().values[0].to_string();
    let g12 = cnc.pmc::<u8>(fwlib32::native::PmcArea::G, 12..=12).unwrap()[0];
    assert!(g12 >= 0x80, "G12 {g12:#x}: inverted (*FV0-7)");
    let alarm = &cnc.alarms().unwrap()[0];
    let want = [
        ("gauge1", gauge),
        ("Fovr_pmc", (!g12).to_string()),
        ("r500", "0".to_string()),
        ("r501", "42".to_string()),
        ("cuttime", cut),
        ("powerontime", on),
        ("XposError", pos_err),
        ("DCLink", dc),
        ("spload", spload),
        ("alarm1", format!("{} {}", alarm.number, alarm.message)),
        ("alarm2", String::new()),
        ("critical1", String::new()),
    ];
    for (item, v) in &want {
        agent.wait_value(item, v);
        // (An empty value must have been sent, not just be absent.)
        assert!(agent.values.contains_key(*item), "{item} sent");
    }
    assert_eq!(agent.value("gauge1"), "25.400");
    assert_eq!(agent.value("Fovr_pmc"), agent.value("Fovr"));
    assert_eq!(agent.value("alarm1"), "500 OVER TRAVEL ( SOFT 1 ) +X");
    let xml = focas()
        .args(["adapter", "--devices-xml", "--config"])
        .arg(&cfg)
        .output()
        .expect("devices-xml");
    let xml = String::from_utf8(xml.stdout).unwrap();
    for (item, _) in &want {
        assert!(xml.contains(&format!(" name=\"{item}\" ")), "{item}");
    }
    assert!(xml.contains(" name=\"gauge1\" type=\"x:MACRO_VARIABLE\""));
}
