//! The wire-fault matrix: every family of calls (status, position,
//! parameter, macro, PMC, alarm, program upload, tool offset, a function
//! described in src/spec/table/) against a CNC that misbehaves once, in
//! the open phase (the open answer, the start-up sysinfo of
//! cnc_allclibhndl3) or the data phase (the call's own answer):
//! connection refused, reset, closed mid-frame, silent, a slow drip
//! (slower than the timeout) and a fast one (which must work), a bad magic,
//! a frame length longer and shorter than the body, a subpacket length
//! that lies, an oversize length, error codes in every subpacket, payloads
//! cut to half.
//!
//! Every cell: a known EW_* code (the same one for every family where the
//! stream itself is broken), within the handle's timeout and a margin,
//! nothing written past the caller's buffers, and a new handle to the same
//! CNC works afterwards. The CNC is a thread answering from a simulated
//! machine (src/sim) and breaking the chosen answer; tests/robust/faults.rs drives
//! the simulator's own scheduled faults, tests/robust/hostile.rs random payloads.

use crate::guard;

use fwlib32::ew::*;
use fwlib32::proto::frame::{Frame, HEADER_LEN, ftype};
use fwlib32::proto::packet::{RespSub, decode_request, encode_response};
use fwlib32::sim::service::CncService;
use fwlib32::sim::{Machine, Profile};
use fwlib32::types::*;
use fwlib32::*;
use std::collections::BTreeMap;
use std::ffi::CString;
use std::io::Write;
use std::net::{Shutdown, TcpStream};
use std::os::fd::AsRawFd;
use std::os::raw::{c_long, c_short, c_ushort};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

const TIMEOUT: i32 = 1;
const BOUND: Duration = Duration::from_secs(TIMEOUT as u64 + 8);

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Fault {
    None,
    Refused,
    Reset,
    ClosedMidFrame,
    Silent,
    SlowDrip,
    FastDrip,
    BadMagic,
    LengthLonger,
    LengthShorter,
    SubLength,
    Oversize,
    ErrorSubs,
    ShortPayloads,
}

const FAULTS: [Fault; 14] = [
    Fault::None,
    Fault::Refused,
    Fault::Reset,
    Fault::ClosedMidFrame,
    Fault::Silent,
    Fault::SlowDrip,
    Fault::FastDrip,
    Fault::BadMagic,
    Fault::LengthLonger,
    Fault::LengthShorter,
    Fault::SubLength,
    Fault::Oversize,
    Fault::ErrorSubs,
    Fault::ShortPayloads,
];

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Phase {
    /// The answer to the first open frame.
    Open,
    /// The first data answer: the start-up sysinfo.
    Startup,
    /// The first answer after the start-up: the call's.
    Data,
}

/// An answer before it is sent: subpackets still editable.
enum Answer {
    Frame(Frame),
    Data(Vec<RespSub>),
    /// The upload start answer and the whole upload, as frames.
    Upload(Vec<Frame>),
}

struct Cnc {
    machine: Mutex<Machine>,
    fault: Fault,
    phase: Phase,
    version: u16,
    /// Data frames answered, all connections.
    data: AtomicUsize,
    opens: AtomicUsize,
    hit: AtomicBool,
    /// Stop accepting (the listener is closed): refused from then on.
    closed: AtomicBool,
    stop: AtomicBool,
}

fn reset(s: TcpStream) {
    let linger = libc::linger {
        l_onoff: 1,
        l_linger: 0,
    };
    unsafe {
        libc::setsockopt(
            s.as_raw_fd(),
            libc::SOL_SOCKET,
            libc::SO_LINGER,
            (&linger as *const libc::linger).cast(),
            std::mem::size_of::<libc::linger>() as libc::socklen_t,
        );
    }
}

impl Cnc {
    fn encode(&self, a: &Answer) -> Vec<u8> {
        match a {
            Answer::Frame(f) => f.encode(),
            Answer::Data(r) => {
                Frame::new(self.version, ftype::DATA_RESP, encode_response(r)).encode()
            }
            Answer::Upload(fs) => fs.iter().flat_map(Frame::encode).collect(),
        }
    }

    /// Breaks `a` as the fault says; None when it is not to be sent
    /// (the connection was dropped, or the CNC keeps silent).
    fn break_answer(&self, s: &mut TcpStream, mut a: Answer) -> Option<Vec<u8>> {
        match self.fault {
            Fault::ErrorSubs => match &mut a {
                Answer::Data(r) => r.iter_mut().for_each(|x| {
                    x.error = EW_NOOPT;
                    x.payload.clear();
                }),
                Answer::Upload(fs) => {
                    fs.truncate(1);
                    fs.push(Frame::new(
                        self.version,
                        ftype::UPLOAD_ABORT,
                        fwlib32::proto::upload::error_body(EW_NOOPT, 0, 0),
                    ));
                }
                Answer::Frame(_) => {}
            },
            Fault::ShortPayloads => match &mut a {
                Answer::Data(r) => r
                    .iter_mut()
                    .for_each(|x| x.payload.truncate(x.payload.len() / 2)),
                Answer::Upload(fs) => fs.iter_mut().skip(1).for_each(|f| {
                    if f.ftype == ftype::UPLOAD_DATA {
                        f.body.truncate(f.body.len() / 2)
                    }
                }),
                Answer::Frame(f) => f.body.truncate(f.body.len() / 2),
            },
            _ => {}
        }
        let mut b = self.encode(&a);
        // The frame whose header breaks: an upload's first text frame
        // (after the start answer, which has no body), else the only one.
        let at = match &a {
            Answer::Upload(fs) if fs.len() > 1 => fs[0].encode().len(),
            _ => 0,
        };
        let len = |b: &[u8]| u16::from_be_bytes([b[at + 8], b[at + 9]]);
        let set_len =
            |b: &mut Vec<u8>, v: u16| b[at + 8..at + 10].copy_from_slice(&v.to_be_bytes());
        match self.fault {
            Fault::Refused => {
                self.closed.store(true, Ordering::SeqCst);
                reset(s.try_clone().unwrap());
                return None;
            }
            Fault::Reset => {
                reset(s.try_clone().unwrap());
                return None;
            }
            Fault::ClosedMidFrame => {
                let _ = s.write_all(&b[..b.len() / 2]);
                let _ = s.shutdown(Shutdown::Both);
                return None;
            }
            Fault::Silent => return None,
            Fault::SlowDrip | Fault::FastDrip => {
                let (piece, pause) = if self.fault == Fault::SlowDrip {
                    (1, Duration::from_millis(100))
                } else {
                    ((b.len() / 50).max(3), Duration::from_millis(2))
                };
                for c in b.chunks(piece) {
                    if s.write_all(c).is_err() {
                        return None;
                    }
                    // The fault itself (a slow line), not a synchronisation.
                    std::thread::sleep(pause);
                }
                return None;
            }
            Fault::BadMagic => b[at] ^= 0xff,
            Fault::LengthLonger => {
                let l = len(&b);
                set_len(&mut b, l + 10);
            }
            Fault::LengthShorter => {
                let l = len(&b);
                set_len(&mut b, l.saturating_sub(4));
            }
            Fault::SubLength => {
                // The first subpacket's length word (data frames only).
                if let Answer::Data(_) = a {
                    let at = HEADER_LEN + 2;
                    let l = u16::from_be_bytes([b[at], b[at + 1]]);
                    b[at..at + 2].copy_from_slice(&(l + 4).to_be_bytes());
                }
            }
            Fault::Oversize => set_len(&mut b, 0xffff),
            _ => {}
        }
        Some(b)
    }

    fn serve(self: Arc<Self>, mut s: TcpStream) {
        let _ = s.set_nodelay(true);
        let mut frames = Frames::new();
        while let Some(frame) = frames.read(&mut s) {
            let mut m = self.machine.lock().unwrap();
            let (answer, phase) = match frame.ftype {
                ftype::OPEN_REQ => {
                    let first = self.opens.fetch_add(1, Ordering::SeqCst) == 0;
                    let f = Frame::new(self.version, ftype::OPEN_RESP, m.open_body().to_bytes());
                    (Answer::Frame(f), first.then_some(Phase::Open))
                }
                ftype::CLOSE_REQ => {
                    let _ =
                        s.write_all(&Frame::new(self.version, ftype::CLOSE_RESP, vec![]).encode());
                    return;
                }
                ftype::DATA_REQ => {
                    let Ok(subs) = decode_request(&frame.body) else {
                        return;
                    };
                    let n = self.data.fetch_add(1, Ordering::SeqCst);
                    let r: Vec<RespSub> = subs.iter().map(|q| m.answer(q)).collect();
                    let phase = match n {
                        0 => Some(Phase::Startup),
                        _ => Some(Phase::Data),
                    };
                    (Answer::Data(r), phase)
                }
                ftype::UPLOAD_START_REQ => {
                    let (_, frames) = fwlib32::sim::session::upload(&mut *m, self.version, &frame);
                    (Answer::Upload(frames), Some(Phase::Data))
                }
                _ => continue,
            };
            drop(m);
            let bytes = if phase == Some(self.phase) && !self.hit.swap(true, Ordering::SeqCst) {
                match self.break_answer(&mut s, answer) {
                    Some(b) => b,
                    None => continue,
                }
            } else {
                self.encode(&answer)
            };
            if s.write_all(&bytes).is_err() {
                return;
            }
        }
    }
}

/// A CNC on a free port breaking one answer; stopped when dropped.
struct Server {
    port: u16,
    cnc: Arc<Cnc>,
}

impl Server {
    fn start(fault: Fault, phase: Phase) -> Server {
        let machine = Machine::new(Profile::default());
        let version = machine.open_body().frame_version();
        let cnc = Arc::new(Cnc {
            machine: Mutex::new(machine),
            fault,
            phase,
            version,
            data: AtomicUsize::new(0),
            opens: AtomicUsize::new(0),
            hit: AtomicBool::new(false),
            closed: AtomicBool::new(fault == Fault::Refused && phase == Phase::Open),
            stop: AtomicBool::new(false),
        });
        let c = cnc.clone();
        let port = listen(move |_, s| {
            if c.stop.load(Ordering::SeqCst) {
                return false;
            }
            if c.closed.load(Ordering::SeqCst) {
                // Refused: a reset at once, as a closed port answers.
                reset(s);
                return true;
            }
            let c = c.clone();
            std::thread::spawn(move || c.serve(s));
            true
        });
        Server { port, cnc }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        self.cnc.stop.store(true, Ordering::SeqCst);
        let _ = TcpStream::connect(("127.0.0.1", self.port));
    }
}

fn alloc(port: u16) -> Result<c_ushort, c_short> {
    let ip = CString::new("127.0.0.1").unwrap();
    let mut h = 0;
    match unsafe { cnc_allclibhndl3(ip.as_ptr(), port, TIMEOUT as _, &mut h) } {
        EW_OK => Ok(h),
        r => Err(r),
    }
}

use guard::*;

fn size<T>() -> usize {
    std::mem::size_of::<T>()
}

/// A family's call on handle `h`: its code, and whether every output is intact.
type Family = (&'static str, fn(c_ushort) -> (c_short, bool));

fn one(n: usize, f: impl FnOnce(&mut Out) -> c_short) -> (c_short, bool) {
    let mut o = Out::new(n);
    let r = f(&mut o);
    (r, o.intact())
}

/// cnc_upstart3, cnc_upload3 until the end, cnc_upend3: the first failure,
/// or EW_OK for a whole upload.
fn upload(h: c_ushort) -> (c_short, bool) {
    match cnc_upstart3(h, 0, 1, 9999) {
        EW_OK => {}
        r => return (r, true),
    }
    let until = Instant::now() + BOUND;
    let mut o = Out::new(1024);
    loop {
        assert!(Instant::now() < until, "the upload never ended");
        let mut len: c_long = 1024;
        match unsafe { cnc_upload3(h, &mut len, o.p()) } {
            EW_OK | EW_BUFFER => std::thread::yield_now(),
            EW_RESET => return (cnc_upend3(h), o.intact()),
            r => {
                let _ = cnc_upend3(h);
                return (r, o.intact());
            }
        }
    }
}

const FAMILIES: &[Family] = &[
    ("status", |h| {
        one(size::<ODBST>(), |o| unsafe { cnc_statinfo(h, o.p()) })
    }),
    ("position", |h| {
        one(size::<ODBAXIS>(), |o| unsafe {
            cnc_absolute(h, -1, size::<ODBAXIS>() as c_short, o.p())
        })
    }),
    ("param", |h| {
        one(size::<IODBPSD>(), |o| unsafe {
            cnc_rdparam(h, 1320, -1, size::<IODBPSD>() as c_short, o.p())
        })
    }),
    ("macro", |h| {
        one(size::<ODBM>(), |o| unsafe {
            cnc_rdmacro(h, 500, 10, o.p())
        })
    }),
    ("pmc", |h| {
        one(8 + 40, |o| unsafe {
            pmc_rdpmcrng(h, 9, 1, 0, 39, 8 + 40, o.p())
        })
    }),
    ("alarm", |h| {
        let mut n: c_short = 10;
        one(size::<ODBALMMSG>() * 10, |o| unsafe {
            cnc_rdalmmsg(h, -1, &mut n, o.p())
        })
    }),
    ("program upload", upload),
    ("tool offset", |h| {
        one(size::<ODBTOFS>(), |o| unsafe {
            cnc_rdtofs(h, 1, 0, 8, o.p())
        })
    }),
    ("described", |h| {
        one(size::<ODBPRO>(), |o| unsafe { cnc_rdprgnum(h, o.p()) })
    }),
];

/// One cell's result.
#[derive(Debug)]
struct Cell {
    family: &'static str,
    phase: Phase,
    fault: Fault,
    rc: c_short,
    took: Duration,
    intact: bool,
    /// A new handle to the same CNC afterwards: its first call's code.
    after: c_short,
}

fn cell(family: &Family, phase: Phase, fault: Fault) -> Cell {
    let server = Server::start(fault, phase);
    let t = Instant::now();
    let (rc, intact) = match alloc(server.port) {
        Err(rc) => (rc, true),
        Ok(h) => {
            let r = if phase == Phase::Data {
                (family.1)(h)
            } else {
                (EW_OK, true)
            };
            let _ = cnc_freelibhndl(h);
            r
        }
    };
    let took = t.elapsed();
    let after = if fault == Fault::Refused {
        EW_OK
    } else {
        match alloc(server.port) {
            Ok(h) => {
                let r = (family.1)(h).0;
                let _ = cnc_freelibhndl(h);
                r
            }
            Err(r) => r,
        }
    };
    Cell {
        family: family.0,
        phase,
        fault,
        rc,
        took,
        intact,
        after,
    }
}

/// The codes a fault may give, where they are fixed: a broken stream is
/// EW_SOCKET (a frame longer than its bytes too: the rest never comes),
/// a frame that cannot be read EW_PROTOCOL; None where the function
/// decides (error codes, short payloads).
fn expected(fault: Fault, phase: Phase, family: &str) -> Option<&'static [c_short]> {
    let upload = phase == Phase::Data && family == "program upload";
    Some(match fault {
        Fault::None | Fault::FastDrip => &[EW_OK],
        Fault::Refused | Fault::Reset | Fault::ClosedMidFrame | Fault::Silent => &[EW_SOCKET],
        Fault::SlowDrip | Fault::LengthLonger => &[EW_SOCKET],
        Fault::BadMagic | Fault::Oversize | Fault::LengthShorter => &[EW_PROTOCOL],
        // No subpackets in an open answer nor in an upload.
        Fault::SubLength | Fault::ErrorSubs if phase == Phase::Open => &[EW_OK],
        Fault::SubLength if upload => &[EW_OK],
        Fault::SubLength => &[EW_PROTOCOL],
        Fault::ErrorSubs | Fault::ShortPayloads => return None,
    })
}

#[test]
fn every_family_in_every_phase_gets_a_clear_code_for_every_wire_fault() {
    let cells: Vec<Cell> = std::thread::scope(|s| {
        let mut jobs = Vec::new();
        // The open phase is cnc_allclibhndl3's: the same for every family.
        for phase in [Phase::Open, Phase::Startup] {
            jobs.push(s.spawn(move || {
                FAULTS
                    .iter()
                    .map(|f| cell(&FAMILIES[0], phase, *f))
                    .collect::<Vec<_>>()
            }));
        }
        for fam in FAMILIES {
            jobs.push(s.spawn(move || {
                FAULTS
                    .iter()
                    .map(|f| cell(fam, Phase::Data, *f))
                    .collect::<Vec<_>>()
            }));
        }
        jobs.into_iter().flat_map(|j| j.join().unwrap()).collect()
    });
    let mut failures = Vec::new();
    let mut table: BTreeMap<(Phase, Fault), Vec<String>> = BTreeMap::new();
    for c in &cells {
        let name = match c.phase {
            Phase::Data => c.family,
            _ => "cnc_allclibhndl3",
        };
        table
            .entry((c.phase, c.fault))
            .or_default()
            .push(format!("{name} {}", c.rc));
        let what = format!("{name} / {:?} / {:?}", c.phase, c.fault);
        if !(-17..=18).contains(&c.rc) || c.rc == EW_UNEXP {
            failures.push(format!("{what}: {} is no clear code", c.rc));
        }
        if let Some(want) = expected(c.fault, c.phase, c.family) {
            if !want.contains(&c.rc) {
                failures.push(format!("{what}: {} (expected one of {want:?})", c.rc));
            }
        } else if c.fault == Fault::ErrorSubs && c.rc <= 0 {
            failures.push(format!("{what}: {} (expected the CNC's error)", c.rc));
        }
        if c.took > BOUND {
            failures.push(format!("{what}: took {:?}", c.took));
        }
        if !c.intact {
            failures.push(format!("{what}: wrote past the caller's buffer"));
        }
        if c.after != EW_OK {
            failures.push(format!("{what}: a new handle afterwards got {}", c.after));
        }
    }
    for ((phase, fault), codes) in &table {
        println!("{phase:?} {fault:?}: {}", codes.join(", "));
    }
    assert_eq!(cells.len(), (2 + FAMILIES.len()) * FAULTS.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
