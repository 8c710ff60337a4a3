//! Program download and DNC operation through the C ABI against the
//! simulator: a program downloaded in each form comes back identical by
//! upload; every refusal returns the CNC's code and changes nothing; one
//! transfer per CNC at a time; data requests go on during a download.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::Profile;
use fwlib32::types::ODBST;
use fwlib32::*;
use std::ffi::CString;
use std::os::raw::{c_long, c_short, c_ushort};

/// cnc_download3 of the whole text.
fn download3(h: c_ushort, text: &[u8]) -> c_short {
    let mut len = text.len() as c_long;
    unsafe { cnc_download3(h, &mut len, text.as_ptr().cast_mut().cast()) }
}

/// The text of program `n` by upload (cnc_upstart3 / cnc_upload3), or the code.
fn upload(h: c_ushort, n: c_long) -> Result<Vec<u8>, c_short> {
    let r = cnc_upstart3(h, 0, n, n);
    if r != EW_OK {
        return Err(r);
    }
    let mut all = Vec::new();
    loop {
        let mut buf = [0u8; 4096];
        let mut len: c_long = buf.len() as c_long;
        match unsafe { cnc_upload3(h, &mut len, buf.as_mut_ptr().cast()) } {
            EW_OK => all.extend_from_slice(&buf[..len as usize]),
            EW_BUFFER => std::thread::yield_now(),
            EW_RESET => break,
            r => {
                cnc_upend3(h);
                return Err(r);
            }
        }
    }
    assert_eq!(cnc_upend3(h), EW_OK);
    Ok(all)
}

/// A program of about `blocks` blocks in punch format.
fn program(number: u32, blocks: usize) -> Vec<u8> {
    let mut t = format!("%\nO{number}(DOWNLOADED)\n");
    for i in 1..=blocks {
        t.push_str(&format!("N{} G01X{}.5Y-{}.F800\n", i * 10, i % 97, i % 13));
    }
    t.push_str("M30\n%");
    t.into_bytes()
}

#[test]
fn a_download_in_each_form_uploads_back_identical() {
    for class in ["30i", "16i"] {
        let p = Profile::parse(
            &fwlib32::sim::profile::DEFAULT_PROFILE
                .replace("class = \"30i\"", &format!("class = \"{class}\"")),
        )
        .unwrap();
        let s = sim::start(p);
        let h = sim::alloc(&s);
        // The first form, 256 bytes at most per call.
        let text = program(4001, 40);
        assert_eq!(cnc_dwnstart(h), EW_OK, "{class}");
        for chunk in text.chunks(256) {
            let r = unsafe {
                cnc_download(h, chunk.as_ptr().cast_mut().cast(), chunk.len() as c_short)
            };
            assert_eq!(r, EW_OK);
        }
        assert_eq!(cnc_dwnend(h), EW_OK);
        assert_eq!(upload(h, 4001).unwrap(), text, "{class} cnc_download");
        // The third form, all at once (frames of 1280 bytes).
        let text = program(4003, 300);
        assert_eq!(cnc_dwnstart3(h, 0), EW_OK);
        assert_eq!(download3(h, &text), EW_OK);
        assert_eq!(cnc_dwnend3(h), EW_OK);
        assert_eq!(upload(h, 4003).unwrap(), text, "{class} cnc_download3");
        // The fourth form, into the path's folder.
        let text = program(4004, 5);
        let folder = CString::new("//CNC_MEM/USER/PATH1/").unwrap();
        assert_eq!(
            unsafe { cnc_dwnstart4(h, 0, folder.as_ptr().cast_mut()) },
            EW_OK
        );
        let mut len = text.len() as c_long;
        assert_eq!(
            unsafe { cnc_download4(h, &mut len, text.as_ptr().cast_mut().cast()) },
            EW_OK
        );
        assert_eq!(len as usize, text.len(), "*length is left as it is");
        assert_eq!(cnc_dwnend4(h), EW_OK);
        assert_eq!(upload(h, 4004).unwrap(), text, "{class} cnc_download4");
        sim::free(h);
    }
}

#[test]
fn refused_downloads_return_the_cnc_code_and_change_nothing() {
    let s = sim::start(Profile::default());
    let h = sim::alloc(&s);
    let before = upload(h, 1234).unwrap();
    let cases: [(&[u8], c_short); 4] = [
        (b"%\nO1234(DUPLICATE)\nM30\n%", EW_DATA),
        (b"%\nO4321\nG0X1.?\nM30\n%", EW_DATA),
        (b"%\n(NO NUMBER)\nM30\n%", EW_DATA),
        // The second program is refused: the first is not stored either.
        (b"%\nO4321\nM30\nO1234\nM30\n%", EW_DATA),
    ];
    for (text, code) in cases {
        assert_eq!(cnc_dwnstart3(h, 0), EW_OK);
        assert_eq!(download3(h, text), EW_OK);
        assert_eq!(cnc_dwnend3(h), code, "{}", String::from_utf8_lossy(text));
    }
    assert_eq!(upload(h, 1234).unwrap(), before, "O1234 unchanged");
    assert_eq!(upload(h, 4321), Err(EW_DATA), "O4321 never stored");

    // Memory full: a profile with little memory.
    let small = fwlib32::sim::profile::DEFAULT_PROFILE.replace("bytes = 524288", "bytes = 2000");
    let s2 = sim::start_toml(&small);
    let h2 = sim::alloc(&s2);
    assert_eq!(cnc_dwnstart3(h2, 0), EW_OK);
    assert_eq!(download3(h2, &program(4005, 200)), EW_OK);
    assert_eq!(cnc_dwnend3(h2), EW_OVRFLOW);
    assert_eq!(upload(h2, 4005), Err(EW_DATA));
    sim::free(h2);
    sim::free(h);
}

#[test]
fn local_checks_send_nothing_and_one_transfer_runs_at_a_time() {
    let s = sim::start(Profile::default());
    let h = sim::alloc(&s);
    let other = sim::alloc(&s);
    assert_eq!(cnc_dwnstart3(h, -1), EW_ATTRIB);
    assert_eq!(
        download3(h, b"%\nO1\nM30\n%"),
        EW_FUNC,
        "no download started"
    );
    assert_eq!(cnc_dwnend3(h), EW_FUNC);
    assert_eq!(cnc_dwnstart3(h, 0), EW_OK);
    assert_eq!(cnc_dwnstart3(h, 0), EW_BUSY);
    assert_eq!(cnc_dwnstart3(other, 0), EW_BUSY, "one transfer per CNC");
    assert_eq!(cnc_upstart3(other, 0, 1234, 1234), EW_BUSY);
    let mut len: c_long = 0;
    assert_eq!(
        unsafe { cnc_download3(h, &mut len, c"x".as_ptr().cast_mut()) },
        EW_LENGTH
    );
    assert_eq!(
        unsafe { cnc_download3(h, std::ptr::null_mut(), c"x".as_ptr().cast_mut()) },
        EW_DATA
    );
    assert_eq!(
        unsafe { cnc_download(h, c"x".as_ptr().cast_mut(), 257) },
        EW_LENGTH
    );
    // Data requests of every handle go on during the download.
    let mut st = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(other, &mut st) }, EW_OK);
    assert_eq!(download3(h, &program(4006, 3)), EW_OK);
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_OK);
    assert_eq!(cnc_dwnend3(h), EW_OK);
    assert!(upload(other, 4006).is_ok());
    // cnc_dncend2: -1 or -32768 only; cnc_dncend before any cnc_dnc.
    assert_eq!(cnc_dncstart(h), EW_OK);
    assert_eq!(cnc_dncend(h), EW_FUNC);
    assert_eq!(unsafe { cnc_dncstart2(h, std::ptr::null_mut()) }, EW_OK);
    assert_eq!(cnc_dncend2(h, 0), EW_DATA);
    assert_eq!(cnc_dncend2(h, i16::MIN), EW_OK);
    sim::free(other);
    sim::free(h);
}

#[test]
fn a_download_cut_by_a_freed_handle_keeps_the_old_store() {
    let s = sim::start(Profile::default());
    let h = sim::alloc(&s);
    let other = sim::alloc(&s);
    assert_eq!(cnc_dwnstart3(h, 0), EW_OK);
    assert_eq!(download3(h, &program(4007, 3)), EW_OK);
    sim::free(h);
    // The freed handle's download is aborted by the next transfer call.
    assert_eq!(cnc_dwnstart3(other, 0), EW_OK);
    assert_eq!(cnc_dwnend3(other), EW_DATA, "an empty download");
    assert_eq!(upload(other, 4007), Err(EW_DATA), "never stored");
    sim::free(other);
}

/// A download over a raw connection 1: open, start, one data frame of
/// program `number`, then the end frame when `end`, or the connection
/// dropped there. Returns once the simulator has closed the session (it
/// read every frame, then the end of the stream).
fn raw_download(s: &fwlib32::sim::Simulator, number: u32, end: bool) {
    use fwlib32::proto::download::DOWNLOAD;
    use fwlib32::proto::frame::{CLIENT_VERSION, Frame, ftype};
    use fwlib32::proto::upload::StartReq;
    use std::io::{Read, Write};
    let sessions = s.sessions();
    {
        let mut c = std::net::TcpStream::connect(s.addr()).unwrap();
        let send = |c: &mut std::net::TcpStream, t: u16, body: Vec<u8>| {
            c.write_all(&Frame::new(CLIENT_VERSION, t, body).encode())
                .unwrap()
        };
        let mut answer = [0u8; 10];
        let mut answered = |c: &mut std::net::TcpStream| {
            c.read_exact(&mut answer).unwrap();
            let mut rest = vec![0u8; usize::from(u16::from_be_bytes([answer[8], answer[9]]))];
            c.read_exact(&mut rest).unwrap();
            u16::from_be_bytes([answer[6], answer[7]])
        };
        send(&mut c, ftype::OPEN_REQ, vec![0, 1]);
        answered(&mut c);
        let req = StartReq {
            dtype: 0,
            path: 1,
            start: Vec::new(),
            end: Vec::new(),
        };
        send(&mut c, DOWNLOAD.start_req(), req.encode());
        assert_eq!(answered(&mut c), DOWNLOAD.start_resp());
        send(&mut c, DOWNLOAD.data_frame(), program(number, 20));
        if end {
            send(&mut c, DOWNLOAD.end_req(), Vec::new());
            assert_eq!(answered(&mut c), DOWNLOAD.end_resp());
        }
        // The connection drops here.
    }
    // The simulator reads the data frame before the end of the stream,
    // then ends the session: wait for that (bounded), not for a while.
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(5);
    while s.sessions() > sessions {
        assert!(
            std::time::Instant::now() < deadline,
            "the session never ended"
        );
        std::thread::yield_now();
    }
}

/// A download cut by a dropped connection, before its end frame: nothing is
/// stored (a CNC keeps the program memory as it was). The same frames with
/// the end frame store the program: the check can fail.
#[test]
fn a_download_cut_by_a_dropped_connection_stores_nothing() {
    let s = sim::start(Profile::default());
    let h = sim::alloc(&s);
    let before = upload(h, 1234).unwrap();
    raw_download(&s, 4322, true);
    assert!(upload(h, 4322).is_ok(), "the whole download is stored");
    raw_download(&s, 4321, false);
    assert_eq!(upload(h, 4321), Err(EW_DATA), "nothing stored");
    assert_eq!(upload(h, 1234).unwrap(), before);
    sim::free(h);
}
