//! The alarm history through the C ABI: against the simulator (profile
//! entries, empty history, year quirks), the simulator's ring buffer
//! (wrap-around), and a CNC that sends hand-made records (malformed entries
//! mixed with good ones, an overrunning message length, a caller `length`
//! too small, a negative count).

mod sim;

use fwlib32::ew::*;
use fwlib32::proto::alarm::{AlmHisRecord, AlmHistory, RDALMHISNO, RDALMHISTRY};
use fwlib32::proto::cmd::SYSINFO;
use fwlib32::proto::offset::Count;
use fwlib32::proto::open::OpenBody;
use fwlib32::proto::packet::{ReqSub, RespSub};
use fwlib32::proto::wire::Wire;
use fwlib32::sim::service::CncService;
use fwlib32::sim::{Machine, Profile, Shared};
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::c_ushort;
use std::time::{Duration, SystemTime};

fn text(c: &[std::os::raw::c_char], n: usize) -> String {
    c[..n].iter().map(|x| *x as u8 as char).collect()
}

/// The whole buffer, pre-filled with 0xCC, as bytes.
fn his(h: c_ushort, s: u16, e: u16, length: u16) -> (i16, Vec<u8>) {
    let mut b = vec![0xCCu8; 4096];
    let r = unsafe { cnc_rdalmhistry(h, s, e, length, b.as_mut_ptr().cast()) };
    (r, b)
}

fn his2(h: c_ushort, s: u16, e: u16, length: u16) -> (i16, Vec<u8>) {
    let mut b = vec![0xCCu8; 4096];
    let r = unsafe { cnc_rdalmhistry2(h, s, e, length, b.as_mut_ptr().cast()) };
    (r, b)
}

fn as_his(b: &[u8]) -> ODBAHIS {
    unsafe { b.as_ptr().cast::<ODBAHIS>().read_unaligned() }
}

fn as_his2(b: &[u8]) -> ODBAHIS2 {
    unsafe { b.as_ptr().cast::<ODBAHIS2>().read_unaligned() }
}

fn hisno(h: c_ushort) -> u16 {
    let mut n: u16 = 0xCCCC;
    assert_eq!(unsafe { cnc_rdalmhisno(h, &mut n) }, EW_OK);
    n
}

#[test]
fn profile_history_reads_back_with_fanucs_year_quirks() {
    let s = sim::start(Profile::default());
    let h = sim::connect(s.port());
    let p = Profile::default();
    let want = &p.alarm_history.entries;
    assert_eq!(usize::from(hisno(h)), want.len());

    let (r, b) = his(h, 1, 10, 486);
    assert_eq!(r, EW_OK);
    let a = as_his(&b);
    assert_eq!((a.s_no, a.e_no), (1, want.len() as u16));
    assert_eq!(a.r#type, -13108, "type is left untouched (0xCCCC)");
    for (i, w) in want.iter().enumerate() {
        let x = a.alm_his[i];
        assert_eq!(x.alm_no as i32, w.number);
        assert_eq!((x.alm_grp, x.axis_no as i16), (w.kind, w.axis));
        let t = fwlib32::sim::history::parse_time(&w.time).unwrap();
        assert_eq!(x.year as u16, t[0] % 100, "ODBAHIS: year mod 100");
        assert_eq!(
            [x.month, x.day, x.hour, x.minute, x.second].map(|v| v as u16),
            [t[1], t[2], t[3], t[4], t[5]]
        );
        assert_eq!(x.len_msg as usize, w.message.len());
        assert_eq!(text(&x.alm_msg, w.message.len()), w.message);
        assert_eq!(
            (x.dummy, x.dummy2 as u8),
            (-13108, 0xCC),
            "dummies untouched"
        );
    }
    // Only the entries that exist are written.
    assert!(b[6 + 48 * want.len()..].iter().all(|x| *x == 0xCC));

    let (r, b) = his2(h, 2, 3, 4 + 2 * 52);
    assert_eq!(r, EW_OK);
    let a = as_his2(&b);
    assert_eq!((a.s_no, a.e_no), (2, 3));
    let x = a.alm_his[0];
    assert_eq!(x.alm_no as i32, want[1].number);
    // 2024 = 0x07e8: the low byte sign-extended, -24, as FANUC's library.
    assert_eq!(x.year, -24);
    assert_eq!(x.axis_no, want[1].axis);
    assert_eq!(text(&x.alm_msg, want[1].message.len()), want[1].message);

    // Start after end: EW_NUMBER without traffic; NULL: EW_DATA.
    assert_eq!(his(h, 3, 2, 486).0, EW_NUMBER);
    assert_eq!(his2(h, 3, 2, 524).0, EW_NUMBER);
    unsafe {
        assert_eq!(cnc_rdalmhistry(h, 1, 2, 486, std::ptr::null_mut()), EW_DATA);
        assert_eq!(
            cnc_rdalmhistry2(h, 1, 2, 524, std::ptr::null_mut()),
            EW_DATA
        );
        assert_eq!(cnc_rdalmhisno(h, std::ptr::null_mut()), EW_DATA);
        assert_eq!(cnc_rdalmhisno(0, std::ptr::null_mut()), EW_HANDLE);
    }
    sim::free(h);
}

#[test]
fn empty_history() {
    let p = Profile::parse("[[path]]\n[[path.axis]]\nname = \"X\"\n").unwrap();
    let s = sim::start(p);
    let h = sim::connect(s.port());
    assert_eq!(hisno(h), 0);
    let (r, b) = his(h, 1, 10, 486);
    assert_eq!(r, EW_OK);
    let a = as_his(&b);
    assert_eq!((a.s_no, a.e_no), (1, 0), "no entries: e_no = s_no - 1");
    assert!(b[6..].iter().all(|x| *x == 0xCC));
    let (r, b) = his2(h, 1, 10, 524);
    assert_eq!(r, EW_OK);
    assert_eq!((as_his2(&b).s_no, as_his2(&b).e_no), (1, 0));
    sim::free(h);
}

#[test]
fn full_ring_wraps_around() {
    let p =
        Profile::parse("[alarm_history]\ncapacity = 4\n[[path]]\n[[path.axis]]\nname = \"X\"\n")
            .unwrap();
    let mut m = Machine::new(p);
    let t0 = SystemTime::UNIX_EPOCH + Duration::from_secs(1_715_953_530); // 2024-05-17 13:45:30 UTC
    for i in 0..10 {
        m.record_alarm(
            1000 + i,
            19,
            0,
            &format!("ALARM {i}"),
            t0 + Duration::from_secs(i as u64 * 61),
        );
    }
    assert_eq!(
        m.profile.alarm_history.entries.len(),
        4,
        "the ring keeps capacity entries"
    );
    // Newest first: 1009, 1008, 1007, 1006; the time stamps are the CNC's.
    let got: Vec<i32> = m
        .history_read(1, 50)
        .unwrap()
        .0
        .iter()
        .map(|r| r.alm_no)
        .collect();
    assert_eq!(got, [1009, 1008, 1007, 1006]);
    let newest = m.history_read(1, 1).unwrap().0[0];
    assert_eq!(
        [
            newest.year,
            newest.month,
            newest.day,
            newest.hour,
            newest.minute,
            newest.second
        ],
        [2024, 5, 17, 13, 54, 39]
    );
    assert_eq!(m.history_count().unwrap().value, 4);

    // The same through the C ABI: a simulator started from the wrapped ring.
    let s = sim::start(m.profile.clone());
    let h = sim::connect(s.port());
    assert_eq!(hisno(h), 4);
    let (r, b) = his2(h, 1, 10, 524);
    assert_eq!(r, EW_OK);
    let a = as_his2(&b);
    assert_eq!(a.e_no, 4);
    let nos: Vec<i16> = a.alm_his[..4].iter().map(|x| x.alm_no).collect();
    assert_eq!(nos, [1009, 1008, 1007, 1006]);
    assert_eq!(text(&a.alm_his[0].alm_msg, 7), "ALARM 9");
    sim::free(h);
}

// ---------------------------------------------------------------------------
// A CNC that sends hand-made history records
// ---------------------------------------------------------------------------

struct Fake {
    m: Machine,
    records: Vec<AlmHisRecord>,
    count: i32,
}

impl CncService for Fake {
    fn open_body(&self) -> OpenBody {
        self.m.open_body()
    }
    /// The machine's sysinfo, the hand-made history; nothing else.
    fn answer(&mut self, sub: &ReqSub) -> RespSub {
        match sub.cmd {
            SYSINFO => self.m.answer(sub),
            RDALMHISTRY => RespSub::ok(sub, AlmHistory(self.records.clone()).to_bytes()),
            RDALMHISNO => RespSub::ok(sub, Count { value: self.count }.to_bytes()),
            _ => RespSub::err(sub, EW_FUNC, 0, 0),
        }
    }
}

struct FakeCnc {
    port: u16,
    rt: Option<tokio::runtime::Runtime>,
}

impl FakeCnc {
    fn start(records: Vec<AlmHisRecord>, count: i32) -> FakeCnc {
        let rt = tokio::runtime::Builder::new_multi_thread()
            .worker_threads(1)
            .enable_all()
            .build()
            .unwrap();
        let fake = Fake {
            m: Machine::new(Profile::default()),
            records,
            count,
        };
        let shared = Shared::new(Box::new(fake));
        let listener = rt
            .block_on(tokio::net::TcpListener::bind("127.0.0.1:0"))
            .unwrap();
        let port = listener.local_addr().unwrap().port();
        rt.spawn(fwlib32::sim::server::serve(listener, shared));
        FakeCnc { port, rt: Some(rt) }
    }
}

impl Drop for FakeCnc {
    fn drop(&mut self) {
        if let Some(rt) = self.rt.take() {
            rt.shutdown_background();
        }
    }
}

fn rec(no: i32, ymdhms: [u16; 6], msg: &str) -> AlmHisRecord {
    let mut m = [0u8; 32];
    m[..msg.len()].copy_from_slice(msg.as_bytes());
    let [year, month, day, hour, minute, second] = ymdhms;
    AlmHisRecord {
        alm_no: no,
        reserved: 0,
        alm_grp: 4,
        axis: 1,
        year,
        month,
        day,
        hour,
        minute,
        second,
        msg_len: msg.len() as i32,
        msg: m,
    }
}

const T: [u16; 6] = [2024, 5, 17, 13, 45, 30];

#[test]
fn malformed_entries_are_skipped_and_the_rest_kept() {
    let bad_times = [
        [2024, 0, 17, 13, 45, 30],
        [2024, 13, 17, 13, 45, 30],
        [2024, 5, 0, 13, 45, 30],
        [2024, 5, 32, 13, 45, 30],
        [2024, 5, 17, 24, 45, 30],
        [2024, 5, 17, 13, 60, 30],
        [2024, 5, 17, 13, 45, 60],
    ];
    let mut records = vec![rec(1, T, "GOOD 1")];
    for (i, t) in bad_times.iter().enumerate() {
        records.push(rec(100 + i as i32, *t, "BAD TIME"));
    }
    records.push(rec(2, [2099, 12, 31, 23, 59, 59], "GOOD 2"));
    let f = FakeCnc::start(records, 9);
    let h = sim::connect(f.port);
    let (r, b) = his(h, 1, 9, 486);
    assert_eq!(r, EW_OK);
    let a = as_his(&b);
    assert_eq!(a.e_no, 2, "two good entries written");
    assert_eq!((a.alm_his[0].alm_no, a.alm_his[1].alm_no), (1, 2));
    assert_eq!(a.alm_his[1].year, 99);
    assert!(b[6 + 2 * 48..].iter().all(|x| *x == 0xCC));
    let (r, b) = his2(h, 1, 9, 524);
    assert_eq!(r, EW_OK);
    let a = as_his2(&b);
    assert_eq!(a.e_no, 2);
    assert_eq!(a.alm_his[1].year, 0x33, "2099 = 0x0833: low byte 0x33");
    sim::free(h);
}

#[test]
fn an_overrunning_message_length_ends_the_list() {
    let mut long = rec(2, T, "TOO LONG");
    long.msg_len = 33;
    let records = vec![rec(1, T, "GOOD"), long, rec(3, T, "AFTER")];
    let f = FakeCnc::start(records, 3);
    let h = sim::connect(f.port);
    let (r, b) = his(h, 1, 3, 486);
    assert_eq!(r, EW_OK);
    let a = as_his(&b);
    assert_eq!(a.e_no, 1, "the list ends before the overrunning entry");
    assert_eq!(a.alm_his[0].alm_no, 1);
    assert!(b[6 + 48..].iter().all(|x| *x == 0xCC));
    let mut neg = rec(1, T, "X");
    neg.msg_len = -1;
    sim::free(h);
    drop(f);
    let f = FakeCnc::start(vec![neg], 1);
    let h2 = sim::connect(f.port);
    let (r, b) = his2(h2, 1, 1, 524);
    assert_eq!(r, EW_OK);
    assert_eq!(as_his2(&b).e_no, 0);
    sim::free(h2);
}

#[test]
fn entries_that_do_not_all_fit_in_length_give_ew_length() {
    let records: Vec<_> = (1..=5).map(|i| rec(i, T, "OT")).collect();
    let f = FakeCnc::start(records, 5);
    let h = sim::connect(f.port);
    // Room for two and a half records: EW_LENGTH after the exchange,
    // nothing written (FANUC's library).
    let (r, b) = his(h, 1, 5, 6 + 2 * 48 + 30);
    assert_eq!(r, EW_LENGTH);
    assert!(b.iter().all(|x| *x == 0xCC));
    let (r, b) = his2(h, 1, 5, 4 + 52);
    assert_eq!(r, EW_LENGTH);
    assert!(b.iter().all(|x| *x == 0xCC));
    // Room for all five: written.
    let (r, b) = his2(h, 1, 5, 4 + 5 * 52);
    assert_eq!(r, EW_OK);
    assert_eq!(as_his2(&b).e_no, 5);
    // Not even the head fits: EW_LENGTH, nothing written.
    let (r, b) = his(h, 1, 5, 5);
    assert_eq!(r, EW_LENGTH);
    assert!(b.iter().all(|x| *x == 0xCC));
    let (r, _) = his2(h, 1, 5, 3);
    assert_eq!(r, EW_LENGTH);
    sim::free(h);
}

#[test]
fn a_negative_count_is_an_empty_history() {
    let f = FakeCnc::start(Vec::new(), -5);
    let h = sim::connect(f.port);
    assert_eq!(hisno(h), 0);
    let (r, b) = his(h, 1, 10, 486);
    assert_eq!(r, EW_OK);
    assert_eq!(as_his(&b).e_no, 0);
    sim::free(h);
}
