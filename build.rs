//! Build script:
//!
//! * gives the cdylib FANUC's soname, `libfwlib32.so.<major>`;
//! * generates the C header `fwlib32.h` into `$OUT_DIR` with cbindgen (and into
//!   `include/fwlib32.h` when `FWLIB32_UPDATE_HEADER=1`), with the `EW_*` block
//!   generated here from src/ew.rs.

use std::env;
use std::fs;
use std::path::{Path, PathBuf};

const UPDATE_VAR: &str = "FWLIB32_UPDATE_HEADER";
const GUARD: &str = "_FWLIB32_H";

fn main() {
    let manifest_dir = PathBuf::from(env::var("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let out_dir = PathBuf::from(env::var("OUT_DIR").expect("OUT_DIR"));

    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=cbindgen.toml");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed={UPDATE_VAR}");

    // Soname, cdylib only (the staticlib and rlib have none).
    let major = env::var("CARGO_PKG_VERSION_MAJOR").expect("CARGO_PKG_VERSION_MAJOR");
    if env::var("CARGO_CFG_TARGET_OS").as_deref() != Ok("macos") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libfwlib32.so.{major}");
    }

    // The target and host triples, for the tests: they run the C programs they
    // build through cargo's runner for the target (`CARGO_TARGET_<TRIPLE>_RUNNER`,
    // e.g. qemu), and tests/install.rs installs for the target.
    let target = env::var("TARGET").expect("TARGET");
    println!("cargo:rustc-env=FWLIB32_TARGET={target}");
    let host = env::var("HOST").expect("HOST");
    println!("cargo:rustc-env=FWLIB32_HOST={host}");

    let header = generate_header(&manifest_dir);
    let generated = out_dir.join("fwlib32.h");
    write_if_changed(&generated, &header);
    println!(
        "cargo:rustc-env=FWLIB32_GENERATED_HEADER={}",
        generated.display()
    );

    if env::var(UPDATE_VAR).as_deref() == Ok("1") {
        let committed = manifest_dir.join("include").join("fwlib32.h");
        fs::create_dir_all(committed.parent().unwrap()).expect("create include/");
        write_if_changed(&committed, &header);
    }
}

fn generate_header(root: &Path) -> String {
    let mut config = cbindgen::Config::from_file(root.join("cbindgen.toml"))
        .unwrap_or_else(|e| panic!("cbindgen.toml: {e}"));

    // Include guard, by hand: cbindgen closes its own guard before the trailer, and
    // the trailer closes the C++ namespace, which must stay inside the guard.
    assert!(
        config.include_guard.is_none(),
        "cbindgen.toml: leave include_guard to build.rs"
    );
    let preamble = config.header.take().unwrap_or_default();
    config.header = Some(format!(
        "{}

#ifndef {GUARD}
#define {GUARD}",
        preamble.trim_end()
    ));

    let ew = fs::read_to_string(root.join("src/ew.rs")).expect("read src/ew.rs");
    let ew_block = ew_defines(&ew);
    config.after_includes = Some(format!(
        "\n{ew_block}\n#ifdef __cplusplus\nnamespace Fwlib32 {{\n#endif  /* __cplusplus */\n"
    ));
    config.trailer = Some(format!(
        "#ifdef __cplusplus\n}}  /* namespace Fwlib32 */\n\nusing namespace Fwlib32;\n#endif  /* __cplusplus */\n\n#endif  /* {GUARD} */"
    ));

    // Every C type of src/types/ goes into the header, used by a function yet or not.
    let mut types = String::new();
    let mut files: Vec<_> = fs::read_dir(root.join("src/types"))
        .expect("read src/types")
        .map(|e| e.expect("read src/types").path())
        .collect();
    files.sort();
    for f in files {
        types.push_str(&fs::read_to_string(&f).expect("read src/types/*.rs"));
    }
    for name in type_names(&types) {
        if !config.export.include.contains(&name) {
            config.export.include.push(name);
        }
    }

    let mut out = Vec::new();
    cbindgen::Builder::new()
        .with_config(config)
        .with_src(root.join("src/types/mod.rs"))
        .with_src(root.join("src/ffi/mod.rs"))
        .generate()
        .unwrap_or_else(|e| panic!("cbindgen failed to generate fwlib32.h: {e}"))
        .write(&mut out);
    let text = String::from_utf8(out).expect("cbindgen wrote UTF-8");
    // Negative constants in brackets, as FANUC writes them: `#define ALL_AXES (-1)`.
    text.lines()
        .map(
            |l| match l.strip_prefix("#define ").and_then(|r| r.split_once(" -")) {
                Some((name, v)) if v.parse::<i64>().is_ok() => format!("#define {name} (-{v})"),
                _ => l.to_owned(),
            },
        )
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}

/// `pub const EW_NAME: c_short = VALUE; // comment` lines of src/ew.rs, as
/// `#define EW_NAME (VALUE) /* comment */` (brackets only around negative values,
/// as FANUC's header has them).
fn ew_defines(src: &str) -> String {
    let mut rows = Vec::new();
    for (n, line) in src.lines().enumerate() {
        let Some(rest) = line.trim().strip_prefix("pub const EW_") else {
            continue;
        };
        let bad = || {
            panic!(
                "src/ew.rs:{}: expected `pub const EW_NAME: c_short = VALUE; // comment`, got `{line}`",
                n + 1
            )
        };
        let Some((name, rest)) = rest.split_once(':') else {
            bad()
        };
        let Some((ty, rest)) = rest.split_once('=') else {
            bad()
        };
        let Some((value, comment)) = rest.split_once(';') else {
            bad()
        };
        let (name, value) = (format!("EW_{}", name.trim()), value.trim());
        if ty.trim() != "c_short" || value.parse::<i16>().is_err() {
            bad();
        }
        let comment = comment
            .trim()
            .strip_prefix("//")
            .map(str::trim)
            .unwrap_or("");
        if comment.contains("*/") {
            bad();
        }
        let value = if value.starts_with('-') {
            format!("({value})")
        } else {
            value.to_owned()
        };
        rows.push((name, value, comment.to_owned()));
    }
    assert!(!rows.is_empty(), "src/ew.rs defines no EW_ constants");
    let width = rows.iter().map(|r| r.0.len()).max().unwrap_or(0);
    let mut s = String::from("/* Result codes (from src/ew.rs). */\n");
    for (name, value, comment) in rows {
        let def = format!("#define {name:<width$} {value:>5}");
        if comment.is_empty() {
            s.push_str(&def);
        } else {
            s.push_str(&format!("{def}  /* {comment} */"));
        }
        s.push('\n');
    }
    s
}

/// Names of the `pub struct`, `pub union` and `pub type` items of src/types/.
fn type_names(src: &str) -> Vec<String> {
    src.lines()
        .filter_map(|l| {
            let l = l.trim();
            ["pub struct ", "pub union ", "pub type "]
                .iter()
                .find_map(|p| l.strip_prefix(p))
                .map(|rest| {
                    rest.split(|c: char| !(c.is_alphanumeric() || c == '_'))
                        .next()
                        .unwrap_or("")
                        .to_owned()
                })
        })
        .filter(|n| !n.is_empty())
        .collect()
}

fn write_if_changed(path: &Path, text: &str) {
    if fs::read_to_string(path).ok().as_deref() != Some(text) {
        fs::write(path, text).unwrap_or_else(|e| panic!("write {}: {e}", path.display()));
    }
}
