//! fwlib_set_reconnect (fwlib32_ext.h): a handle whose CNC dropped off the
//! network works again once the CNC is back, without being freed; without
//! it (the default, as FANUC's library) the handle keeps answering
//! EW_SOCKET. The CNC is a simulator stopped and started again on the same
//! port.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::ODBST;
use fwlib32::*;
use std::ffi::CString;
use std::time::{Duration, Instant};

fn statinfo(h: u16) -> i16 {
    let mut st = ODBST::default();
    unsafe { cnc_statinfo(h, &mut st) }
}

fn connect(host: &str, port: u16) -> u16 {
    let ip = CString::new(host).unwrap();
    let mut h = 0;
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), port, 2, &mut h) },
        EW_OK
    );
    h
}

/// A simulator on `port` again: the old one's listener closes in the
/// background, so binding is retried until the port is free (5 s at most).
fn restart(port: u16) -> Simulator {
    let until = Instant::now() + Duration::from_secs(5);
    loop {
        match Simulator::start(Profile::default(), &format!("127.0.0.1:{port}")) {
            Ok(s) => return s,
            Err(e) if Instant::now() < until => {
                assert_eq!(e.kind(), std::io::ErrorKind::AddrInUse, "{e}");
                std::thread::yield_now();
            }
            Err(e) => panic!("port {port} still taken: {e}"),
        }
    }
}

#[test]
fn a_handle_with_reconnect_works_again_when_the_cnc_is_back() {
    let s = sim::start(Profile::default());
    let port = s.port();
    // Two CNC connections (the library shares one per host:port string).
    let h = connect("127.0.0.1", port);
    let plain = connect("localhost", port);
    assert_eq!(fwlib_set_reconnect(h, 1), EW_OK);
    assert_eq!(fwlib_set_reconnect(0x7fff, 1), EW_HANDLE);
    assert_eq!((statinfo(h), statinfo(plain)), (EW_OK, EW_OK));

    drop(s);
    // The CNC is away: every call ends within its timeout with EW_SOCKET,
    // the reconnecting handle trying again each time.
    for _ in 0..3 {
        let t = Instant::now();
        assert_eq!(statinfo(h), EW_SOCKET);
        assert_eq!(statinfo(plain), EW_SOCKET);
        assert!(t.elapsed() < Duration::from_secs(5));
    }

    let _s = restart(port);
    assert_eq!(statinfo(h), EW_OK, "reconnected");
    assert_eq!(statinfo(h), EW_OK);
    assert_eq!(statinfo(plain), EW_SOCKET, "FANUC's behaviour by default");

    // Turned off again: a failure is final again.
    assert_eq!(fwlib_set_reconnect(h, 0), EW_OK);
    assert_eq!(cnc_freelibhndl(h), EW_OK);
    assert_eq!(fwlib_set_reconnect(h, 1), EW_HANDLE);
    let _ = cnc_freelibhndl(plain);
}

/// cnc_resetconnect drops the CNC's connections as FANUC's library does on
/// Ethernet: EW_OK, then EW_SOCKET on every handle to that CNC, except that a
/// handle with reconnection on connects again at its next call.
#[test]
fn resetconnect_drops_the_connections() {
    let s = sim::start(Profile::default());
    let (a, b) = (
        connect("127.0.0.1", s.port()),
        connect("127.0.0.1", s.port()),
    );
    assert_eq!((statinfo(a), statinfo(b)), (EW_OK, EW_OK));
    assert_eq!(cnc_resetconnect(a), EW_OK);
    assert_eq!((statinfo(a), statinfo(b)), (EW_SOCKET, EW_SOCKET));
    assert_eq!(cnc_resetconnect(a), EW_OK, "again, on dead connections");
    assert_eq!(fwlib_set_reconnect(b, 1), EW_OK);
    assert_eq!(statinfo(b), EW_OK, "b reconnects the pair a shares");
    assert_eq!(statinfo(a), EW_OK);
    assert_eq!(cnc_resetconnect(0x7fff), EW_HANDLE);
    let _ = (cnc_freelibhndl(a), cnc_freelibhndl(b));
}
