//! Functions FANUC's header declares but none of its Ethernet libraries
//! implements: exported so that programs link, answering EW_VERSION (-7)
//! without traffic and writing nothing (cnc_allclibhndl: EW_MMCSYS, -3).
//! The CNC is a replay of a connection recorded from FANUC's library, which
//! fails the test on any frame the calls would send.

use crate::common;

use common::{Replay, find_case, load_file};
use fwlib32::ew::*;
use fwlib32::*;
use std::ffi::CString;
use std::os::raw::{c_short, c_ushort};

/// One call on a handle.
type Call<'a> = Box<dyn Fn(c_ushort) -> c_short + 'a>;

#[test]
fn declared_but_not_on_ethernet() {
    let file = load_file(
        &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/vectors/cnc_statinfo.json"),
    );
    let case = find_case(
        std::slice::from_ref(&file),
        "cnc_statinfo",
        "statinfo_v3_base",
    );
    let frames = |word: &str| {
        case.calls
            .iter()
            .find(|c| c.word() == word)
            .unwrap()
            .frames
            .clone()
    };
    let mut cnc = Replay::start();
    let port = cnc.port;
    let host = CString::new("127.0.0.1").unwrap();
    let mut h: c_ushort = 0;
    let (r, m) = cnc.step("alloc", frames("alloc"), || unsafe {
        cnc_allclibhndl3(host.as_ptr(), port, 10, &mut h)
    });
    assert_eq!((r, m), (EW_OK, vec![]));

    let mut buf = [0xCCu8; 512];
    let b = buf.as_mut_ptr();
    let np: *mut c_short = Box::into_raw(Box::new(4));
    let calls: [(&str, Call<'_>); 7] = [
        (
            "cnc_rdexecpt",
            Box::new(|h| cnc_rdexecpt(h, b.cast(), b.wrapping_add(8).cast())),
        ),
        (
            "cnc_rdprogline",
            Box::new(|h| {
                let at = |n| b.wrapping_add(n).cast();
                cnc_rdprogline(h, 1, 1, b.cast(), at(300), at(308))
            }),
        ),
        ("cnc_svdtstartrd", Box::new(|h| cnc_svdtstartrd(h, 1))),
        (
            "cnc_svdtrddata",
            Box::new(|h| {
                cnc_svdtrddata(
                    h,
                    b.cast(),
                    b.wrapping_add(4).cast(),
                    b.wrapping_add(8).cast(),
                )
            }),
        ),
        ("cnc_svdtendrd", Box::new(|h| cnc_svdtendrd(h))),
        (
            "cnc_rdspdlnamem",
            Box::new(|h| cnc_rdspdlnamem(h, np, b.cast())),
        ),
        (
            "cnc_rdalmmsg3",
            Box::new(|h| cnc_rdalmmsg3(h, -1, np, b.cast())),
        ),
    ];
    for (name, f) in &calls {
        let (r, m) = cnc.step(name, vec![], || f(h));
        assert_eq!(r, EW_VERSION, "{name}");
        assert!(m.is_empty(), "{name} sent something: {m:?}");
        assert_eq!(f(0x7fff), EW_HANDLE, "{name} with a never-issued handle");
    }
    assert!(buf.iter().all(|x| *x == 0xCC), "nothing is written");
    assert_eq!(unsafe { *np }, 4);
    drop(unsafe { Box::from_raw(np) });

    let mut h2: c_ushort = 0x1234;
    assert_eq!(unsafe { cnc_allclibhndl(&mut h2) }, EW_MMCSYS);
    assert_eq!(h2, 0x1234);

    let (r, m) = cnc.step("free", frames("free"), || cnc_freelibhndl(h));
    assert_eq!((r, m), (EW_OK, vec![]));
    assert!(cnc.finish().is_empty());
}
