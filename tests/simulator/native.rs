//! The Rust API (fwlib32::native) against the simulator, beyond its doc
//! tests: batches split into frames of at most 16 subpackets, errors with
//! their call, code and detail, connections shared, cloned and closed.

use fwlib32::native::{Cnc, Decimal, Error, Ew, Mode, PmcArea, Value};
use fwlib32::sim::{Profile, Simulator};
use std::time::Duration;

fn sim() -> Simulator {
    let s = Simulator::start(Profile::default(), "127.0.0.1:0").unwrap();
    s.set_elapsed(Duration::ZERO);
    s
}

fn connect(s: &Simulator) -> Cnc {
    Cnc::connect(&s.addr().to_string(), Duration::from_secs(5)).unwrap()
}

#[test]
fn a_batch_takes_as_few_frames_as_fit() {
    let s = sim();
    let cnc = connect(&s);
    // 3 + 10 + 4 subpackets: more than one frame holds.
    let mut b = cnc.batch();
    let (st, pos, ex) = (b.status(), b.positions(), b.execution());
    let mut r = b.send().unwrap();
    assert_eq!(r.frames(), 2);
    assert_eq!(r.take(st).unwrap().mode, Mode::Mem);
    assert_eq!(r.take(pos).unwrap()[0].absolute, Decimal::new(125000, 3));
    assert_eq!(r.take(ex).unwrap().program, 1234);

    // Twenty one-subpacket reads: 16 in the first frame (a 30i).
    let mut b = cnc.batch();
    let t: Vec<_> = (0..20).map(|i| b.macro_var(500 + i)).collect();
    let mut r = b.send().unwrap();
    assert_eq!(r.frames(), 2);
    let v: Vec<_> = t.into_iter().map(|t| r.take(t).unwrap()).collect();
    assert_eq!(v[0], Some(Decimal::new(25400, 3)));
    assert_eq!(v[19], None);

    // A ticket is taken once; a bad argument fails its own ticket only.
    let mut b = cnc.batch();
    let (bad, good) = (
        b.param::<i32>(1320, Some(0)),
        b.pmc::<u8>(PmcArea::G, 30..=30),
    );
    let mut r = b.send().unwrap();
    assert_eq!(r.take(bad).unwrap_err().code(), Ew::ATTRIB);
    assert_eq!(r.take(good).unwrap(), [100]);
    assert_eq!(cnc.batch().send().unwrap().frames(), 0);
}

#[test]
fn errors_name_the_call_code_and_detail() {
    let s = sim();
    let cnc = connect(&s);
    match cnc.param::<i32>(9999, None) {
        Err(e @ Error::Cnc { .. }) => {
            assert_eq!((e.call(), e.code()), ("cnc_rdparam", Ew::NUMBER));
            assert_eq!(e.code().name(), "EW_NUMBER");
        }
        r => panic!("{r:?}"),
    }
    let e = cnc.param::<i8>(6711, None).unwrap_err(); // 1234 does not fit
    assert!(
        matches!(
            e,
            Error::Invalid {
                code: Ew::ATTRIB,
                ..
            }
        ),
        "{e}"
    );
    assert!(
        e.to_string().contains("parameter 6711 is 2word (1234)"),
        "{e}"
    );
    assert_eq!(
        cnc.param::<Value>(1320, None).unwrap_err().code(),
        Ew::ATTRIB
    );
    assert_eq!(cnc.set_path(2).unwrap_err().code(), Ew::PATH);
    assert_eq!(cnc.diag::<f64>(4901, None).unwrap(), 23.5);

    let port = {
        let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
        l.local_addr().unwrap().port()
    };
    let e = Cnc::connect(&format!("127.0.0.1:{port}"), Duration::from_secs(2)).unwrap_err();
    assert_eq!((e.call(), e.code()), ("cnc_allclibhndl3", Ew::SOCKET));
    assert_eq!((e.detail().err_no, e.detail().err_dtno), (1, 0));
}

#[test]
fn clones_share_one_session() {
    let s = sim();
    let a = connect(&s);
    let b = connect(&s);
    let c = a.try_clone().unwrap();
    assert_eq!(s.sessions(), 1);
    let t = std::thread::spawn(move || c.positions().map(|p| p.len()));
    assert_eq!(t.join().unwrap().unwrap(), 3);
    assert_eq!(b.macro_var(500).unwrap(), Some(Decimal::new(25400, 3)));
    drop(a);
    drop(b);
    // The last one closed the pair: a new connection opens a new one.
    assert_eq!(connect(&s).status().unwrap().mode, Mode::Mem);
}

#[test]
fn programs_upload_with_progress() {
    let s = sim();
    let cnc = connect(&s);
    let mut seen = Vec::new();
    let text = cnc.program_with(100, |n| seen.push(n)).unwrap();
    assert_eq!(seen.last(), Some(&text.len()));
    assert!(text.contains("N30 G04 X60."));
    let e = cnc.program(4242).unwrap_err();
    assert_eq!(e.call(), "cnc_upload3");
    // The connection stays usable after a refused upload.
    assert_eq!(cnc.program(100).unwrap(), text);
}
