//! The C examples, compiled with the system C compiler against
//! include/fwlib32.h and the built libfwlib32.so, run against the simulator.

use fwlib32::ew::EW_RESET;
use fwlib32::sim::{Profile, Simulator};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

use crate::toolchain;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn cc(args: &[&str]) {
    let out = Command::new(toolchain::cc())
        .args(args)
        .output()
        .expect("cc (the system C compiler) must be installed");
    assert!(
        out.status.success(),
        "cc {:?} failed:\n{}",
        args,
        String::from_utf8_lossy(&out.stderr)
    );
}

fn build_example(name: &str, dir: &Path) -> PathBuf {
    build_c(&root().join("c-examples").join(format!("{name}.c")), dir)
}

/// Compiles one C source against include/fwlib32.h and the library in `dir`.
fn build_c(src: &Path, dir: &Path) -> PathBuf {
    let name = src.file_stem().unwrap().to_str().unwrap();
    let exe = dir.join(name);
    let inc = root().join("include");
    cc(&[
        "-std=c99",
        "-Wall",
        "-Wextra",
        "-Werror",
        "-I",
        inc.to_str().unwrap(),
        src.to_str().unwrap(),
        "-L",
        dir.to_str().unwrap(),
        "-lfwlib32",
        "-o",
        exe.to_str().unwrap(),
    ]);
    exe
}

/// A C test of tests/c: the program compiled against the header and the
/// built library, run against a simulator of `profile` (host and port as
/// its arguments). It must exit 0; its `key=value` lines are returned with
/// the simulator, for the test to compare with the machine's state.
pub(crate) fn run_c_test(name: &str, profile: Profile) -> (HashMap<String, String>, Simulator) {
    let sim = Simulator::start(profile, "127.0.0.1:0").unwrap();
    (run_c_against(name, &sim), sim)
}

/// [`run_c_test`] against a simulator already started (and set up).
pub(crate) fn run_c_against(name: &str, sim: &Simulator) -> HashMap<String, String> {
    // A directory of its own per run: tests running the same program on
    // other profiles at the same time must not build over each other
    // ("Text file busy") nor remove each other's directory.
    static RUNS: AtomicUsize = AtomicUsize::new(0);
    let run = RUNS.fetch_add(1, Ordering::Relaxed);
    let dir = toolchain::lib_dir(&format!("{name}-{run}"));
    let exe = build_c(&root().join("tests/c").join(format!("{name}.c")), &dir);
    let out = toolchain::target_command(&exe)
        .args(["127.0.0.1", &sim.port().to_string()])
        .env("LD_LIBRARY_PATH", &*dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "tests/c/{name}.c failed: {}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    key_values(&out.stdout)
}

fn key_values(stdout: &[u8]) -> HashMap<String, String> {
    String::from_utf8_lossy(stdout)
        .lines()
        .filter_map(|l| l.split_once('='))
        .map(|(k, v)| (k.to_string(), v.split(" (").next().unwrap_or(v).to_string()))
        .collect()
}

fn check_status_output(out: &std::process::Output, p: &Profile) {
    assert!(
        out.status.success(),
        "status failed: {}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let kv = key_values(&out.stdout);
    let st = p.paths[0].status;
    assert_eq!(kv["cnc_type"], p.cnc.cnc_type);
    assert_eq!(kv["series"], p.cnc.series);
    assert_eq!(kv["version"], p.cnc.version);
    assert_eq!(kv["axes"], format!("{:>2}", p.paths[0].axes.len()));
    assert_eq!(kv["max_axis"], p.cnc.max_axes.to_string());
    assert_eq!(kv["aut"], st.aut.to_string());
    assert_eq!(kv["run"], st.run.to_string());
    assert_eq!(kv["alarm"], st.alarm.to_string());
    let id: Vec<String> = p.cnc.cnc_id.iter().map(|w| format!("{w:08x}")).collect();
    assert_eq!(kv["cnc_id"], id.join("-"));
}

#[test]
fn status_example_reads_the_profile() {
    let dir = toolchain::lib_dir("status");
    let exe = build_example("status", &dir);
    let sim = Simulator::start(Profile::default(), "127.0.0.1:0").unwrap();
    let out = toolchain::target_command(&exe)
        .args(["127.0.0.1", &sim.port().to_string()])
        .env("LD_LIBRARY_PATH", &dir)
        .output()
        .unwrap();
    check_status_output(&out, &Profile::default());
}

/// A program linked against some other libfwlib32.so.1 (here a do-nothing
/// stub standing in for FANUC's) runs against ours with LD_PRELOAD.
#[test]
fn ld_preload_replaces_another_libfwlib32() {
    let dir = toolchain::lib_dir("preload");
    let stub_dir = dir.join("stub");
    std::fs::create_dir_all(&stub_dir).unwrap();
    let stub_c = stub_dir.join("stub.c");
    std::fs::write(
        &stub_c,
        "short cnc_allclibhndl3(const char *a, unsigned short b, long c, unsigned short *d)\
         { (void)a; (void)b; (void)c; (void)d; return -15; }\n\
         short cnc_sysinfo(unsigned short a, void *b) { (void)a; (void)b; return -15; }\n\
         short cnc_statinfo(unsigned short a, void *b) { (void)a; (void)b; return -15; }\n\
         short cnc_rdcncid(unsigned short a, unsigned long *b) { (void)a; (void)b; return -15; }\n\
         short cnc_freelibhndl(unsigned short a) { (void)a; return -15; }\n",
    )
    .unwrap();
    let stub_so = stub_dir.join("libfwlib32.so.1");
    cc(&[
        "-shared",
        "-fPIC",
        "-Wl,-soname,libfwlib32.so.1",
        stub_c.to_str().unwrap(),
        "-o",
        stub_so.to_str().unwrap(),
    ]);
    std::os::unix::fs::symlink("libfwlib32.so.1", stub_dir.join("libfwlib32.so")).unwrap();
    let exe = build_example("status", &stub_dir);
    let sim = Simulator::start(Profile::default(), "127.0.0.1:0").unwrap();
    let port = sim.port().to_string();

    // Against the stub alone the program fails ...
    let out = toolchain::target_command(&exe)
        .args(["127.0.0.1", &port])
        .env("LD_LIBRARY_PATH", &stub_dir)
        .output()
        .unwrap();
    assert!(!out.status.success(), "the stub must not reach the CNC");

    // ... with ours preloaded it talks to the simulator.
    let out = toolchain::target_command(&exe)
        .args(["127.0.0.1", &port])
        .env("LD_LIBRARY_PATH", &stub_dir)
        .env("LD_PRELOAD", dir.join("libfwlib32.so.1"))
        .output()
        .unwrap();
    check_status_output(&out, &Profile::default());
}

/// The numbers after the letter `axis` (e.g. 'X') in a program's text, in
/// least input increments.
fn program_coordinates(text: &str, axis: char, decimals: i16) -> Vec<i64> {
    let scale = 10f64.powi(decimals as i32);
    text.split(|c: char| c.is_whitespace() || c == ';')
        .filter_map(|w| w.strip_prefix(axis))
        .filter_map(|v| v.parse::<f64>().ok())
        .map(|v| (v * scale).round() as i64)
        .collect()
}

/// adapter.c makes the MTConnect adapter's calls in its order against the
/// default profile while its program runs: every value must be one the
/// profile allows at some point of the cycle, and the machine must move.
#[test]
fn adapter_example_polls_the_running_machine() {
    let dir = toolchain::lib_dir("adapter");
    let exe = build_example("adapter", &dir);
    let p = Profile::default();
    let sim = Simulator::start(p.clone(), "127.0.0.1:0").unwrap();
    let polls = 4;
    let out = toolchain::target_command(&exe)
        .args([
            "127.0.0.1",
            &sim.port().to_string(),
            &polls.to_string(),
            "600",
        ])
        .env("LD_LIBRARY_PATH", &dir)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "adapter failed:\n{text}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let kv = key_values(&out.stdout);
    let path = &p.paths[0];
    let prog = p
        .programs
        .iter()
        .find(|s| s.number == path.cycle.program)
        .expect("the default profile runs a stored program");

    // Once, at connect.
    assert_eq!(kv["series"], p.cnc.series);
    assert_eq!(kv["axes"], path.axes.len().to_string());
    for (i, a) in path.axes.iter().enumerate() {
        assert_eq!(kv[&format!("axis{}", i + 1)].trim(), a.name);
        assert_eq!(kv[&format!("figure{}", i + 1)], a.decimals.to_string());
    }
    assert_eq!(kv["spindles"], path.spindles.len().to_string());

    // Every poll.
    let lines: Vec<&str> = prog.text.lines().map(str::trim).collect();
    let seqs: Vec<String> = lines
        .iter()
        .filter_map(|l| l.split_whitespace().next())
        .filter_map(|w| w.strip_prefix('N'))
        .map(str::to_string)
        .collect();
    let speeds: Vec<i64> = std::iter::once(0)
        .chain(std::iter::once(i64::from(path.spindles[0].speed)))
        .chain(program_coordinates(&prog.text, 'S', 0))
        .collect();
    let diag308 = p
        .param
        .diagnostics
        .iter()
        .find(|d| d.number == 308)
        .unwrap();
    let msg = &path.opmsgs[0];
    let mut seen = std::collections::BTreeSet::new();
    for n in 0..polls {
        let at = |k: &str| kv[&format!("{n}.{k}")].clone();
        assert_eq!(at("prgnum"), prog.number.to_string());
        assert_eq!(at("prgmnum"), prog.number.to_string());
        assert!(at("program").ends_with(&format!("O{}", prog.number)));
        assert!(seqs.contains(&at("seqnum")), "seqnum {}", at("seqnum"));
        assert!(
            lines.contains(&at("block").as_str()),
            "block {:?}",
            at("block")
        );
        seen.insert(at("seqnum"));
        for a in &path.axes {
            let mut range =
                program_coordinates(&prog.text, a.name.chars().next().unwrap(), a.decimals);
            range.push(i64::from(a.absolute));
            let (lo, hi) = (*range.iter().min().unwrap(), *range.iter().max().unwrap());
            let v: f64 = at(&format!("abs{}", a.name)).parse().unwrap();
            let v = (v * 10f64.powi(a.decimals as i32)).round() as i64;
            assert!(
                (lo..=hi).contains(&v),
                "{} at {v} outside {lo}..{hi}",
                a.name
            );
        }
        let s: i64 = at("speed1").parse().unwrap();
        assert!(speeds.contains(&s), "spindle speed {s}");
        assert_eq!(at("alarms"), "0", "no alarm in the first 30 s");
        assert_eq!(at("opmsg"), format!("{} {}", msg.number, msg.text));
        assert!(at("parts").parse::<i32>().unwrap() >= 1234);
        assert_eq!(at("diag308"), diag308.values[0].to_string());
        assert_eq!(at("macro500"), "25.400");
        assert_eq!(at("feed_override"), "100");
        assert_eq!(at("spindle_override"), "100");
    }
    assert!(
        seen.len() > 1,
        "the program advances between polls: {seen:?}"
    );

    // The upload is the stored program, in punch format.
    let uploaded = text
        .split("upload-begin\n")
        .nth(1)
        .and_then(|t| t.split("\nupload-end").next())
        .expect("upload markers");
    let want: Vec<String> = prog
        .text
        .lines()
        .map(|l| l.trim().trim_end_matches(';').to_string())
        .filter(|l| !l.is_empty())
        .collect();
    let got: Vec<String> = uploaded
        .lines()
        .map(|l| l.trim().to_string())
        .filter(|l| !l.is_empty() && l != "%")
        .collect();
    let want: Vec<String> = want.into_iter().filter(|l| l != "%").collect();
    assert_eq!(got, want);
    assert_eq!(kv["upload_ret"], EW_RESET.to_string());
}

/// data.c writes a parameter (part counter and a real per-axis one), a
/// macro, a PMC word, a tool and a work offset, and dumps the alarm history;
/// a second run only reads, over a new connection: the simulator kept what
/// was written. Parameter writes need MDI mode and parameter write enable.
#[test]
fn data_example_writes_and_reads_back() {
    let dir = toolchain::lib_dir("data");
    let exe = build_example("data", &dir);
    let text = fwlib32::sim::profile::DEFAULT_PROFILE
        .replace("param_write_enable = false", "param_write_enable = true")
        .replacen("aut = 1 ", "aut = 0 ", 1);
    let p = Profile::parse(&text).unwrap();
    assert!(p.param.param_write_enable && p.paths[0].status.aut == 0);
    let sim = Simulator::start(p.clone(), "127.0.0.1:0").unwrap();
    let port = sim.port().to_string();
    let run = |mode: &str| {
        let out = toolchain::target_command(&exe)
            .args(["127.0.0.1", &port, mode])
            .env("LD_LIBRARY_PATH", &dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "data {mode} failed:\n{}\n{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stdout)
            .lines()
            .filter_map(|l| l.split_once('='))
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect::<HashMap<String, String>>()
    };
    let before = run("read");
    assert_eq!(before["macro500"], "25400/3");
    let written = run("write");
    assert_eq!(written["written"], "ok");
    let after = run("read");
    for kv in [&written, &after] {
        // The part counter counts on from what was written as parts finish.
        assert!(kv["param6711"].parse::<i32>().unwrap() >= 4321);
        assert_eq!(kv["param1320.x"], "812500/3");
        assert_eq!(kv["macro500"], "12345/3");
        assert_eq!(kv["pmcD100"], 0x1234.to_string());
        assert_eq!(kv["tofs1.0"], "-25");
        assert_eq!(kv["zofs54.x"], "-300000");
    }
    // The history as the profile gives it, newest first, FANUC's 2-digit year.
    let h = &p.alarm_history.entries;
    assert_eq!(after["history"], h.len().to_string());
    for (i, e) in h.iter().enumerate() {
        let (date, time) = e.time.split_once(' ').unwrap();
        let want = format!(
            "{}/{} {} {}",
            &date[2..4],
            &date[5..].replace('-', "/"),
            time,
            e.number
        );
        assert_eq!(
            after[&format!("history{}", i + 1)],
            format!("{want} {}", e.message)
        );
    }

    // Without parameter write enable the same program is refused with EW_PASSWD.
    let locked = Simulator::start(Profile::default(), "127.0.0.1:0").unwrap();
    let out = toolchain::target_command(&exe)
        .args(["127.0.0.1", &locked.port().to_string(), "write"])
        .env("LD_LIBRARY_PATH", &dir)
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("cnc_wrparam(h, 4 + 4, &prm) failed: 17")
    );
}

/// transfer.c: list, download a file, select it, start it, watch it run
/// to its end, upload it back and compare, against the simulator.
#[test]
fn transfer_example_downloads_runs_and_uploads_a_program() {
    let dir = toolchain::lib_dir("transfer");
    let exe = build_example("transfer", &dir);
    let text = fwlib32::sim::profile::DEFAULT_PROFILE
        .replace("block_seconds = 0.5", "block_seconds = 0.02");
    let sim = Simulator::start(Profile::parse(&text).unwrap(), "127.0.0.1:0").unwrap();
    let file = dir.join("O4242.nc");
    let program = "%\nO4242(TRANSFER EXAMPLE)\nN10 G90 G00 X10. Y5.\nN20 G01 X20. F500 S1200 M03\nN30 G91 Y-5.\nN40 M05\nN50 M30\n%";
    std::fs::write(&file, program).unwrap();
    let out = toolchain::target_command(&exe)
        .args(["127.0.0.1", &sim.port().to_string(), file.to_str().unwrap()])
        .env("LD_LIBRARY_PATH", &dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "transfer failed:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let kv = key_values(&out.stdout);
    assert!(
        stdout.contains("program=O1234 "),
        "the profile's programs are listed:\n{stdout}"
    );
    assert_eq!(kv["downloaded"], format!("O4242 bytes={}", program.len()));
    assert_eq!(kv["main"], "O4242");
    assert_eq!(kv["ran"], "O4242 started=yes ended=yes blocks=5");
    // G90 X20. (3 decimals) last: the machine moved as the program says,
    // and its M30 counted a part.
    assert_eq!(kv["end_x"], "20000 parts=+1");
    assert_eq!(kv["upload"], format!("identical bytes={}", program.len()));
}

/// adapter.c --batch: each poll's 20 reads in one batch give exactly the
/// values of the same reads made one by one (the simulator's clock stands
/// still), in 2 request frames a poll instead of 20.
#[test]
fn adapter_example_batched_reads_the_same_values_in_two_frames_a_poll() {
    let dir = toolchain::lib_dir("adapter-batch");
    let exe = build_example("adapter", &dir);
    let sim = Simulator::start(Profile::default(), "127.0.0.1:0").unwrap();
    sim.set_elapsed(std::time::Duration::from_millis(3300));
    let run = |batch: bool, polls: u32| {
        let mut args = vec![];
        if batch {
            args.push("--batch".to_string());
        }
        args.extend([
            "127.0.0.1".into(),
            sim.port().to_string(),
            polls.to_string(),
            "0".into(),
        ]);
        let before = sim.data_frames();
        let out = toolchain::target_command(&exe)
            .args(&args)
            .env("LD_LIBRARY_PATH", &dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "adapter {args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8_lossy(&out.stdout).to_string();
        let polled: Vec<&str> = text
            .lines()
            .filter(|l| l.starts_with(|c: char| c.is_ascii_digit()))
            .collect();
        (polled.join("\n"), sim.data_frames() - before)
    };
    let (_, outside) = run(false, 0);
    let (alone, frames_alone) = run(false, 3);
    let (batched, frames_batched) = run(true, 3);
    assert_eq!(batched, alone);
    assert!(alone.contains("2.parts="), "{alone}");
    // Round trips a poll, beyond the start-up and upload exchanges.
    assert_eq!(
        (frames_alone - outside) / 3,
        19,
        "one a call, one answered locally"
    );
    // 37 subpackets a poll (33 different), at most 16 a frame on a 30i.
    assert_eq!((frames_batched - outside) / 3, 3);
}

#[test]
fn maintenance_example_reports_the_histories() {
    let dir = toolchain::lib_dir("maintenance");
    let exe = build_example("maintenance", &dir);
    let p = Profile::default();
    let sim = Simulator::start(p.clone(), "127.0.0.1:0").unwrap();
    let out = toolchain::target_command(&exe)
        .args(["127.0.0.1", &sim.port().to_string()])
        .env("LD_LIBRARY_PATH", &dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "maintenance failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let kv = key_values(&out.stdout);
    // Tool life left: each group's life less what has been used (the
    // running program's T words use it up from the profile's count).
    let groups = &p.paths[0].tool_groups;
    assert_eq!(kv["tool_groups"], groups.len().to_string());
    for (i, g) in groups.iter().enumerate() {
        let line = &kv[format!("tool_group{}", i + 1).as_str()];
        let w: Vec<i64> = line
            .split_whitespace()
            .filter_map(|t| t.parse().ok())
            .collect();
        assert_eq!(w[0], i64::from(g.life), "{line}");
        assert!(w[1] >= i64::from(g.count), "{line}");
        assert_eq!(w[2], w[0] - w[1], "{line}");
    }
    let sp = &p.paths[0].spindles[0];
    assert!(
        kv["spindle1"].starts_with(&format!("load {}% ", sp.load)),
        "{}",
        kv["spindle1"]
    );
    assert_eq!(kv["current"].split_whitespace().count(), 3);
    // The maintenance items, their life counting down from the profile's.
    let items = &p.maintenance.items;
    assert_eq!(kv["maintenance"], items.len().to_string());
    for (i, it) in items.iter().enumerate() {
        let line = &kv[format!("item{}", i + 1).as_str()];
        let rest = line
            .strip_prefix(&format!("{} left ", it.name))
            .unwrap_or_else(|| panic!("{line}"));
        let left: i32 = rest.split_whitespace().next().unwrap().parse().unwrap();
        assert!(left <= it.remain, "{line}");
        assert!(rest.contains(&format!(" of {} min", it.total)), "{line}");
    }
    // The PMC's alarm messages: those whose A bit the profile sets (A0.0
    // and A0.2 in the default profile).
    let msgs = &p.pmc.info[0].messages;
    assert_eq!(kv["pmc_alarms"], "2");
    assert_eq!(kv["pmc_alarm1"], msgs[0]);
    assert_eq!(kv["pmc_alarm2"], msgs[2]);
    assert_eq!(
        kv["operations"],
        p.operation_history.entries.len().to_string()
    );
    assert_eq!(kv["op1"], "alarm 1001");
    assert_eq!(kv["op2"], "signal 0.43 01->05");
    assert_eq!(kv["op4"], "time 13:45:30");
    assert_eq!(kv["op5"], "date 24-05-17");
    assert_eq!(
        kv["messages"], "3",
        "the message on display, the profile's two"
    );
    assert_eq!(kv["msg2"], "2002 2024-05-17 TOOL 12 LIFE EXPIRED");
    let a = &p.alarm_history.entries[0];
    assert_eq!(kv["alarms"], "3");
    assert_eq!(
        kv["alarm1"],
        format!("{} {} {}", a.number, a.time, a.message)
    );
}

/// The C tests of tests/c, one module per program.
mod collectors;
mod collectors_3dhandle;
mod collectors_axes;
mod collectors_history_timers;
mod collectors_magazine;
mod collectors_o8;
mod collectors_panel_system;
mod collectors_pcode;
mod collectors_pmcctl;
mod collectors_pmcdata;
mod collectors_programs_macros;
mod collectors_settings;
mod collectors_system;
mod collectors_system_ids;
mod collectors_tool;
mod collectors_tool_axis;
mod collectors_tool_ranges;
mod sampling;
