//! The alarm history through the C ABI: against the simulator (profile
//! entries, empty history, year quirks), the simulator's ring buffer
//! (wrap-around), and a CNC that sends hand-made records (malformed entries
//! mixed with good ones, an overrunning message length, a caller `length`
//! too small, a negative count).
//!
//! The operation history, the operator message histories and alarm history
//! 5 through the C ABI against the simulator: the profile's entries, a
//! signal change the test itself made, bad ranges and short lengths.

use crate::sim;

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
fn a_negative_count_reads_as_its_low_16_bits_and_no_entries() {
    // cnc_rdalmhisno writes the low 16 bits of the CNC's count, as FANUC's
    // library does (tests/vectors/cnc_rdalmhisno.fuzz.json); the history
    // itself has no entries.
    let f = FakeCnc::start(Vec::new(), -5);
    let h = sim::connect(f.port);
    assert_eq!(hisno(h), -5i16 as u16);
    let (r, b) = his(h, 1, 10, 486);
    assert_eq!(r, EW_OK);
    assert_eq!(as_his(&b).e_no, 0);
    sim::free(h);
}

fn ophis(h: c_ushort, s: u16, e: u16, length: u16) -> (i16, ODBHIS) {
    let mut b = ODBHIS::default();
    let r = unsafe { cnc_rdophistry(h, s, e, length, &mut b) };
    (r, b)
}

#[test]
fn operation_history_reads_the_profile_and_a_signal_written_here() {
    let (s, h) = sim::start_alloc(Profile::default());
    let (r, b) = ophis(h, 1, 5, 86);
    assert_eq!(r, EW_OK);
    assert_eq!((b.s_no, b.e_no), (1, 5));
    let d = |i: usize| b.data[i];
    unsafe {
        assert_eq!((d(0).rec_alm.rec_type, d(0).rec_alm.alm_no), (2, 1001));
        assert_eq!(d(0).rec_alm.alm_grp, 19);
        let g = d(1).rec_sgn;
        assert_eq!((g.rec_type, g.sig_no, g.sig_old, g.sig_new), (1, 43, 1, 5));
        assert_eq!((d(2).rec_mdi.rec_type, d(2).rec_mdi.key_code), (0, 0x52));
        let t = d(3).rec_time;
        assert_eq!((t.rec_type, t.hour, t.minute, t.second), (4, 13, 45, 30));
        let y = d(4).rec_date;
        assert_eq!((y.rec_type, y.year, y.month, y.day), (3, 24, 5, 17));
    }

    // A G-signal byte written through FOCAS is recorded, newest first,
    // after a date and a time stamp.
    let mut w = [0u8; 9];
    w[4..6].copy_from_slice(&10u16.to_le_bytes());
    w[6..8].copy_from_slice(&10u16.to_le_bytes());
    w[8] = 0x81;
    assert_eq!(unsafe { pmc_wrpmcrng(h, 9, w.as_mut_ptr().cast()) }, EW_OK);
    let (r, b) = ophis(h, 1, 3, 86);
    assert_eq!(r, EW_OK);
    unsafe {
        let g = b.data[0].rec_sgn;
        assert_eq!((g.rec_type, g.sig_no, g.sig_name), (1, 10, 0));
        assert_eq!((g.sig_old as u8, g.sig_new as u8), (0, 0x81));
        assert_eq!(b.data[1].rec_time.rec_type, 4);
        assert_eq!(b.data[2].rec_date.rec_type, 3);
    }

    // Bad range, short length: nothing written.
    assert_eq!(ophis(h, 3, 2, 86).0, EW_NUMBER);
    assert_eq!(ophis(h, 1, 5, 14).0, EW_LENGTH);
    assert_eq!(
        unsafe { cnc_rdophistry(h, 1, 5, 86, std::ptr::null_mut()) },
        EW_DATA
    );
    sim::free(h);
    drop(s);
}

#[test]
fn operator_message_histories_read_the_profile() {
    let (s, h) = sim::start_alloc(Profile::default());
    let mut b: ODBOMHIS2 = unsafe { std::mem::zeroed() };
    let r = unsafe { cnc_rdomhistry2(h, 1, 10, 2724, &mut b) };
    assert_eq!(r, EW_OK);
    // The message on display at power-on first, then the profile's two.
    assert_eq!((b.s_no, b.e_no), (1, 3));
    let m = b.opm_his[1];
    assert_eq!((m.om_no, m.year, m.month, m.day), (2002, 2024, 5, 17));
    assert_eq!(m.dsp_flg, 0);
    assert_eq!(b.opm_his[0].dsp_flg, 1);
    let text: String = m
        .ope_msg
        .iter()
        .take_while(|c| **c != 0)
        .map(|c| *c as u8 as char)
        .collect();
    assert_eq!(text, "TOOL 12 LIFE EXPIRED");
    assert_eq!(unsafe { cnc_rdomhistry2(h, 1, 10, 100, &mut b) }, EW_LENGTH);

    let mut one: [ODBOMHIS; 5] = unsafe { std::mem::zeroed() };
    let mut num: u16 = 5;
    assert_eq!(
        unsafe { cnc_rdomhistry(h, 1, &mut num, one.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(num, 2);
    assert_eq!((one[0].om_no, one[0].year), (2002, 24));
    num = 0;
    assert_eq!(
        unsafe { cnc_rdomhistry(h, 1, &mut num, one.as_mut_ptr()) },
        EW_LENGTH
    );
    sim::free(h);
    drop(s);
}

#[test]
fn alarm_history_5_reads_the_ring_two_entries_an_exchange() {
    let (s, h) = sim::start_alloc(Profile::default());
    let mut b: Box<ODBAHIS5> = Box::new(unsafe { std::mem::zeroed() });
    let r = unsafe { cnc_rdalmhistry5(h, 1, 10, 5164, &mut *b) };
    assert_eq!(r, EW_OK);
    let want = &Profile::default().alarm_history.entries;
    assert_eq!(usize::from(b.e_no), want.len());
    let a = b.alm_his[1];
    assert_eq!((a.alm_no, a.alm_grp, a.axis_no), (500, 4, 3));
    assert_eq!((a.year, a.month, a.day, a.hour), (2024, 5, 16, 9));
    assert_eq!((a.pth_no, a.len_msg), (1, 18));
    assert_eq!(
        unsafe { cnc_rdalmhistry5(h, 0, 10, 5164, &mut *b) },
        EW_NUMBER
    );
    assert_eq!(
        unsafe { cnc_rdalmhistry5(h, 1, 10, 520, &mut *b) },
        EW_LENGTH
    );
    sim::free(h);
    drop(s);
}

#[test]
fn pitch_error_table_reads_the_profile_across_exchanges() {
    let (s, h) = sim::start_alloc(Profile::default());
    let p = Profile::default().pitch;
    let mut n = 0i16;
    assert_eq!(unsafe { cnc_rdpitchinfo(h, &mut n) }, EW_OK);
    assert_eq!(i32::from(n), p.size);
    // Points 0..=999: two exchanges (716 points each at most).
    let mut b = vec![0x55u8; 6 + 1000 + 8];
    let r = unsafe { cnc_rdpitchr(h, 0, 999, 1006, b.as_mut_ptr().cast()) };
    assert_eq!(r, EW_OK);
    assert_eq!(i16::from_le_bytes([b[4], b[5]]), 999);
    for (i, v) in p.values.iter().enumerate() {
        assert_eq!(b[6 + i] as i8, *v, "point {i}");
    }
    assert_eq!(b[6 + 1000], 0x55, "nothing past the points");
    assert_eq!(
        unsafe { cnc_rdpitchr(h, 0, 999, 100, b.as_mut_ptr().cast()) },
        EW_LENGTH
    );
    assert_eq!(
        unsafe { cnc_rdpitchr(h, 5, 4, 100, b.as_mut_ptr().cast()) },
        EW_NUMBER
    );
    sim::free(h);
    drop(s);
}

/// cnc_rdophistry4 into a buffer: (code, last number, bytes written, buffer).
fn ophis4(h: c_ushort, s: u16, e: u16, length: u16) -> (i16, u16, u16, Vec<u8>) {
    let mut b = vec![0xccu8; 8192];
    let (mut e, mut l) = (e, length);
    let r = unsafe { cnc_rdophistry4(h, s, &mut e, &mut l, b.as_mut_ptr().cast()) };
    (r, e, l, b)
}

/// The records of a cnc_rdophistry4 buffer: (rec_type, body bytes).
fn records4(b: &[u8], len: u16) -> Vec<(i16, Vec<u8>)> {
    let mut out = Vec::new();
    let mut at = 0;
    while at < usize::from(len) {
        let n = i16::from_ne_bytes([b[at], b[at + 1]]) as usize;
        let t = i16::from_ne_bytes([b[at + 2], b[at + 3]]);
        out.push((t, b[at + 4..at + n].to_vec()));
        at += n;
    }
    out
}

fn short_at(b: &[u8], at: usize) -> i16 {
    i16::from_ne_bytes([b[at], b[at + 1]])
}

#[test]
fn operation_history_4_reads_the_profile_and_a_signal_written_here() {
    let (s, h) = sim::start_alloc(Profile::default());
    // The profile's alarm, signal, MDI key and date (its time stamp is in
    // every record), 24 + 20 + 16 + 20 bytes.
    let (r, e, l, b) = ophis4(h, 1, 10, 4096);
    assert_eq!((r, e, l), (EW_OK, 4, 80));
    let recs = records4(&b, l);
    let types: Vec<i16> = recs.iter().map(|r| r.0).collect();
    assert_eq!(types, [2, 1, 0, 3]);
    unsafe {
        let alm = (*b.as_ptr().cast::<ODBOPHIS4>()).u.rec_alm;
        assert_eq!(
            (alm.alm_grp, alm.alm_no, alm.year, alm.month),
            (19, 1001, 2024, 5)
        );
        assert_eq!((alm.hour, alm.minute, alm.second), (13, 45, 30));
        let sgn = (*b.as_ptr().add(24).cast::<ODBOPHIS4>()).u.rec_sgn;
        assert_eq!(
            (sgn.sig_name, sgn.sig_no, sgn.sig_old, sgn.sig_new),
            (0, 43, 1, 5)
        );
        let mdi = (*b.as_ptr().add(44).cast::<ODBOPHIS4>()).u.rec_mdi;
        assert_eq!((mdi.key_code as u8, mdi.hour, mdi.second), (0x52, 13, 30));
        let date = (*b.as_ptr().add(60).cast::<ODBOPHIS4>()).u.rec_date;
        assert_eq!((date.year, date.month, date.day), (2024, 5, 17));
    }

    // A G-signal byte written through FOCAS is recorded, newest first,
    // after today's date record.
    let mut w = [0u8; 9];
    w[4..6].copy_from_slice(&12u16.to_le_bytes());
    w[6..8].copy_from_slice(&12u16.to_le_bytes());
    w[8] = 0x42;
    assert_eq!(unsafe { pmc_wrpmcrng(h, 9, w.as_mut_ptr().cast()) }, EW_OK);
    let (r, e, l, b) = ophis4(h, 1, 2, 4096);
    assert_eq!((r, e, l), (EW_OK, 2, 40));
    let recs = records4(&b, l);
    assert_eq!((recs[0].0, recs[1].0), (1, 3));
    assert_eq!(short_at(&recs[0].1, 2), 12);
    assert_eq!(recs[0].1[5], 0x42, "the new bits");
    assert!(short_at(&recs[1].1, 2) >= 2025, "today's date");

    // Only what fits: the first record alone; none: EW_LENGTH. A start
    // past the history: nothing; 0 or after the end: EW_NUMBER.
    let (r, e, l, _) = ophis4(h, 3, 6, 30);
    assert_eq!((r, e, l), (EW_OK, 3, 24));
    let (r, e, l, _) = ophis4(h, 3, 6, 10);
    assert_eq!((r, e, l), (EW_LENGTH, 6, 0));
    let (r, e, l, _) = ophis4(h, 7, 9, 4096);
    assert_eq!((r, e, l), (EW_OK, 9, 0));
    assert_eq!(ophis4(h, 0, 9, 4096).0, EW_NUMBER);
    assert_eq!(ophis4(h, 5, 4, 4096).0, EW_NUMBER);
    let (mut e, mut l) = (5u16, 100u16);
    let null = std::ptr::null_mut();
    assert_eq!(
        unsafe { cnc_rdophistry4(h, 1, &mut e, &mut l, null) },
        EW_DATA
    );
    sim::free(h);
    drop(s);
}

#[test]
fn operation_history_4_reads_a_long_range_in_several_exchanges() {
    let mut p = Profile::default();
    let key = |k: i32| fwlib32::sim::history::Operation {
        kind: "mdi".into(),
        number: k,
        time: "2024-05-17 13:45:30".into(),
        ..Default::default()
    };
    p.operation_history.entries = (0..150).map(key).collect();
    let (s, h) = sim::start_alloc(p);
    // 150 MDI records of 20 bytes: 71 an answer, three exchanges.
    let (r, e, l, b) = ophis4(h, 1, 200, 8000);
    assert_eq!((r, e, l), (EW_OK, 150, 2400));
    let recs = records4(&b, l);
    assert_eq!(recs.len(), 150);
    assert!(
        recs.iter()
            .enumerate()
            .all(|(i, r)| r.0 == 0 && r.1[0] == i as u8)
    );
    // A buffer for 100: the second exchange's records up to the 100th.
    let (r, e, l, _) = ophis4(h, 1, 150, 1600);
    assert_eq!((r, e, l), (EW_OK, 100, 1600));
    sim::free(h);
    drop(s);
}

/// The newest operation record, as (type, address type, byte, old, new)
/// for a signal record.
fn newest_signal(h: c_ushort) -> (i16, i16, i16, u8, u8) {
    let (r, b) = ophis(h, 1, 1, 86);
    assert_eq!(r, EW_OK);
    let g = unsafe { b.data[0].rec_sgn };
    (
        g.rec_type,
        g.sig_name.into(),
        g.sig_no,
        g.sig_old as u8,
        g.sig_new as u8,
    )
}

#[test]
fn a_reset_a_cycle_start_and_a_mode_change_go_into_the_operation_history() {
    use std::time::Duration;
    // The default machine, its mode switch turned to MDI from 2 s to 3 s.
    let text = format!(
        "{}\n[[event]]\nat = 2.0\nduration = 1.0\naction = \"mode\"\nvalue = 0\n",
        fwlib32::sim::profile::DEFAULT_PROFILE
    );
    let s = sim::start_toml(&text);
    s.set_elapsed(Duration::from_millis(500));
    let h = sim::alloc(&s);
    let mut n = 0u16;
    assert_eq!(unsafe { cnc_rdophisno(h, &mut n) }, EW_OK);
    let before = n;

    // A reset this test did: RST (F1.1) set, the newest record.
    assert_eq!(cnc_reset(h), EW_OK);
    let (t, adr, byte, old, new) = newest_signal(h);
    assert_eq!((t, adr, byte), (1, 1, 1), "a signal record of F1");
    assert_eq!(new, old | 0x02);
    assert_eq!(unsafe { cnc_rdophisno(h, &mut n) }, EW_OK);
    assert!(n > before, "{n} records, {before} before");

    // A cycle start: ST (G7.2).
    assert_eq!(cnc_start(h), EW_OK);
    let (t, adr, byte, old, new) = newest_signal(h);
    assert_eq!((t, adr, byte), (1, 0, 7));
    assert_eq!(new, old | 0x04);

    // The mode switch: MEMORY (MD1) to MDI and back, G43.
    s.set_elapsed(Duration::from_millis(2500));
    let mut st = ODBST::default();
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_OK);
    assert_eq!(st.aut, 0, "MDI");
    assert_eq!(newest_signal(h), (1, 0, 43, 0b001, 0b000));
    s.set_elapsed(Duration::from_millis(3500));
    assert_eq!(unsafe { cnc_statinfo(h, &mut st) }, EW_OK);
    assert_eq!(st.aut, 1, "MEMORY");
    assert_eq!(newest_signal(h), (1, 0, 43, 0b000, 0b001));
    sim::free(h);
}

/// An IODBSIG3 of 0xCC bytes (what a caller's unset memory may hold).
fn sig3_cc() -> IODBSIG3 {
    // SAFETY: IODBSIG3 is plain integers.
    unsafe { std::mem::transmute([0xccu8; std::mem::size_of::<IODBSIG3>()]) }
}

#[test]
fn history_signals_read_the_profiles_table() {
    let (_s, h) = sim::start_alloc(Profile::default());
    let mut b = sig3_cc();
    assert_eq!(unsafe { cnc_rdhissgnl3(h, &mut b) }, EW_OK);
    // datano and type are left as they were.
    assert_eq!((b.datano, b.r#type), (-13108, -13108));
    let e = |i: usize| {
        let d = b.data[i];
        (d.ent_no, d.pmc_no, d.sig_no, d.sig_name, d.mask_pat as u8)
    };
    // G43 (the mode), G7.2 (ST), F1.1 (RST), G10 (*JV), G12 (*FV), then
    // empty entries.
    assert_eq!(e(0), (1, 1, 43, 0, 0xff));
    assert_eq!(e(1), (2, 1, 7, 0, 0x04));
    assert_eq!(e(2), (3, 1, 1, 1, 0x02));
    assert_eq!(e(3), (4, 1, 10, 0, 0xff));
    assert_eq!(e(4), (5, 1, 12, 0, 0xff));
    assert_eq!(e(5), (6, 0, 0, 0, 0));
    assert_eq!(e(59), (60, 0, 0, 0, 0));
    // NULL: EW_DATA (FANUC's library crashes).
    assert_eq!(unsafe { cnc_rdhissgnl3(h, std::ptr::null_mut()) }, EW_DATA);
    sim::free(h);
}

#[test]
fn history_signals_write_then_read_back_and_a_refused_write_changes_nothing() {
    let (_s, h) = sim::start_alloc(Profile::default());
    let read = || {
        let mut b = sig3_cc();
        assert_eq!(unsafe { cnc_rdhissgnl3(h, &mut b) }, EW_OK);
        b
    };
    let before = read();
    // A G20 byte the table does not list is not recorded.
    let g20 = |v: u8| {
        let mut w = [0u8; 9];
        w[4..6].copy_from_slice(&20u16.to_le_bytes());
        w[6..8].copy_from_slice(&20u16.to_le_bytes());
        w[8] = v;
        assert_eq!(unsafe { pmc_wrpmcrng(h, 9, w.as_mut_ptr().cast()) }, EW_OK);
    };
    let count = || {
        let mut n = 0u16;
        assert_eq!(unsafe { cnc_rdophisno(h, &mut n) }, EW_OK);
        n
    };
    let n0 = count();
    g20(0x80);
    assert_eq!(count(), n0, "G20 is not in the table");

    // Two entries: G20 bits 0..3 in entry 7, and entry 1 (G43) cleared
    // (PMC 0).
    let mut w = sig3_cc();
    w.datano = 0;
    w.r#type = 2;
    w.data[0] = IODBSIG3_DATA {
        ent_no: 7,
        pmc_no: 1,
        sig_no: 20,
        sig_name: 0,
        mask_pat: 0x0f,
    };
    w.data[1] = IODBSIG3_DATA {
        ent_no: 1,
        pmc_no: 0,
        ..Default::default()
    };
    assert_eq!(unsafe { cnc_wrhissgnl3(h, &mut w) }, EW_OK);
    let b = read();
    let e = |b: &IODBSIG3, i: usize| {
        let d = b.data[i];
        (d.ent_no, d.pmc_no, d.sig_no, d.sig_name, d.mask_pat as u8)
    };
    assert_eq!(e(&b, 6), (7, 1, 20, 0, 0x0f));
    assert_eq!(e(&b, 0), (1, 0, 0, 0, 0));
    assert_eq!(e(&b, 1), e(&before, 1), "the others stay");
    assert_eq!(e(&b, 4), e(&before, 4));
    assert_eq!(e(&b, 5), (6, 0, 0, 0, 0));

    // Now G20 is recorded, when a bit its mask selects changes.
    let n1 = count();
    g20(0x40);
    assert_eq!(count(), n1, "bit 6 is not in the mask");
    g20(0x41);
    assert!(count() > n1, "bit 0 is");

    // Refused by the CNC (entry 61; address type 4), the whole write:
    // the good first entry is not applied either.
    for bad in [
        IODBSIG3_DATA {
            ent_no: 61,
            pmc_no: 1,
            sig_no: 9,
            ..Default::default()
        },
        IODBSIG3_DATA {
            ent_no: 7,
            pmc_no: 1,
            sig_no: 9,
            sig_name: 4,
            mask_pat: 1,
        },
    ] {
        w.data[0] = IODBSIG3_DATA {
            ent_no: 2,
            pmc_no: 1,
            sig_no: 100,
            sig_name: 0,
            mask_pat: 1,
        };
        w.data[1] = bad;
        assert_eq!(unsafe { cnc_wrhissgnl3(h, &mut w) }, EW_DATA);
        assert_eq!(read(), b, "a refused write changes nothing");
    }
    // type outside 0..=60: EW_LENGTH before any traffic; NULL: EW_DATA.
    for t in [-1, 61] {
        w.r#type = t;
        assert_eq!(unsafe { cnc_wrhissgnl3(h, &mut w) }, EW_LENGTH);
    }
    assert_eq!(unsafe { cnc_wrhissgnl3(h, std::ptr::null_mut()) }, EW_DATA);
    // type 0: nothing sent to change.
    w.r#type = 0;
    assert_eq!(unsafe { cnc_wrhissgnl3(h, &mut w) }, EW_OK);
    assert_eq!(read(), b);
    sim::free(h);
}
