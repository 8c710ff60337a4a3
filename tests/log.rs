//! cnc_startupprocess / cnc_exitprocess and the library log (own test
//! binary: the log is process-wide).

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::ODBST;
use fwlib32::*;
use std::ffi::CString;

#[test]
fn level_3_logs_every_frame_and_exitprocess_frees_everything() {
    let dir = std::env::temp_dir().join(format!("fwlib32-log-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("focas.log");
    let cfile = CString::new(file.to_str().unwrap()).unwrap();

    // Levels outside 0..=3 are refused as FANUC's library refuses them.
    assert_eq!(unsafe { cnc_startupprocess(5, cfile.as_ptr()) }, EW_NUMBER);
    assert_eq!(unsafe { cnc_startupprocess(-1, cfile.as_ptr()) }, EW_NUMBER);
    assert!(!file.exists());
    // A log file that cannot be created never aborts, and is not an error.
    let bad = CString::new("/nonexistent-dir/x.log").unwrap();
    assert_eq!(unsafe { cnc_startupprocess(1, bad.as_ptr()) }, EW_OK);

    assert_eq!(unsafe { cnc_startupprocess(3, cfile.as_ptr()) }, EW_OK);
    let sim = Simulator::start(Profile::default(), "127.0.0.1:0").unwrap();
    let ip = CString::new("127.0.0.1").unwrap();
    let mut h = 0;
    assert_eq!(
        unsafe { cnc_allclibhndl3(ip.as_ptr(), sim.port(), 5, &mut h) },
        EW_OK
    );
    let mut st = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_OK);
    assert_eq!(unsafe { cnc_statinfo(0x7777, &mut st) }, EW_HANDLE);
    assert_eq!(cnc_exitprocess(), EW_OK);
    // exitprocess freed the handle.
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_HANDLE);

    let log = std::fs::read_to_string(&file).unwrap();
    // The statinfo request, byte for byte (SPEC.md §5.1), and its answer.
    assert!(log.contains("send conn2"), "{log}");
    assert!(
        log.contains("a0a0a0a00001210100560003001c0001000100190000"),
        "{log}"
    );
    assert!(log.contains("recv conn2"), "{log}");
    assert!(log.contains("cnc_statinfo -> 0"), "{log}");
    assert!(log.contains("cnc_statinfo -> -8"), "{log}");
    // The close handshake of exitprocess.
    assert!(log.contains("a0a0a0a0000102010000"), "{log}");
    // Each line starts with its time, RFC 3339 in UTC, to the millisecond:
    // 2026-11-28T11:22:06.123Z pid ...
    for l in log.lines() {
        let (t, rest) = l.split_once(' ').unwrap();
        assert!(rest.starts_with("pid "), "{l}");
        let b = t.as_bytes();
        assert_eq!(t.len(), 24, "{l}");
        assert_eq!((b[4], b[10], b[19], b[23]), (b'-', b'T', b'.', b'Z'), "{l}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
