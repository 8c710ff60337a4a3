//! Program upload through the C ABI against the simulator: every stored
//! program comes back as the profile has it (in a CNC's punch format),
//! aborts, missing programs, two handles, and data requests on
//! connection 2 during an upload. No sleeps: EW_BUFFER is retried, as the
//! API asks.

use crate::common;
use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::ffi::CString;
use std::os::raw::{c_long, c_short, c_ushort};

fn big_program() -> String {
    let mut t = String::from("O7000 (LONG ONE);\n");
    for i in 1..=600 {
        t.push_str(&format!(
            "N{} G01 X{}.5 Y-{}. F800;\n",
            i * 10,
            i % 97,
            i % 13
        ));
    }
    t.push_str("M30;\n%\n");
    t
}

fn profile(class: &str) -> Profile {
    let mut p = Profile::default();
    if class == "16i" {
        p = Profile::parse(
            &fwlib32::sim::profile::DEFAULT_PROFILE.replace("class = \"30i\"", "class = \"16i\""),
        )
        .expect("16i profile");
    }
    p.programs.push(fwlib32::sim::run::StoredProgram {
        number: 7000,
        text: big_program(),
        ..Default::default()
    });
    p
}

fn sim(class: &str) -> (Simulator, Profile) {
    let p = profile(class);
    (sim::start(p.clone()), p)
}

/// What a CNC punches for these stored texts.
fn punched(texts: &[&str]) -> Vec<u8> {
    let mut out = String::from("%\n");
    for t in texts {
        for l in t.lines() {
            let l = l.trim().trim_end_matches(';').trim_end();
            if !l.is_empty() && l != "%" {
                out.push_str(l);
                out.push('\n');
            }
        }
    }
    out.push('%');
    out.into_bytes()
}

fn text_of(p: &Profile, number: i32) -> &str {
    &p.programs.iter().find(|x| x.number == number).unwrap().text
}

/// One cnc_upload3 call with room for `room` bytes.
fn upload3(h: c_ushort, room: usize) -> (c_short, Vec<u8>) {
    let mut buf = vec![0u8; room];
    let mut len: c_long = room as c_long;
    let r = unsafe { cnc_upload3(h, &mut len, buf.as_mut_ptr().cast()) };
    buf.truncate(if r == EW_OK { len as usize } else { 0 });
    (r, buf)
}

/// Reads with cnc_upload3 until the end (EW_RESET); Err(code) on another error.
fn read_all(h: c_ushort, room: usize) -> Result<Vec<u8>, c_short> {
    let mut all = Vec::new();
    loop {
        match upload3(h, room) {
            (EW_OK, b) => {
                assert!(!b.is_empty() && b.len() <= room);
                all.extend(b)
            }
            (EW_BUFFER, _) => std::thread::yield_now(),
            (EW_RESET, _) => return Ok(all),
            (r, _) => return Err(r),
        }
    }
}

#[test]
fn every_stored_program_uploads_as_stored() {
    for class in ["30i", "16i"] {
        let (s, p) = sim(class);
        let h = sim::alloc(&s);
        for prog in &p.programs {
            assert_eq!(cnc_upstart(h, prog.number as c_short), EW_OK);
            let got = read_all(h, 1024).expect("upload");
            assert_eq!(
                String::from_utf8_lossy(&got),
                String::from_utf8_lossy(&punched(&[&prog.text])),
                "{class} O{}",
                prog.number
            );
            assert_eq!(upload3(h, 256).0, EW_RESET, "EW_RESET again after the end");
            assert_eq!(cnc_upend3(h), EW_OK);
        }
        sim::free(h);
    }
}

#[test]
fn ranges_names_and_the_odbup_functions() {
    let (s, p) = sim("30i");
    let h = sim::alloc(&s);
    // A range: every program in it, ascending, between one pair of '%'.
    assert_eq!(cnc_upstart3(h, 0, 1, 9999), EW_OK);
    let want = punched(&[text_of(&p, 100), text_of(&p, 1234), text_of(&p, 7000)]);
    assert_eq!(read_all(h, 4096).expect("range"), want);
    assert_eq!(cnc_upend3(h), EW_OK);

    // By name (cnc_upstart4), read with cnc_upload4 / cnc_upend4.
    let name = CString::new("O0100").unwrap();
    assert_eq!(
        unsafe { cnc_upstart4(h, 0, name.as_ptr().cast_mut()) },
        EW_OK
    );
    let mut got = Vec::new();
    loop {
        let mut buf = [0u8; 300];
        let mut len: c_long = 300;
        match unsafe { cnc_upload4(h, &mut len, buf.as_mut_ptr().cast()) } {
            EW_OK => got.extend_from_slice(&buf[..len as usize]),
            EW_BUFFER => std::thread::yield_now(),
            EW_RESET => break,
            r => panic!("cnc_upload4 returned {r}"),
        }
    }
    assert_eq!(got, punched(&[text_of(&p, 100)]));
    assert_eq!(cnc_upend4(h), EW_OK);

    // cnc_upload (waits for data) into ODBUP, then cnc_upend.
    assert_eq!(cnc_upstart(h, 1234), EW_OK);
    let mut got = Vec::new();
    loop {
        let mut up = ODBUP::default();
        let mut len: c_ushort = 256;
        match unsafe { cnc_upload(h, &mut up, &mut len) } {
            EW_OK => {
                assert_eq!(up.dummy, [0, 0], "dummy is not written");
                got.extend(up.data[..len as usize].iter().map(|c| *c as u8));
            }
            EW_RESET => break,
            r => panic!("cnc_upload returned {r}"),
        }
    }
    assert_eq!(got, punched(&[text_of(&p, 1234)]));
    assert_eq!(cnc_upend(h), EW_OK);
    sim::free(h);
}

#[test]
fn upend_before_the_end_aborts_and_the_next_upload_works() {
    let (s, p) = sim("30i");
    let h = sim::alloc(&s);
    assert_eq!(cnc_upstart(h, -5), EW_OK, "sent as \"O-5-O-5\"");
    assert_eq!(read_all(h, 256), Err(EW_DATA), "no such program");
    assert_eq!(cnc_upend3(h), EW_DATA, "the CNC's error, once more");

    assert_eq!(cnc_upstart3(h, 0, 7000, 7000), EW_OK);
    let first = loop {
        match upload3(h, 256) {
            (EW_OK, b) => break b,
            (EW_BUFFER, _) => std::thread::yield_now(),
            (r, _) => panic!("{r}"),
        }
    };
    assert_eq!(first.len(), 256);
    assert_eq!(cnc_upend3(h), EW_OK, "aborted before the end");
    assert_eq!(upload3(h, 256).0, EW_FUNC, "no upload any more");
    // The rest of the aborted upload is skipped; a new one starts clean.
    assert_eq!(cnc_upstart3(h, 0, 7000, 7000), EW_OK);
    assert_eq!(read_all(h, 2000), Ok(punched(&[text_of(&p, 7000)])));
    assert_eq!(cnc_upend3(h), EW_OK);
    sim::free(h);
}

#[test]
fn missing_programs_and_bad_arguments() {
    let (s, _) = sim("30i");
    let h = sim::alloc(&s);
    // Nothing started.
    assert_eq!(upload3(h, 256).0, EW_FUNC);
    assert_eq!(cnc_upend3(h), EW_FUNC);
    // A program that is not stored: the start is accepted, the upload fails.
    assert_eq!(cnc_upstart(h, 4321), EW_OK);
    assert_eq!(read_all(h, 256), Err(EW_DATA));
    assert_eq!(cnc_upend(h), EW_DATA);
    // A range the wrong way round; a data type the simulator does not store.
    assert_eq!(cnc_upstart3(h, 0, 9, 1), EW_OK);
    assert_eq!(read_all(h, 256), Err(EW_NUMBER));
    assert_eq!(cnc_upend3(h), EW_NUMBER);
    assert_eq!(cnc_upstart3(h, 1, 1, 9999), EW_OK);
    assert_eq!(read_all(h, 256), Err(EW_ATTRIB));
    assert_eq!(cnc_upend3(h), EW_ATTRIB);

    // Lengths (after the start, as FANUC checks them), NULLs, handles.
    assert_eq!(cnc_upstart(h, 7000), EW_OK);
    assert_eq!(upload3(h, 255).0, EW_LENGTH);
    // Room counts in whole 256 bytes; ODBUP never gets more than its 256.
    let first = loop {
        match upload3(h, 511) {
            (EW_BUFFER, _) => std::thread::yield_now(),
            (r, b) => break (r, b.len()),
        }
    };
    assert_eq!(first, (EW_OK, 256));
    let mut up = ODBUP::default();
    let mut len: c_ushort = 1000;
    assert_eq!(unsafe { cnc_upload(h, &mut up, &mut len) }, EW_OK);
    assert!(len <= 256, "{len}");
    let mut up = ODBUP::default();
    let mut len: c_ushort = 255;
    assert_eq!(unsafe { cnc_cupload(h, &mut up, &mut len) }, EW_LENGTH);
    let mut l: c_long = 256;
    assert_eq!(
        unsafe { cnc_upload3(h, std::ptr::null_mut(), up.data.as_mut_ptr()) },
        EW_DATA
    );
    assert_eq!(
        unsafe { cnc_upload3(h, &mut l, std::ptr::null_mut()) },
        EW_DATA
    );
    assert_eq!(cnc_upend3(h), EW_OK);
    assert_eq!(cnc_upstart(0x7777, 100), EW_HANDLE);
    assert_eq!(
        unsafe { cnc_upload3(0x7777, &mut l, up.data.as_mut_ptr()) },
        EW_HANDLE
    );
    assert_eq!(cnc_upend3(0x7777), EW_HANDLE);
    sim::free(h);
}

#[test]
fn two_handles_upload_in_turn() {
    let (s, p) = sim("30i");
    let (h1, h2) = (sim::alloc(&s), sim::alloc(&s));
    assert_eq!(s.sessions(), 1, "both handles share one connection pair");
    assert_eq!(cnc_upstart(h1, 100), EW_OK);
    assert_eq!(
        cnc_upstart(h2, 1234),
        EW_BUSY,
        "one upload at a time per pair"
    );
    assert_eq!(cnc_upstart(h1, 1234), EW_BUSY, "also for the same handle");
    assert_eq!(upload3(h2, 256).0, EW_BUSY);
    assert_eq!(cnc_upend3(h2), EW_BUSY);
    assert_eq!(read_all(h1, 512), Ok(punched(&[text_of(&p, 100)])));
    assert_eq!(cnc_upend3(h1), EW_OK);
    assert_eq!(cnc_upstart(h2, 1234), EW_OK);
    assert_eq!(read_all(h2, 512), Ok(punched(&[text_of(&p, 1234)])));
    assert_eq!(cnc_upend3(h2), EW_OK);

    // A handle freed in the middle of its upload: the next start aborts it.
    assert_eq!(cnc_upstart(h1, 7000), EW_OK);
    sim::free(h1);
    assert_eq!(cnc_upstart(h2, 100), EW_OK);
    assert_eq!(read_all(h2, 512), Ok(punched(&[text_of(&p, 100)])));
    assert_eq!(cnc_upend3(h2), EW_OK);
    sim::free(h2);
}

#[test]
fn data_requests_go_on_during_an_upload() {
    let (s, p) = sim("30i");
    let (h1, h2) = (sim::alloc(&s), sim::alloc(&s));
    assert_eq!(cnc_upstart3(h1, 0, 7000, 7000), EW_OK);
    let mut got = Vec::new();
    let mut st = ODBST::default();
    loop {
        // Connection 2 between every piece, from both handles and another thread.
        assert_eq!(unsafe { cnc_statinfo(h1, &mut st) }, EW_OK);
        assert_eq!(unsafe { cnc_statinfo(h2, &mut st) }, EW_OK);
        let t = std::thread::spawn(move || {
            let mut st = ODBST::default();
            unsafe { cnc_statinfo(h2, &mut st) }
        });
        assert_eq!(t.join().unwrap(), EW_OK);
        match upload3(h1, 256) {
            (EW_OK, b) => got.extend(b),
            (EW_BUFFER, _) => std::thread::yield_now(),
            (EW_RESET, _) => break,
            (r, _) => panic!("{r}"),
        }
    }
    assert_eq!(got, punched(&[text_of(&p, 7000)]));
    assert_eq!(cnc_upend3(h1), EW_OK);
    sim::free(h1);
    sim::free(h2);
}

/// Against a replayed CNC that answers the start and then sends nothing:
/// after the handle's timeout the library aborts (0x1804), closes both
/// connections and returns EW_SOCKET with detail (9, 4), as FANUC's code does.
#[test]
fn a_stalled_upload_ends_after_the_timeout() {
    use common::{Ev, Event, Replay, find_case, load_vectors};
    let files = load_vectors();
    let connect = find_case(&files, "cnc_allclibhndl3", "v3_one_path").calls[0]
        .frames
        .clone();
    let start = find_case(&files, "cnc_upload3", "v3_not_started_yet").calls[0]
        .frames
        .clone();
    let mut server = Replay::start();
    let ip = CString::new("127.0.0.1").unwrap();
    let (mut h, port): (c_ushort, u16) = (0, server.port);
    let (r, m) = server.step("connect", connect, || unsafe {
        cnc_allclibhndl3(ip.as_ptr(), port, 3, &mut h)
    });
    assert_eq!((r, m), (EW_OK, vec![]));
    let (r, m) = server.step("upstart", start, || cnc_upstart(h, 1234));
    assert_eq!((r, m), (EW_OK, vec![]));
    assert_eq!(cnc_settimeout(h, 1), EW_OK);
    let stall = vec![
        Event::parse(1, "req", "a0a0a0a00001180400080000000000000000"),
        Event::new(1, Ev::Eof),
        Event::new(2, Ev::Eof),
    ];
    let (r, m) = server.step("stalled cnc_upload", stall, || {
        let mut up = ODBUP::default();
        let mut len: c_ushort = 256;
        unsafe { cnc_upload(h, &mut up, &mut len) }
    });
    assert_eq!((r, m), (EW_SOCKET, vec![]));
    let mut e = ODBERR::default();
    assert_eq!(unsafe { cnc_getdtailerr(h, &mut e) }, EW_OK);
    assert_eq!((e.err_no, e.err_dtno), (9, 4));
    let (r, m) = server.step("free", vec![], || cnc_freelibhndl(h));
    assert_eq!((r, m), (EW_OK, vec![]));
    assert_eq!(server.finish(), Vec::<String>::new());
}

/// FANUC's buffer rule (oracle findings, no vectors): the room is `*length`
/// in whole 256 bytes; queued frames are copied, a frame that does not fit
/// split, while 256 bytes or more of room are left.
#[test]
fn room_in_whole_256s_frames_split_to_fit() {
    use common::{Event, Replay, find_case, hex, load_vectors};
    use fwlib32::proto::frame::{Frame, ftype};
    let files = load_vectors();
    let connect = find_case(&files, "cnc_allclibhndl3", "v3_one_path").calls[0]
        .frames
        .clone();
    let start_req =
        find_case(&files, "cnc_upload3", "v3_not_started_yet").calls[0].frames[0].clone();
    let pushed = |sizes: &[usize]| {
        let mut b = Frame::new(3, ftype::UPLOAD_START_RESP, vec![]).encode();
        for (i, n) in sizes.iter().enumerate() {
            b.extend(Frame::new(3, ftype::UPLOAD_DATA, vec![b'a' + i as u8; *n]).encode());
        }
        b.extend(Frame::new(3, ftype::UPLOAD_END, vec![]).encode());
        vec![start_req.clone(), Event::parse(1, "resp", &hex(&b))]
    };
    let ack = || vec![Event::parse(1, "req", "a0a0a0a0000117020000")];
    let mut server = Replay::start();
    let ip = CString::new("127.0.0.1").unwrap();
    let (mut h, port): (c_ushort, u16) = (0, server.port);
    let (r, m) = server.step("connect", connect, || unsafe {
        cnc_allclibhndl3(ip.as_ptr(), port, 3, &mut h)
    });
    assert_eq!((r, m), (EW_OK, vec![]));

    for (sizes, room, want) in [
        (&[300, 600, 10][..], 768, &[768, 142][..]),
        (&[300, 300, 10][..], 256, &[256, 44, 256, 44, 10][..]),
        (&[300, 300, 10][..], 1000, &[600, 10][..]),
        (&[19, 5][..], 511, &[19, 5][..]),
        (&[19, 5][..], 512, &[24][..]),
    ] {
        let (r, m) = server.step("upstart", pushed(sizes), || cnc_upstart(h, 1234));
        assert_eq!((r, m), (EW_OK, vec![]));
        // The 0x1702 goes out when the end frame is taken: with the last
        // piece when 256 bytes of room were left, else on the next call.
        let ((got, last), m) = server.step("upload", ack(), || {
            let got: Vec<(c_short, usize)> = want
                .iter()
                .map(|_| {
                    let (r, b) = upload3(h, room);
                    (r, b.len())
                })
                .collect();
            (got, upload3(h, room).0)
        });
        assert_eq!(m, Vec::<String>::new());
        let want: Vec<(c_short, usize)> = want.iter().map(|n| (EW_OK, *n)).collect();
        assert_eq!(got, want, "frames {sizes:?}, room {room}");
        assert_eq!(last, EW_RESET);
        assert_eq!(cnc_upend3(h), EW_OK);
    }
    let close = vec![
        Event::parse(1, "req", "a0a0a0a0000102010000"),
        Event::parse(1, "resp", "a0a0a0a0000302020000"),
        Event::parse(2, "req", "a0a0a0a0000102010000"),
        Event::parse(2, "resp", "a0a0a0a0000302020000"),
    ];
    let (r, m) = server.step("free", close, || cnc_freelibhndl(h));
    assert_eq!((r, m), (EW_OK, vec![]));
    assert_eq!(server.finish(), Vec::<String>::new());
}

/// cnc_upstart4 with the full path name cnc_exeprgname2 reports (as
/// fanuc_driver uploads the running program), and "O<n>" in that folder.
#[test]
fn upstart4_takes_the_path_name_exeprgname2_reports() {
    let (s, p) = sim("30i");
    let h = sim::alloc(&s);
    let mut pn = [0u8; 256];
    assert_eq!(unsafe { cnc_exeprgname2(h, pn.as_mut_ptr().cast()) }, EW_OK);
    let end = pn.iter().position(|b| *b == 0).unwrap();
    let running = std::str::from_utf8(&pn[..end]).unwrap().to_string();
    assert_eq!(running, "//CNC_MEM/USER/PATH1/O1234");
    let by_name = |name: &str| {
        let c = CString::new(name).unwrap();
        assert_eq!(unsafe { cnc_upstart4(h, 0, c.as_ptr().cast_mut()) }, EW_OK);
        let r = read_all(h, 4096);
        assert_eq!(cnc_upend4(h), *r.as_ref().err().unwrap_or(&EW_OK));
        r
    };
    assert_eq!(by_name(&running), Ok(punched(&[text_of(&p, 1234)])));
    for name in ["//CNC_MEM/USER/PATH1/O100", "//CNC_MEM/USER/PATH1/O0100"] {
        assert_eq!(by_name(name), Ok(punched(&[text_of(&p, 100)])), "{name}");
    }
    // Another folder, or a program the folder does not hold: EW_DATA.
    for name in ["//CNC_MEM/USER/PATH2/O1234", "//CNC_MEM/USER/PATH1/O4321"] {
        assert_eq!(by_name(name), Err(EW_DATA), "{name}");
    }
    sim::free(h);
}
