//! include/fwlib32.h: fresh (equal to what build.rs generates), and usable from
//! C99 and C++ the way programs written against FANUC's header use it.

use crate::toolchain;

use std::process::Command;
use toolchain::{cc, cxx, header_path, header_text, run, scratch};

/// The header build.rs generated for this build (in `$OUT_DIR`).
const GENERATED: &str = env!("FWLIB32_GENERATED_HEADER");

#[test]
fn committed_header_is_fresh() {
    let generated = std::fs::read(GENERATED).unwrap_or_else(|e| panic!("read {GENERATED}: {e}"));
    let committed = std::fs::read(header_path()).unwrap_or_default();
    if generated != committed {
        let first = generated
            .split(|b| *b == b'\n')
            .zip(committed.split(|b| *b == b'\n'))
            .position(|(a, b)| a != b)
            .map(|i| format!("first difference at line {}", i + 1))
            .unwrap_or_else(|| "one is a prefix of the other".to_owned());
        panic!(
            "include/fwlib32.h is stale ({first}): it differs from the header build.rs \
             generates ({GENERATED}).\nRun `FWLIB32_UPDATE_HEADER=1 cargo build` and commit \
             include/fwlib32.h."
        );
    }
}

/// The same for include/fwlib32_ext.h.
#[test]
fn committed_ext_header_is_fresh() {
    let generated = env!("FWLIB32_GENERATED_EXT_HEADER");
    let generated = std::fs::read(generated).unwrap();
    let committed = std::fs::read(toolchain::ext_header_path()).unwrap_or_default();
    assert!(
        generated == committed,
        "include/fwlib32_ext.h is stale: run `FWLIB32_UPDATE_HEADER=1 cargo build` and commit it"
    );
}

/// Uses a few structures, constants and calls, in plain C; also includes the
/// header twice (include guard) and checks LONG/ULONG are 32 bits.
const C_UNIT: &str = r#"
#include <stdio.h>
#include "fwlib32.h"
#include "fwlib32.h"

typedef char long_is_32_bits[(sizeof(LONG) == 4 && sizeof(ULONG) == 4) ? 1 : -1];
typedef char max_axis_is_32[(MAX_AXIS == 32 && MAX_SPINDLE == 8) ? 1 : -1];
typedef char ew_handle_negative[(EW_HANDLE == -8 && -EW_HANDLE == 8) ? 1 : -1];

short poll(unsigned short h, struct ODBST *st, ODBSYS *sys)
{
    ODBERR err;
    short path_no, maxpath_no;
    unsigned long id[4];
    short ret = cnc_statinfo(h, st);
    if (ret == EW_OK)
        ret = cnc_sysinfo(h, sys);
    if (ret == EW_OK)
        ret = cnc_getpath(h, &path_no, &maxpath_no);
    if (ret == EW_OK)
        ret = cnc_rdcncid(h, id);
    if (ret != EW_OK && cnc_getdtailerr(h, &err) == EW_OK)
        printf("%d/%d\n", err.err_no, err.err_dtno);
    return ret;
}

int connect_and_poll(const char *ip)
{
    unsigned short h;
    ODBST st;
    struct ODBSYS sys;
    ODBST2 st2;
    long timeout = 10;
    if (cnc_startupprocess(0, "focas.log") != EW_OK)
        return 1;
    if (cnc_allclibhndl3(ip, 8193, timeout, &h) != EW_OK)
        return 2;
    cnc_settimeout(h, 5);
    cnc_setpath(h, 1);
    poll(h, &st, &sys);
    cnc_statinfo2(h, &st2);
    cnc_freelibhndl(h);
    cnc_exitprocess();
    return st.run + st2.restart;
}
"#;

/// FANUC-style C++: `Fwlib32::` names, `using namespace Fwlib32`, and `long *` /
/// `unsigned long *` arguments where FANUC's prototypes have them.
const CXX_UNIT: &str = r#"
#include "fwlib32.h"
#include "fwlib32.h"

static_assert(sizeof(Fwlib32::LONG) == 4, "LONG is 32 bits");
static_assert(sizeof(::ODBST) == sizeof(Fwlib32::ODBST), "one ODBST");

namespace app {
using namespace Fwlib32;

short read_all(unsigned short h)
{
    Fwlib32::ODBST st;
    ODBST2 st2;
    struct ODBSYS sys;
    Fwlib32::ODBERR err;
    unsigned long id[4];
    short ret = Fwlib32::cnc_statinfo(h, &st);
    ret = cnc_statinfo2(h, &st2);
    ret = cnc_sysinfo(h, &sys);
    ret = cnc_rdcncid(h, id);
    if (ret != EW_OK)
        cnc_getdtailerr(h, &err);
    return ret;
}
}  // namespace app

int main()
{
    unsigned short h = 0;
    long timeout = 10;
    unsigned long id = 0x12345678UL;
    const char *ip = "192.168.0.1";
    if (cnc_allclibhndl4(ip, 8193, timeout, id, &h) != EW_OK)
        return 1;
    Fwlib32::cnc_settimeout(h, timeout);
    short ret = app::read_all(h);
    ::cnc_freelibhndl(h);
    return ret == EW_HANDLE ? 1 : 0;
}
"#;

fn include_dir() -> std::path::PathBuf {
    header_path().parent().unwrap().to_path_buf()
}

#[test]
fn header_compiles_as_c99() {
    let dir = scratch("header-c99");
    let src = dir.join("unit.c");
    std::fs::write(&src, C_UNIT).unwrap();
    run(Command::new(cc())
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
            "-c",
            "-o",
        ])
        .arg(dir.join("unit.o"))
        .arg("-I")
        .arg(include_dir())
        .arg(&src));
}

#[test]
fn header_compiles_as_cxx() {
    let dir = scratch("header-cxx");
    // The C unit, compiled as C++ (callers include the header from both).
    let src = dir.join("unit_c.cpp");
    std::fs::write(&src, C_UNIT).unwrap();
    run(Command::new(cxx())
        .args(["-Wall", "-Wextra", "-Werror", "-c", "-o"])
        .arg(dir.join("unit_c.o"))
        .arg("-I")
        .arg(include_dir())
        .arg(&src));
}

#[test]
fn header_accepts_fanuc_style_cxx() {
    let dir = scratch("header-fanuc-cxx");
    let src = dir.join("fanuc.cpp");
    std::fs::write(&src, CXX_UNIT).unwrap();
    for std in ["-std=c++11", "-std=c++17"] {
        run(Command::new(cxx())
            .args([std, "-Wall", "-Wextra", "-Werror", "-pedantic", "-c", "-o"])
            .arg(dir.join("fanuc.o"))
            .arg("-I")
            .arg(include_dir())
            .arg(&src));
    }
}

/// The `EW_*` block of the header is src/ew.rs, value for value, and negative
/// values are bracketed.
#[test]
fn ew_codes_match_src_ew() {
    let header = header_text();
    let mut n = 0;
    for &(name, value, _) in fwlib32::ew::CODES {
        let want = if value < 0 {
            format!("({value})")
        } else {
            value.to_string()
        };
        let found: Vec<&str> = header
            .lines()
            .filter(|l| l.starts_with("#define") && l.split_whitespace().nth(1) == Some(name))
            .collect();
        assert_eq!(
            found.len(),
            1,
            "{name} must be defined exactly once in the header: {found:?}"
        );
        let words: Vec<&str> = found[0].split_whitespace().collect();
        assert_eq!(
            words[..3],
            ["#define", name, want.as_str()],
            "{name} in the header: {}",
            found[0]
        );
        n += 1;
    }
    assert!(n >= 40, "src/ew.rs has only {n} EW_ constants?");
    assert_eq!(fwlib32::ew::EW_HANDLE, -8);
}

/// include/fwlib32_ext.h (our `fwlib_` extensions) includes fwlib32.h and
/// compiles from C99 and C++, alone and after fwlib32.h.
#[test]
fn ext_header_compiles_as_c99_and_cxx() {
    let dir = scratch("header-ext");
    let unit = "#include \"fwlib32_ext.h\"\n#include \"fwlib32.h\"\n#include \"fwlib32_ext.h\"\n\
                int ok(unsigned short h, ODBST *st) { return cnc_statinfo(h, st) == EW_OK; }\n";
    let c = dir.join("ext.c");
    let cpp = dir.join("ext.cpp");
    std::fs::write(&c, unit).unwrap();
    std::fs::write(&cpp, unit).unwrap();
    run(Command::new(cc())
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
            "-c",
            "-o",
        ])
        .arg(dir.join("ext_c.o"))
        .arg("-I")
        .arg(include_dir())
        .arg(&c));
    run(Command::new(cxx())
        .args(["-Wall", "-Wextra", "-Werror", "-pedantic", "-c", "-o"])
        .arg(dir.join("ext_cpp.o"))
        .arg("-I")
        .arg(include_dir())
        .arg(&cpp));
}
