//! Shared by the tests that drive the C ABI against the simulator
//! (tests/ffi/alarm.rs, macros.rs, offset.rs, ...): start a simulator from a
//! profile, allocate a library handle on it with `cnc_allclibhndl3`, free it.

#![allow(dead_code)]

use fwlib32::ew::EW_OK;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::{cnc_allclibhndl3, cnc_freelibhndl};
use std::ffi::CString;
use std::os::raw::{c_short, c_ushort};

/// A one-path 30i profile running O0001 a block a second (`repeat`: over
/// and over), then `rest`: the head the running-machine tests share.
#[allow(unused_macros)]
macro_rules! running_30i {
    ($repeat:literal, $rest:literal) => {
        concat!(
            "[cnc]\nclass = \"30i\"\n\n[[path]]\n[path.status]\naut = 1\nrun = 3\nmotion = 1\n\n",
            "[path.cycle]\nprogram = 1\nblock_seconds = 1.0\nrepeat = ",
            stringify!($repeat),
            "\n",
            $rest
        )
    };
}
#[allow(unused_imports)]
pub(crate) use running_30i;

/// A simulator serving `p` on a free port of 127.0.0.1.
pub fn start(p: Profile) -> Simulator {
    Simulator::start(p, "127.0.0.1:0").expect("simulator")
}

/// A simulator serving the TOML profile `text`.
pub fn start_toml(text: &str) -> Simulator {
    start(Profile::parse(text).expect("profile"))
}

/// `cnc_allclibhndl3` to 127.0.0.1:`port` (timeout 5 s): the handle, or the
/// return code.
pub fn try_connect(port: u16) -> Result<c_ushort, c_short> {
    let ip = CString::new("127.0.0.1").unwrap();
    let mut h: c_ushort = 0;
    let r = unsafe { cnc_allclibhndl3(ip.as_ptr(), port, 5, &mut h) };
    if r == EW_OK { Ok(h) } else { Err(r) }
}

/// `cnc_allclibhndl3` to the simulator `s`: the handle, or the return code.
pub fn try_alloc(s: &Simulator) -> Result<c_ushort, c_short> {
    try_connect(s.port())
}

/// A handle to 127.0.0.1:`port`; the allocation must return EW_OK.
pub fn connect(port: u16) -> c_ushort {
    match try_connect(port) {
        Ok(h) => h,
        Err(r) => panic!("cnc_allclibhndl3 returned {r}, expected EW_OK"),
    }
}

/// A handle to the simulator `s`; the allocation must return EW_OK.
pub fn alloc(s: &Simulator) -> c_ushort {
    connect(s.port())
}

/// A simulator serving `p` and a handle to it.
pub fn start_alloc(p: Profile) -> (Simulator, c_ushort) {
    let s = start(p);
    let h = alloc(&s);
    (s, h)
}

/// Frees the handle `h`; `cnc_freelibhndl` must return EW_OK.
pub fn free(h: c_ushort) {
    assert_eq!(cnc_freelibhndl(h), EW_OK);
}
