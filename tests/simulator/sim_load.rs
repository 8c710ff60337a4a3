//! The simulator holds thousands of FOCAS sessions at once, and still
//! enforces a profile's session limit.

use fwlib32::proto::cmd;
use fwlib32::proto::frame::{CLIENT_VERSION, Frame, ftype};
use fwlib32::proto::packet::{ReqSub, decode_response, encode_request};
use fwlib32::proto::status::Status;
use fwlib32::proto::wire::Wire;
use fwlib32::sim::{Profile, Simulator};
use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::Duration;

fn recv(s: &mut TcpStream) -> Frame {
    let mut buf = Vec::new();
    let mut chunk = [0u8; 1024];
    loop {
        if let Some((f, _)) = Frame::decode(&buf).expect("valid frame") {
            return f;
        }
        let n = s.read(&mut chunk).expect("read");
        assert!(n > 0, "simulator closed the connection");
        buf.extend_from_slice(&chunk[..n]);
    }
}

fn open(port: u16, number: u16) -> (TcpStream, Frame) {
    let mut s = TcpStream::connect(("127.0.0.1", port)).expect("connect");
    s.set_read_timeout(Some(Duration::from_secs(10))).unwrap();
    s.write_all(
        &Frame::new(
            CLIENT_VERSION,
            ftype::OPEN_REQ,
            number.to_be_bytes().to_vec(),
        )
        .encode(),
    )
    .unwrap();
    let f = recv(&mut s);
    (s, f)
}

#[test]
fn thousands_of_concurrent_sessions() {
    let sim = Simulator::start(
        Profile::parse("[cnc]\nmax_sessions = 0\n[[path]]\nstatus = { aut = 1 }\n").unwrap(),
        "127.0.0.1:0",
    )
    .unwrap();
    const N: usize = 2000;
    let mut conns = Vec::with_capacity(N);
    for _ in 0..N {
        let (s, f) = open(sim.port(), 1);
        assert_eq!(f.ftype, ftype::OPEN_RESP);
        conns.push(s);
    }
    assert_eq!(sim.sessions(), N);
    // Every one of them is served while all are open.
    let req = Frame::new(
        CLIENT_VERSION,
        ftype::DATA_REQ,
        encode_request(&[ReqSub {
            path: 1,
            ..ReqSub::cnc(cmd::STATINFO, &[])
        }]),
    )
    .encode();
    for s in &mut conns {
        s.write_all(&req).unwrap();
    }
    for s in &mut conns {
        let f = recv(s);
        let subs = decode_response(&f.body).unwrap();
        assert_eq!(Status::from_bytes(&subs[0].payload).unwrap().aut, 1);
    }
}

#[test]
fn session_limit_answers_0x0103() {
    let sim = Simulator::start(
        Profile::parse("[cnc]\nmax_sessions = 2\n[[path]]\n").unwrap(),
        "127.0.0.1:0",
    )
    .unwrap();
    let (_a, fa) = open(sim.port(), 1);
    let (_b, fb) = open(sim.port(), 1);
    let (_c, fc) = open(sim.port(), 1);
    assert_eq!(
        (fa.ftype, fb.ftype, fc.ftype),
        (ftype::OPEN_RESP, ftype::OPEN_RESP, ftype::OPEN_REJECT)
    );
    // The data connection of an admitted session is not counted again.
    let (_d, fd) = open(sim.port(), 2);
    assert_eq!(fd.ftype, ftype::OPEN_RESP);
    drop(_a);
    // Once a session closes, a new one is admitted (the server notices the close
    // asynchronously, so retry a bounded number of times).
    let mut admitted = false;
    for _ in 0..200 {
        let (_e, fe) = open(sim.port(), 1);
        if fe.ftype == ftype::OPEN_RESP {
            admitted = true;
            break;
        }
    }
    assert!(admitted, "a freed session slot is reused");
}
