//! The exported C functions, called as Rust functions, against an in-process
//! simulator on 127.0.0.1:0. Values must equal the profile's.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::ffi::CString;
use std::os::raw::c_ulong;

fn default_sim() -> Simulator {
    sim::start(Profile::default())
}

fn text(c: &[std::os::raw::c_char]) -> String {
    c.iter().map(|x| *x as u8 as char).collect()
}

#[test]
fn default_profile_reads_back() {
    let s = default_sim();
    // The machine runs (src/sim/run.rs): at 1.25 s O1234 is in N30 G00,
    // a move, so the status words are the profile's run 3 / motion 1.
    s.set_elapsed(std::time::Duration::from_millis(1250));
    let p = Profile::default();
    let h = sim::try_alloc(&s).expect("alloc");
    assert_ne!(h, 0);

    let mut sys = ODBSYS::default();
    assert_eq!(unsafe { cnc_sysinfo(h, &mut sys) }, EW_OK);
    assert_eq!(text(&sys.cnc_type), p.cnc.cnc_type);
    assert_eq!(text(&sys.mt_type), " M");
    assert_eq!(text(&sys.series), p.cnc.series);
    assert_eq!(text(&sys.version), p.cnc.version);
    assert_eq!(text(&sys.axes), format!("{:>2}", p.paths[0].axes.len()));
    assert_eq!(sys.max_axis as u16, p.cnc.max_axes);
    assert_eq!(sys.addinfo as u16, p.cnc.addinfo);

    let st = p.paths[0].status;
    let mut o = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(h, &mut o) }, EW_OK);
    assert_eq!(
        [
            o.hdck,
            o.tmmode,
            o.aut,
            o.run,
            o.motion,
            o.mstb,
            o.emergency,
            o.alarm,
            o.edit
        ],
        [
            st.hdck,
            st.tmmode,
            st.aut,
            st.run,
            st.motion,
            st.mstb,
            st.emergency,
            st.alarm,
            st.edit
        ]
    );
    let mut o2 = ODBST2::default();
    assert_eq!(unsafe { cnc_statinfo2(h, &mut o2) }, EW_OK);
    assert_eq!(
        (o2.aut, o2.run, o2.warning, o2.restart),
        (st.aut, st.run, st.warning, st.restart)
    );

    let mut id = [0u32; 4];
    assert_eq!(
        unsafe { cnc_rdcncid(h, id.as_mut_ptr().cast::<c_ulong>()) },
        EW_OK
    );
    assert_eq!(id.to_vec(), p.cnc.cnc_id);

    let (mut path, mut max) = (0, 0);
    assert_eq!(unsafe { cnc_getpath(h, &mut path, &mut max) }, EW_OK);
    assert_eq!((path, max), (1, 1));
    assert_eq!(cnc_setpath(h, 2), EW_PATH);

    assert_eq!(cnc_freelibhndl(h), EW_OK);
    assert_eq!(cnc_freelibhndl(h), EW_HANDLE, "double free");
    assert_eq!(
        unsafe { cnc_statinfo(h, &mut o) },
        EW_HANDLE,
        "stale handle"
    );
}

const TWO_PATHS: &str = r#"
[cnc]
cnc_id = [1, 2, 3, 4]
[[path]]
machine = "lathe"
status = { aut = 1, run = 3 }
axis = [{ name = "X" }, { name = "Z" }]
[[path]]
machine = "mill"
status = { aut = 5, run = 0 }
axis = [{ name = "X" }, { name = "Y" }, { name = "Z" }, { name = "B" }]
"#;

#[test]
fn path_is_per_handle() {
    let s = sim::start_toml(TWO_PATHS);
    let a = sim::try_alloc(&s).unwrap();
    let b = sim::try_alloc(&s).unwrap();
    assert_ne!(a, b);
    assert_eq!(cnc_setpath(a, 2), EW_OK);
    let (mut st_a, mut st_b) = (ODBST::default(), ODBST::default());
    assert_eq!(unsafe { cnc_statinfo(a, &mut st_a) }, EW_OK);
    assert_eq!(unsafe { cnc_statinfo(b, &mut st_b) }, EW_OK);
    assert_eq!((st_a.aut, st_a.run), (5, 0), "handle a is on path 2");
    assert_eq!((st_b.aut, st_b.run), (1, 3), "handle b stays on path 1");
    let mut sys = ODBSYS::default();
    assert_eq!(unsafe { cnc_sysinfo(a, &mut sys) }, EW_OK);
    assert_eq!(
        (text(&sys.mt_type), text(&sys.axes)),
        (" M".into(), " 4".into())
    );
    assert_eq!(unsafe { cnc_sysinfo(b, &mut sys) }, EW_OK);
    assert_eq!(
        (text(&sys.mt_type), text(&sys.axes)),
        (" T".into(), " 2".into())
    );
    let (mut p, mut m) = (0, 0);
    assert_eq!(unsafe { cnc_getpath(a, &mut p, &mut m) }, EW_OK);
    assert_eq!((p, m), (2, 2));
    assert_eq!(cnc_setpath(a, 0), EW_OK);
    assert_eq!(unsafe { cnc_getpath(a, &mut p, &mut m) }, EW_OK);
    assert_eq!(p, 1);
    assert_eq!(s.sessions(), 1, "both handles share one connection pair");
    assert_eq!(cnc_freelibhndl(a), EW_OK);
    assert_eq!(cnc_freelibhndl(b), EW_OK);
}

#[test]
fn series16_class_profile() {
    let s = sim::start_toml(
        r#"
[cnc]
class = "16i"
cnc_type = "16"
series = "B0H1"
version = "0020"
max_axes = 8
max_spindles = 4
[[path]]
status = { aut = 1, run = 1, edit = 2 }
axis = [{ name = "X" }, { name = "Y" }, { name = "Z" }, { name = "A" }]
"#,
    );
    let h = sim::try_alloc(&s).unwrap();
    let mut sys = ODBSYS::default();
    assert_eq!(unsafe { cnc_sysinfo(h, &mut sys) }, EW_OK);
    assert_eq!(
        (text(&sys.cnc_type), sys.max_axis, text(&sys.axes)),
        ("16".into(), 8, " 4".into())
    );
    let mut st = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_OK);
    assert_eq!((st.aut, st.run, st.edit), (1, 1, 2));
    assert_eq!(cnc_freelibhndl(h), EW_OK);
}

#[test]
fn null_pointers_and_bad_handles() {
    let s = default_sim();
    let h = sim::try_alloc(&s).unwrap();
    unsafe {
        assert_eq!(cnc_sysinfo(h, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_statinfo(h, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_statinfo2(h, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_rdcncid(h, std::ptr::null_mut()), EW_DATA);
        assert_eq!(
            cnc_getpath(h, std::ptr::null_mut(), std::ptr::null_mut()),
            EW_DATA
        );
        assert_eq!(cnc_getdtailerr(h, std::ptr::null_mut()), EW_DATA);
        let mut hh = 0;
        assert_eq!(
            cnc_allclibhndl3(std::ptr::null(), s.port(), 3, &mut hh),
            EW_DATA
        );
        let ip = CString::new("127.0.0.1").unwrap();
        assert_eq!(
            cnc_allclibhndl3(ip.as_ptr(), s.port(), 3, std::ptr::null_mut()),
            EW_DATA
        );
        let mut st = ODBST::default();
        assert_eq!(cnc_statinfo(0, &mut st), EW_HANDLE);
        assert_eq!(cnc_statinfo(0x1234, &mut st), EW_HANDLE);
    }
    assert_eq!(cnc_settimeout(0, 3), EW_HANDLE);
    assert_eq!(cnc_setpath(0, 1), EW_HANDLE);
    assert_eq!(cnc_freelibhndl(h), EW_OK);
}

#[test]
fn output_untouched_on_error() {
    let s = default_sim();
    let h = sim::try_alloc(&s).unwrap();
    // Path 2 does not exist on the default machine: setpath refuses it,
    // and nothing is written by a failing call.
    assert_eq!(cnc_setpath(h, 2), EW_PATH);
    let before = ODBST {
        hdck: 77,
        ..ODBST::default()
    };
    let mut st = before;
    assert_eq!(cnc_freelibhndl(h), EW_OK);
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_HANDLE);
    assert_eq!(st, before);
}

#[test]
fn session_limit_is_enforced() {
    let s = sim::start_toml("[cnc]\nmax_sessions = 1\n[[path]]\n");
    let h = sim::try_alloc(&s).unwrap();
    // Same host:port shares the pair, so a second handle is fine ...
    let h2 = sim::try_alloc(&s).unwrap();
    // ... but a second connection pair (here: to "localhost") is refused by the CNC.
    let ip = CString::new("localhost").unwrap();
    let mut h3 = 0;
    let r = unsafe { cnc_allclibhndl3(ip.as_ptr(), s.port(), 3, &mut h3) };
    assert_eq!(r, EW_SOCKET);
    assert_eq!(h3, 0, "no handle on failure");
    assert_eq!(cnc_freelibhndl(h), EW_OK);
    assert_eq!(cnc_freelibhndl(h2), EW_OK);
}

#[test]
fn connection_refused_is_ew_socket() {
    let port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let ip = CString::new("127.0.0.1").unwrap();
    let mut h = 0;
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), port, 2, &mut h) },
        EW_SOCKET
    );
}

#[test]
fn handles_work_from_any_thread_in_parallel() {
    let s = default_sim();
    let h = sim::try_alloc(&s).unwrap();
    std::thread::scope(|sc| {
        for _ in 0..8 {
            sc.spawn(|| {
                for _ in 0..50 {
                    let mut st = ODBST::default();
                    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_OK);
                    assert_eq!(st.aut, 1);
                }
            });
        }
    });
    // A handle made on one thread is freed on another.
    std::thread::spawn(move || assert_eq!(cnc_freelibhndl(h), EW_OK))
        .join()
        .unwrap();
}

#[test]
fn many_handles_far_beyond_fanucs_1024() {
    let s = default_sim();
    let mut hs = Vec::new();
    for _ in 0..3000 {
        hs.push(sim::try_alloc(&s).expect("alloc"));
    }
    let mut sorted = hs.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(sorted.len(), hs.len(), "handles are unique");
    assert!(!hs.contains(&0));
    let mut st = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(hs[2999], &mut st) }, EW_OK);
    for h in &hs {
        assert_eq!(cnc_freelibhndl(*h), EW_OK);
    }
    // A freed number is not handed out again right away.
    let again = sim::try_alloc(&s).unwrap();
    assert!(!hs.contains(&again));
    assert_eq!(cnc_freelibhndl(again), EW_OK);
}

#[test]
fn reconnects_after_the_simulator_restarts() {
    let s = default_sim();
    let port = s.port();
    let h = sim::try_alloc(&s).unwrap();
    drop(s);
    let mut st = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_SOCKET);
    assert_eq!(
        unsafe { cnc_statinfo(h, &mut st) },
        EW_SOCKET,
        "pair stays down"
    );
    let mut e = ODBERR::default();
    assert_eq!(unsafe { cnc_getdtailerr(h, &mut e) }, EW_OK);
    assert_ne!((e.err_no, e.err_dtno), (0, 0));
    assert_eq!(cnc_freelibhndl(h), EW_OK);
    // A new simulator on the same port (if still free) accepts a fresh connection.
    if let Ok(s2) = Simulator::start(Profile::default(), &format!("127.0.0.1:{port}")) {
        let h2 = sim::try_alloc(&s2).expect("reconnect");
        assert_eq!(unsafe { cnc_statinfo(h2, &mut st) }, EW_OK);
        assert_eq!(cnc_freelibhndl(h2), EW_OK);
    }
}
