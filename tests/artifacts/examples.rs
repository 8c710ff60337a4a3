//! The examples in the other languages FOCAS programs are written in, run
//! against the simulator on the built library: examples/python (ctypes) and
//! examples/go (cgo, built with `#cgo pkg-config: fwlib32` from a generated
//! fwlib32.pc). Their `key=value` output must be the profile's values: system
//! information, status words, axis names and positions, the active alarm and
//! two parameters; a refused connection must be reported with its EW_* code.
//!
//! The Python test needs `python3`: without it the test is skipped with a
//! message, except under CI (`CI` set, not "false" or "0"), where it fails.
//! The Go test runs only where `go` is on PATH. Both are skipped in a cross
//! build: the host's interpreter and toolchain cannot load or link the
//! target's library.

use crate::toolchain;

use fwlib32::sim::profile::cycle::Alarm;
use fwlib32::sim::{Profile, Simulator};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use toolchain::{cc, lib_dir, manifest_dir};

/// The built-in profile, idle (no program in cycle, so positions stay as
/// configured) and with one alarm active.
fn profile() -> Profile {
    let mut p = Profile::default();
    p.paths[0].cycle.program = 0;
    p.paths[0].alarms.push(Alarm {
        number: 500,
        kind: 4,
        axis: 1,
        message: "OVER TRAVEL ( SOFT 1 ) +X".to_owned(),
    });
    p
}

/// `value · 10^-decimals` with `decimals` places, as the examples print it.
fn fixed(value: i32, decimals: i16) -> String {
    if decimals <= 0 {
        return (i64::from(value) * 10i64.pow(u32::from(decimals.unsigned_abs()))).to_string();
    }
    let scale = 10u64.pow(decimals as u32);
    let v = i64::from(value).unsigned_abs();
    let sign = if value < 0 { "-" } else { "" };
    format!(
        "{sign}{}.{:0width$}",
        v / scale,
        v % scale,
        width = decimals as usize
    )
}

fn text(out: &Output) -> String {
    format!(
        "--- stdout ---\n{}--- stderr ---\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// Checks an example's output against the profile it ran on.
fn check_output(out: &Output, p: &Profile) {
    assert!(out.status.success(), "the example failed:\n{}", text(out));
    let kv: HashMap<&str, &str> = std::str::from_utf8(&out.stdout)
        .unwrap()
        .lines()
        .filter_map(|l| l.split_once('='))
        .collect();
    let get = |k: &str| -> &str {
        kv.get(k)
            .unwrap_or_else(|| panic!("no {k}= in the output:\n{}", text(out)))
    };
    // "1 (MEM)": the number.
    let number = |k: &str| get(k).split(" (").next().unwrap().to_owned();

    assert_eq!(get("cnc_type"), p.cnc.cnc_type);
    assert_eq!(get("series"), p.cnc.series);
    assert_eq!(get("version"), p.cnc.version);

    let path = &p.paths[0];
    let st = path.status;
    assert_eq!(number("aut"), st.aut.to_string());
    assert_eq!(get("aut"), "1 (MEM)");
    assert_eq!(number("run"), st.run.to_string());
    assert_eq!(get("motion"), st.motion.to_string());
    assert_eq!(get("mstb"), st.mstb.to_string());
    assert_eq!(get("emergency"), st.emergency.to_string());
    assert_eq!(get("alarm"), "1", "an alarm is active");
    assert_eq!(get("edit"), st.edit.to_string());
    assert_eq!(get("program"), "O0", "idle");

    assert_eq!(get("axes"), path.axes.len().to_string());
    for a in &path.axes {
        for (kind, v) in [
            ("absolute", a.absolute),
            ("machine", a.machine),
            ("relative", a.relative),
            ("distance", a.distance),
        ] {
            assert_eq!(
                get(&format!("{}.{kind}", a.name)),
                fixed(v, a.decimals),
                "{} {kind}",
                a.name
            );
        }
    }

    assert_eq!(get("alarms"), path.alarms.len().to_string());
    for (i, a) in path.alarms.iter().enumerate() {
        assert_eq!(
            get(&format!("alarm{}", i + 1)),
            format!(
                "{} (type {}, axis {}) {}",
                a.number, a.kind, a.axis, a.message
            )
        );
    }

    let param = |n: i32| {
        p.param
            .parameters
            .iter()
            .find(|e| e.number == n)
            .unwrap_or_else(|| panic!("parameter {n} in the profile"))
    };
    assert_eq!(get("param6711"), param(6711).values[0].to_string());
    let stroke = param(1320);
    for (a, v) in path.axes.iter().zip(&stroke.values) {
        assert_eq!(
            get(&format!("param1320.{}", a.name)),
            fixed(*v, stroke.decimals)
        );
    }
}

/// A port on 127.0.0.1 nothing listens on (bound, read back and closed).
fn closed_port() -> u16 {
    let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    l.local_addr().unwrap().port()
}

/// A failed connect: exit status 1, the function and its EW_* code on stderr.
fn check_refused(out: &Output) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{}", text(out));
    assert!(
        stderr.contains("cnc_allclibhndl3 failed: EW_SOCKET (-16)"),
        "{}",
        text(out)
    );
}

fn in_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| !v.is_empty() && v != "false" && v != "0")
}

/// Why a host program cannot use this build's library, if it cannot.
fn cross_build() -> Option<String> {
    let (target, host) = (env!("FWLIB32_TARGET"), env!("FWLIB32_HOST"));
    (target != host).then(|| format!("the library is built for {target}, not for the host {host}"))
}

/// `tool` found on PATH.
fn on_path(tool: &str) -> Option<PathBuf> {
    std::env::split_paths(&std::env::var_os("PATH")?)
        .map(|d| d.join(tool))
        .find(|p| p.is_file())
}

fn python() -> Option<PathBuf> {
    if let Some(why) = cross_build() {
        eprintln!("skipped: {why}");
        return None;
    }
    match on_path("python3") {
        Some(p) => Some(p),
        None if in_ci() => panic!("python3 is not on PATH: CI must install it (.ci/run)"),
        None => {
            eprintln!("skipped: python3 is not on PATH");
            None
        }
    }
}

fn python_example() -> PathBuf {
    manifest_dir().join("examples/python/focas_status.py")
}

#[test]
fn python_example_reads_the_profile() {
    let Some(python) = python() else { return };
    let dir = lib_dir("python");
    let p = profile();
    let sim = Simulator::start(p.clone(), "127.0.0.1:0").unwrap();
    let lib = dir.join("libfwlib32.so.1");
    let out = Command::new(&python)
        .arg(python_example())
        .args(["127.0.0.1", &sim.port().to_string()])
        .env("FWLIB32", &lib)
        .current_dir(&dir)
        .output()
        .unwrap();
    check_output(&out, &p);
    assert!(
        String::from_utf8_lossy(&out.stdout).contains(&format!("library={}\n", lib.display())),
        "the library named by $FWLIB32:\n{}",
        text(&out)
    );
}

#[test]
fn python_example_reports_a_refused_connection() {
    let Some(python) = python() else { return };
    let dir = lib_dir("python-refused");
    let out = Command::new(&python)
        .arg(python_example())
        .args(["127.0.0.1", &closed_port().to_string(), "--lib"])
        .arg(dir.join("libfwlib32.so.1"))
        .current_dir(&dir)
        .output()
        .unwrap();
    check_refused(&out);
    assert!(
        !String::from_utf8_lossy(&out.stderr).contains("Traceback"),
        "{}",
        text(&out)
    );
}

/// A fwlib32.pc for the build tree: our header, the library in `lib`.
fn write_pc(lib: &Path) -> PathBuf {
    let dir = lib.join("pkgconfig");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("fwlib32.pc"),
        format!(
            "libdir={}\nincludedir={}\n\nName: fwlib32\nDescription: fwlib32-rs (build tree)\n\
             Version: {}\nLibs: -L${{libdir}} -lfwlib32\nCflags: -I${{includedir}}\n",
            lib.display(),
            manifest_dir().join("include").display(),
            env!("CARGO_PKG_VERSION")
        ),
    )
    .unwrap();
    dir
}

#[test]
fn go_example_builds_and_reads_the_profile() {
    if let Some(why) = cross_build() {
        eprintln!("skipped: {why}");
        return;
    }
    let Some(go) = on_path("go") else {
        eprintln!("skipped: no Go toolchain (go) on PATH");
        return;
    };
    let dir = lib_dir("go");
    let pc = write_pc(&dir);
    let exe = dir.join("focas-status");
    // Go's caches in the scratch directory, offline, with the toolchain on
    // PATH. Not shared between runs: Go keeps cgo's link flags (this run's
    // -L, a scratch directory removed at its end) with the cached package,
    // and a later run would link against a folder that is gone.
    let cache = dir.join("go");
    toolchain::run(
        Command::new(go)
            .args(["build", "-buildvcs=false", "-o"])
            .arg(&exe)
            .arg(".")
            .current_dir(manifest_dir().join("examples/go"))
            .env("PKG_CONFIG_PATH", &pc)
            .env("CGO_ENABLED", "1")
            .env("CC", cc())
            .env("GOCACHE", cache.join("cache"))
            .env("GOPATH", cache.join("path"))
            .env("GOTOOLCHAIN", "local")
            .env("GOPROXY", "off")
            .env("GOFLAGS", ""),
    );

    let p = profile();
    let sim = Simulator::start(p.clone(), "127.0.0.1:0").unwrap();
    let out = Command::new(&exe)
        .args(["127.0.0.1", &sim.port().to_string()])
        .env("LD_LIBRARY_PATH", &dir)
        .current_dir(&dir)
        .output()
        .unwrap();
    check_output(&out, &p);

    let out = Command::new(&exe)
        .args(["127.0.0.1", &closed_port().to_string()])
        .env("LD_LIBRARY_PATH", &dir)
        .current_dir(&dir)
        .output()
        .unwrap();
    check_refused(&out);
}
