//! Periodic maintenance through the C ABI against the simulator: the
//! profile's item names and items, an item's remaining life counting down
//! with the operating time as the machine runs, writes read back, refused
//! writes changing nothing, local checks.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::Profile;
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_char, c_short, c_ushort};
use std::time::Duration;

fn text(b: &[c_char]) -> String {
    b.iter()
        .take_while(|&&c| c != 0)
        .map(|&c| c as u8 as char)
        .collect()
}

fn name(s: &str) -> [c_char; 62] {
    let mut n = [0 as c_char; 62];
    for (d, c) in n.iter_mut().zip(s.bytes()) {
        *d = c as c_char;
    }
    n
}

type ReadNames =
    unsafe extern "C" fn(c_ushort, c_short, *mut c_short, *mut [c_char; 62]) -> c_short;

/// A names read into `room` slots (one more to see overruns): (code,
/// *data_num, names).
fn names(
    f: ReadNames,
    h: c_ushort,
    start: c_short,
    num: c_short,
    room: usize,
) -> (c_short, c_short, Vec<String>) {
    let mut b = vec![[0x55 as c_char; 62]; room + 1];
    let mut n = num;
    let r = unsafe { f(h, start, &mut n, b.as_mut_ptr()) };
    let k = if r == EW_OK { n as usize } else { 0 };
    assert!(
        b[k..].iter().all(|x| x.iter().all(|&c| c == 0x55)),
        "nothing past the names"
    );
    (r, n, b[..k].iter().map(|x| text(x)).collect())
}

fn items(h: c_ushort, start: c_short, num: c_short) -> (c_short, c_short, Vec<IODBPMAINTE>) {
    let mut b = vec![IODBPMAINTE::default(); num.max(0) as usize + 1];
    let mut n = num;
    let r = unsafe { cnc_rdpm_item(h, start, &mut n, b.as_mut_ptr()) };
    let k = if r == EW_OK { n as usize } else { 0 };
    b.truncate(k);
    (r, n, b)
}

/// cnc_rdtimer `kind` in whole minutes.
fn minutes(h: c_ushort, kind: c_short) -> i32 {
    let mut t = IODBTIME::default();
    assert_eq!(unsafe { cnc_rdtimer(h, kind, &mut t) }, EW_OK);
    t.minute
}

#[test]
fn maintenance_names_are_the_profiles_and_written_back() {
    let p = Profile::default();
    let m = &p.maintenance;
    let (_s, h) = sim::start_alloc(p.clone());
    assert_eq!(
        names(cnc_rdpm_cncitem, h, 1, 4, 4),
        (EW_OK, 4, m.cnc_items[..4].to_vec())
    );
    let last = m.cnc_items.len() as c_short;
    assert_eq!(
        names(cnc_rdpm_cncitem, h, last, 4, 4),
        (EW_OK, 1, vec![m.cnc_items[last as usize - 1].clone()])
    );
    assert_eq!(names(cnc_rdpm_cncitem, h, last + 1, 4, 4).0, EW_NUMBER);
    let mut mcn = m.machine_items.clone();
    mcn.push(String::new());
    assert_eq!(names(cnc_rdpm_mcnitem, h, 1, 4, 4), (EW_OK, 4, mcn.clone()));
    // Written, then read back; slots past the written ones unchanged.
    let mut new = [name("SPINDLE GREASE"), name("TOOL CLAMP")];
    assert_eq!(
        unsafe { cnc_wrpm_mcnitem(h, 3, 2, new.as_mut_ptr()) },
        EW_OK
    );
    let got = names(cnc_rdpm_mcnitem, h, 1, 5, 5);
    assert_eq!(
        got.2,
        [&mcn[..2], &["SPINDLE GREASE".into(), "TOOL CLAMP".into()]]
            .concat()
            .into_iter()
            .chain([String::new()])
            .collect::<Vec<_>>()
    );
    // Refused: past the 20 slots; nothing changed.
    assert_eq!(
        unsafe { cnc_wrpm_mcnitem(h, 20, 2, new.as_mut_ptr()) },
        EW_NUMBER
    );
    assert_eq!(
        names(cnc_rdpm_mcnitem, h, 20, 1, 1),
        (EW_OK, 1, vec![String::new()])
    );
    // Local checks.
    assert_eq!(names(cnc_rdpm_cncitem, h, 1, 0, 1), (EW_LENGTH, 0, vec![]));
    assert_eq!(
        names(cnc_rdpm_mcnitem, h, 1, -1, 1),
        (EW_LENGTH, -1, vec![])
    );
    assert_eq!(
        unsafe { cnc_wrpm_mcnitem(h, 1, 0, new.as_mut_ptr()) },
        EW_LENGTH
    );
    sim::free(h);
}

#[test]
fn maintenance_items_count_down_with_operating_time() {
    let p = Profile::default();
    let m = &p.maintenance;
    let s = sim::start(p.clone());
    s.set_elapsed(Duration::ZERO);
    let h = sim::alloc(&s);
    let (r, n, it) = items(h, 1, 4);
    assert_eq!((r, n), (EW_OK, 4));
    for (got, want) in it.iter().zip(&m.items) {
        assert_eq!(
            (text(&got.name), got.r#type, got.total, got.remain, got.stat),
            (want.name.clone(), want.r#type, want.total, want.remain, 0)
        );
    }
    assert_eq!(
        (text(&it[3].name), it[3].r#type),
        (String::new(), 0),
        "an empty slot"
    );
    // The machine runs for 50 minutes: the operating-time item (1) and the
    // power-on item (2) count down by those counters.
    let (op0, on0) = (minutes(h, 1), minutes(h, 0));
    s.set_elapsed(Duration::from_secs(50 * 60));
    let (op, on) = (minutes(h, 1) - op0, minutes(h, 0) - on0);
    assert_eq!(on, 50);
    assert!(op > 0, "the machine ran");
    let it = items(h, 1, 2).2;
    assert_eq!(it[0].remain, m.items[0].remain - op);
    assert_eq!(it[1].remain, m.items[1].remain - on);
    // A new life for item 1 (reset): remain = total from now on.
    let mut new = [IODBPMAINTE {
        name: name("LUBRICATION OIL 2"),
        r#type: 1,
        total: 30,
        remain: 0,
        stat: 0,
    }];
    assert_eq!(
        unsafe { cnc_wrpm_item(h, 1, 1, 1, new.as_mut_ptr()) },
        EW_OK
    );
    let it = items(h, 1, 1).2;
    assert_eq!(
        (
            text(&it[0].name),
            it[0].r#type,
            it[0].total,
            it[0].remain,
            it[0].stat
        ),
        ("LUBRICATION OIL 2".into(), 1, 30, 30, 0)
    );
    s.set_elapsed(Duration::from_secs(70 * 60));
    assert_eq!(items(h, 1, 1).2[0].remain, 10);
    s.set_elapsed(Duration::from_secs(90 * 60));
    let it = items(h, 1, 1).2;
    assert_eq!((it[0].remain, it[0].stat), (0, 1), "life used up");
    // Without reset the remain sent is kept.
    new[0].remain = 25;
    assert_eq!(
        unsafe { cnc_wrpm_item(h, 0, 4, 1, new.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(items(h, 4, 1).2[0].remain, 25);
    // Refused writes change nothing: a remain above the total, a type the
    // CNC lacks, past the ten slots.
    let before = items(h, 1, 10);
    new[0].remain = 31;
    assert_eq!(
        unsafe { cnc_wrpm_item(h, 0, 1, 1, new.as_mut_ptr()) },
        EW_DATA
    );
    new[0].remain = 5;
    new[0].r#type = 9;
    assert_eq!(
        unsafe { cnc_wrpm_item(h, 0, 1, 1, new.as_mut_ptr()) },
        EW_DATA
    );
    new[0].r#type = 0;
    assert_eq!(
        unsafe { cnc_wrpm_item(h, 0, 11, 1, new.as_mut_ptr()) },
        EW_NUMBER
    );
    assert_eq!(items(h, 1, 10), before);
    // Local checks.
    assert_eq!(items(h, 1, 0).0, EW_LENGTH);
    assert_eq!(
        unsafe { cnc_wrpm_item(h, 0, 1, 0, new.as_mut_ptr()) },
        EW_LENGTH
    );
    sim::free(h);
}
