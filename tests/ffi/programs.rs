//! Programs in memory through the C ABI against the simulator's program
//! store: what the oracle's single calls cannot show, that a change is seen
//! by the next directory read and upload, and that a refusal changes
//! nothing.

use crate::sim;

use fwlib32::ew::*;
use fwlib32::sim::Profile;
use fwlib32::sim::run::StoredProgram;
use fwlib32::types::*;
use fwlib32::*;
use std::os::raw::{c_char, c_long, c_short, c_ulong, c_ushort};

/// The built-in profile with path 1 idle (no program in cycle, none
/// selected) and a protected O0500.
fn idle() -> Profile {
    let mut p = Profile::default();
    p.paths[0].cycle.program = 0;
    p.programs.push(StoredProgram {
        number: 500,
        text: "O0500 (KEEP);\nG04 X1.;\nM30;\n%\n".into(),
        protect: true,
        ..Default::default()
    });
    p
}

/// (number, size, comment) of every program, by cnc_rdprogdir3 type 2.
fn dir(h: c_ushort) -> Vec<(i32, i32, String)> {
    let mut buf = vec![PRGDIR3::default(); 20];
    let (mut top, mut num): (c_long, c_short) = (0, 20);
    assert_eq!(
        unsafe { cnc_rdprogdir3(h, 2, &mut top, &mut num, buf.as_mut_ptr()) },
        EW_OK
    );
    buf[..num as usize]
        .iter()
        .map(|d| {
            let c = d.comment.iter().take_while(|&&b| b != 0).map(|&b| b as u8);
            (d.number, d.length, String::from_utf8(c.collect()).unwrap())
        })
        .collect()
}

fn numbers(h: c_ushort) -> Vec<i32> {
    dir(h).into_iter().map(|d| d.0).collect()
}

/// The uploaded text of program `n`, or the error of its upload.
fn upload(h: c_ushort, n: i32) -> Result<String, c_short> {
    let r = cnc_upstart3(h, 0, n as c_long, n as c_long);
    if r != EW_OK {
        return Err(r);
    }
    let mut all = Vec::new();
    loop {
        let mut buf = vec![0u8; 1024];
        let mut len: c_long = 1024;
        match unsafe { cnc_upload3(h, &mut len, buf.as_mut_ptr().cast()) } {
            EW_OK => all.extend_from_slice(&buf[..len as usize]),
            EW_BUFFER => std::thread::yield_now(),
            EW_RESET => break,
            e => {
                cnc_upend3(h);
                return Err(e);
            }
        }
    }
    assert_eq!(cnc_upend3(h), EW_OK);
    Ok(String::from_utf8(all).unwrap())
}

fn proginfo(h: c_ushort) -> ODBNC_bin {
    let mut o = ODBNC::default();
    assert_eq!(unsafe { cnc_rdproginfo(h, 0, 12, &mut o) }, EW_OK);
    unsafe { o.u.bin }
}

#[test]
fn delete_removes_a_program_and_refusals_change_nothing() {
    let (_s, h) = sim::start_alloc(Profile::default());
    assert_eq!(numbers(h), vec![100, 1234]);
    assert_eq!(cnc_delete(h, 100), EW_OK);
    assert_eq!(numbers(h), vec![1234]);
    assert_eq!(upload(h, 100), Err(EW_DATA));
    assert_eq!(cnc_delete(h, 100), EW_DATA, "gone");
    // O1234 is executing (and the main program).
    assert_eq!(cnc_delete(h, 1234), EW_BUSY);
    assert_eq!(cnc_renameprog(h, 1234, 1), EW_BUSY);
    assert_eq!(cnc_search(h, 1234), EW_BUSY, "the path is running");
    assert_eq!(numbers(h), vec![1234]);
    assert!(upload(h, 1234).unwrap().contains("POCKET DEMO"));
}

#[test]
fn a_protected_program_stays() {
    let (_s, h) = sim::start_alloc(idle());
    let before = dir(h);
    assert_eq!(cnc_delete(h, 500), EW_PROT);
    assert_eq!(cnc_renameprog(h, 500, 501), EW_PROT);
    assert_eq!(cnc_delall(h), EW_OK);
    assert_eq!(numbers(h), vec![500], "delall leaves the protected program");
    assert_eq!(dir(h)[0], before[1]);
    assert!(upload(h, 500).unwrap().contains("O0500"));
}

#[test]
fn rename_and_copy_show_in_directory_and_upload() {
    let (_s, h) = sim::start_alloc(idle());
    assert_eq!(cnc_renameprog(h, 100, 200), EW_OK);
    assert_eq!(numbers(h), vec![200, 500, 1234]);
    assert_eq!(upload(h, 100), Err(EW_DATA));
    let text = upload(h, 200).unwrap();
    assert!(text.starts_with("%\nO0200 (WARM UP)\n"), "{text}");
    assert_eq!(cnc_renameprog(h, 200, 1234), EW_DATA, "number in use");
    assert_eq!(cnc_renameprog(h, 7, 8), EW_DATA, "no such program");

    assert_eq!(cnc_copyprog(h, 200, 300), EW_OK);
    assert_eq!(upload(h, 300).unwrap(), text.replace("O0200", "O0300"));
    assert_eq!(cnc_copyprog(h, 200, 300), EW_DATA, "number in use");
    assert_eq!(cnc_copyprog(h, 7, 301), EW_DATA, "no such program");
    assert_eq!(numbers(h), vec![200, 300, 500, 1234]);

    let mut d2 = vec![PRGDIR2::default(); 8];
    let (mut top, mut num): (c_short, c_short) = (250, 8);
    assert_eq!(
        unsafe { cnc_rdprogdir2(h, 2, &mut top, &mut num, d2.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!((top, num), (300, 3));
    assert_eq!(d2[0].length, dir(h)[1].1, "cnc_rdprogdir3's size");
}

#[test]
fn search_selects_the_main_program() {
    let (_s, h) = sim::start_alloc(idle());
    let prgnum = || {
        let mut p = ODBPRO::default();
        assert_eq!(unsafe { cnc_rdprgnum(h, &mut p) }, EW_OK);
        (p.data, p.mdata)
    };
    assert_eq!(prgnum(), (0, 0));
    assert_eq!(cnc_search(h, 7), EW_DATA);
    assert_eq!(cnc_search(h, 100), EW_OK);
    assert_eq!(prgnum(), (100, 100));
    let mut e = ODBEXEPRG::default();
    assert_eq!(unsafe { cnc_exeprgname(h, &mut e) }, EW_OK);
    assert_eq!(
        (e.o_num, e.name[..5].to_vec()),
        (100, b"O0100".map(|b| b as c_char).to_vec())
    );
    assert_eq!(cnc_delete(h, 100), EW_BUSY, "the main program");
    assert_eq!(cnc_delall(h), EW_OK);
    assert_eq!(numbers(h), vec![100, 500]);
}

#[test]
fn memory_information_follows_the_store() {
    let mut p = idle();
    let used: usize = p.programs.iter().map(|x| x.text.len()).sum();
    p.paths[0].memory.bytes = Some(used + 10);
    let (_s, h) = sim::start_alloc(p);
    let i = proginfo(h);
    assert_eq!((i.reg_prg, i.unreg_prg), (3, 397));
    assert_eq!((i.used_mem as usize, i.unused_mem), (used, 10));
    // Type 1: the same numbers as text.
    let mut o = ODBNC::default();
    assert_eq!(unsafe { cnc_rdproginfo(h, 1, 31, &mut o) }, EW_OK);
    let asc: Vec<u8> = unsafe { o.u.asc }.iter().map(|&b| b as u8).collect();
    let want = format!("%\n3\n397\n{used}\n10\n%\0");
    assert_eq!(&asc[..want.len()], want.as_bytes());
    // A copy that does not fit changes nothing.
    assert_eq!(cnc_copyprog(h, 100, 101), EW_OVRFLOW);
    assert_eq!(numbers(h), vec![100, 500, 1234]);
    assert_eq!(cnc_delete(h, 100), EW_OK);
    let i = proginfo(h);
    assert_eq!((i.reg_prg, i.unreg_prg), (2, 398));
}

#[test]
fn the_mdi_program_and_pointer_round_trip() {
    let (_s, h) = sim::start_alloc(idle());
    let mut text = *b"G91G28Z0;\nM30;\n%";
    let n = text.len() as c_short;
    assert_eq!(
        unsafe { cnc_wrmdiprog(h, n, text.as_mut_ptr().cast()) },
        EW_OK
    );
    let mut buf = [0 as c_char; 64];
    let mut len: c_short = 64;
    assert_eq!(
        unsafe { cnc_rdmdiprog(h, &mut len, buf.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(len, n);
    assert_eq!(
        buf[..len as usize]
            .iter()
            .map(|&b| b as u8)
            .collect::<Vec<_>>(),
        text
    );
    assert_eq!(cnc_wrmdipntr(h, 5), EW_OK);
    let mut p = ODBMDIP::default();
    assert_eq!(unsafe { cnc_rdmdipntr(h, &mut p) }, EW_OK);
    assert_eq!((p.mdipntr, p.crntpntr), (5, 5));
}

fn cs(s: &str) -> std::ffi::CString {
    std::ffi::CString::new(s).unwrap()
}

/// A one-name folder function on `name`.
fn on(
    f: unsafe extern "C" fn(c_ushort, *mut c_char) -> c_short,
    h: c_ushort,
    name: &str,
) -> c_short {
    unsafe { f(h, cs(name).as_ptr().cast_mut()) }
}

type Two = unsafe extern "C" fn(c_ushort, *mut c_char, *mut c_char) -> c_short;

fn two(f: Two, h: c_ushort, a: &str, b: &str) -> c_short {
    unsafe { f(h, cs(a).as_ptr().cast_mut(), cs(b).as_ptr().cast_mut()) }
}

fn subdirn(h: c_ushort, dir: &str) -> (c_short, c_short) {
    let mut n = ODBPDFNFIL::default();
    let r = unsafe { cnc_rdpdf_subdirn(h, cs(dir).as_ptr().cast_mut(), &mut n) };
    assert_eq!(r, EW_OK, "{dir}");
    (n.dir_num, n.file_num)
}

fn name256(f: impl FnOnce(*mut c_char) -> c_short) -> String {
    let mut b = [0 as c_char; 256];
    assert_eq!(f(b.as_mut_ptr()), EW_OK);
    let b: Vec<u8> = b
        .iter()
        .take_while(|&&c| c != 0)
        .map(|&c| c as u8)
        .collect();
    String::from_utf8(b).unwrap()
}

const P1: &str = "//CNC_MEM/USER/PATH1/";

#[test]
fn folders_hold_the_store() {
    let (_s, h) = sim::start_alloc(idle());
    let mut drv = ODBPDFDRV::default();
    assert_eq!(unsafe { cnc_rdpdf_drive(h, &mut drv) }, EW_OK);
    assert_eq!(drv.max_num, 1);
    assert_eq!(subdirn(h, "//CNC_MEM/USER/"), (2, 0), "LIBRARY and PATH1");
    assert_eq!(subdirn(h, P1), (0, 3));
    assert_eq!(on(cnc_pdf_add, h, "//CNC_MEM/USER/JOBS/"), EW_OK);
    assert_eq!(
        on(cnc_pdf_add, h, "//CNC_MEM/USER/JOBS/"),
        EW_DATA,
        "exists"
    );
    assert_eq!(
        on(cnc_pdf_add, h, "//CNC_MEM/NONE/X/"),
        EW_DATA,
        "no parent"
    );
    assert_eq!(subdirn(h, "//CNC_MEM/USER/"), (3, 0));
    assert_eq!(on(cnc_pdf_del, h, P1), EW_DATA, "the CNC's own folder");
    assert_eq!(on(cnc_pdf_del, h, "//CNC_MEM/USER/JOBS/"), EW_OK);
    // Programs: the path's store.
    assert_eq!(on(cnc_pdf_add, h, &format!("{P1}O0042")), EW_OK);
    assert_eq!(numbers(h), vec![42, 100, 500, 1234]);
    assert_eq!(on(cnc_pdf_del, h, &format!("{P1}O0500")), EW_PROT);
    assert_eq!(on(cnc_pdf_del, h, &format!("{P1}O0042")), EW_OK);
    assert_eq!(
        two(cnc_pdf_rename, h, &format!("{P1}O0100"), "O0200"),
        EW_OK
    );
    assert_eq!(
        two(cnc_pdf_copy, h, &format!("{P1}O0200"), P1),
        EW_DATA,
        "same number"
    );
    assert_eq!(
        two(
            cnc_pdf_copy,
            h,
            &format!("{P1}O0200"),
            &format!("{P1}O0300")
        ),
        EW_OK
    );
    assert_eq!(
        two(
            cnc_pdf_move,
            h,
            &format!("{P1}O0300"),
            &format!("{P1}O0400")
        ),
        EW_OK
    );
    assert_eq!(numbers(h), vec![200, 400, 500, 1234]);
    assert!(upload(h, 400).unwrap().starts_with("%\nO0400 (WARM UP)"));
    // Current folder and main program; a bare name is in the current folder.
    let cur = |k: c_short| name256(|b| unsafe { cnc_rdpdf_curdir(h, k, b) });
    assert_eq!(cur(1), P1);
    assert_eq!(on(cnc_pdf_slctmain, h, "O0400"), EW_OK);
    assert_eq!(
        name256(|b| unsafe { cnc_pdf_rdmain(h, b) }),
        format!("{P1}O0400")
    );
    let dir = cs("//CNC_MEM/USER/LIBRARY/");
    assert_eq!(
        unsafe { cnc_wrpdf_curdir(h, 2, dir.as_ptr().cast_mut()) },
        EW_OK
    );
    assert_eq!(
        (cur(1), cur(2)),
        (P1.to_string(), "//CNC_MEM/USER/LIBRARY/".to_string())
    );
    assert_eq!(
        unsafe { cnc_rdpdf_curdir(h, 3, [0 as c_char; 256].as_mut_ptr()) },
        EW_ATTRIB
    );
}

/// Lines `from..` (`lines` of them) of program `name`, by cnc_rdpdf_line.
fn read_lines(h: c_ushort, name: &str, from: u32, lines: u32) -> String {
    let mut buf = [0 as c_char; 512];
    let (mut ll, mut dl): (c_ulong, c_ulong) = (lines as c_ulong, 512);
    let p = cs(name);
    let r = unsafe {
        cnc_rdpdf_line(
            h,
            p.as_ptr().cast_mut(),
            from as c_ulong,
            buf.as_mut_ptr(),
            &mut ll,
            &mut dl,
        )
    };
    assert_eq!(r, EW_OK);
    buf[..dl as usize]
        .iter()
        .map(|&c| c as u8 as char)
        .collect()
}

#[test]
fn lines_of_a_program_are_edited_in_place() {
    let (_s, h) = sim::start_alloc(idle());
    let o100 = format!("{P1}O0100");
    assert_eq!(
        read_lines(h, &o100, 2, 2),
        "N10 G91 G28 Z0.;\nN20 M03 S1000;\n"
    );
    let mut add = *b"N15 G04 X1.;\n";
    let p = cs(&o100);
    let r = unsafe {
        cnc_wrpdf_line(
            h,
            p.as_ptr().cast_mut(),
            2,
            add.as_mut_ptr().cast(),
            add.len() as c_ulong,
        )
    };
    assert_eq!(r, EW_OK);
    assert_eq!(
        read_lines(h, &o100, 2, 3),
        "N10 G91 G28 Z0.;\nN15 G04 X1.;\nN20 M03 S1000;\n"
    );
    assert_eq!(
        unsafe { cnc_pdf_delline(h, p.as_ptr().cast_mut(), 3, 1) },
        EW_OK
    );
    assert!(
        upload(h, 100).unwrap().contains("Z0.\nN20 M03"),
        "the upload sees the edit"
    );
    let keep = cs(&format!("{P1}O0500"));
    assert_eq!(
        unsafe { cnc_pdf_delline(h, keep.as_ptr().cast_mut(), 1, 1) },
        EW_PROT
    );
    // Execution pointer on a program, then delete all (the protected one stays).
    let mut blk: c_long = 3;
    assert_eq!(
        unsafe { cnc_pdf_wractpt(h, p.as_ptr().cast_mut(), 0, &mut blk) },
        EW_OK
    );
    assert_eq!(blk, 3);
    let dir = cs(P1);
    assert_eq!(
        unsafe { cnc_pdf_delall(h, 1, dir.as_ptr().cast_mut()) },
        EW_OK
    );
    assert_eq!(numbers(h), vec![500]);
}

#[test]
fn directory_lists_show_folders_and_programs() {
    let (_s, h) = sim::start_alloc(idle());
    let mut inp: IDBPDFADIR = unsafe { std::mem::zeroed() };
    for (d, c) in inp.path.iter_mut().zip(P1.bytes()) {
        *d = c as c_char;
    }
    let mut out: [ODBPDFADIR; 8] = unsafe { std::mem::zeroed() };
    let mut n: c_short = 8;
    assert_eq!(
        unsafe { cnc_rdpdf_alldir(h, &mut n, &mut inp, out.as_mut_ptr()) },
        EW_OK
    );
    assert_eq!(n, 3);
    let name = |d: &[c_char]| -> String {
        d.iter()
            .take_while(|&&c| c != 0)
            .map(|&c| c as u8 as char)
            .collect()
    };
    let got: Vec<(c_short, String, i32)> = out[..3]
        .iter()
        .map(|e| (e.data_kind, name(&e.d_f), e.size))
        .collect();
    assert_eq!(
        got.iter().map(|g| g.1.as_str()).collect::<Vec<_>>(),
        ["O0100", "O0500", "O1234"]
    );
    assert_eq!(got[0].2, dir(h)[0].1, "the size cnc_rdprogdir3 reports");
    assert_eq!(name(&out[0].comment), "(WARM UP)");

    let mut sin: IDBPDFSDIR = unsafe { std::mem::zeroed() };
    for (d, c) in sin.path.iter_mut().zip("//CNC_MEM/USER/".bytes()) {
        *d = c as c_char;
    }
    assert_eq!(on(cnc_pdf_add, h, "//CNC_MEM/USER/JOBS/"), EW_OK);
    let mut sub: [ODBPDFSDIR; 8] = unsafe { std::mem::zeroed() };
    let mut n: c_short = 8;
    assert_eq!(
        unsafe { cnc_rdpdf_subdir(h, &mut n, &mut sin, sub.as_mut_ptr()) },
        EW_OK
    );
    let names: Vec<String> = sub[..n as usize].iter().map(|s| name(&s.d_f)).collect();
    assert_eq!(names, ["LIBRARY", "PATH1", "JOBS"]);
    let mut n: c_short = 0;
    assert_eq!(
        unsafe { cnc_rdpdf_subdir(h, &mut n, &mut sin, sub.as_mut_ptr()) },
        EW_LENGTH
    );
}
