//! PMC areas through the C ABI against the simulator: bytes, words and
//! longs written and read back (the same addresses read as bytes and as
//! words agree: big-endian on the wire), read-only areas, ranges, local
//! checks and pmc_getdtailerr.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::{Profile, Simulator};
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_short, c_ushort};

const G: c_short = 0;
const F: c_short = 1;
const X: c_short = 3;
const R: c_short = 5;
const D: c_short = 9;
const BYTE: c_short = 0;
const WORD: c_short = 1;
const LONG: c_short = 2;

fn start() -> Simulator {
    sim::start(Profile::default())
}

/// pmc_rdpmcrng into a 0xCC-filled buffer of `8 + room` bytes (plus slack
/// to see overruns); returns (code, buffer).
fn read(h: c_ushort, a: c_short, t: c_short, s: u16, e: u16, room: usize) -> (c_short, Vec<u8>) {
    let mut b = vec![0xCCu8; 8 + room + 64];
    let r = unsafe { pmc_rdpmcrng(h, a, t, s, e, (8 + room) as c_ushort, b.as_mut_ptr().cast()) };
    (r, b)
}

/// The data bytes of a successful read of `s..=e`.
fn data(h: c_ushort, a: c_short, t: c_short, s: u16, e: u16) -> Vec<u8> {
    let n = usize::from(e - s + 1);
    let (r, b) = read(h, a, t, s, e, n);
    assert_eq!(r, EW_OK, "read {a}/{t} {s}..{e}");
    assert_eq!(&b[0..8], header(a, t, s, e).as_slice());
    assert!(b[8 + n..].iter().all(|x| *x == 0xCC), "overrun");
    b[8..8 + n].to_vec()
}

fn header(a: c_short, t: c_short, s: u16, e: u16) -> Vec<u8> {
    [
        a.to_le_bytes(),
        t.to_le_bytes(),
        s.to_le_bytes(),
        e.to_le_bytes(),
    ]
    .concat()
}

/// pmc_wrpmcrng with `data` in host order.
fn write(h: c_ushort, a: c_short, t: c_short, s: u16, e: u16, data: &[u8]) -> c_short {
    let mut b = header(a, t, s, e);
    b.extend_from_slice(data);
    unsafe { pmc_wrpmcrng(h, b.len() as c_ushort, b.as_mut_ptr().cast()) }
}

#[test]
fn default_profile_signals() {
    let s = start();
    let h = sim::alloc(&s);
    // As the MTConnect adapter reads them: one byte, length 8 + 1.
    let mut buf = IODBPMC::default();
    assert_eq!(
        unsafe { pmc_rdpmcrng(h, G, BYTE, 12, 12, 9, &mut buf) },
        EW_OK
    );
    assert_eq!(unsafe { buf.u.cdata[0] } as u8, 0x9b);
    assert_eq!(
        (buf.type_a, buf.type_d, buf.datano_s, buf.datano_e),
        (G, BYTE, 12, 12)
    );
    assert_eq!(data(h, G, BYTE, 30, 30), [100]);
    assert_eq!(data(h, R, WORD, 500, 501), 42u16.to_le_bytes());
    assert_eq!(data(h, D, LONG, 0, 3), 1000i32.to_le_bytes());
    assert_eq!(data(h, F, BYTE, 0, 0), [0x20]);
    sim::free(h);
}

#[test]
fn bytes_words_and_longs_agree() {
    let s = start();
    let h = sim::alloc(&s);
    // Bytes in, words and a long out.
    assert_eq!(
        write(h, R, BYTE, 100, 103, &[0x01, 0x02, 0x03, 0x84]),
        EW_OK
    );
    assert_eq!(data(h, R, BYTE, 100, 103), [0x01, 0x02, 0x03, 0x84]);
    assert_eq!(
        data(h, R, WORD, 100, 103),
        [0x0102u16.to_le_bytes(), 0x0384u16.to_le_bytes()].concat()
    );
    assert_eq!(data(h, R, LONG, 100, 103), 0x0102_0384u32.to_le_bytes());

    // Words in (host order), bytes out high byte first.
    let words = [600i16, -2];
    let host: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    assert_eq!(write(h, D, WORD, 2204, 2207, &host), EW_OK);
    assert_eq!(data(h, D, BYTE, 2204, 2207), [0x02, 0x58, 0xff, 0xfe]);
    assert_eq!(data(h, D, WORD, 2204, 2207), host);

    // Longs, negative.
    let longs = [70000i32, -1];
    let host: Vec<u8> = longs.iter().flat_map(|w| w.to_le_bytes()).collect();
    assert_eq!(write(h, D, LONG, 1870, 1877, &host), EW_OK);
    assert_eq!(data(h, D, LONG, 1870, 1877), host);
    assert_eq!(
        data(h, D, BYTE, 1870, 1873),
        70000i32.to_be_bytes().to_vec()
    );
    sim::free(h);
}

#[test]
fn read_only_areas_and_ranges() {
    let s = start();
    let h = sim::alloc(&s);
    // X and F are the machine's: EW_PROT, nothing changes.
    let x0 = data(h, X, BYTE, 0, 0);
    assert_eq!(write(h, X, BYTE, 0, 0, &[0x55]), EW_PROT);
    assert_eq!(data(h, X, BYTE, 0, 0), x0);
    assert_eq!(write(h, F, WORD, 0, 1, &[1, 2]), EW_PROT);
    assert_eq!(data(h, F, BYTE, 0, 0), [0x20]);

    // Outside the area (R0-R7999, K0-K99/K900-K999): EW_RANGE (3), nothing written.
    let (r, b) = read(h, R, BYTE, 7999, 8000, 2);
    assert_eq!(r, EW_RANGE);
    assert!(b.iter().all(|x| *x == 0xCC));
    assert_eq!(write(h, R, BYTE, 7999, 8000, &[1, 2]), EW_RANGE);
    assert_eq!(data(h, R, BYTE, 7999, 7999), [0]);
    assert_eq!(read(h, 7, BYTE, 100, 100, 1).0, EW_RANGE);
    assert_eq!(read(h, 7, BYTE, 900, 900, 1).0, EW_OK);
    // A word range of an odd number of bytes: EW_RANGE.
    assert_eq!(read(h, R, WORD, 0, 2, 3).0, EW_RANGE);
    // Unknown area or data type: EW_TYPE (4).
    assert_eq!(read(h, 99, BYTE, 0, 0, 1).0, EW_TYPE);
    assert_eq!(read(h, R, 3, 0, 3, 4).0, EW_TYPE);
    assert_eq!(write(h, R, 3, 0, 3, &[0; 4]), EW_TYPE);
    sim::free(h);
}

#[test]
fn buffers_are_bounded_by_length() {
    let s = start();
    let h = sim::alloc(&s);
    assert_eq!(
        write(h, R, BYTE, 0, 9, &[1, 2, 3, 4, 5, 6, 7, 8, 9, 10]),
        EW_OK
    );
    // Ten bytes asked for, room for four: EW_LENGTH before any traffic
    // (as FANUC's library), nothing written.
    let (r, b) = read(h, R, BYTE, 0, 9, 4);
    assert_eq!(r, EW_LENGTH);
    assert!(b.iter().all(|x| *x == 0xCC));
    let (r, b) = read(h, R, WORD, 0, 9, 3);
    assert_eq!(r, EW_LENGTH);
    assert!(b.iter().all(|x| *x == 0xCC));
    // Room for the range: the range written, nothing more.
    let (r, b) = read(h, R, BYTE, 0, 3, 4);
    assert_eq!(r, EW_OK);
    assert_eq!(&b[8..12], &[1, 2, 3, 4]);
    assert!(b[12..].iter().all(|x| *x == 0xCC));
    // length below the header: EW_LENGTH before any traffic.
    let mut buf = [0xCCu8; 16];
    assert_eq!(
        unsafe { pmc_rdpmcrng(h, R, BYTE, 0, 0, 7, buf.as_mut_ptr().cast()) },
        EW_LENGTH
    );
    assert!(buf.iter().all(|x| *x == 0xCC));
    // A write whose length does not cover the range: EW_LENGTH, nothing sent.
    let mut w = header(R, BYTE, 0, 3);
    w.extend_from_slice(&[9, 9, 9, 9]);
    assert_eq!(
        unsafe { pmc_wrpmcrng(h, 8 + 3, w.as_mut_ptr().cast()) },
        EW_LENGTH
    );
    assert_eq!(data(h, R, BYTE, 0, 3), [1, 2, 3, 4]);
    sim::free(h);
}

#[test]
fn null_pointers_and_handles() {
    let s = start();
    let h = sim::alloc(&s);
    assert_eq!(
        unsafe { pmc_rdpmcrng(h, R, BYTE, 0, 0, 9, std::ptr::null_mut()) },
        EW_DATA
    );
    assert_eq!(unsafe { pmc_wrpmcrng(h, 9, std::ptr::null_mut()) }, EW_DATA);
    assert_eq!(unsafe { pmc_getdtailerr(h, std::ptr::null_mut()) }, EW_DATA);
    sim::free(h);
    let mut buf = IODBPMC::default();
    assert_eq!(
        unsafe { pmc_rdpmcrng(h, R, BYTE, 0, 0, 9, &mut buf) },
        EW_HANDLE
    );
    let mut e = ODBPMCERR::default();
    assert_eq!(unsafe { pmc_getdtailerr(h, &mut e) }, EW_HANDLE);
}

/// pmc_getdtailerr answers from the handle's PMC detail (FANUC's details
/// for a PMC error are checked by the vector pmc_rdpmcrng/v3_error; the
/// simulator's details are 0/0).
#[test]
fn pmc_getdtailerr_reads_the_pmc_detail() {
    let s = start();
    let h = sim::alloc(&s);
    let mut e = ODBPMCERR {
        err_no: 9,
        err_dtno: 9,
    };
    assert_eq!(unsafe { pmc_getdtailerr(h, &mut e) }, EW_OK);
    assert_eq!((e.err_no, e.err_dtno), (0, 0));
    // A PMC error (3) updates the PMC detail (the simulator's details are 0/0).
    assert_eq!(read(h, R, BYTE, 9000, 9000, 1).0, EW_RANGE);
    assert_eq!(unsafe { pmc_getdtailerr(h, &mut e) }, EW_OK);
    assert_eq!((e.err_no, e.err_dtno), (0, 0));
    sim::free(h);
}

#[test]
fn pmc_info_lists_the_areas() {
    let s = start();
    let h = sim::alloc(&s);
    let mut i = ODBPMCINF::default();
    assert_eq!(unsafe { pmc_rdpmcinfo(h, 0, &mut i) }, EW_OK);
    let areas: Vec<(u8, u16, u16)> = i.info[..i.datano as usize]
        .iter()
        .map(|a| (a.pmc_adr as u8, a.top_num, a.last_num))
        .collect();
    assert!(areas.contains(&(b'G', 0, 767)), "{areas:?}");
    assert!(areas.contains(&(b'R', 0, 7999)));
    assert!(areas.contains(&(b'K', 900, 999)));
    assert_eq!(
        unsafe { pmc_rdpmcinfo(h, 0, std::ptr::null_mut()) },
        EW_DATA
    );
    sim::free(h);
}

/// datano is the reply's count, which (the simulator's count always fitting)
/// equals the records written: those before it are written, the one after
/// it keeps the caller's bytes (FANUC's library writes the count too; a
/// count larger than the records written is capped, see docs/protocol/pmc.md).
#[test]
fn pmc_info_datano_is_the_count_of_records_written() {
    let s = start();
    let h = sim::alloc(&s);
    let mut b = vec![0xCCu8; std::mem::size_of::<ODBPMCINF>()];
    assert_eq!(unsafe { pmc_rdpmcinfo(h, 0, b.as_mut_ptr().cast()) }, EW_OK);
    let n = i16::from_le_bytes([b[0], b[1]]) as usize;
    assert!((1..64).contains(&n), "datano {n}");
    for i in 0..n {
        let r = &b[2 + 6 * i..8 + 6 * i];
        assert!(r[0].is_ascii_uppercase(), "record {i}: {r:02x?}");
    }
    assert_eq!(&b[2 + 6 * n..], &vec![0xCC; b.len() - 2 - 6 * n][..]);
    sim::free(h);
}

/// The built-in profile has two PMC units: a handle's selection addresses
/// its own later PMC calls (the path word of PMC subpackets), each unit its
/// own memory; other handles keep unit 1.
#[test]
fn pmc_units_are_selected_per_handle() {
    let s = start();
    let h = sim::alloc(&s);
    let other = sim::alloc(&s);
    let mut n = [0i32; 2];
    assert_eq!(
        unsafe { pmc_get_number_of_pmc(h, n.as_mut_ptr().cast()) },
        EW_OK
    );
    assert_eq!(n[0], 2);
    let (mut types, mut count) = ([-1i32; 4], [4i32, -1]);
    assert_eq!(
        unsafe { pmc_get_pmc_unit_types(h, types.as_mut_ptr().cast(), count.as_mut_ptr().cast()) },
        EW_OK
    );
    assert_eq!((count, &types[..3]), ([2, -1], &[1, 2, -1][..]));
    let current = |h| {
        let mut u = [-1i32; 2];
        assert_eq!(
            unsafe { pmc_get_current_pmc_unit(h, u.as_mut_ptr().cast()) },
            EW_OK
        );
        u[0]
    };
    assert_eq!(current(h), 1);

    let d0 = data(h, D, WORD, 100, 101);
    assert_eq!(pmc_select_pmc_unit(h, 2), EW_OK);
    assert_eq!((current(h), current(other)), (2, 1));
    assert_eq!(data(h, D, WORD, 100, 101), [0, 0], "unit 2 starts zeroed");
    assert_eq!(write(h, D, WORD, 100, 101, &0x0a0bu16.to_le_bytes()), EW_OK);
    assert_eq!(data(h, D, WORD, 100, 101), 0x0a0bu16.to_le_bytes());
    assert_eq!(data(other, D, WORD, 100, 101), d0, "unit 1 unchanged");
    // A unit the CNC lacks: refused, the selection stays.
    assert_eq!(pmc_select_pmc_unit(h, 3), EW_NOPMC);
    assert_eq!(current(h), 2);
    assert_eq!(pmc_select_pmc_unit(h, 1), EW_OK);
    assert_eq!(data(h, D, WORD, 100, 101), d0);
    assert_eq!(
        unsafe { pmc_get_current_pmc_unit(h, std::ptr::null_mut()) },
        EW_DATA
    );
}

/// pmc_rdpmctitle: the profile's texts, each member zero-padded past what
/// the CNC sends; NULL is EW_DATA.
#[test]
fn pmc_title_is_the_profiles() {
    let p = Profile::default();
    let (_s, h) = sim::start_alloc(p.clone());
    let mut t = std::mem::MaybeUninit::<ODBPMCTITLE>::uninit();
    unsafe {
        std::ptr::write_bytes(t.as_mut_ptr(), 0xcc, 1);
        assert_eq!(pmc_rdpmctitle(h, t.as_mut_ptr()), EW_OK);
        assert_eq!(pmc_rdpmctitle(h, std::ptr::null_mut()), EW_DATA);
    }
    let t = unsafe { t.assume_init() };
    let text = |m: &[std::os::raw::c_char]| -> String {
        m.iter()
            .take_while(|&&c| c != 0)
            .map(|&c| c as u8 as char)
            .collect()
    };
    let title = &p.pmc.info[0].title;
    assert_eq!(text(&t.mtb), title[0]);
    assert_eq!(text(&t.machine), title[1]);
    assert_eq!(text(&t.prgvers), title[4]);
    assert_eq!(text(&t.remarks), title[9]);
    assert!(t.remarks[32..].iter().all(|&c| c == 0));
    // The second unit has its own title.
    assert_eq!(pmc_select_pmc_unit(h, 2), EW_OK);
    let mut t = std::mem::MaybeUninit::<ODBPMCTITLE>::uninit();
    assert_eq!(unsafe { pmc_rdpmctitle(h, t.as_mut_ptr()) }, EW_OK);
    let t = unsafe { t.assume_init() };
    assert_eq!(text(&t.machine), p.pmc.info[1].title[1]);
    assert_ne!(p.pmc.info[1].title[1], title[1]);
    sim::free(h);
}

/// pmc_rdalmmsg into a 0xCC-filled array of `room` messages: (code,
/// *read_num after, *exist, the texts of the messages written).
fn alarms(
    h: c_ushort,
    s: c_short,
    num: c_short,
    room: usize,
) -> (c_short, c_short, c_short, Vec<String>) {
    let mut buf = vec![0xCCu8; 128 * (room + 1)];
    let (mut n, mut exist) = (num, 0x7777);
    let r = unsafe { pmc_rdalmmsg(h, s, &mut n, &mut exist, buf.as_mut_ptr().cast()) };
    let k = if r == EW_OK { n as usize } else { 0 };
    assert!(
        buf[128 * k..].iter().all(|&b| b == 0xCC),
        "nothing past *read_num"
    );
    let texts = buf[..128 * k]
        .chunks(128)
        .map(|m| String::from_utf8_lossy(m.split(|&b| b == 0).next().unwrap()).into_owned())
        .collect();
    (r, n, exist, texts)
}

/// pmc_rdalmmsg: the profile's messages whose A bits are set; A bits the
/// running machine writes raise and clear alarms; more than one answer
/// holds (11) are read in several exchanges; the second unit has its own;
/// local checks.
#[test]
fn pmc_alarm_messages_follow_the_a_bits() {
    let p = Profile::default();
    let (_s, h) = sim::start_alloc(p.clone());
    let msg = |u: usize, i: usize| p.pmc.info[u].messages[i].clone();
    // The profile: A0 = 0x05, messages 1 and 3.
    assert_eq!(
        alarms(h, 1, 10, 10),
        (EW_OK, 2, 0, vec![msg(0, 0), msg(0, 2)])
    );
    assert_eq!(alarms(h, 1, 1, 1), (EW_OK, 1, 1, vec![msg(0, 0)]));
    assert_eq!(alarms(h, 2, 5, 5), (EW_OK, 1, 0, vec![msg(0, 2)]));
    assert_eq!(alarms(h, 3, 5, 5), (EW_OK, 0, 0, vec![]));
    // The machine raises all fourteen (A0-A1), then clears them.
    assert_eq!(write(h, 4, BYTE, 0, 1, &[0xff, 0x3f]), EW_OK);
    let (r, n, exist, texts) = alarms(h, 1, 20, 20);
    assert_eq!((r, n, exist), (EW_OK, 14, 0));
    assert_eq!(texts, (0..14).map(|i| msg(0, i)).collect::<Vec<_>>());
    assert_eq!(
        alarms(h, 12, 2, 2),
        (EW_OK, 2, 1, vec![msg(0, 11), msg(0, 12)])
    );
    assert_eq!(write(h, 4, BYTE, 0, 1, &[0, 0]), EW_OK);
    assert_eq!(alarms(h, 1, 10, 10), (EW_OK, 0, -1, vec![]));
    // The second unit: its own messages and A bits.
    assert_eq!(pmc_select_pmc_unit(h, 2), EW_OK);
    assert_eq!(alarms(h, 1, 10, 10), (EW_OK, 1, 0, vec![msg(1, 1)]));
    // Local checks: nothing written, *read_num kept.
    assert_eq!(alarms(h, 0, 10, 10), (EW_NUMBER, 10, 0x7777, vec![]));
    assert_eq!(alarms(h, 1, 0, 1), (EW_DATA, 0, 0x7777, vec![]));
    assert_eq!(alarms(h, 1, -1, 1), (EW_DATA, -1, 0x7777, vec![]));
    sim::free(h);
}

fn timers(h: c_ushort, s: c_ushort, e: c_ushort) -> (c_short, Vec<c_short>) {
    let mut t = vec![0x7777 as c_short; usize::from(e.max(s)) - usize::from(s) + 2];
    let r = unsafe { pmc_get_timer_type(h, s, e, t.as_mut_ptr()) };
    assert_eq!(*t.last().unwrap(), 0x7777, "nothing past the range");
    t.pop();
    (r, t)
}

/// pmc_get_timer_type / pmc_set_timer_type: the profile's types, a write
/// read back, a refused write changes nothing, per unit; local checks.
#[test]
fn pmc_timer_types_are_written_and_read_back() {
    let p = Profile::default();
    let (_s, h) = sim::start_alloc(p.clone());
    let types = &p.pmc.info[0].timer_types;
    assert_eq!(timers(h, 1, 4), (EW_OK, types[..4].to_vec()));
    let mut new: [c_short; 2] = [1, 2];
    assert_eq!(
        unsafe { pmc_set_timer_type(h, 2, 3, new.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(timers(h, 1, 4), (EW_OK, vec![types[0], 1, 2, types[3]]));
    // A type the PMC lacks: EW_DATA with the timer's number as detail,
    // nothing changed.
    let mut bad: [c_short; 2] = [3, 9];
    assert_eq!(
        unsafe { pmc_set_timer_type(h, 3, 4, bad.as_mut_ptr()) },
        EW_DATA
    );
    let mut err = ODBPMCERR::default();
    assert_eq!(unsafe { pmc_getdtailerr(h, &mut err) }, EW_OK);
    assert_eq!(err.err_dtno, 4);
    assert_eq!(timers(h, 1, 4), (EW_OK, vec![types[0], 1, 2, types[3]]));
    // The last timer, and one past it (the CNC's EW_NUMBER).
    assert_eq!(timers(h, 250, 250), (EW_OK, vec![0]));
    assert_eq!(timers(h, 250, 251).0, EW_NUMBER);
    // The second unit keeps its own.
    assert_eq!(pmc_select_pmc_unit(h, 2), EW_OK);
    assert_eq!(
        timers(h, 1, 2),
        (EW_OK, p.pmc.info[1].timer_types[..2].to_vec())
    );
    // Local checks, before any traffic.
    assert_eq!(timers(h, 0, 1), (EW_NUMBER, vec![0x7777, 0x7777]));
    assert_eq!(timers(h, 2, 1).0, EW_NUMBER);
    assert_eq!(
        unsafe { pmc_set_timer_type(h, 0, 1, new.as_mut_ptr()) },
        EW_NUMBER
    );
    sim::free(h);
}

/// cnc_rdopnlsgnl: the software operator panel's signals follow the F
/// area (F73 mode, F75 switches, F76 handle / rapid, F77 handle axis, F78
/// feed override, F79-F80 jog override); a PMC write shows at once.
#[test]
fn operator_panel_signals_follow_the_f_area() {
    let p = "[[path]]\n[pmc.area.F]\nwritable = true\n\
             data = { 73 = [0x01, 0x00, 0x3c, 0x12, 0x05, 0x9b, 0x64, 0x00] }\n";
    let s = sim::start(Profile::parse(p).expect("profile"));
    let h = sim::alloc(&s);
    let panel = |h| {
        let mut g = IODBSGNL {
            datano: 77,
            ..IODBSGNL::default()
        };
        assert_eq!(unsafe { cnc_rdopnlsgnl(h, 0x1fff, &mut g) }, EW_OK);
        assert_eq!(
            (g.datano, g.r#type),
            (77, 0x1fff),
            "datano kept, type echoed"
        );
        g
    };
    let g = panel(h);
    assert_eq!(
        (
            g.mode,
            g.hndl_ax,
            g.hndl_mv,
            g.rpd_ovrd,
            g.jog_ovrd,
            g.feed_ovrd
        ),
        (1, 5, 2, 1, 100, 0x9b)
    );
    assert_eq!(
        [
            g.blck_del,
            g.sngl_blck,
            g.machn_lock,
            g.dry_run,
            g.mem_prtct,
            g.feed_hold
        ],
        [1, 1, 1, 1, 0, 0]
    );
    // The ladder turns single block off and feed hold on.
    assert_eq!(write(h, F, BYTE, 75, 75, &[0xb4]), EW_OK);
    let g = panel(h);
    assert_eq!(
        [
            g.blck_del,
            g.sngl_blck,
            g.machn_lock,
            g.dry_run,
            g.mem_prtct,
            g.feed_hold
        ],
        [1, 0, 1, 1, 0, 1]
    );
    sim::free(h);
}
