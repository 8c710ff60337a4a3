//! The `focas` binary against an in-process simulator (the built-in
//! profile, a 31i mill, its clock stopped where a test needs it): every
//! command as text and as `--json`, checked against the profile; a dead
//! port, a bad address, a CNC that never answers and an absent parameter
//! each give one line on stderr and exit status 1.

use crate::toolchain;
use fwlib32::sim::{Profile, Simulator};
use serde_json::Value;
use std::process::Output;
use std::time::Duration;

fn sim() -> Simulator {
    let s = Simulator::start(Profile::default(), "127.0.0.1:0").expect("simulator");
    s.set_elapsed(Duration::ZERO);
    s
}

/// The time zone the commands run in (a POSIX rule: no tz database
/// needed), UTC+05:30: times show its offset.
const TZ: &str = "IST-5:30";

/// `focas --host 127.0.0.1 --port PORT ARGS...`.
fn run_port(port: u16, args: &[&str]) -> Output {
    toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
        .env_remove("FOCAS_HOST")
        .env_remove("FOCAS_PORT")
        .env("TZ", TZ)
        .args([
            "--host",
            "127.0.0.1",
            "--port",
            &port.to_string(),
            "--timeout",
            "5",
        ])
        .args(args)
        .output()
        .expect("run focas")
}

/// The command's stdout; it must succeed with nothing on stderr.
fn ok(s: &Simulator, args: &[&str]) -> String {
    let o = run_port(s.port(), args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "focas {args:?}: {:?}: {err}", o.status);
    assert!(err.is_empty(), "focas {args:?} wrote to stderr: {err}");
    String::from_utf8(o.stdout).unwrap()
}

/// The command's one JSON line.
fn json(s: &Simulator, args: &[&str]) -> Value {
    let mut a = vec!["--json"];
    a.extend_from_slice(args);
    let out = ok(s, &a);
    assert_eq!(out.lines().count(), 1, "{out}");
    serde_json::from_str(&out).unwrap()
}

/// A failure: exit status 1 and exactly one line on stderr, containing `want`.
fn fails(o: Output, want: &[&str]) -> String {
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    assert!(err.starts_with("focas: "), "{err}");
    assert!(
        !err.contains("panicked") && !err.contains("backtrace"),
        "{err}"
    );
    for w in want {
        assert!(err.contains(w), "{err:?} lacks {w:?}");
    }
    assert!(o.stdout.is_empty());
    err
}

#[test]
fn info() {
    let s = sim();
    let t = ok(&s, &["info"]);
    assert!(t.contains("0a0b0c0d-12345678-9abcdef0-00c0ffee"), "{t}");
    assert!(
        t.contains("path 1  31M series G421 version 08.0, 3 axes (max 32)"),
        "{t}"
    );
    let j = json(&s, &["info"]);
    assert_eq!(j["cnc_id"], "0a0b0c0d-12345678-9abcdef0-00c0ffee");
    let p = &j["paths"][0];
    assert_eq!(
        (p["cnc_type"].as_str(), p["mt_type"].as_str()),
        (Some("31"), Some("M"))
    );
    assert_eq!(
        (p["series"].as_str(), p["version"].as_str()),
        (Some("G421"), Some("08.0"))
    );
    assert_eq!(
        (p["axes"].as_u64(), p["max_axes"].as_u64()),
        (Some(3), Some(32))
    );
}

#[test]
fn status() {
    let s = sim();
    let t = ok(&s, &["status"]);
    for line in [
        "mode       MEM",
        "run        STRT",
        "program    O1234 (main O1234)",
    ] {
        assert!(t.lines().any(|l| l == line), "{line:?} in {t}");
    }
    let j = json(&s, &["status"]);
    assert_eq!(j["mode"], serde_json::json!({"code": 1, "name": "MEM"}));
    assert_eq!(j["run"]["name"], "STRT");
    assert_eq!(j["emergency"]["code"], 0);
    assert_eq!(j["program"], 1234);
    assert_eq!(j["spindle_speed"], 12000);
}

#[test]
fn positions() {
    let s = sim();
    let t = ok(&s, &["pos"]);
    let lines: Vec<&str> = t.lines().collect();
    assert_eq!(
        lines[0],
        "axis  absolute  machine  relative  distance  unit"
    );
    assert_eq!(lines[1], "X      125.000  125.000   125.000     0.000  mm");
    assert_eq!(lines[2], "Y      -42.500  -42.500   -42.500     0.000  mm");
    let j = json(&s, &["pos"]);
    let z = &j["axes"][2];
    assert_eq!(
        (z["name"].as_str(), z["absolute"].as_f64()),
        (Some("Z"), Some(10.0))
    );
    assert_eq!(
        (z["decimals"].as_i64(), z["unit"].as_str()),
        (Some(3), Some("mm"))
    );
}

#[test]
fn alarms_and_history() {
    let s = sim();
    // The history first: a raised alarm joins it.
    let t = ok(&s, &["alarms", "--history"]);
    assert!(
        t.starts_with("2024-05-17 13:45:30  PC1001          COOLANT LEVEL LOW\n"),
        "{t}"
    );
    let h = json(&s, &["alarms", "--history"]);
    // RFC 3339: the CNC's clock, in this computer's zone.
    assert_eq!(h["history"][1]["time"], "2024-05-16T09:12:05+05:30");
    assert_eq!(h["history"][1]["code"], "OT0500");
    assert_eq!(h["history"][2]["message"], "SERVO ALARM: EXCESS ERROR");
    assert_eq!(ok(&s, &["alarms"]), "no alarm\n");
    assert_eq!(json(&s, &["alarms"])["alarms"], serde_json::json!([]));
    s.set_elapsed(Duration::from_secs(35)); // the profile's event: 30 s, for 10 s
    let t = ok(&s, &["alarms"]);
    assert_eq!(t, "OT0500  axis 1  OVER TRAVEL ( SOFT 1 ) +X\n");
    let a = &json(&s, &["alarms"])["alarms"][0];
    assert_eq!(
        (a["number"].as_i64(), a["prefix"].as_str()),
        (Some(500), Some("OT"))
    );
}

#[test]
fn params_and_diagnosis() {
    let s = sim();
    assert_eq!(ok(&s, &["param", "6711"]), "6711  2word  1234\n");
    assert_eq!(ok(&s, &["param", "0"]), "0  bit  00000010\n");
    assert_eq!(
        ok(&s, &["param", "1320"]),
        "1320  real  X  800.000\n            Y  500.000\n            Z    0.000\n"
    );
    assert_eq!(
        ok(&s, &["param", "1320", "--axis", "2"]),
        "1320  real  Y  500.000\n"
    );
    let j = json(&s, &["param", "1320"]);
    assert_eq!(j["values"], serde_json::json!([800.0, 500.0, 0.0]));
    assert_eq!(j["axes"], serde_json::json!(["X", "Y", "Z"]));
    assert_eq!(
        (j["kind"].as_str(), j["per_axis"].as_bool()),
        (Some("real"), Some(true))
    );
    let j = json(&s, &["param", "6711"]);
    assert_eq!(
        (j["values"][0].as_i64(), j["per_axis"].as_bool()),
        (Some(1234), Some(false))
    );
    let j = json(&s, &["diag", "411", "--axis", "3"]);
    assert_eq!(
        (j["kind"].as_str(), j["values"][0].as_i64()),
        (Some("word"), Some(35))
    );
    assert!(ok(&s, &["diag", "300"]).contains("Y  -8\n"));
}

#[test]
fn macro_variables() {
    let s = sim();
    assert_eq!(ok(&s, &["macro", "500"]), "#500  25.400\n");
    assert_eq!(ok(&s, &["macro", "150"]), "#150  vacant\n");
    assert_eq!(ok(&s, &["macro", "150=-2.50"]), "#150  -2.50\n");
    let j = json(&s, &["macro", "150"]);
    assert_eq!(
        (j["value"].as_f64(), j["decimals"].as_i64()),
        (Some(-2.5), Some(2))
    );
    let j = json(&s, &["macro", "150=vacant"]);
    assert!(j["value"].is_null());
}

#[test]
fn pmc() {
    let s = sim();
    assert_eq!(ok(&s, &["pmc", "D0", "--type", "long"]), "D0  1000\n");
    assert_eq!(ok(&s, &["pmc", "G30"]), "G30  100\n");
    assert_eq!(ok(&s, &["pmc", "F0.5"]), "F0.5  1\n");
    let t = ok(&s, &["pmc", "R500..R501", "--type", "word"]);
    assert_eq!(t, "R500  42\n");
    let j = json(&s, &["pmc", "D100..D120", "--type", "word"]);
    let v = j["values"].as_array().unwrap();
    assert_eq!((v.len(), v[10]["address"].as_u64()), (11, Some(120)));
    let j = json(&s, &["pmc", "R0.3"]);
    assert_eq!(
        (j["area"].as_str(), j["value"].as_bool()),
        (Some("R"), Some(false))
    );
    let o = run_port(s.port(), &["pmc", "Q1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("no PMC area \"Q\""));
}

#[test]
fn programs() {
    let s = sim();
    let t = ok(&s, &["prog", "ls"]);
    assert!(t.contains("O0100") && t.contains("O1234"), "{t}");
    assert!(t.contains("2024-05-17 13:45  POCKET DEMO"), "{t}");
    let j = json(&s, &["prog", "ls"]);
    assert_eq!(j["programs"][1]["comment"], "POCKET DEMO");
    assert_eq!(j["programs"][0]["number"], 100);
    assert_eq!(j["programs"][1]["modified"], "2024-05-17T13:45:00+05:30");

    let text = ok(&s, &["prog", "get", "1234"]);
    assert!(
        text.starts_with("%\nO1234 (POCKET DEMO)\nN10 G90 G17 G40 G49 G80\n"),
        "{text}"
    );
    assert!(text.ends_with("N130 M30\n%\n"), "{text}");
    let j = json(&s, &["prog", "get", "100"]);
    assert!(j["text"].as_str().unwrap().contains("N30 G04 X60."));

    let dir = std::env::temp_dir().join(format!("focas-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("O1234.nc");
    let t = ok(&s, &["prog", "get", "1234", file.to_str().unwrap()]);
    assert!(t.starts_with("O1234: "), "{t}");
    assert_eq!(
        std::fs::read_to_string(&file).unwrap().trim_end(),
        text.trim_end()
    );

    // Download a new program, list it, fetch it back, delete it.
    let new = dir.join("O4242.nc");
    std::fs::write(&new, "%\nO4242 (FROM THE CLI)\nG00 X1.\nM30\n%").unwrap();
    let t = ok(&s, &["prog", "put", new.to_str().unwrap()]);
    assert!(t.ends_with(": 36 bytes downloaded\n"), "{t}");
    assert!(ok(&s, &["prog", "ls"]).contains("FROM THE CLI"));
    assert_eq!(
        ok(&s, &["prog", "get", "4242"]).trim_end(),
        "%\nO4242 (FROM THE CLI)\nG00 X1.\nM30\n%"
    );
    // The same number again: the CNC refuses it (EW_DATA), said in words.
    fails(
        run_port(s.port(), &["prog", "put", new.to_str().unwrap()]),
        &["O4242 already in memory", "cnc_dwnend3: EW_DATA (5)"],
    );
    let e = json_fails(
        run_port(s.port(), &["--json", "prog", "put", new.to_str().unwrap()]),
        1,
    );
    assert_eq!(
        e["reason"]
            .as_str()
            .map(|r| r.starts_with("O4242 already in memory")),
        Some(true),
        "{e}"
    );
    assert_eq!(
        (e["function"].as_str(), e["code"].as_i64()),
        (Some("cnc_dwnend3"), Some(5))
    );
    assert_eq!(json(&s, &["prog", "rm", "4242"])["deleted"], 4242);
    // A program without an O number refused: the bare code.
    let anon = dir.join("anon.nc");
    std::fs::write(&anon, "%\nG00 X1.\nM30\n%").unwrap();
    let e = fails(
        run_port(s.port(), &["prog", "put", anon.to_str().unwrap()]),
        &["cnc_dwnend3"],
    );
    assert!(!e.contains("already"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();

    fails(
        run_port(s.port(), &["prog", "get", "4242"]),
        &["O4242 not found", "cnc_upload3: EW_DATA (5)"],
    );
    // The running program cannot go.
    fails(
        run_port(s.port(), &["prog", "rm", "1234"]),
        &["O1234 is running", "cnc_delete: EW_BUSY (-1)"],
    );
    assert!(ok(&s, &["prog", "ls"]).contains("O1234"));
    let o = run_port(s.port(), &["prog", "put", "x.nc"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("x.nc"));
    fails(
        run_port(s.port(), &["prog", "rm", "4242"]),
        &["O4242 not found", "cnc_delete: EW_DATA (5)"],
    );
}

#[test]
fn watch() {
    let s = sim();
    let t = ok(&s, &["watch", "--count", "2", "--interval", "0"]);
    let lines: Vec<&str> = t.lines().collect();
    assert_eq!(lines.len(), 2, "{t}");
    assert!(lines[0].starts_with("MEM STRT "), "{t}");
    assert!(lines[0].contains("O1234") && lines[0].contains("X125.000 Y-42.500 Z10.000"));
    let out = ok(&s, &["--json", "watch", "-n", "3", "-i", "0"]);
    assert_eq!(out.lines().count(), 3);
    for l in out.lines() {
        let j: Value = serde_json::from_str(l).unwrap();
        assert_eq!(j["status"]["mode"]["name"], "MEM");
        assert_eq!(j["axes"][1]["absolute"], -42.5);
        // 2026-11-28T11:22:06.123+05:30
        let t = j["time"].as_str().unwrap();
        assert!(t.ends_with("+05:30") && t.len() == 29, "{t}");
        assert_eq!((&t[4..5], &t[10..11], &t[19..20]), ("-", "T", "."), "{t}");
        assert_eq!(j["available"], true);
    }
}

#[test]
fn watch_a_dead_cnc_keeps_trying() {
    let (_dead, port) = dead_port();
    let o = run_port(port, &["watch", "-n", "3", "-i", "0"]);
    assert_eq!(o.status.code(), Some(1), "the last sample failed");
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let t = String::from_utf8(o.stdout).unwrap();
    assert_eq!(t.lines().count(), 3, "{t}");
    for l in t.lines() {
        assert!(l.starts_with("UNAVAILABLE  "), "{t}");
        assert!(l.contains("cnc_allclibhndl3: EW_SOCKET (-16)"), "{t}");
        assert!(l.contains("refused"), "{t}");
    }
    // On a terminal (a pty, by script(1)) too: each outage a line of its
    // own, never glued to a status line.
    let cmd = format!(
        "{} -H 127.0.0.1:{port} watch -n 2 -i 0",
        toolchain::target_command_line(env!("CARGO_BIN_EXE_focas"))
    );
    let o = std::process::Command::new("script")
        .args(["-q", "-e", "-c", &cmd, "/dev/null"])
        .env("TERM", "xterm")
        .env_remove("FOCAS_HOST")
        .env_remove("FOCAS_PORT")
        .stdin(std::process::Stdio::null())
        .output()
        .expect("script(1), from util-linux");
    assert_eq!(o.status.code(), Some(1));
    let tty = String::from_utf8_lossy(&o.stdout);
    let lines: Vec<&str> = tty
        .split("\r\n")
        .map(|l| l.trim_start_matches("\r\x1b[2K"))
        .filter(|l| !l.is_empty())
        .collect();
    assert_eq!(lines.len(), 2, "{tty:?}");
    assert!(
        lines.iter().all(|l| l.starts_with("UNAVAILABLE  ")),
        "{tty:?}"
    );
    let o = run_port(port, &["watch", "-n", "2", "-i", "0", "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let t = String::from_utf8(o.stdout).unwrap();
    assert_eq!(t.lines().count(), 2, "{t}");
    for l in t.lines() {
        let j: Value = serde_json::from_str(l).unwrap();
        assert_eq!(j["available"], false, "{j}");
        assert_eq!(j["error"]["ew"], "EW_SOCKET", "{j}");
        assert!(j["time"].as_str().unwrap().ends_with("+05:30"), "{j}");
    }
}

/// A focas-sim process on `listen`, killed when dropped.
struct SimProcess(std::process::Child);

impl SimProcess {
    fn start(listen: &str) -> SimProcess {
        SimProcess::with(listen, &[])
    }

    fn with(listen: &str, args: &[&str]) -> SimProcess {
        use std::io::BufRead;
        let mut c = toolchain::target_command(env!("CARGO_BIN_EXE_focas-sim"))
            .args(["--listen", listen])
            .args(args)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("start focas-sim");
        let mut line = String::new();
        std::io::BufReader::new(c.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        assert_eq!(line.trim(), format!("listening on {listen}"));
        SimProcess(c)
    }
}

impl Drop for SimProcess {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

#[test]
fn watch_shows_an_outage_and_reconnects() {
    use std::io::BufRead;
    let listen = format!("127.0.0.1:{}", free_port());
    let sim = SimProcess::start(&listen);
    // --count bounds the run should the test fail half-way.
    let mut watch = toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
        .env_remove("FOCAS_HOST")
        .args(["watch", "-H", &listen, "-t", "2", "-i", "0.1", "-n", "600"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut lines = std::io::BufReader::new(watch.stdout.take().unwrap()).lines();
    let mut seen = Vec::new();
    let mut next_until = |want: &dyn Fn(&str) -> bool| loop {
        let l = lines
            .next()
            .unwrap_or_else(|| panic!("watch ended: {seen:?}"))
            .unwrap();
        seen.push(l.clone());
        if want(&l) {
            return l;
        }
    };
    let values = |l: &str| l.contains("X") && !l.starts_with("UNAVAILABLE");
    next_until(&values);
    drop(sim);
    let down = next_until(&|l: &str| l.starts_with("UNAVAILABLE"));
    assert!(down.contains("EW_SOCKET"), "{down}");
    assert!(down.contains(&listen), "{down}");
    let _sim = SimProcess::start(&listen);
    let back = next_until(&values);
    assert!(back.contains("O1234"), "{back}");
    assert!(watch.try_wait().unwrap().is_none(), "watch still runs");
    let _ = watch.kill();
    let _ = watch.wait();
}

#[test]
fn a_dead_port_is_one_line() {
    let port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let e = fails(
        run_port(port, &["status"]),
        &["cnc_allclibhndl3", "EW_SOCKET (-16)"],
    );
    assert!(e.contains("refused"), "{e}");
}

#[test]
fn a_bad_address_is_one_line() {
    let o = toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
        .args(["--host", "no.such.host.invalid", "--timeout", "2", "info"])
        .output()
        .unwrap();
    fails(
        o,
        &["no.such.host.invalid", "cnc_allclibhndl3", "EW_SOCKET"],
    );
}

#[test]
fn a_silent_cnc_times_out() {
    // Accepts the connection, never answers.
    let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let port = l.local_addr().unwrap().port();
    let o = toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
        .args(["--host", "127.0.0.1", "--port", &port.to_string()])
        .args(["--timeout", "1", "status"])
        .output()
        .unwrap();
    drop(l);
    fails(o, &["cnc_allclibhndl3", "EW_SOCKET", "timed out"]);
}

#[test]
fn an_absent_parameter_is_the_cncs_ew_number() {
    let s = sim();
    let e = fails(
        run_port(s.port(), &["param", "9999"]),
        &["cnc_rdparam", "EW_NUMBER (3)"],
    );
    assert!(e.contains(&format!("127.0.0.1:{}", s.port())), "{e}");
    let e = fails(run_port(s.port(), &["macro", "1=5"]), &["cnc_wrmacro"]);
    assert!(e.contains("EW_NUMBER"), "{e}");
}

/// With --json: exit status `code`, nothing on stderr, and one JSON
/// object on stdout, `{"error": {...}}`.
fn json_fails(o: Output, code: i32) -> Value {
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(code), "{err}");
    assert!(err.is_empty(), "{err}");
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(out.lines().count(), 1, "{out}");
    let j: Value = serde_json::from_str(&out).unwrap();
    assert!(
        j["error"]["message"]
            .as_str()
            .is_some_and(|m| !m.is_empty()),
        "{j}"
    );
    j["error"].clone()
}

#[test]
fn json_errors_are_json_on_stdout() {
    let s = sim();
    let e = json_fails(run_port(s.port(), &["--json", "macro", "1=5"]), 1);
    assert_eq!(e["function"], "cnc_wrmacro");
    assert_eq!(e["ew"], "EW_NUMBER");
    assert_eq!(e["code"], 3);
    assert_eq!(e["host"], format!("127.0.0.1:{}", s.port()));
    assert!(e["meaning"].as_str().unwrap().contains("number"), "{e}");
    let m = e["message"].as_str().unwrap();
    assert!(m.contains("cnc_wrmacro: EW_NUMBER (3)"), "{m}");
    // --json after the subcommand, a dead CNC.
    let (_dead, port) = dead_port();
    let e = json_fails(run_port(port, &["status", "--json"]), 1);
    assert_eq!(
        (e["function"].as_str(), e["code"].as_i64(), e["ew"].as_str()),
        (Some("cnc_allclibhndl3"), Some(-16), Some("EW_SOCKET"))
    );
    // A bad command line: exit 2.
    let e = json_fails(run_port(port, &["pmc", "Q1", "--json"]), 2);
    assert_eq!(e["usage"], true);
    assert!(
        e["message"].as_str().unwrap().contains("no PMC area"),
        "{e}"
    );
    let e = json_fails(bare(&["--json", "status"]), 2);
    assert!(e["message"].as_str().unwrap().contains("--host"), "{e}");
    // compat, on a file that is not a program.
    let readme = toolchain::manifest_dir().join("README.md");
    let e = json_fails(bare(&["compat", "--json", readme.to_str().unwrap()]), 1);
    assert!(e["message"].as_str().unwrap().contains("README.md"), "{e}");
    assert!(e.get("function").is_none(), "{e}");
}

#[test]
fn no_host_is_a_usage_error() {
    let o = toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
        .env_remove("FOCAS_HOST")
        .arg("status")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--host"));
}

#[test]
fn the_host_comes_from_focas_host() {
    let s = sim();
    let o = toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
        .env("FOCAS_HOST", "127.0.0.1")
        .args(["--port", &s.port().to_string(), "--json", "status"])
        .output()
        .unwrap();
    assert!(o.status.success());
    let j: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(j["program"], 1234);
}

/// `focas ARGS...` with no host or port from the environment.
fn bare(args: &[&str]) -> Output {
    toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
        .env_remove("FOCAS_HOST")
        .env_remove("FOCAS_PORT")
        .args(args)
        .output()
        .expect("run focas")
}

fn success(o: &Output) -> String {
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{:?}: {err}", o.status);
    assert!(err.is_empty(), "{err}");
    String::from_utf8(o.stdout.clone()).unwrap()
}

#[test]
fn host_port_in_the_host_and_options_anywhere() {
    let s = sim();
    let at = format!("127.0.0.1:{}", s.port());
    // The port in --host; the options after the subcommand.
    let t = success(&bare(&["-H", &at, "status"]));
    assert!(t.contains("program    O1234"), "{t}");
    let t = success(&bare(&["status", "-H", &at, "-t", "5", "--json"]));
    assert_eq!(serde_json::from_str::<Value>(&t).unwrap()["program"], 1234);
    let port = s.port().to_string();
    let t = success(&bare(&["prog", "ls", "-H", "127.0.0.1", "-p", &port]));
    assert!(t.contains("O1234"), "{t}");
    // The port in --host wins over --port.
    let t = success(&bare(&["-p", "1", "pos", "--host", &at]));
    assert!(t.starts_with("axis "), "{t}");
    // FOCAS_HOST with a port.
    let o = toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
        .env("FOCAS_HOST", &at)
        .env_remove("FOCAS_PORT")
        .args(["param", "6711"])
        .output()
        .unwrap();
    assert_eq!(success(&o), "6711  2word  1234\n");
    // A bad port is a usage error, echoed.
    let o = bare(&["-H", "127.0.0.1:80x", "status"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("\"80x\""));
}

#[test]
fn an_ipv6_host_with_its_port() {
    let s = Simulator::start(Profile::default(), "[::1]:0").expect("a simulator on ::1");
    s.set_elapsed(Duration::ZERO);
    let at = format!("[::1]:{}", s.port());
    let t = success(&bare(&["--host", &at, "--json", "status"]));
    assert_eq!(serde_json::from_str::<Value>(&t).unwrap()["program"], 1234);
    let port = s.port().to_string();
    let t = success(&bare(&["info", "-H", "::1", "-p", &port]));
    assert!(t.contains(&format!("[::1]:{port}")), "{t}");
}

/// A port nobody listens on.
/// A port free when asked (for a simulator to listen on).
fn free_port() -> u16 {
    let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    l.local_addr().unwrap().port()
}

/// A port no CNC answers on, held while the socket lives: bound but not
/// listening, so a connection is refused and no other test of the run can
/// take the port (a closed free port can be).
fn dead_port() -> (std::os::fd::OwnedFd, u16) {
    use std::os::fd::FromRawFd;
    unsafe {
        let fd = libc::socket(libc::AF_INET, libc::SOCK_STREAM, 0);
        assert!(fd >= 0, "socket: {}", std::io::Error::last_os_error());
        let fd = std::os::fd::OwnedFd::from_raw_fd(fd);
        let mut sa: libc::sockaddr_in = std::mem::zeroed();
        sa.sin_family = libc::AF_INET as libc::sa_family_t;
        sa.sin_addr.s_addr = u32::from(std::net::Ipv4Addr::LOCALHOST).to_be();
        let len = size_of::<libc::sockaddr_in>() as libc::socklen_t;
        use std::os::fd::AsRawFd;
        let r = libc::bind(fd.as_raw_fd(), (&raw const sa).cast(), len);
        assert_eq!(r, 0, "bind: {}", std::io::Error::last_os_error());
        let mut got: libc::sockaddr_in = std::mem::zeroed();
        let mut n = len;
        let r = libc::getsockname(fd.as_raw_fd(), (&raw mut got).cast(), &mut n);
        assert_eq!(r, 0, "getsockname: {}", std::io::Error::last_os_error());
        (fd, u16::from_be(got.sin_port))
    }
}

#[test]
fn arguments_are_checked_before_connecting() {
    // The CNC is down: a bad argument is still a usage error (exit 2)
    // that names the argument, not EW_SOCKET.
    let (_dead, port) = dead_port();
    for (args, says) in [
        (&["pmc", "D1OO"][..], "\"D1OO\" is not an address"),
        (&["pmc", "Q1"][..], "no PMC area \"Q\""),
        (&["pmc", "D5..D1"][..], "ends before it starts"),
        (&["macro", "500=abc"][..], "500=abc"),
        (
            &["prog", "put", "/nonexistent/O1.nc"][..],
            "/nonexistent/O1.nc",
        ),
        (&["prog", "get", "x"][..], "'x'"),
        (&["status", "--path", "0"][..], "--path"),
        (&["param", "1320", "--axis", "0"][..], "--axis"),
    ] {
        let o = run_port(port, args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.starts_with("error: "), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err:?} lacks {says:?}");
        assert!(err.contains("--help"), "{args:?}: {err}");
        assert!(!err.contains("EW_SOCKET"), "{args:?}: {err}");
        assert!(o.stdout.is_empty());
    }
    // A good one reaches the (dead) CNC: EW_SOCKET, exit 1.
    fails(run_port(port, &["pmc", "D100"]), &["EW_SOCKET"]);
}

/// A slow CNC (focas-sim --delay-ms: each frame of a transfer late): a
/// program of 14 KB goes down and comes back whole; on a terminal (a pty,
/// by script(1)) the bar shows the rate and the time left.
#[test]
fn a_slow_transfer_with_rate_and_eta() {
    let listen = format!("127.0.0.1:{}", free_port());
    let _sim = SimProcess::with(&listen, &["--delay-ms", "20"]);
    let dir = toolchain::scratch("cli-slow-transfer");
    let file = dir.join("O4343.nc");
    let mut text = String::from("%\nO4343 (SLOW)\n");
    for i in 0..500 {
        text.push_str(&format!("N{i} G01 X{i}.000 F1000\n"));
    }
    text.push_str("M30\n%");
    std::fs::write(&file, &text).unwrap();
    let focas = toolchain::target_command_line(env!("CARGO_BIN_EXE_focas"));
    let cmd = format!("{focas} -H {listen} prog put {}", file.display());
    let o = std::process::Command::new("script")
        .args(["-q", "-e", "-c", &cmd, "/dev/null"])
        .env("TERM", "xterm")
        .env_remove("FOCAS_HOST")
        .stdin(std::process::Stdio::null())
        .output()
        .expect("script(1), from util-linux");
    let tty = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{tty}");
    assert!(
        tty.contains(&format!("{} bytes downloaded", text.len())),
        "{tty}"
    );
    assert!(
        tty.contains("B/s") && tty.contains("ETA "),
        "no rate or ETA: {tty:?}"
    );
    let back = success(&bare(&["-H", &listen, "prog", "get", "4343"]));
    assert_eq!(back.trim_end(), text.trim_end());
    let _ = std::fs::remove_dir_all(&dir);
}
