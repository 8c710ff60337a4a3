//! Build script:
//!
//! * gives the cdylib FANUC's soname, `libfwlib32.so.<major>`;
//! * links the cdylib's unwinder statically, so that loading it does not
//!   load libgcc_s.so too (see `static_unwinder`);
//! * generates the C header `fwlib32.h` into `$OUT_DIR` with cbindgen (and into
//!   `include/fwlib32.h` when `FWLIB32_UPDATE_HEADER=1`), with the `EW_*` block
//!   generated here from src/ew.rs;
//! * writes the table of every exported function and how it is made
//!   (`$OUT_DIR/exports.rs`, `fwlib32::ffi::exports`), from the lists of
//!   src/ffi/exported.rs and the table.
//!
//! Its inputs are data it includes (`#[path]`: src/ew.rs, src/ffi/exported.rs,
//! src/spec/), and the sources cbindgen reads; the one text it reads itself
//! is the names of the C types of src/types/, which cbindgen declares even
//! where no function uses them.

// The data build.rs writes code from: the function descriptions
// (src/spec/, with the command registry they name), whose exported
// functions src/ffi/described/mod.rs includes; the result codes (src/ew.rs),
// the header's `EW_*` block; the functions src/ffi/ exports by hand
// (src/ffi/exported.rs), the export table.
#[allow(dead_code)]
#[path = "src/spec/commands.rs"]
mod commands;
#[allow(dead_code)]
#[path = "src/ew.rs"]
mod ew;
#[allow(dead_code)]
#[path = "src/ffi/exported.rs"]
mod exported;
#[allow(dead_code)]
#[path = "src/spec/func.rs"]
mod func;
#[allow(dead_code)]
#[path = "src/spec/reply.rs"]
mod reply;
#[allow(dead_code)]
#[path = "src/spec/rules.rs"]
mod rules;
#[allow(dead_code)]
#[path = "src/spec/table/mod.rs"]
mod table;
#[allow(dead_code)]
#[path = "src/spec/types.rs"]
mod types;

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

    // The installed library's build (the Makefile's, FWLIB32_SLIM=1): the
    // static table leaves out what only build.rs, the oracle and
    // COMPATIBILITY.md read (src/spec/table/mod.rs, `kept`).
    println!("cargo:rerun-if-env-changed=FWLIB32_SLIM");
    if env::var("FWLIB32_SLIM").as_deref() == Ok("1") {
        println!("cargo:rustc-cfg=fwlib32_slim");
    }

    // Soname, cdylib only (the staticlib and rlib have none).
    let major = env::var("CARGO_PKG_VERSION_MAJOR").expect("CARGO_PKG_VERSION_MAJOR");
    if env::var("CARGO_CFG_TARGET_OS").as_deref() != Ok("macos") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libfwlib32.so.{major}");
    }

    static_unwinder(&out_dir);

    // The target and host triples, for the tests: they run the C programs they
    // build through cargo's runner for the target (`CARGO_TARGET_<TRIPLE>_RUNNER`,
    // e.g. qemu), and tests/artifacts/install.rs installs for the target.
    let target = env::var("TARGET").expect("TARGET");
    println!("cargo:rustc-env=FWLIB32_TARGET={target}");
    let host = env::var("HOST").expect("HOST");
    println!("cargo:rustc-env=FWLIB32_HOST={host}");

    let described = out_dir.join("described.rs");
    write_if_changed(&described, &described_exports(table::FUNCS));
    let absent = out_dir.join("absent.rs");
    write_if_changed(&absent, &absent_exports());

    write_if_changed(&out_dir.join("exports.rs"), &exports_table(table::FUNCS));

    let header = generate_header(&manifest_dir, &[&described, &absent]);
    let generated = out_dir.join("fwlib32.h");
    write_if_changed(&generated, &header);
    println!(
        "cargo:rustc-env=FWLIB32_GENERATED_HEADER={}",
        generated.display()
    );

    let ext = generate_ext_header(&manifest_dir);
    let generated_ext = out_dir.join("fwlib32_ext.h");
    write_if_changed(&generated_ext, &ext);
    println!(
        "cargo:rustc-env=FWLIB32_GENERATED_EXT_HEADER={}",
        generated_ext.display()
    );

    if env::var(UPDATE_VAR).as_deref() == Ok("1") {
        let include = manifest_dir.join("include");
        fs::create_dir_all(&include).expect("create include/");
        write_if_changed(&include.join("fwlib32.h"), &header);
        write_if_changed(&include.join("fwlib32_ext.h"), &ext);
    }
}

/// On GNU/Linux, links the cdylib's unwinder (the `_Unwind_*` functions
/// that panics and `catch_unwind` use) from gcc's static `libgcc_eh.a`
/// instead of `libgcc_s.so.1`: a C host that loads the library then loads
/// one shared object, not two (libgcc_s was most of dlopen's time).
///
/// Rust's std asks the linker for `-lgcc_s`; the cdylib's link searches
/// first a directory of ours where `libgcc_s.so` is a linker script naming
/// the static archives, so nothing in the library refers to libgcc_s.so.1
/// and `--as-needed` drops it. The unwinder's symbols stay local (the
/// cdylib exports only the C functions), and panics never leave the library,
/// so it never meets the host's unwinder. Where the C compiler has no
/// `libgcc_eh.a` the library links libgcc_s.so.1 as before. The tests and
/// binaries are linked as usual (the link arguments are the cdylib's only).
///
/// `FWLIB32_STATIC_UNWINDER` is set to 1 or 0 for the tests.
fn static_unwinder(out_dir: &Path) {
    println!("cargo:rerun-if-env-changed=RUSTC_LINKER");
    let gnu_linux = env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux")
        && env::var("CARGO_CFG_TARGET_ENV").as_deref() == Ok("gnu");
    let archives = gnu_linux
        .then(|| {
            // The driver rustc links with, asked where its archives are
            // (when cross-building, only a linker named for the target
            // knows the target's).
            let cc = env::var("RUSTC_LINKER").ok().or_else(|| {
                (env::var("TARGET").ok() == env::var("HOST").ok()).then(|| "cc".to_string())
            })?;
            let ask = |arg: &str| -> Option<PathBuf> {
                let out = std::process::Command::new(&cc).arg(arg).output().ok()?;
                let p = PathBuf::from(String::from_utf8(out.stdout).ok()?.trim());
                (out.status.success() && p.is_absolute() && p.is_file()).then_some(p)
            };
            Some((
                ask("-print-file-name=libgcc_eh.a")?,
                ask("-print-libgcc-file-name")?,
            ))
        })
        .flatten();
    let Some((eh, gcc)) = archives else {
        println!("cargo:rustc-env=FWLIB32_STATIC_UNWINDER=0");
        return;
    };
    let dir = out_dir.join("static-unwinder");
    fs::create_dir_all(&dir).expect("create static-unwinder/");
    write_if_changed(
        &dir.join("libgcc_s.so"),
        &format!(
            "/* Written by build.rs: the unwinder from gcc's static archives. */\nGROUP ( \"{}\" \"{}\" )\n",
            eh.display(),
            gcc.display()
        ),
    );
    println!("cargo:rustc-cdylib-link-arg=-L{}", dir.display());
    println!("cargo:rustc-env=FWLIB32_STATIC_UNWINDER=1");
}

fn generate_header(root: &Path, generated: &[&Path]) -> String {
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

    let ew_block = ew_defines(ew::CODES);
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

    // Our fwlib_* extensions go into fwlib32_ext.h only.
    config
        .export
        .exclude
        .extend(exported::EXTENSIONS.iter().map(|n| n.to_string()));

    let mut out = Vec::new();
    let mut builder = cbindgen::Builder::new()
        .with_config(config)
        .with_src(root.join("src/types/mod.rs"))
        .with_src(root.join("src/ffi/mod.rs"));
    for g in generated {
        builder = builder.with_src(g);
    }
    builder
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

const EXT_SRC: &str = "src/ffi/ext.rs";
const EXT_GUARD: &str = "_FWLIB32_EXT_H";

/// include/fwlib32_ext.h: the `fwlib_*` functions of src/ffi/ext.rs, after
/// `#include "fwlib32.h"`.
fn generate_ext_header(root: &Path) -> String {
    let mut config = cbindgen::Config::from_file(root.join("cbindgen.toml"))
        .unwrap_or_else(|e| panic!("cbindgen.toml: {e}"));
    config.header = Some(format!(
        "/*
 * fwlib32_ext.h: extensions of fwlib32-rs beyond FANUC's FOCAS2 interface.
 *
 * GENERATED FILE: do not edit. build.rs writes it with cbindgen from
 * {EXT_SRC}; refresh the committed copy with
 *     FWLIB32_UPDATE_HEADER=1 cargo build
 *
 * FANUC's functions are declared in fwlib32.h (included here) under FANUC's
 * names. Functions of our own, which FANUC's library does not have, are named
 * fwlib_* and are declared in this header only: a program that includes just
 * fwlib32.h stays buildable against FANUC's library, and one that uses an
 * extension says so by including fwlib32_ext.h.
 */

#ifndef {EXT_GUARD}
#define {EXT_GUARD}"
    ));
    config.sys_includes = Vec::new();
    config.includes = vec!["fwlib32.h".to_string()];
    config.after_includes = None;
    config.trailer = Some(format!("#endif  /* {EXT_GUARD} */"));
    config.export.include = Vec::new();
    let mut out = Vec::new();
    cbindgen::Builder::new()
        .with_config(config)
        .with_src(root.join(EXT_SRC))
        .generate()
        .unwrap_or_else(|e| panic!("cbindgen failed to generate fwlib32_ext.h: {e}"))
        .write(&mut out);
    String::from_utf8(out).expect("cbindgen wrote UTF-8")
}

/// `fwlib32::ffi::exports::EXPORTS`: every function the library exports, by
/// name, and how it is made: written by hand in src/ffi/<area>.rs
/// (`Written`), answering a code without traffic (`NotOnEthernet`: an
/// entry of src/spec/table/absent.rs, or cnc_allclibhndl in
/// src/ffi/absent.rs), one of our extensions (`Extension`, src/ffi/ext.rs),
/// all three listed in src/ffi/exported.rs; or an entry of src/spec/table/
/// (`Described`). tests/artifacts/artifacts.rs checks the names against the built
/// library's dynamic symbols.
fn exports_table(funcs: &[types::Func]) -> String {
    let mut rows: Vec<(String, String)> = funcs
        .iter()
        .map(|f| (f.name.to_string(), "How::Described".to_string()))
        .collect();
    // Declared, on no Ethernet library of FANUC's: EW_VERSION.
    for (name, _) in table::absent::ROWS.iter().copied().flatten() {
        rows.push((
            name.to_string(),
            format!(
                "How::NotOnEthernet {{ code: {}, ew: \"EW_VERSION\" }}",
                ew::EW_VERSION
            ),
        ));
    }
    for (area, names) in exported::WRITTEN {
        for n in *names {
            rows.push((
                n.to_string(),
                format!("How::Written {{ area: \"{area}\" }}"),
            ));
        }
    }
    for (name, code) in exported::ABSENT {
        let ew = ew_name(*code)
            .unwrap_or_else(|| panic!("src/ffi/exported.rs: {name}: {code} is no EW_* code"));
        rows.push((
            name.to_string(),
            format!("How::NotOnEthernet {{ code: {code}, ew: \"{ew}\" }}"),
        ));
    }
    for n in exported::EXTENSIONS {
        rows.push((n.to_string(), "How::Extension".to_string()));
    }
    rows.sort();
    for w in rows.windows(2) {
        assert!(w[0].0 != w[1].0, "{} is exported twice", w[0].0);
    }
    let mut s = String::from(
        "// GENERATED by build.rs from src/ffi/exported.rs and src/spec/table/.\npub const EXPORTS: &[Export] = &[\n",
    );
    for (name, how) in rows {
        s.push_str(&format!("    Export {{ name: \"{name}\", how: {how} }},\n"));
    }
    s.push_str("];\n");
    s
}

/// The export of each function of src/spec/table/absent/ (its row: its
/// name and FANUC's C parameters after the handle, there for the header
/// only), answering `EW_VERSION` through `crate::ffi::absent::not_on_ethernet`
/// with its own address, by which that finds its name. On x86-64 and
/// aarch64 each export is a naked jump (12 or 8 bytes, no unwind entry: it
/// is never on the stack when something unwinds), elsewhere a call.
fn absent_exports() -> String {
    let naked = matches!(
        env::var("CARGO_CFG_TARGET_ARCH").as_deref(),
        Ok("x86_64" | "aarch64")
    );
    let mut s = String::from("// GENERATED by build.rs from src/spec/table/absent/.\n");
    for &(name, params) in table::absent::ROWS.iter().copied().flatten() {
        let mut args = vec!["FlibHndl: c_ushort".to_string()];
        let unnamed = params.split(',').map(str::trim).filter(|p| !p.is_empty());
        for (i, p) in unnamed.enumerate() {
            let (ty, arg) = c_param(p).unwrap_or_else(|| {
                panic!("src/spec/table/absent/: {name}: cannot read the parameter `{p}`")
            });
            let arg = arg.unwrap_or_else(|| ((b'a' + i as u8) as char).to_string());
            args.push(format!("{}: {ty}", ident(&arg)));
        }
        let (attr, body) = match naked {
            true => ("#[unsafe(naked)]\n", "jump!()".to_string()),
            false => (
                "",
                format!("not_on_ethernet(FlibHndl, {name} as *const c_void)"),
            ),
        };
        s.push_str(&format!(
            "/// Declared by FANUC's header, in none of its Ethernet libraries:\n\
             /// `EW_VERSION` (-7) without traffic, nothing written.\n\
             #[unsafe(no_mangle)]\n{attr}\
             pub extern \"C\" fn {name}({}) -> c_short {{\n    {body}\n}}\n\n",
            args.join(", ")
        ));
    }
    s
}

/// One C parameter as FANUC's header declares it (`const char *name`,
/// `IODBPSD *`, `short`, `SCDL_1D data[]`): its Rust type, and its name if
/// it has one.
fn c_param(p: &str) -> Option<(String, Option<String>)> {
    let p = p.replace('*', " * ").replace("[]", " * ");
    let mut words: Vec<&str> = p.split_whitespace().collect();
    let konst = words.first() == Some(&"const");
    words.retain(|w| *w != "const");
    let stars = words.iter().filter(|w| **w == "*").count();
    let mut ty: Vec<&str> = words.iter().copied().filter(|w| *w != "*").collect();
    // A name follows a type of more than one word, or a C type name.
    let scalar = |t: &[&str]| {
        matches!(
            t,
            ["unsigned", _] | ["short" | "long" | "char" | "int" | "void" | "double" | "float"]
        )
    };
    let name = match ty.len() {
        n if n > 1
            && (scalar(&ty[..n - 1])
                || ty[n - 2]
                    .chars()
                    .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_')) =>
        {
            ty.pop().map(str::to_string)
        }
        _ => None,
    };
    let base = match ty.join(" ").as_str() {
        "unsigned char" => "c_uchar".to_string(),
        "int" => "c_int".to_string(),
        "unsigned int" => "c_uint".to_string(),
        "float" => "f32".to_string(),
        "" => return None,
        t => rust_type(t),
    };
    let ptr = if konst { "*const " } else { "*mut " };
    Some((format!("{}{base}", ptr.repeat(stars)), name))
}

/// Byte offsets and sizes as a `Site` keeps them: `u16`s (`at` fails the
/// build for one past 65535).
fn narrow(list: &[String]) -> String {
    let each: Vec<String> = list.iter().map(|x| format!("at({x})")).collect();
    each.join(", ")
}

/// The name of EW_* code `code` (src/ew.rs).
fn ew_name(code: i16) -> Option<&'static str> {
    ew::CODES.iter().find(|c| c.1 == code).map(|c| c.0)
}

/// The codes of src/ew.rs as `#define EW_NAME (VALUE) /* comment */` lines
/// (brackets only around negative values, as FANUC's header has them).
fn ew_defines(codes: &[(&str, i16, &str)]) -> String {
    assert!(!codes.is_empty(), "src/ew.rs defines no EW_ constants");
    let rows: Vec<(String, String, String)> = codes
        .iter()
        .map(|&(name, value, comment)| {
            assert!(
                !comment.is_empty() && !comment.contains("*/"),
                "src/ew.rs: {name}: its comment must be one C comment's text"
            );
            let value = if value < 0 {
                format!("({value})")
            } else {
                value.to_string()
            };
            (name.to_owned(), value, comment.to_owned())
        })
        .collect();
    let width = rows.iter().map(|r| r.0.len()).max().unwrap_or(0);
    let mut s = String::from("/* Result codes (from src/ew.rs). */\n");
    for (name, value, comment) in rows {
        s.push_str(&format!(
            "#define {name:<width$} {value:>5}  /* {comment} */\n"
        ));
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

/// The `extern "C"` function of every described function: its signature
/// from the parameters, its body one `exec` call with the number arguments,
/// the outputs and the byte offset of each reply field's member (checked at
/// compile time to fit in its output).
fn described_exports(funcs: &[types::Func]) -> String {
    use types::Param;
    let mut s = String::from("// GENERATED by build.rs from src/spec/table/.\n");
    for (i, f) in funcs.iter().enumerate() {
        let c_param = |p: &Param| match *p {
            Param::Short(n) | Param::ShortAs(n, _) => format!("{}: c_short", ident(n)),
            Param::Long(n) => format!("{}: c_long", ident(n)),
            Param::ULong(n) => format!("{}: c_ulong", ident(n)),
            Param::Text(n, _) => format!("{}: *mut c_char", ident(n)),
            Param::UShort(n) => format!("{}: c_ushort", ident(n)),
            Param::Char(n) => format!("{}: c_char", ident(n)),
            Param::Out(n, t) => format!("{}: *mut {}", ident(n), rust_type(t)),
            Param::Count(n) => format!("{}: *mut c_short", ident(n)),
            Param::LongCount(n) => format!("{}: *mut c_ulong", ident(n)),
            Param::In(n, t) | Param::InOut(n, t) => format!("{}: *mut {}", ident(n), rust_type(t)),
            Param::Io(n) => format!("{}: *mut c_short", ident(n)),
        };
        let params: Vec<String> = f.params.iter().map(c_param).collect();
        let count = f.params.iter().find_map(|p| match *p {
            Param::Count(n) | Param::LongCount(n) => Some(ident(n)),
            _ => None,
        });
        // The count's value is read by exec, once its pointer is checked.
        let numbers: Vec<String> = f
            .numbers()
            .map(|n| {
                let cut = f.params.iter().find_map(|p| match *p {
                    Param::ShortAs(m, c) if m == n => Some(c.rust()),
                    _ => None,
                });
                match (&count, cut) {
                    (Some(c), _) if *c == ident(n) => "0".to_string(),
                    // Read by exec through its pointer (`io`).
                    _ if f.params.contains(&Param::Io(n)) => "0".to_string(),
                    // As FANUC's library converts it before anything else.
                    (_, Some(t)) => format!("{} as {t} as i32", ident(n)),
                    _ => format!("{} as i32", ident(n)),
                }
            })
            .collect();
        assert!(
            count.is_none() || f.records.is_some() || f.pages.is_some(),
            "src/spec/table/: {}: a Param::Count counts records (or a paging function's)",
            f.name
        );
        assert!(
            numbers.len() <= 8,
            "src/spec/table/: {}: more number parameters than exec takes (MAX_NUMBERS)",
            f.name
        );
        let outs: Vec<(&str, &str)> = f.outs().collect();
        let out_ptrs: Vec<String> = outs
            .iter()
            .map(|(n, _)| format!("{}.cast()", ident(n)))
            .collect();
        let mut offsets = Vec::new();
        let mut checks = Vec::new();
        for field in f.reply {
            // A field nobody reads may have no output (a paging write's count).
            let Some(&(_, ty)) = outs.get(field.out as usize) else {
                assert!(
                    field.to.is_none(),
                    "src/spec/table/: {}: a reply field without its output",
                    f.name
                );
                offsets.push("0".to_string());
                continue;
            };
            let off = match field.to {
                Some(m) if !m.is_empty() => member_offset(&rust_type(ty), m, field.c.size()),
                _ => "0".to_string(),
            };
            let len = field.c.size() * field.n as usize;
            match (field.to, c_size(ty)) {
                (None, _) => {}
                // The scalar output as an array: `n` elements of its width
                // from the pointee on (cnc_sdtread1shot's 8 `unsigned
                // short`s); the header promises their bytes.
                (Some(""), Some(size)) if field.n > 1 && field.c.size() == size => {}
                (Some(_), Some(size)) => assert!(
                    len <= size,
                    "src/spec/table/: {}: {len} bytes written into a {ty}",
                    f.name
                ),
                // A struct member: checked when the crate compiles.
                (Some(_), None) => checks.push(format!(
                    "const _: () = if {off} + {len} > size_of::<{ty}>() {{\n    panic!(\"{}: a reply field does not fit in {ty}\")\n}};\n",
                    f.name
                )),
            }
            offsets.push(off);
        }
        let ios: Vec<String> = f
            .params
            .iter()
            .filter_map(|p| match *p {
                Param::Io(n) => Some(ident(n)),
                _ => None,
            })
            .collect();
        // Lookups (types::Lookup): their members' offsets after the reply
        // fields'; each whole array must fit in output 0.
        for l in f.lookups {
            let (_, ty) = outs[0];
            let off = member_offset(&rust_type(ty), l.to, l.c.size());
            let len = l.c.size() * l.values();
            assert!(
                f.records.is_none() && c_size(ty).is_none(),
                "src/spec/table/: {}: lookups go to a struct, without records",
                f.name
            );
            checks.push(format!(
                "const _: () = if {off} + {len} > size_of::<{ty}>() {{\n    panic!(\"{}: a lookup does not fit in {ty}\")\n}};\n",
                f.name
            ));
            offsets.push(off);
        }
        // Records: where the array starts, one element's size, each field's
        // member in the element; the whole array must fit in a struct output.
        let (records, rec_offsets) = match &f.records {
            // No records: a paging write's count is still the caller's.
            None => (
                "rec_base: 0, rec_stride: 0, rec_count: None".to_string(),
                vec![],
            ),
            Some(r) => {
                let (_, ty) = outs[r.out as usize];
                let base = if r.to.is_empty() {
                    "0".to_string()
                } else {
                    format!("offset_of!({}, {})", rust_type(ty), ident(r.to))
                };
                let (stride, offs) = element(r.elem, r.fields);
                // With a count the output is the caller's array of that many;
                // with a room, of the size the caller gives; records of the
                // output's own struct from its start: the caller's array of
                // `max` (cnc_absolute2_exdgt's ODBEXPOS per axis).
                let own = r.to.is_empty() && r.elem == ty;
                if c_size(ty).is_none() && count.is_none() && r.room.is_none() && !own {
                    checks.push(format!(
                        "const _: () = if {base} + {} * {stride} > size_of::<{ty}>() {{\n    panic!(\"{}: the records do not fit in {ty}\")\n}};\n",
                        r.max, f.name
                    ));
                }
                let member = match r.count {
                    Some(m) => format!("Some(at(offset_of!({}, {})))", rust_type(ty), ident(m)),
                    None => "None".to_string(),
                };
                (
                    format!("rec_base: at({base}), rec_stride: at({stride}), rec_count: {member}"),
                    offs,
                )
            }
        };
        // The text parameters' strings.
        let texts: Vec<String> = f
            .texts()
            .map(|(n, _)| format!("{}.cast_const()", ident(n)))
            .collect();

        // A write's payload: where each field's member is in one element.
        let (input, (pay, pay_offsets, pay_words)) = match (&f.payload, f.input()) {
            (Some(p), Some((n, t))) => {
                let (stride, offs) = element(p.elem, p.fields);
                // The records in a member of the input (types::Func::payload_in):
                // the input members request words carry are the struct's.
                let (base, of) = match f.payload_in {
                    "" => ("0".to_string(), p.elem.to_string()),
                    m => (
                        format!("offset_of!({}, {})", rust_type(t), ident(m)),
                        rust_type(t),
                    ),
                };
                // The input members request words carry, in the first element.
                let words: Vec<String> = f
                    .inputs()
                    .map(|(m, c)| {
                        // A `short`, or a 32-bit `long` (types::Word::Input).
                        let size = if c.size() == 4 { 4 } else { 2 };
                        checks.push(format!(
                            "const _: () = if offset_of!({of}, {m}) + {size} > size_of::<{of}>() {{\n    panic!(\"{}: an input word does not fit in {of}\")\n}};\n",
                            f.name,
                            m = ident(m),
                        ));
                        format!("offset_of!({of}, {})", ident(m))
                    })
                    .collect();
                (
                    format!("{}.cast_const().cast()", ident(n)),
                    (
                        format!("pay_base: at({base}), pay_stride: at({stride})"),
                        offs,
                        words,
                    ),
                )
            }
            // A typed parameter block (types::Block): the one struct.
            (None, Some((n, t))) if f.block.is_some() => (
                format!("{}.cast_const().cast()", ident(n)),
                (
                    format!("pay_base: 0, pay_stride: at(size_of::<{}>())", rust_type(t)),
                    vec![],
                    vec![],
                ),
            ),
            // No payload, or one of the numbers (types::NUMBERS).
            (None, None)
            | (
                Some(types::Payload {
                    count: types::NUMBERS,
                    ..
                }),
                None,
            ) => (
                "std::ptr::null()".to_string(),
                ("pay_base: 0, pay_stride: 0".to_string(), vec![], vec![]),
            ),
            _ => panic!(
                "src/spec/table/: {}: a payload needs one Param::In, and a Param::In a payload",
                f.name
            ),
        };
        // A range's records: `e - s + 1` of them (types::Func::span).
        let span = f.span.map(|(s, e)| {
            let name = |i: u8| f.numbers().nth(usize::from(i)).unwrap_or("?");
            format!("`{} - {} + 1`", name(e), name(s))
        });
        let safety: Vec<String> =
            match &count {
                None => outs
                    .iter()
                    .enumerate()
                    .map(|(i, (n, t))| match (&f.records, c_size(t)) {
                        (Some(r), Some(_)) if usize::from(r.out) == i && span.is_some() => format!(
                            "/// `{n}` must be NULL or point to {} writable `{}` elements (one per record answered).",
                            span.as_deref().unwrap_or_default(),
                            r.elem
                        ),
                        // Records into a scalar output: an array of them, at
                        // most `max`, each the element's size as FANUC's
                        // library writes it (4 bytes per `long`).
                        (Some(r), Some(_)) if usize::from(r.out) == i => {
                            let room = r
                                .room
                                .map(|k| f.numbers().nth(usize::from(k)).unwrap_or("?"));
                            let size = c_size(r.elem).unwrap_or_else(|| {
                                panic!("src/spec/table/: {}: records of {} into a {t}", f.name, r.elem)
                            });
                            let all = usize::from(r.max) * size;
                            match room {
                                Some(k) => format!(
                                    "/// `{n}` must be NULL or point to `{k}` writable bytes (one {size}-byte `{}` per record answered, at most {} = {all} bytes).",
                                    r.elem, r.max
                                ),
                                None => format!(
                                    "/// `{n}` must be NULL or point to {all} writable bytes: one {size}-byte `{}` per record answered, at most {}.",
                                    r.elem, r.max
                                ),
                            }
                        }
                        // Records of the output's own struct: the caller's
                        // array of `max` (cnc_absolute2_exdgt).
                        (Some(r), None) if usize::from(r.out) == i && r.to.is_empty() && r.elem == *t => format!(
                            "/// `{n}` must be NULL or point to {} writable {t}, one per record answered (at most {}).",
                            r.max, r.max
                        ),
                        // Records into a struct with a room: the caller's
                        // `room` bytes, none written past them.
                        (Some(r), None) if usize::from(r.out) == i && r.room.is_some() => {
                            let k = r.room.and_then(|k| f.numbers().nth(usize::from(k))).unwrap_or("?");
                            format!("/// `{n}` must be NULL or point to `{k}` writable bytes (nothing is written past them).")
                        }
                        _ => match text_buf(t).map(|size| format!("/// `{n}` must be NULL or point to {size} writable bytes.")).or_else(|| fixed_array(f, i, t).map(|k| format!(
                                "/// `{n}` must be NULL or point to {} writable bytes: {k} `{t}`s.",
                                k * c_size(t).unwrap_or(0)
                            ))) {
                            Some(text) => text,
                            None => format!("/// `{n}` must be NULL or point to a writable {}.", doc_type(t)),
                        },
                    })
                    .collect(),
                Some(c) => std::iter::once(if f.long_count() {
                    format!("/// `{c}` must be NULL or point to 4 readable and writable bytes (the count).")
                } else {
                    format!("/// `{c}` must be NULL or point to a writable short.")
                })
                .chain(outs.iter().enumerate().map(|(i, (n, t))| {
                    // The records' output is the caller's array of `*count`;
                    // another output (cnc_rdsyssoft3's `total`) one value.
                    match &f.records {
                        Some(r) if usize::from(r.out) != i => {
                            format!("/// `{n}` must be NULL or point to a writable {}.", doc_type(t))
                        }
                        _ => format!("/// `{n}` must be NULL or point to `*{c}` writable {}.", doc_type(t)),
                    }
                }))
                .collect(),
            };
        let mut safety = safety;
        if f.answers().is_some() {
            safety = vec!["/// Nothing is written through the pointers.".to_string()];
        }
        for n in &ios {
            safety.push(format!(
                "/// `{n}` must be NULL or point to a readable and writable short."
            ));
        }
        if let Some(r) = f.block.and_then(|b| b.range.map(|_| b)) {
            // The packed records go to the caller's `*length` bytes.
            let len = f.numbers().nth(usize::from(r.length)).unwrap_or("?");
            for (n, _) in &outs {
                let line = format!("/// `{n}` must be NULL or point to");
                if let Some(l) = safety.iter_mut().find(|l| l.starts_with(&line)) {
                    *l = format!("{line} `*{len}` writable bytes.");
                }
            }
        }
        if let (None, Some((n, t))) = (&f.payload, f.input()) {
            safety.push(format!(
                "/// `{n}` must be NULL or point to a readable {}.",
                doc_type(t)
            ));
        }
        if let (Some(p), Some((n, t))) = (&f.payload, f.input()) {
            let room = f
                .pages
                .and_then(|pg| pg.room)
                .and_then(|(a, _)| f.numbers().nth(usize::from(a)));
            match f.numbers().nth(usize::from(p.count)) {
                // The records in a member (types::Func::payload_in), read
                // within the caller's size (types::Pages::room).
                _ if !f.payload_in.is_empty() => safety.push(format!(
                    "/// `{n}` must be NULL or point to `{}` readable bytes: a {} whose `{}` array holds a record for each number written.",
                    room.unwrap_or("?"),
                    doc_type(t),
                    f.payload_in,
                )),
                // types::TEXT: read up to its NUL, at most the field's bytes.
                _ if p.count == types::SPAN => safety.push(format!(
                    "/// `{n}` must be NULL or point to {} readable `{t}` elements.",
                    span.as_deref().unwrap_or_default(),
                )),
                _ if p.count == types::TEXT => safety.push(format!(
                    "/// `{n}` must be NULL or point to {} readable bytes, or to a C string ending within them.",
                    p.fields.iter().map(|x| x.wire_len()).sum::<usize>()
                )),
                // Paging: every record of the caller's count is read.
                Some(count) if f.pages.is_some() => safety.push(format!(
                    "/// `{n}` must be NULL or point to `*{count}` readable {}.",
                    doc_type(t)
                )),
                Some(count) => safety.push(format!(
                    "/// `{n}` must be NULL or point to `{count}` readable {} (at most {} are read).",
                    doc_type(t),
                    p.max
                )),
                // types::ONE: the one element it points to; its members
                // sent as request words are written back converted.
                None if f.inputs().next().is_some() => safety.push(format!(
                    "/// `{n}` must be NULL or point to a readable and writable {}.",
                    doc_type(t)
                )),
                None => safety.push(format!(
                    "/// `{n}` must be NULL or point to a readable {}.",
                    doc_type(t)
                )),
            }
        }
        for (n, size) in f.texts() {
            safety.push(format!(
                "/// `{n}` must be NULL or point to {size} readable bytes, or to a C string ending within them."
            ));
        }
        assert!(
            f.numbers().count() + f.inputs().count() <= 8,
            "src/spec/table/: {}: more arguments than exec takes (MAX_NUMBERS)",
            f.name
        );
        assert!(
            outs.len() <= 4 && ios.len() <= 4 && texts.len() <= 4,
            "src/spec/table/: {}: more outputs, numbers by pointer or texts than a Call holds (MAX_POINTERS)",
            f.name
        );
        let pointers = !outs.is_empty() || f.input().is_some() || f.texts().next().is_some();
        s.push_str(&format!(
            r#"
{doc}{safety}
#[unsafe(no_mangle)]
pub {unsafe_}extern "C" fn {name}(FlibHndl: c_ushort{params}) -> c_short {{
    static SITE: Site = Site {{
        func: {i},
        batch: {batch},
        numbers: {n_numbers},
        outs: {n_outs},
        io: {n_io},
        texts: {n_texts},
        {records},
        {pay},
        lens: [{lens}],
        data: &[{data}],
    }};
    // SAFETY: the outputs are the caller's, as documented; none without pointers.
    unsafe {{
        run(
            &SITE,
            FlibHndl,
            Call {{
                numbers: [{numbers}],
                outs: [{out_ptrs}],
                asked: {asked},
                io: [{ios}],
                input: {input},
                texts: [{texts}],
            }},
        )
    }}
}}
{checks}"#,
            doc = wrap_doc(f.doc),
            // Pointer parameters make the function unsafe to call.
            safety = if pointers {
                format!("\n///\n/// # Safety\n{}", safety.join("\n"))
            } else {
                String::new()
            },
            unsafe_ = if pointers { "unsafe " } else { "" },
            // A read may join a batch (fwlib_batch_begin); a command not,
            // nor a range read (its next request needs the answer), nor a
            // paging read (several exchanges, as cnc_rdtool), nor a read
            // cut per answer (types::Word::Upto reading on: a full answer asks again,
            // cnc_rdpmacror).
            batch = !(outs.is_empty()
                || f.answers().is_some()
                || f.block.is_some_and(|b| b.range.is_some())
                || f.pages.is_some()
                || f.forms.iter().any(|fm| {
                    fm.words
                        .iter()
                        .any(|w| matches!(w, types::Word::Upto(_, _, _, true)))
                })),
            n_numbers = numbers.len(),
            n_outs = out_ptrs.len(),
            n_io = ios.len(),
            n_texts = texts.len(),
            // A Param::LongCount's 4 bytes are read through the same pointer.
            asked = match (&count, f.long_count()) {
                (Some(c), true) => format!("{c}.cast()"),
                (Some(c), false) => c.clone(),
                (None, _) => "std::ptr::null_mut()".to_string(),
            },
            ios = padded(&ios, "std::ptr::null_mut()", 4),
            input = input,
            texts = padded(&texts, "std::ptr::null()", 4),
            name = f.name,
            params = params.iter().map(|p| format!(", {p}")).collect::<String>(),
            checks = checks.concat(),
            numbers = padded(&numbers, "0", 8),
            out_ptrs = padded(&out_ptrs, "std::ptr::null_mut()", 4),
            lens = [&offsets, &rec_offsets, &pay_offsets, &pay_words]
                .map(|l| l.len().to_string())
                .join(", "),
            data = narrow(&[offsets, rec_offsets, pay_offsets, pay_words].concat()),
            records = records,
            pay = pay,
        ));
    }
    s
}

/// An array element's layout in Rust: its size, and the offset of each
/// field's member in it (`""` or no member: 0).
fn element(elem: &str, fields: &[types::Field]) -> (String, Vec<String>) {
    let stride = match c_size(elem) {
        Some(n) => n.to_string(),
        None => format!("size_of::<{elem}>()"),
    };
    let offsets = fields
        .iter()
        .map(|x| match x.to {
            Some(m) if !m.is_empty() => member_offset(elem, m, x.c.size()),
            _ => "0".to_string(),
        })
        .collect();
    (stride, offsets)
}

/// The byte offset of member `m` of struct `ty`: `name`, or `name[i]`
/// (element i of an array member, `size` bytes each; `[i]`: of `ty`
/// itself, an array).
fn member_offset(ty: &str, m: &str, size: usize) -> String {
    match m.strip_suffix(']').and_then(|x| x.split_once('[')) {
        Some((name, i)) => {
            let i: usize = i
                .parse()
                .unwrap_or_else(|_| panic!("src/spec/table/: member {m}"));
            match name {
                // An element of the array the record element itself is.
                "" => (i * size).to_string(),
                // Element 0: the member's own offset (no `+ 0`).
                name if i == 0 => format!("offset_of!({ty}, {})", ident(name)),
                name => format!("offset_of!({ty}, {}) + {}", ident(name), i * size),
            }
        }
        None => format!("offset_of!({ty}, {})", ident(m)),
    }
}

/// `text` as `///` lines of at most 76 columns.
/// `items` then `fill` up to `len` of them, as a Rust array's elements
/// (ffi::described's `Call`: MAX_NUMBERS, MAX_POINTERS).
fn padded(items: &[String], fill: &str, len: usize) -> String {
    assert!(items.len() <= len, "{items:?}: more than {len}");
    let mut all = items.to_vec();
    all.resize(len, fill.to_string());
    all.join(", ")
}

fn wrap_doc(text: &str) -> String {
    let mut lines = vec![String::from("///")];
    for w in text.split_whitespace() {
        let last = lines.last_mut().unwrap();
        if last.len() + 1 + w.len() > 76 && last.len() > 3 {
            lines.push(format!("/// {w}"));
        } else {
            last.push(' ');
            last.push_str(w);
        }
    }
    lines.join("\n")
}

/// A C name as a Rust identifier (`type` is `r#type`).
fn ident(name: &str) -> String {
    match name {
        "type" | "match" | "loop" | "move" | "ref" | "mod" | "use" | "fn" | "impl" => {
            format!("r#{name}")
        }
        n => n.to_string(),
    }
}

/// The Rust type of an output's C type.
fn rust_type(c: &str) -> String {
    match c {
        "char" => "c_char".into(),
        "short" => "c_short".into(),
        "unsigned short" => "c_ushort".into(),
        "long" => "c_long".into(),
        "unsigned long" => "c_ulong".into(),
        "double" => "f64".into(),
        "void" => "c_void".into(),
        t => match (char_array(t), text_buf(t)) {
            (Some(n), _) => format!("[c_char; {n}]"),
            (_, Some(_)) => "c_char".into(),
            _ => t.into(),
        },
    }
}

/// A C type in a doc comment: an array type (`char[62]`) quoted as code, so
/// rustdoc reads no link in its brackets.
fn doc_type(t: &str) -> String {
    if t.contains('[') {
        format!("`{t}`")
    } else {
        t.to_owned()
    }
}

/// N of a `text[N]` output: a `char *` to N bytes.
fn text_buf(c: &str) -> Option<usize> {
    c.strip_prefix("text[")?.strip_suffix(']')?.parse().ok()
}

/// The elements a function's fixed reply fields write into its scalar
/// output `i` (of C type `t`) as an array (a field of `to: ""` and `n` of
/// them, of `t`'s width), if more than one.
fn fixed_array(f: &types::Func, i: usize, t: &str) -> Option<usize> {
    let size = c_size(t)?;
    f.reply
        .iter()
        .filter(|x| usize::from(x.out) == i && x.to == Some("") && x.c.size() == size)
        .map(|x| usize::from(x.n))
        .max()
        .filter(|&k| k > 1)
}

/// N of a `char[N]` output.
fn char_array(c: &str) -> Option<usize> {
    c.strip_prefix("char[")?.strip_suffix(']')?.parse().ok()
}

/// The bytes a scalar output of C type `c` has (`long`: the 4 FANUC's
/// x86-64 library writes); None for a struct.
fn c_size(c: &str) -> Option<usize> {
    match c {
        "char" => Some(1),
        "short" | "unsigned short" => Some(2),
        // 4 bytes written, as FANUC's x86-64 library writes them.
        "long" | "unsigned long" => Some(4),
        "double" => Some(8),
        t => char_array(t).or_else(|| text_buf(t)),
    }
}
