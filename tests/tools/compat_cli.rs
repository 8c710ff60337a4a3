//! `focas compat`: the C examples, built against our header and library,
//! use only functions we support (exit 0); a program built against another
//! libfwlib32 (a stub standing in for FANUC's) that calls a function we
//! lack is told so (exit 1), and one calling a function FANUC's Ethernet
//! library answers EW_VERSION is told that.

use crate::toolchain;

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Output;

fn root() -> PathBuf {
    toolchain::manifest_dir()
}

/// `focas ARGS...` (no CNC: no --host, none in the environment).
fn focas(args: &[&str]) -> Output {
    toolchain::output(
        toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
            .env_remove("FOCAS_HOST")
            .args(args),
    )
}

fn cc(args: &[&str]) {
    toolchain::run(std::process::Command::new(toolchain::cc()).args(args));
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// `focas --json compat FILE`: its exit code and its one JSON line.
fn compat_json(file: &Path) -> (Option<i32>, Value) {
    let o = focas(&["--json", "compat", path(file)]);
    let out = String::from_utf8(o.stdout).unwrap();
    assert_eq!(out.lines().count(), 1, "{out}");
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    (o.status.code(), serde_json::from_str(&out).unwrap())
}

/// The status of each function in a `--json` report.
fn statuses(j: &Value) -> Vec<(String, String)> {
    j["functions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            (
                f["name"].as_str().unwrap().to_string(),
                f["status"].as_str().unwrap().to_string(),
            )
        })
        .collect()
}

#[test]
fn the_c_examples_use_only_supported_functions() {
    let dir = toolchain::lib_dir("compat-examples");
    let inc = root().join("include");
    for name in ["status", "adapter", "data"] {
        let src = root().join("c-examples").join(format!("{name}.c"));
        let exe = dir.join(name);
        cc(&[
            "-std=c99",
            "-I",
            path(&inc),
            path(&src),
            "-L",
            path(&dir),
            "-lfwlib32",
            "-o",
            path(&exe),
        ]);
        let o = focas(&["compat", path(&exe)]);
        let text = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(0), "{name}: {text}");
        assert!(o.stderr.is_empty());
        assert!(text.contains("cnc_allclibhndl3  "), "{name}: {text}");
        assert!(text.contains(" 0 missing\n"), "{name}: {text}");
        assert!(!text.contains("MISSING"), "{name}: {text}");
        // In the user's words: how a function is made is ours to know.
        assert!(!text.contains("described"), "{name}: {text}");

        let (code, j) = compat_json(&exe);
        assert_eq!(code, Some(0));
        let st = statuses(&j);
        assert!(st.len() >= 4, "{name}: {j}");
        assert!(st.iter().all(|(_, s)| s == "supported"), "{name}: {j}");
        assert!(
            st.iter().any(|(f, _)| f == "cnc_freelibhndl"),
            "{name}: {j}"
        );
        assert_eq!(j["supported"], st.len());
        assert_eq!(
            (j["missing"].clone(), j["not_on_ethernet"].clone()),
            (0.into(), 0.into())
        );
        assert_eq!(j["bits"], 64);
        assert_eq!(j["loadable"], true);
        assert_eq!(j["file"], path(&exe));
    }
}

/// A program built against a stand-in for FANUC's libfwlib32.so.1 that
/// defines the functions `prog` calls; returns the program.
fn build_against_stub(dir: &Path, stub: &str, prog: &str) -> PathBuf {
    let stub_c = dir.join("stub.c");
    std::fs::write(&stub_c, stub).unwrap();
    let so = dir.join("libfwlib32.so.1");
    cc(&[
        "-shared",
        "-fPIC",
        "-Wl,-soname,libfwlib32.so.1",
        path(&stub_c),
        "-o",
        path(&so),
    ]);
    std::os::unix::fs::symlink("libfwlib32.so.1", dir.join("libfwlib32.so")).unwrap();
    let prog_c = dir.join("prog.c");
    std::fs::write(&prog_c, prog).unwrap();
    let exe = dir.join("prog");
    let inc = root().join("include");
    cc(&[
        "-Wall",
        "-Werror",
        "-I",
        path(&inc),
        path(&prog_c),
        "-L",
        path(dir),
        "-lfwlib32",
        "-o",
        path(&exe),
    ]);
    exe
}

#[test]
fn a_function_we_lack_is_missing() {
    let dir = toolchain::scratch("compat-missing");
    // cnc_dwnstart3_f is FANUC's (program download), not in our header: the
    // program declares it itself.
    let exe = build_against_stub(
        &dir,
        "short cnc_allclibhndl3(const char *a, unsigned short b, long c, unsigned short *d)\
         { (void)a; (void)b; (void)c; (void)d; return -15; }\n\
         short cnc_dwnstart3_f(unsigned short a, short b, char *c, char *d) { (void)a; (void)b; (void)c; (void)d; return -15; }\n\
         short cnc_rdexecpt(unsigned short a, void *b, void *c) { (void)a; (void)b; (void)c; return -15; }\n\
         short cnc_freelibhndl(unsigned short a) { (void)a; return -15; }\n",
        "#include \"fwlib32.h\"\n\
         short cnc_dwnstart3_f(unsigned short, short, char *, char *);\n\
         int main(void) {\n\
             unsigned short h = 0;\n\
             PRGPNT a, b;\n\
             char path[] = \"//CNC_MEM/USER/PATH1/\";\n\
             if (cnc_allclibhndl3(\"127.0.0.1\", 8193, 10, &h)) return 1;\n\
             cnc_rdexecpt(h, &a, &b);\n\
             cnc_dwnstart3_f(h, 0, path, path);\n\
             return cnc_freelibhndl(h);\n\
         }\n",
    );
    let o = focas(&["compat", path(&exe)]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{text}");
    assert!(o.stderr.is_empty());
    let line = |f: &str| {
        text.lines()
            .find(|l| l.starts_with(&format!("{f} ")))
            .unwrap_or_else(|| panic!("no line for {f}: {text}"))
            .to_string()
    };
    assert!(line("cnc_dwnstart3_f").contains("MISSING"), "{text}");
    assert!(
        line("cnc_dwnstart3_f").contains("FANUC's Linux library has it"),
        "{text}"
    );
    assert!(line("cnc_rdexecpt").contains("EW_VERSION"), "{text}");
    assert!(line("cnc_allclibhndl3").contains("supported"), "{text}");
    assert!(text.contains("2 supported, 1 not on Ethernet"), "{text}");
    assert!(text.contains(", 1 missing\n"), "{text}");
    assert!(text.contains("symbol lookup error"), "{text}");

    let (code, j) = compat_json(&exe);
    assert_eq!(code, Some(1));
    assert_eq!(
        statuses(&j),
        [
            ("cnc_allclibhndl3", "supported"),
            ("cnc_dwnstart3_f", "missing"),
            ("cnc_freelibhndl", "supported"),
            ("cnc_rdexecpt", "not_on_ethernet"),
        ]
        .map(|(a, b)| (a.to_string(), b.to_string()))
    );
    let f = &j["functions"][1];
    assert_eq!(f["fanuc_header"], true);
    assert_eq!(f["fanuc_linux"], true);
    assert_eq!(f["how"], Value::Null);
    assert_eq!(
        (j["supported"].clone(), j["missing"].clone()),
        (2.into(), 1.into())
    );

    // The same calls from a shared library (a plug-in, a language binding).
    let so = dir.join("libplugin.so");
    cc(&[
        "-shared",
        "-fPIC",
        "-I",
        path(&root().join("include")),
        path(&dir.join("prog.c")),
        "-o",
        path(&so),
    ]);
    let o = focas(&["compat", path(&so)]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{text}");
    assert!(
        text.contains("shared library, 4 FOCAS functions used"),
        "{text}"
    );
}

#[test]
fn an_ew_version_function_is_reported_as_such() {
    let dir = toolchain::scratch("compat-ew-version");
    let exe = build_against_stub(
        &dir,
        "short cnc_allclibhndl3(const char *a, unsigned short b, long c, unsigned short *d)\
         { (void)a; (void)b; (void)c; (void)d; return -15; }\n\
         short cnc_rdexecpt(unsigned short a, void *b, void *c) { (void)a; (void)b; (void)c; return -15; }\n\
         short cnc_freelibhndl(unsigned short a) { (void)a; return -15; }\n",
        "#include \"fwlib32.h\"\n\
         int main(void) {\n\
             unsigned short h = 0;\n\
             PRGPNT a, b;\n\
             if (cnc_allclibhndl3(\"127.0.0.1\", 8193, 10, &h)) return 1;\n\
             cnc_rdexecpt(h, &a, &b);\n\
             return cnc_freelibhndl(h);\n\
         }\n",
    );
    let o = focas(&["compat", path(&exe)]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{text}");
    let line = text
        .lines()
        .find(|l| l.starts_with("cnc_rdexecpt "))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(
        line.contains("EW_VERSION")
            && line.contains(
                "answers EW_VERSION (-7) without a request, as FANUC's Ethernet library does"
            ),
        "{line}"
    );
    assert!(text.contains(" 0 missing\n"), "{text}");

    let (code, j) = compat_json(&exe);
    assert_eq!(code, Some(0));
    let f = j["functions"]
        .as_array()
        .unwrap()
        .iter()
        .find(|f| f["name"] == "cnc_rdexecpt")
        .unwrap()
        .clone();
    assert_eq!(f["status"], "not_on_ethernet");
    assert_eq!(f["ew"], "EW_VERSION");
    assert_eq!(f["code"], -7);
    assert_eq!(f["fanuc_header"], true);
    assert_eq!(f["fanuc_linux"], false);
    assert_eq!(j["not_on_ethernet"], 1);
}

#[test]
fn a_file_that_is_not_elf_is_one_line_on_stderr() {
    let o = focas(&["compat", path(&root().join("README.md"))]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("focas: ") && err.contains("not an ELF file"),
        "{err}"
    );
    assert!(o.stdout.is_empty());
    let o = focas(&["compat", "/nonexistent/program"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("/nonexistent/program"));
}

/// The README's example: its output is what `focas compat` prints for that
/// program (built for x86-64 there; for the target here).
#[test]
fn the_readme_example_is_true() {
    let dir = toolchain::scratch("compat-readme");
    build_against_stub(
        &dir,
        "short cnc_allclibhndl3(const char *a, unsigned short b, long c, unsigned short *d)\
         { (void)a; (void)b; (void)c; (void)d; return -15; }\n\
         short cnc_dwnstart3_f(unsigned short a, short b, char *c, char *d) { (void)a; (void)b; (void)c; (void)d; return -15; }\n\
         short cnc_rdexecpt(unsigned short a, void *b, void *c) { (void)a; (void)b; (void)c; return -15; }\n\
         short cnc_statinfo(unsigned short a, void *b) { (void)a; (void)b; return -15; }\n\
         short cnc_freelibhndl(unsigned short a) { (void)a; return -15; }\n",
        "#include \"fwlib32.h\"\n\
         short cnc_dwnstart3_f(unsigned short, short, char *, char *);\n\
         int main(void) {\n\
             unsigned short h = 0;\n\
             PRGPNT a, b;\n\
             ODBST st;\n\
             char path[] = \"//CNC_MEM/USER/PATH1/\";\n\
             if (cnc_allclibhndl3(\"127.0.0.1\", 8193, 10, &h)) return 1;\n\
             cnc_statinfo(h, &st);\n\
             cnc_rdexecpt(h, &a, &b);\n\
             cnc_dwnstart3_f(h, 0, path, path);\n\
             return cnc_freelibhndl(h);\n\
         }\n",
    );
    std::fs::rename(dir.join("prog"), dir.join("my-adapter")).unwrap();
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let want: String = readme
        .split("$ focas compat ./my-adapter\n")
        .nth(1)
        .expect("README shows `focas compat ./my-adapter`")
        .lines()
        .take_while(|l| !l.starts_with("```"))
        .map(|l| format!("{l}\n"))
        .collect();
    let arch = if cfg!(target_arch = "aarch64") {
        "aarch64"
    } else {
        "x86-64"
    };
    let want = want.replacen(": x86-64 program", &format!(": {arch} program"), 1);
    let o = toolchain::output(
        toolchain::target_command(env!("CARGO_BIN_EXE_focas"))
            .current_dir(&dir)
            .args(["compat", "./my-adapter"]),
    );
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(String::from_utf8_lossy(&o.stdout), want);
}

/// A program that loads the library itself (dlopen) and looks its
/// functions up by name (dlsym) links none of them: compat finds their
/// names in its strings, and says they are only mentioned.
#[test]
fn a_dlopen_program_names_its_functions_in_its_strings() {
    let dir = toolchain::scratch("compat-dlopen");
    let src = dir.join("dl.c");
    std::fs::write(
        &src,
        "#include <dlfcn.h>\n\
         #include <stdio.h>\n\
         typedef short (*alloc_t)(const char *, unsigned short, long, unsigned short *);\n\
         typedef short (*stat_t)(unsigned short, void *);\n\
         int main(void) {\n\
             void *lib = dlopen(\"libfwlib32.so.1\", RTLD_NOW);\n\
             if (!lib) { fprintf(stderr, \"%s\\n\", dlerror()); return 1; }\n\
             alloc_t alloc = (alloc_t)dlsym(lib, \"cnc_allclibhndl3\");\n\
             stat_t stat = (stat_t)dlsym(lib, \"cnc_statinfo\");\n\
             void *exec = dlsym(lib, \"cnc_rdexecpt\");\n\
             void *dwn = dlsym(lib, \"cnc_dwnstart3_f\");\n\
             printf(\"%p %p %p %p\\n\", (void *)alloc, (void *)stat, exec, dwn);\n\
             return 0;\n\
         }\n",
    )
    .unwrap();
    let exe = dir.join("dl");
    cc(&[path(&src), "-o", path(&exe), "-ldl"]);
    let o = focas(&["compat", path(&exe)]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "one is missing: {text}");
    assert!(o.stderr.is_empty());
    assert!(
        text.contains("program, 0 FOCAS functions linked, 4 named in its strings\n"),
        "{text}"
    );
    assert!(text.contains("only mentioned"), "{text}");
    let line = |f: &str| {
        text.lines()
            .find(|l| l.starts_with(&format!("{f} ")))
            .unwrap_or_else(|| panic!("no line for {f}: {text}"))
            .to_string()
    };
    assert!(line("cnc_allclibhndl3").contains("supported"), "{text}");
    assert!(line("cnc_statinfo").contains("supported"), "{text}");
    assert!(line("cnc_rdexecpt").contains("EW_VERSION"), "{text}");
    assert!(line("cnc_dwnstart3_f").contains("MISSING"), "{text}");
    assert!(text.contains("dlsym"), "{text}");
    assert!(!text.contains("symbol lookup error"), "{text}");

    let (code, j) = compat_json(&exe);
    assert_eq!(code, Some(1));
    let f = j["functions"].as_array().unwrap();
    assert_eq!(f.len(), 4, "{j}");
    assert!(f.iter().all(|f| f["linked"] == false), "{j}");
    assert_eq!(
        (j["supported"].clone(), j["missing"].clone()),
        (2.into(), 1.into())
    );
}

/// Source files: the FOCAS names they contain, whatever the language.
#[test]
fn source_files_list_the_focas_names_they_call() {
    let dir = toolchain::scratch("compat-sources");
    for (file, text, lang, names, code) in [
        (
            "poll.py",
            "import ctypes\nlib = ctypes.cdll.LoadLibrary(\"libfwlib32.so\")\n\
             h = ctypes.c_ushort()\ncnc_handle = None  # not a function\n\
             lib.cnc_allclibhndl3(b\"10.0.0.5\", 8193, 10, ctypes.byref(h))\n\
             lib.cnc_statinfo(h, ctypes.byref(st))\nlib.cnc_freelibhndl(h)\n",
            "Python",
            &["cnc_allclibhndl3", "cnc_freelibhndl", "cnc_statinfo"][..],
            0,
        ),
        (
            "Focas.java",
            "public interface Fwlib32 extends Library {\n  \
             short cnc_allclibhndl3(String ip, short port, int timeout, ShortByReference h);\n  \
             short cnc_dwnstart3_f(short h, short type, String a, String b);\n}\n",
            "Java",
            &["cnc_allclibhndl3", "cnc_dwnstart3_f"][..],
            1,
        ),
        (
            "Focas1.cs",
            "[DllImport(\"fwlib32.dll\")]\npublic static extern short cnc_rdexecpt(ushort h, PRGPNT a, PRGPNT b);\n\
             [DllImport(\"fwlib32.dll\")]\npublic static extern short pmc_rdpmcrng(ushort h, short a, short t, ushort s, ushort e, ushort l, IODBPMC0 b);\n",
            "C#",
            &["cnc_rdexecpt", "pmc_rdpmcrng"][..],
            0,
        ),
        (
            "poll.go",
            "// #cgo LDFLAGS: -lfwlib32\n// #include \"fwlib32.h\"\nimport \"C\"\n\
             func status(h C.ushort) { var st C.ODBST; C.cnc_statinfo(h, &st) }\n",
            "Go",
            &["cnc_statinfo"][..],
            0,
        ),
        (
            "adapter.c",
            "#include \"fwlib32.h\"\nint main(void) { unsigned short h;\n\
             return cnc_allclibhndl3(\"cnc\", 8193, 10, &h) || cnc_rdparam(h, 6711, 0, 8, 0); }\n",
            "C",
            &["cnc_allclibhndl3", "cnc_rdparam"][..],
            0,
        ),
    ] {
        let f = dir.join(file);
        std::fs::write(&f, text).unwrap();
        let o = focas(&["compat", path(&f)]);
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(code), "{file}: {out}");
        let head = format!(
            "{}: {lang} source, {} FOCAS function{} named\n",
            path(&f),
            names.len(),
            if names.len() == 1 { "" } else { "s" }
        );
        assert!(out.starts_with(&head), "{file}: {out}");
        let (_, j) = compat_json(&f);
        assert_eq!(j["source"], lang);
        let got: Vec<&str> = j["functions"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["name"].as_str().unwrap())
            .collect();
        assert_eq!(got, names, "{file}: {j}");
    }
}

/// The families data collectors call (operator panel signals, system and
/// software IDs, 8-digit programs, P-code macros, settings, magazine and
/// tool information, spindle and position errors): a program calling every
/// one of them, built against a stand-in for FANUC's library, is told
/// nothing is missing.
#[test]
fn the_collector_families_are_all_supported() {
    #[rustfmt::skip]
    const FAMILIES: &[&str] = &[
        "cnc_rdopnlsgnl", "cnc_wropnlsgnl", "cnc_rdopnlgnrl", "cnc_wropnlgnrl", "cnc_rdopnlgsname", "cnc_wropnlgsname",
        "cnc_rdsyshard", "cnc_rdsyssoft3", "cnc_rdsyssoft", "cnc_rdsyssoft2", "cnc_rdsyssoft3_str", "cnc_rdservoid", "cnc_rdspindleid", "cnc_rdfromservoid", "cnc_rdfromspindleid",
        "cnc_rdprgnumo8", "cnc_rddynamico8", "cnc_rdprogdiro8", "cnc_rdprogdir2o8", "cnc_searcho8", "cnc_deleteo8", "cnc_rdmdipntro8",
        "cnc_rdpmacro", "cnc_wrpmacro", "cnc_rdpmacror", "cnc_rdpmacroinfo", "cnc_rdpmacroinfo2", "cnc_rdmacronum",
        "cnc_rdsetnum", "cnc_rdset", "cnc_wrset", "cnc_rdsetr",
        "cnc_rdtlinfo", "cnc_rdmaxgrp", "cnc_rdmaxtool", "cnc_rdusegrpid", "cnc_rd1tlifedata", "cnc_rd2tlifedata", "cnc_wrmagazine", "cnc_wrtool",
        "cnc_rdmagazine", "cnc_regmagazine", "cnc_delmagazine", "cnc_regtool", "cnc_regtool_f2",
        "cnc_rdnspdl", "cnc_rdspcss", "cnc_rdcommand", "cnc_rd3dtooltip", "cnc_rdposerrs", "cnc_rdposerrs2", "cnc_rdposerrz",
    ];
    let dir = toolchain::scratch("compat-collectors");
    let stub: String = FAMILIES
        .iter()
        .map(|f| format!("short {f}(void) {{ return -15; }}\n"))
        .collect();
    let decls: String = FAMILIES
        .iter()
        .map(|f| format!("short {f}(void);\n"))
        .collect();
    let calls: String = FAMILIES
        .iter()
        .map(|f| format!("    r |= {f}();\n"))
        .collect();
    let prog = format!("{decls}int main(void) {{\n    short r = 0;\n{calls}    return r;\n}}\n");
    let exe = build_against_stub(&dir, &stub, &prog);
    let o = focas(&["compat", path(&exe)]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{text}");
    assert!(text.contains(" 0 missing\n"), "{text}");
    let (code, j) = compat_json(&exe);
    assert_eq!(code, Some(0));
    let st = statuses(&j);
    assert_eq!(st.len(), FAMILIES.len(), "{j}");
    for (f, s) in &st {
        assert_eq!(s, "supported", "{f}: {j}");
    }
}
