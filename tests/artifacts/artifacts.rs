//! The shared library cargo builds (`libfwlib32.so`): its soname, its exported
//! symbols, and a C program linked against it.

use crate::toolchain;

use std::collections::BTreeSet;
use std::process::Command;
use toolchain::{
    cc, cdylib, ffi_functions, header_functions, header_path, header_text, nm, readelf, run,
    scratch, target_command,
};

fn expected_soname() -> String {
    format!("libfwlib32.so.{}", env!("CARGO_PKG_VERSION_MAJOR"))
}

#[test]
fn soname_is_libfwlib32_so_major() {
    let lib = cdylib();
    let out = run(Command::new(readelf()).arg("-d").arg(&lib));
    let text = String::from_utf8_lossy(&out.stdout);
    let sonames: Vec<&str> = text
        .lines()
        .filter(|l| l.contains("(SONAME)"))
        .filter_map(|l| l.split_once('[')?.1.split_once(']').map(|x| x.0))
        .collect();
    assert_eq!(
        sonames,
        [expected_soname()],
        "SONAME of {} (readelf -d):\n{text}",
        lib.display()
    );
}

/// `(type, name)` of the defined dynamic symbols of the library.
fn exported(lib: &std::path::Path) -> Vec<(String, String)> {
    let out = run(Command::new(nm()).args(["-D", "--defined-only"]).arg(lib));
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            let (ty, name) = match w.as_slice() {
                [_, ty, name] | [ty, name] => (*ty, *name),
                _ => return None,
            };
            let name = name.split('@').next().unwrap();
            Some((ty.to_owned(), name.to_owned()))
        })
        .collect()
}

#[test]
fn exports_are_exactly_the_ffi_functions() {
    let lib = cdylib();
    let symbols = exported(&lib);
    let strays: Vec<_> = symbols
        .iter()
        .filter(|(ty, name)| {
            ty != "T"
                || !(name.starts_with("cnc_")
                    || name.starts_with("pmc_")
                    || name.starts_with("fwlib_"))
        })
        .collect();
    assert!(
        strays.is_empty(),
        "{} exports symbols other than cnc_*/pmc_*/fwlib_* functions: {strays:?}",
        lib.display()
    );

    let exported: BTreeSet<String> = symbols.into_iter().map(|s| s.1).collect();
    let ffi = ffi_functions();
    assert!(
        !ffi.is_empty(),
        "no `pub extern \"C\" fn` found in src/ffi/*.rs"
    );
    let unexported: Vec<_> = ffi.difference(&exported).collect();
    assert!(
        unexported.is_empty(),
        "extern \"C\" functions of src/ffi/ not exported by {}: {unexported:?} (missing #[unsafe(no_mangle)]?)",
        lib.display()
    );
    let unknown: Vec<_> = exported.difference(&ffi).collect();
    assert!(
        unknown.is_empty(),
        "exported but not a `pub extern \"C\" fn` of src/ffi/*.rs: {unknown:?}"
    );
    // The table build.rs writes (COMPATIBILITY.md and `focas compat` read it).
    let table: BTreeSet<String> = fwlib32::ffi::exports::EXPORTS
        .iter()
        .map(|e| e.name.to_string())
        .collect();
    assert_eq!(
        table,
        exported,
        "fwlib32::ffi::exports::EXPORTS (written by build.rs) vs the symbols {} exports",
        lib.display()
    );

    // FANUC's API in fwlib32.h, our fwlib_* extensions in fwlib32_ext.h only.
    let declared = header_functions(&header_text());
    let ext_text = std::fs::read_to_string(toolchain::ext_header_path()).unwrap();
    let ext = header_functions(&ext_text);
    assert!(
        declared.iter().all(|n| !n.starts_with("fwlib_")),
        "fwlib_* in fwlib32.h"
    );
    assert!(
        ext.iter().all(|n| n.starts_with("fwlib_")),
        "FANUC's names in fwlib32_ext.h"
    );
    assert_eq!(
        declared.union(&ext).cloned().collect::<BTreeSet<_>>(),
        exported,
        "functions declared by {} and fwlib32_ext.h vs exported by {}",
        header_path().display(),
        lib.display()
    );
}

/// Loading the library loads nothing but libc (and the dynamic loader):
/// no libm (on x86-64; elsewhere nothing used from it), and no libgcc_s where
/// build.rs linked the unwinder statically (every GNU toolchain with gcc's
/// libgcc_eh.a).
#[test]
fn the_library_needs_only_libc() {
    let lib = cdylib();
    let out = run(Command::new(readelf()).arg("-d").arg(&lib));
    let text = String::from_utf8_lossy(&out.stdout);
    let needed: Vec<&str> = text
        .lines()
        .filter(|l| l.contains("(NEEDED)"))
        .filter_map(|l| l.split_once('[')?.1.split_once(']').map(|x| x.0))
        .collect();
    // Debian's aarch64 toolchain keeps libm.so.6 named though nothing of it
    // is used (std asks for -lm); nothing is, when no symbol version comes
    // from it.
    let versions = run(Command::new(readelf()).arg("-V").arg(&lib));
    let uses_libm = String::from_utf8_lossy(&versions.stdout).contains("File: libm.so");
    let allowed = |n: &&str| {
        n.starts_with("libc.so")
            || n.starts_with("ld-linux")
            || (n.starts_with("libgcc_s.so") && env!("FWLIB32_STATIC_UNWINDER") == "0")
            || (n.starts_with("libm.so") && !uses_libm && !cfg!(target_arch = "x86_64"))
    };
    let strays: Vec<&&str> = needed.iter().filter(|n| !allowed(n)).collect();
    assert!(
        strays.is_empty(),
        "{} needs {strays:?} (readelf -d):\n{text}",
        lib.display()
    );
}

/// Linked by soname, as a program built against FANUC's library is; only
/// calls that need no CNC.
const SMOKE: &str = r#"
#include <stdio.h>
#include <string.h>
#include "fwlib32.h"

#define CHECK(call, want) do { short r_ = (call); if (r_ != (want)) { \
    printf("%s returned %d, expected %d\n", #call, r_, (want)); return 1; } } while (0)

int main(void)
{
    ODBST st;
    ODBERR err;
    unsigned short h = 0;
    unsigned long id[4];
    memset(&st, 0x55, sizeof st);
    CHECK(cnc_startupprocess(7, NULL), EW_NUMBER);
    CHECK(cnc_startupprocess(0, NULL), EW_OK);
    CHECK(cnc_allclibhndl3("127.0.0.1", 8193, 1, NULL), EW_DATA);
    CHECK(cnc_allclibhndl3(NULL, 8193, 1, &h), EW_DATA);
    CHECK(cnc_statinfo(0x7777, &st), EW_HANDLE);
    CHECK(cnc_rdcncid(0x7777, id), EW_HANDLE);
    CHECK(cnc_getdtailerr(0x7777, &err), EW_HANDLE);
    CHECK(cnc_freelibhndl(0x7777), EW_HANDLE);
    CHECK(cnc_exitprocess(), EW_OK);
    if (st.hdck != 0x5555 || h != 0) {
        printf("an output was written by a failing call\n");
        return 1;
    }
    printf("ok\n");
    return 0;
}
"#;

#[test]
fn c_program_links_and_runs_against_the_library() {
    let lib = cdylib();
    let dir = scratch("artifacts-link");
    // What the dynamic linker looks for: the soname.
    let soname = dir.join(expected_soname());
    std::os::unix::fs::symlink(&lib, &soname).unwrap();
    std::os::unix::fs::symlink(&lib, dir.join("libfwlib32.so")).unwrap();
    let src = dir.join("smoke.c");
    let exe = dir.join("smoke");
    std::fs::write(&src, SMOKE).unwrap();
    run(Command::new(cc())
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-o"])
        .arg(&exe)
        .arg("-I")
        .arg(header_path().parent().unwrap())
        .arg(&src)
        .arg("-L")
        .arg(&dir)
        .arg("-lfwlib32")
        .arg(format!("-Wl,-rpath,{}", dir.display())));
    let out = run(&mut target_command(&exe));
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "ok");
}

/// `cnc_allclibhdl3`, the alias of `cnc_allclibhndl3` some programs call, from
/// C against a simulator: it connects, and the handle it gives works.
const ALIAS: &str = r#"
#include <stdio.h>
#include <stdlib.h>
#include "fwlib32.h"

int main(int argc, char **argv)
{
    unsigned short h = 0;
    ODBSYS sys;
    short r;
    if (argc != 2)
        return 2;
    r = cnc_allclibhdl3(NULL, 8193, 1, &h);
    if (r != EW_DATA || h != 0) {
        printf("cnc_allclibhdl3(NULL) returned %d, handle %u\n", r, h);
        return 1;
    }
    r = cnc_allclibhdl3("127.0.0.1", (unsigned short)atoi(argv[1]), 5, &h);
    if (r != EW_OK || h == 0) {
        printf("cnc_allclibhdl3 returned %d, handle %u\n", r, h);
        return 1;
    }
    r = cnc_sysinfo(h, &sys);
    if (r != EW_OK) {
        printf("cnc_sysinfo returned %d\n", r);
        return 1;
    }
    printf("series=%.4s\n", sys.series);
    r = cnc_freelibhndl(h);
    if (r != EW_OK) {
        printf("cnc_freelibhndl returned %d\n", r);
        return 1;
    }
    return 0;
}
"#;

#[test]
fn cnc_allclibhdl3_is_cnc_allclibhndl3_from_c() {
    use fwlib32::sim::{Profile, Simulator};
    let lib = cdylib();
    let dir = scratch("artifacts-alias");
    std::os::unix::fs::symlink(&lib, dir.join(expected_soname())).unwrap();
    std::os::unix::fs::symlink(&lib, dir.join("libfwlib32.so")).unwrap();
    let src = dir.join("alias.c");
    let exe = dir.join("alias");
    std::fs::write(&src, ALIAS).unwrap();
    run(Command::new(cc())
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-o"])
        .arg(&exe)
        .arg("-I")
        .arg(header_path().parent().unwrap())
        .arg(&src)
        .arg("-L")
        .arg(&dir)
        .arg("-lfwlib32")
        .arg(format!("-Wl,-rpath,{}", dir.display())));
    let profile = Profile::default();
    let sim = Simulator::start(profile.clone(), "127.0.0.1:0").unwrap();
    let out = run(target_command(&exe).arg(sim.port().to_string()));
    assert_eq!(
        String::from_utf8_lossy(&out.stdout).trim(),
        format!("series={}", profile.cnc.series)
    );
}

/// A library-only build (`default-features = false`) brings none of the
/// simulator's or the command line's crates: the client is libc,
/// parking_lot, thiserror and jiff (and what those need).
#[test]
fn the_library_alone_needs_no_simulator_crates() {
    let out = run(Command::new(env!("CARGO"))
        .current_dir(toolchain::manifest_dir())
        .args([
            "tree",
            "--offline",
            "--locked",
            "-e",
            "normal",
            "--no-default-features",
        ])
        .args(["--prefix", "none", "--format", "{p}"]));
    let text = String::from_utf8_lossy(&out.stdout);
    let crates: BTreeSet<&str> = text
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "fwlib32")
        .collect();
    for foreign in ["tokio", "toml", "clap", "serde", "serde_json", "indicatif"] {
        assert!(
            !crates.contains(foreign),
            "{foreign} in the library-only build: {crates:?}"
        );
    }
    for needed in ["libc", "parking_lot", "thiserror", "jiff"] {
        assert!(crates.contains(needed), "{needed} missing: {crates:?}");
    }
    assert!(crates.len() <= 16, "{} crates: {crates:?}", crates.len());
}
