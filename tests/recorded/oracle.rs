//! The oracle's vectors (tests/vectors/*.json, recorded from FANUC's library
//! by tools/oracle) replayed to our library through the same C probe: every
//! request byte, return code, in-out count and output byte must be FANUC's,
//! except where the DEVIATIONS table of tests/deviations/mod.rs says why not.

use crate::common;
use crate::deviations;
use crate::probe;
use crate::replay;
use crate::toolchain;

use std::path::PathBuf;
use std::sync::Mutex;

fn vector_files() -> Vec<PathBuf> {
    let dir = toolchain::manifest_dir().join("tests/vectors");
    let mut v: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    v.sort();
    v
}

#[test]
fn oracle_vectors_replay() {
    let lib = toolchain::cdylib();
    let probe_dir = toolchain::scratch("oracle-probe"); // removed when the test ends
    let probe_exe = probe::build(&toolchain::manifest_dir(), &probe_dir);
    // ORACLE_ONLY=cnc_rdparam,cnc_modal replays those files alone.
    let only: Vec<String> = std::env::var("ORACLE_ONLY")
        .map(|s| s.split(',').map(String::from).collect())
        .unwrap_or_default();
    let all: Vec<common::Case> = vector_files()
        .iter()
        .map(|f| common::load_file(f))
        .filter(|f| only.is_empty() || only.contains(&f.function))
        .flat_map(|f| f.cases)
        .collect();
    assert!(
        !only.is_empty() || all.len() >= 1000,
        "only {} recorded cases in tests/vectors",
        all.len()
    );
    // Under an emulator (the aarch64 CI step) every eighth case: the whole
    // set runs natively; this checks the ABI on that target.
    let emulated = !toolchain::runner().is_empty();
    let cases: Vec<common::Case> = all
        .into_iter()
        .enumerate()
        .filter(|(i, _)| !emulated || i % 8 == 0)
        .map(|(_, c)| c)
        .collect();
    let next = Mutex::new(0usize);
    let failures = Mutex::new(Vec::new());
    let (passed, deviated) = (Mutex::new(0usize), Mutex::new(0usize));
    // (function, listed pattern) -> its recorded cases that differ.
    let classes = Mutex::new(std::collections::BTreeMap::new());
    let threads = std::thread::available_parallelism()
        .map_or(2, |n| n.get())
        .min(4);
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let i = {
                    let mut n = next.lock().unwrap();
                    *n += 1;
                    *n - 1
                };
                let Some(case) = cases.get(i) else { return };
                let m = replay::replay_case(|| toolchain::target_command(&probe_exe), &lib, case);
                let pattern = deviations::oracle_pattern(case);
                if let Some(p) = pattern {
                    let mut c = classes.lock().unwrap();
                    let e = c.entry((case.function.clone(), p)).or_insert(0);
                    *e += usize::from(!m.is_empty());
                }
                match (m.is_empty(), deviations::oracle(case)) {
                    (true, None) => *passed.lock().unwrap() += 1,
                    // A member of a listed class that agrees: the class
                    // must still differ somewhere (checked below).
                    (true, Some(_)) if pattern.is_some_and(deviations::is_glob) => {
                        *passed.lock().unwrap() += 1
                    }
                    (false, Some(_)) => *deviated.lock().unwrap() += 1,
                    (false, None) => failures
                        .lock()
                        .unwrap()
                        .push(format!("{}/{}:\n{}", case.function, case.name, m.join("\n"))),
                    (true, Some(d)) => failures.lock().unwrap().push(format!(
                        "{}/{}: listed as a deviation ({}) but agrees with FANUC's library: remove it from the table",
                        case.function, case.name, d.reason
                    )),
                }
            });
        }
    });
    let mut failures = failures.into_inner().unwrap();
    // Every listed class has a recorded member that differs, or it is
    // stale (on the whole set; an emulated run replays every eighth case).
    if !emulated && only.is_empty() {
        for ((function, pat), differing) in classes.into_inner().unwrap() {
            if differing == 0 && deviations::is_glob(pat) {
                failures.push(format!(
                    "{function}: the listed class `{pat}` has no recorded case that differs from FANUC's library: narrow or remove it"
                ));
            }
        }
    }
    println!(
        "oracle vectors: {} cases, {} identical to FANUC's library, {} listed deviations, {} differ",
        cases.len(),
        passed.into_inner().unwrap(),
        deviated.into_inner().unwrap(),
        failures.len()
    );
    assert!(
        failures.is_empty(),
        "{} of {} recorded cases differ from FANUC's library:\n\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n\n")
    );
}

/// The oracle builds its probe with -m32 for a 32-bit library (FANUC's x86
/// build): told by the ELF class byte, not by the name.
#[test]
fn a_32_bit_library_is_told_by_its_elf_class() {
    let dir = toolchain::scratch("elf-class");
    let file = |name: &str, bytes: &[u8]| {
        let p = dir.join(name);
        std::fs::write(&p, bytes).unwrap();
        p
    };
    let elf = |class: u8| [0x7f, b'E', b'L', b'F', class, 1, 1, 0];
    assert!(probe::elf32(&file("x86.so", &elf(1))));
    assert!(!probe::elf32(&file("x64.so", &elf(2))));
    assert!(!probe::elf32(&file("text.so", b"\x7fELX\x01 not an ELF")));
    assert!(!probe::elf32(&file("short.so", b"\x7fEL")));
    assert!(!probe::elf32(&dir.join("absent.so")));
    // Our own library (the build's target): 64-bit on x86-64 and aarch64.
    if cfg!(target_pointer_width = "64") {
        assert!(!probe::elf32(&toolchain::cdylib()));
    }
}
