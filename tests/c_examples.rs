//! The C examples, compiled with the system C compiler against
//! include/fwlib32.h and the built libfwlib32.so, run against the simulator.

use fwlib32::sim::{Profile, Simulator};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;

mod toolchain;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A scratch dir holding libfwlib32.so.1 -> the built library (the SONAME
/// a program linked with -lfwlib32 asks the loader for).
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("fwlib32-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    let so = toolchain::cdylib();
    std::fs::copy(&so, d.join("libfwlib32.so.1")).unwrap();
    std::os::unix::fs::symlink("libfwlib32.so.1", d.join("libfwlib32.so")).unwrap();
    d
}

fn cc(args: &[&str]) {
    let out = Command::new("cc")
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
    let src = root().join("c-examples").join(format!("{name}.c"));
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
    let dir = scratch("status");
    let exe = build_example("status", &dir);
    let sim = Simulator::start(Profile::default(), "127.0.0.1:0").unwrap();
    let out = Command::new(&exe)
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
    let dir = scratch("preload");
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
    let out = Command::new(&exe)
        .args(["127.0.0.1", &port])
        .env("LD_LIBRARY_PATH", &stub_dir)
        .output()
        .unwrap();
    assert!(!out.status.success(), "the stub must not reach the CNC");

    // ... with ours preloaded it talks to the simulator.
    let out = Command::new(&exe)
        .args(["127.0.0.1", &port])
        .env("LD_LIBRARY_PATH", &stub_dir)
        .env("LD_PRELOAD", dir.join("libfwlib32.so.1"))
        .output()
        .unwrap();
    check_status_output(&out, &Profile::default());
}
