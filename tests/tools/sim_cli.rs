//! The `focas-sim` program itself: a fleet from the command line (an
//! address line per machine, one runtime's threads for all), faults from
//! `--fault` and the profile, `--trace` for a known call sequence, and the
//! errors of a bad command line.

use crate::toolchain;

use fwlib32::ew::*;
use fwlib32::types::{IODBPSD, ODBM, ODBST};
use fwlib32::*;
use std::collections::BTreeSet;
use std::ffi::CString;
use std::io::{BufRead, BufReader, Read};
use std::os::raw::{c_short, c_ulong, c_ushort};
use std::process::{Child, Stdio};
use toolchain::target_command;

/// A running focas-sim, killed when dropped.
struct Sim {
    child: Child,
    addrs: Vec<(String, u16)>,
}

impl Drop for Sim {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn command(args: &[&str]) -> std::process::Command {
    let mut c = target_command(env!("CARGO_BIN_EXE_focas-sim"));
    c.args(args);
    c
}

/// Starts focas-sim with `args` and reads its `machines` address lines.
fn start(args: &[&str], machines: usize, stderr: Stdio) -> Sim {
    let mut child = command(args)
        .stdout(Stdio::piped())
        .stderr(stderr)
        .spawn()
        .expect("start focas-sim");
    let mut out = BufReader::new(child.stdout.take().unwrap());
    let mut sim = Sim {
        child,
        addrs: Vec::new(),
    };
    for _ in 0..machines {
        let mut line = String::new();
        out.read_line(&mut line).unwrap();
        let addr = line
            .trim()
            .strip_prefix("listening on ")
            .unwrap_or_else(|| panic!("focas-sim printed {line:?}"));
        let (host, port) = addr.rsplit_once(':').unwrap();
        sim.addrs.push((host.to_string(), port.parse().unwrap()));
    }
    sim
}

fn alloc(host: &str, port: u16) -> Result<c_ushort, c_short> {
    let ip = CString::new(host).unwrap();
    let mut h = 0;
    match unsafe { cnc_allclibhndl3(ip.as_ptr(), port, 5, &mut h) } {
        EW_OK => Ok(h),
        r => Err(r),
    }
}

fn statinfo(h: c_ushort) -> c_short {
    let mut st = ODBST::default();
    unsafe { cnc_statinfo(h, &mut st) }
}

fn last_id_word(h: c_ushort) -> u32 {
    let mut id = [0u32; 4];
    assert_eq!(
        unsafe { cnc_rdcncid(h, id.as_mut_ptr().cast::<c_ulong>()) },
        EW_OK
    );
    id[3]
}

fn status_value(pid: u32, key: &str) -> usize {
    std::fs::read_to_string(format!("/proc/{pid}/status"))
        .unwrap()
        .lines()
        .find_map(|l| l.strip_prefix(key))
        .and_then(|v| v.split_whitespace().next()?.parse().ok())
        .unwrap()
}

#[test]
fn a_fleet_prints_an_address_per_machine_and_each_is_its_own_cnc() {
    let sim = start(
        &["--fleet", "5", "--listen", "127.0.0.1:0"],
        5,
        Stdio::null(),
    );
    let ports: BTreeSet<u16> = sim.addrs.iter().map(|a| a.1).collect();
    assert_eq!(ports.len(), 5);
    let ids: Vec<u32> = sim
        .addrs
        .iter()
        .map(|(host, port)| {
            let h = alloc(host, *port).unwrap();
            let id = last_id_word(h);
            assert_eq!(cnc_freelibhndl(h), EW_OK);
            id
        })
        .collect();
    let first = ids[0];
    assert_eq!(ids, (0..5).map(|i| first + i).collect::<Vec<_>>());
}

#[test]
fn a_large_fleet_runs_on_the_threads_of_one_runtime() {
    let one = start(&["--listen", "127.0.0.1:0"], 1, Stdio::null());
    let many = start(
        &["--fleet", "300", "--listen", "127.0.0.1:0"],
        300,
        Stdio::null(),
    );
    let (t1, t300) = (
        status_value(one.child.id(), "Threads:"),
        status_value(many.child.id(), "Threads:"),
    );
    assert!(
        t300 <= t1 + 1,
        "{t300} threads for 300 machines, {t1} for one"
    );
    let (host, port) = &many.addrs[299];
    let h = alloc(host, *port).unwrap();
    assert_eq!(statinfo(h), EW_OK);
    assert_eq!(cnc_freelibhndl(h), EW_OK);
}

#[test]
fn consecutive_ports_from_a_given_one() {
    // Three consecutive ports below the kernel's ephemeral range, where the
    // other tests' `127.0.0.1:0` listeners and outgoing connections (hundreds
    // at once in a full run) never land; seen free just before the start,
    // and retried if something else took one meanwhile.
    let low = std::fs::read_to_string("/proc/sys/net/ipv4/ip_local_port_range")
        .ok()
        .and_then(|r| r.split_whitespace().next()?.parse::<u16>().ok())
        .unwrap_or(32768);
    let mut pick = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos() ^ std::process::id());
    let mut last = String::new();
    for _ in 0..20 {
        pick = pick.wrapping_mul(1_103_515_245).wrapping_add(12_345);
        let base = 10_000 + (pick >> 8) as u16 % low.saturating_sub(10_003).max(1);
        let free = (0..3).all(|i| std::net::TcpListener::bind(("127.0.0.1", base + i)).is_ok());
        if !free {
            continue;
        }
        let listen = format!("127.0.0.1:{base}");
        let mut child = command(&["--fleet", "3", "--listen", &listen])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut out = String::new();
        let mut stdout = child.stdout.take().unwrap();
        let mut line = [0u8; 1];
        // Three lines, or the end when a port was taken.
        while out.matches('\n').count() < 3 && stdout.read(&mut line).unwrap_or(0) == 1 {
            out.push(line[0] as char);
        }
        let _ = child.kill();
        let status = child.wait();
        let mut err = String::new();
        if let Some(mut e) = child.stderr.take() {
            let _ = e.read_to_string(&mut err);
        }
        if out.matches('\n').count() == 3 {
            let want: String = (0..3)
                .map(|i| format!("listening on 127.0.0.1:{}\n", base + i))
                .collect();
            assert_eq!(out, want);
            return;
        }
        last = format!("from {base}: {out:?}, {status:?}, stderr {err:?}");
    }
    panic!("no three free consecutive ports found (last try {last})");
}

#[test]
fn faults_from_the_command_line() {
    let sim = start(
        &[
            "--fleet",
            "3",
            "--listen",
            "127.0.0.1:0",
            "--fault",
            "error:functions=cnc_statinfo,code=EW_BUSY,machines=2",
            "--fault",
            "off:machines=3",
            "--delay-ms",
            "2",
            "--max-sessions",
            "1",
        ],
        3,
        Stdio::null(),
    );
    let (host, port) = &sim.addrs[0];
    let h = alloc(host, *port).unwrap();
    assert_eq!(statinfo(h), EW_OK);
    assert_eq!(
        alloc("localhost", *port).err(),
        Some(EW_SOCKET),
        "one session"
    );
    let h2 = alloc(&sim.addrs[1].0, sim.addrs[1].1).unwrap();
    assert_eq!(statinfo(h2), EW_BUSY);
    assert_eq!(
        alloc(&sim.addrs[2].0, sim.addrs[2].1).err(),
        Some(EW_SOCKET),
        "machine 3 is off"
    );
    assert_eq!(cnc_freelibhndl(h), EW_OK);
    assert_eq!(cnc_freelibhndl(h2), EW_OK);
}

#[test]
fn a_profile_lists_its_machines_and_faults() {
    let dir = std::env::temp_dir().join(format!("focas-sim-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("fleet.toml");
    std::fs::write(
        &file,
        "[fleet]\nmachines = 3\n[[path]]\n\
         [[fault]]\nkind = \"error\"\ncommands = [0x19]\ncode = \"EW_NOOPT\"\nmachines = [1]\n",
    )
    .unwrap();
    let sim = start(
        &[
            "--profile",
            file.to_str().unwrap(),
            "--listen",
            "127.0.0.1:0",
        ],
        3,
        Stdio::null(),
    );
    let codes: Vec<c_short> = sim
        .addrs
        .iter()
        .map(|(host, port)| {
            let h = alloc(host, *port).unwrap();
            let r = statinfo(h);
            assert_eq!(cnc_freelibhndl(h), EW_OK);
            r
        })
        .collect();
    assert_eq!(codes, vec![EW_NOOPT, EW_OK, EW_OK]);
    let _ = std::fs::remove_dir_all(dir);
}

/// The trace lines without their time stamp.
fn untimed(text: &str) -> Vec<String> {
    text.lines()
        .map(|l| {
            l.trim_start()
                .split_once(' ')
                .map_or("", |x| x.1)
                .to_string()
        })
        .collect()
}

/// A known call sequence, and the lines the trace must show for it.
fn known_sequence(host: &str, port: u16) -> Vec<&'static str> {
    let h = alloc(host, port).unwrap();
    assert_eq!(statinfo(h), EW_OK);
    let mut p = IODBPSD::default();
    assert_eq!(unsafe { cnc_rdparam(h, 6711, 0, 8, &mut p) }, EW_OK);
    let mut m = ODBM::default();
    assert_eq!(unsafe { cnc_rdmacro(h, 50, 10, &mut m) }, EW_NUMBER);
    assert_eq!(cnc_freelibhndl(h), EW_OK);
    vec![
        "m1 c1 <- open conn 1",
        "m1 c1 -> open ok, 72 bytes",
        "m1 c2 <- open conn 2",
        "m1 c2 -> open ok, 72 bytes",
        "m1 c2 <- data cnc_sysinfo 0x0018 p1 (0, 0, 0, 0, 0)",
        "m1 c2 -> data cnc_sysinfo 0x0018 p1 rc 0 EW_OK, 18 bytes",
        "m1 c2 <- data cnc_statinfo 0x0019 p1 (0, 0, 0, 0, 0) \
         | cnc_statinfo 0x00e1 p1 (0, 0, 0, 0, 0) | cnc_statinfo 0x0098 p1 (0, 0, 0, 0, 0)",
        "m1 c2 -> data cnc_statinfo 0x0019 p1 rc 0 EW_OK, 14 bytes \
         | cnc_statinfo 0x00e1 p1 rc 0 EW_OK, 2 bytes | cnc_statinfo 0x0098 p1 rc 0 EW_OK, 2 bytes",
        "m1 c2 <- data cnc_rdparam 0x008d p1 (6711, 6711, 0, 0, 0)",
        "m1 c2 -> data cnc_rdparam 0x008d p1 rc 0 EW_OK, 264 bytes",
        "m1 c2 <- data cnc_rdmacro 0x0015 p1 (50, 50, 0, 0, 0)",
        "m1 c2 -> data cnc_rdmacro 0x0015 p1 rc 3 EW_NUMBER, 0 bytes",
        "m1 c1 <- close",
        "m1 c1 -> close ok",
        "m1 c2 <- close",
        "m1 c2 -> close ok",
    ]
}

#[test]
fn trace_on_stderr_shows_every_frame_decoded() {
    let mut sim = start(&["--listen", "127.0.0.1:0", "--trace"], 1, Stdio::piped());
    let (host, port) = sim.addrs[0].clone();
    let want = known_sequence(&host, port);
    // Every line is written before its frame is answered: all are in.
    let _ = sim.child.kill();
    let mut text = String::new();
    sim.child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut text)
        .unwrap();
    assert_eq!(untimed(&text), want, "{text}");
}

#[test]
fn trace_into_a_file() {
    let file = std::env::temp_dir().join(format!("focas-sim-trace-{}.txt", std::process::id()));
    let sim = start(
        &[
            "--listen",
            "127.0.0.1:0",
            "--trace-file",
            file.to_str().unwrap(),
        ],
        1,
        Stdio::null(),
    );
    let (host, port) = sim.addrs[0].clone();
    let want = known_sequence(&host, port);
    drop(sim);
    let text = std::fs::read_to_string(&file).unwrap();
    let _ = std::fs::remove_file(&file);
    assert_eq!(untimed(&text), want, "{text}");
}

#[test]
fn a_bad_command_line_says_why() {
    for (args, says) in [
        (&["--fault", "melt"][..], "off, refuse"),
        (&["--fleet", "0"][..], "1 to"),
        (
            &["--fleet", "2", "--fault", "off:machines=3"][..],
            "machine 3",
        ),
        (&["--fault", "delay"][..], "delay_ms"),
        (&["--delay-ms", "soon"][..], "milliseconds"),
        // Bad values are echoed.
        (&["--delay-ms", "soon"][..], "'soon'"),
        (&["--fleet", "0"][..], "'0'"),
        (&["--listen", "127.0.0.1"][..], "'127.0.0.1'"),
        (&["--listen=localhost:80x"][..], "\"80x\" is not a TCP port"),
        (&["--fault", "melt"][..], "\"melt\""),
        (&["--trace", "--trace-file", "x"][..], "cannot be used with"),
        (&["--no-such-option"][..], "'--no-such-option'"),
    ] {
        let out = command(args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{args:?}: {err}");
    }
}

#[test]
fn version_help_and_listen_with_an_equals_sign() {
    let out = command(&["--version"]).output().unwrap();
    assert!(out.status.success());
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        format!("focas-sim {}\n", env!("CARGO_PKG_VERSION"))
    );
    let out = command(&["--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    for opt in [
        "--listen <ADDR>",
        "--fault <SPEC>",
        "--delay-ms <MS>",
        "--print-profile",
    ] {
        assert!(help.contains(opt), "{opt}: {help}");
    }
    // --listen=ADDR: one machine, its address line.
    let sim = start(&["--listen=127.0.0.1:0"], 1, Stdio::null());
    let (host, port) = &sim.addrs[0];
    assert_eq!(host, "127.0.0.1");
    let h = alloc(host, *port).unwrap();
    assert_eq!(statinfo(h), EW_OK);
    assert_eq!(cnc_freelibhndl(h), EW_OK);
    // An address it cannot serve on: named, exit 1.
    let out = command(&["--listen", "no.such.host.invalid:0"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("no.such.host.invalid:0"), "{err}");
}
