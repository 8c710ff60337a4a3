//! Every fault the simulator injects, observed through the C API: each
//! call comes back with an EW_* code within the handle's timeout, never
//! hangs, and the handle works again when the fault is over (with
//! fwlib_set_reconnect where the connection was lost). The clock is frozen
//! and moved by the test (Fleet::set_elapsed), so every fault starts and
//! ends at a known point. `TRACE=1 cargo test --test robust faults::` shows the
//! frames (focas-sim's --trace).

use fwlib32::ew::*;
use fwlib32::sim::profile::fault::Fault;
use fwlib32::sim::{Fleet, FleetOptions, Profile};
use fwlib32::types::{IODBPSD, ODBST};
use fwlib32::*;
use std::ffi::CString;
use std::os::raw::{c_long, c_short, c_ushort};
use std::time::{Duration, Instant};

/// Handles' timeout, seconds.
const TIMEOUT: u16 = 1;
/// Longest any call may take: the timeout and a generous margin for a
/// loaded machine (a hang would take for ever).
const BOUND: Duration = Duration::from_secs(TIMEOUT as u64 + 10);

/// One machine with `faults`, its clock at 1 s.
fn machine(faults: &[&str]) -> Fleet {
    let f = Fleet::start(
        &[Profile::default()],
        "127.0.0.1:0",
        FleetOptions {
            faults: faults
                .iter()
                .map(|s| Fault::parse_spec(s).unwrap())
                .collect(),
            worker_threads: Some(1),
            trace: std::env::var_os("TRACE").map(|_| fwlib32::sim::fleet::TraceTo::Stderr),
            ..FleetOptions::default()
        },
    )
    .expect("simulator");
    at(&f, 1.0);
    f
}

fn at(f: &Fleet, secs: f64) {
    f.set_elapsed(Duration::from_secs_f64(secs));
}

/// Runs `f`, checks it came back within [`BOUND`], returns its result.
fn bounded<T>(what: &str, f: impl FnOnce() -> T) -> T {
    let t = Instant::now();
    let r = f();
    assert!(t.elapsed() < BOUND, "{what} took {:?}", t.elapsed());
    r
}

/// `cnc_allclibhndl3` to `host`:`port` (the library keeps one connection
/// pair per host string and port: another spelling of the host is another
/// pair, another FOCAS session).
fn alloc(host: &str, port: u16) -> Result<c_ushort, c_short> {
    let ip = CString::new(host).unwrap();
    let mut h = 0;
    match bounded("cnc_allclibhndl3", || unsafe {
        cnc_allclibhndl3(ip.as_ptr(), port, TIMEOUT as _, &mut h)
    }) {
        EW_OK => Ok(h),
        r => Err(r),
    }
}

fn handle(f: &Fleet) -> c_ushort {
    alloc("127.0.0.1", f.port(0)).expect("a handle")
}

fn statinfo(h: c_ushort) -> c_short {
    let mut st = ODBST::default();
    bounded("cnc_statinfo", || unsafe { cnc_statinfo(h, &mut st) })
}

fn rdparam(h: c_ushort, n: c_short) -> c_short {
    let mut p = IODBPSD::default();
    bounded("cnc_rdparam", || unsafe { cnc_rdparam(h, n, 0, 8, &mut p) })
}

fn reconnecting(f: &Fleet) -> c_ushort {
    let h = handle(f);
    assert_eq!(fwlib_set_reconnect(h, 1), EW_OK);
    h
}

#[test]
fn refused_connections_while_open_ones_go_on() {
    let f = machine(&["refuse:at=10,duration=10"]);
    let h = handle(&f);
    at(&f, 12.0);
    // A new connection pair (another host string) is refused.
    assert_eq!(alloc("localhost", f.port(0)), Err(EW_SOCKET));
    assert_eq!(statinfo(h), EW_OK, "the open session goes on");
    at(&f, 20.0);
    let h2 = alloc("localhost", f.port(0)).expect("accepting again");
    assert_eq!(statinfo(h2), EW_OK);
}

#[test]
fn a_cnc_switched_off_and_on_again_with_reconnect() {
    let f = machine(&["off:at=10,every=100,duration=10"]);
    let h = reconnecting(&f);
    let plain = alloc("localhost", f.port(0)).unwrap();
    assert_eq!((statinfo(h), statinfo(plain)), (EW_OK, EW_OK));
    at(&f, 12.0);
    assert_eq!(statinfo(h), EW_SOCKET, "the connection is gone");
    assert_eq!(statinfo(h), EW_SOCKET, "reconnecting is refused while off");
    assert_eq!(statinfo(plain), EW_SOCKET);
    assert_eq!(alloc("127.1", f.port(0)).err(), Some(EW_SOCKET));
    at(&f, 25.0);
    assert_eq!(statinfo(h), EW_OK, "reconnected after the outage");
    assert_eq!(
        statinfo(plain),
        EW_SOCKET,
        "without reconnect: EW_SOCKET until freed"
    );
    // The next outage (every 100 s) takes the new connection too.
    at(&f, 111.0);
    assert_eq!(statinfo(h), EW_SOCKET);
    at(&f, 121.0);
    assert_eq!(statinfo(h), EW_OK);
    assert_eq!(cnc_freelibhndl(plain), EW_OK);
    assert_eq!(cnc_freelibhndl(h), EW_OK);
}

#[test]
fn an_outage_between_two_polls_is_noticed_by_the_next() {
    let f = machine(&["off:at=10,duration=5"]);
    let h = reconnecting(&f);
    assert_eq!(statinfo(h), EW_OK);
    // Off from 10 to 15 s, polled again at 30 s: the old connection is dead.
    at(&f, 30.0);
    assert_eq!(statinfo(h), EW_SOCKET);
    assert_eq!(statinfo(h), EW_OK);
}

#[test]
fn a_silent_cnc_times_out() {
    let f = machine(&["silent:at=10,duration=10"]);
    let h = reconnecting(&f);
    at(&f, 12.0);
    let t = Instant::now();
    assert_eq!(statinfo(h), EW_SOCKET);
    assert!(
        t.elapsed() >= Duration::from_secs(TIMEOUT as u64),
        "waited the timeout"
    );
    // A new connection is accepted but never answered either.
    assert_eq!(alloc("localhost", f.port(0)).err(), Some(EW_SOCKET));
    at(&f, 25.0);
    assert_eq!(statinfo(h), EW_OK, "answering again");
}

#[test]
fn an_answer_reset_half_way() {
    let f = machine(&["reset:at=10,duration=10,count=1"]);
    let h = reconnecting(&f);
    at(&f, 12.0);
    assert_eq!(statinfo(h), EW_SOCKET);
    // One cut per occurrence (count = 1): the reconnect and call succeed.
    assert_eq!(statinfo(h), EW_OK);
    assert_eq!(statinfo(h), EW_OK);
}

#[test]
fn an_answer_closed_half_way() {
    let f = machine(&["close:at=10,duration=10"]);
    let h = reconnecting(&f);
    at(&f, 12.0);
    assert_eq!(statinfo(h), EW_SOCKET);
    // Every answer is cut while it holds, the start-up exchange of a reconnect too.
    assert_eq!(statinfo(h), EW_SOCKET);
    at(&f, 20.0);
    assert_eq!(statinfo(h), EW_OK);
}

#[test]
fn slow_answers() {
    let f = machine(&[
        "delay:at=10,duration=10,delay_ms=300",
        "delay:at=30,delay_ms=1500",
    ]);
    let h = reconnecting(&f);
    at(&f, 12.0);
    let t = Instant::now();
    assert_eq!(statinfo(h), EW_OK);
    assert!(
        t.elapsed() >= Duration::from_millis(300),
        "{:?}",
        t.elapsed()
    );
    // Later than the handle's timeout: EW_SOCKET within it.
    at(&f, 31.0);
    assert_eq!(statinfo(h), EW_SOCKET);
}

#[test]
fn too_many_focas_clients() {
    let f = machine(&["sessions:at=10,sessions=1"]);
    let a = handle(&f);
    let b = alloc("localhost", f.port(0)).unwrap();
    at(&f, 12.0);
    // Two sessions already open stay; a third is refused.
    assert_eq!(statinfo(b), EW_OK);
    assert_eq!(alloc("127.1", f.port(0)).err(), Some(EW_SOCKET));
    assert_eq!(cnc_freelibhndl(b), EW_OK);
    assert_eq!(cnc_freelibhndl(a), EW_OK);
    let c = alloc("127.1", f.port(0)).expect("one session allowed");
    assert_eq!(alloc("localhost", f.port(0)).err(), Some(EW_SOCKET));
    assert_eq!(f.sessions(0), 1);
    assert_eq!(cnc_freelibhndl(c), EW_OK);
}

#[test]
fn an_error_code_for_chosen_functions() {
    let f = machine(&[
        "error:functions=cnc_rdparam,code=EW_NOOPT,at=10,duration=10",
        "error:commands=0x0019,code=-1,at=30",
    ]);
    let h = handle(&f);
    at(&f, 12.0);
    assert_eq!(rdparam(h, 6711), EW_NOOPT);
    assert_eq!(statinfo(h), EW_OK);
    at(&f, 25.0);
    assert_eq!(rdparam(h, 6711), EW_OK);
    at(&f, 30.0);
    assert_eq!(statinfo(h), EW_BUSY);
    assert_eq!(rdparam(h, 6711), EW_OK);
}

/// cnc_upload3 until it returns something else than data or EW_BUFFER.
fn upload_until_failure(h: c_ushort) -> c_short {
    let until = Instant::now() + BOUND;
    let mut buf = vec![0u8; 1024];
    loop {
        assert!(Instant::now() < until, "the upload never ended");
        let mut len: c_long = buf.len() as c_long;
        match unsafe { cnc_upload3(h, &mut len, buf.as_mut_ptr().cast()) } {
            EW_OK | EW_BUFFER => std::thread::yield_now(),
            r => return r,
        }
    }
}

#[test]
fn off_the_network_during_an_upload() {
    let mut p = Profile::default();
    // A program long enough for several frames.
    let body: String = (1..=400)
        .map(|i| format!("N{i} G01 X{i}. F500;\n"))
        .collect();
    p.programs[0].text = format!("O1234 (LONG);\n{body}M30;\n%\n");
    let f = Fleet::start(
        &[p],
        "127.0.0.1:0",
        FleetOptions {
            faults: vec![Fault::parse_spec("upload_drop:at=10,duration=10,count=1").unwrap()],
            worker_threads: Some(1),
            ..FleetOptions::default()
        },
    )
    .unwrap();
    at(&f, 1.0);
    let h = reconnecting(&f);
    let other = alloc("localhost", f.port(0)).unwrap();
    at(&f, 12.0);
    assert_eq!(cnc_upstart3(h, 0, 1234, 1234), EW_OK);
    assert_eq!(upload_until_failure(h), EW_SOCKET);
    // Every connection of the CNC went: the other client's too.
    assert_eq!(statinfo(other), EW_SOCKET);
    // Back on the network: the reconnecting handle uploads the whole program.
    assert_eq!(statinfo(h), EW_OK);
    assert_eq!(cnc_upstart3(h, 0, 1234, 1234), EW_OK);
    assert_eq!(upload_until_failure(h), EW_RESET, "the end of the program");
    assert_eq!(cnc_upend3(h), EW_OK);
}

#[test]
fn a_single_simulator_takes_its_profile_s_faults() {
    let p = Profile::parse(
        "[[path]]\n[[fault]]\nkind = \"error\"\ncommands = [0x19]\ncode = 7\n\
         [[fault]]\nkind = \"refuse\"\nat = 3600.0\n",
    )
    .unwrap();
    let s = fwlib32::sim::Simulator::start(p, "127.0.0.1:0").unwrap();
    let h = alloc("127.0.0.1", s.port()).unwrap();
    assert_eq!(statinfo(h), EW_PROT);
    s.set_elapsed(Duration::from_secs(3601));
    assert_eq!(alloc("localhost", s.port()).err(), Some(EW_SOCKET));
    assert_eq!(cnc_freelibhndl(h), EW_OK);
}
