//! Helpers shared by the tests that build and run C programs: the C toolchain
//! (cc, c++, nm, readelf, each overridable through $CC, $CXX, $NM, $READELF for
//! a cross build), cargo's runner for the target, scratch directories, and
//! reading include/fwlib32.h. A missing tool fails the test with a clear message;
//! nothing is skipped.

#![allow(dead_code)]

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub fn manifest_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The committed header, include/fwlib32.h.
pub fn header_path() -> PathBuf {
    manifest_dir().join("include").join("fwlib32.h")
}

/// include/fwlib32_ext.h: our `fwlib_*` extensions.
pub fn ext_header_path() -> PathBuf {
    manifest_dir().join("include").join("fwlib32_ext.h")
}

pub fn header_text() -> String {
    let p = header_path();
    std::fs::read_to_string(&p).unwrap_or_else(|e| {
        panic!(
            "cannot read {}: {e}; run `FWLIB32_UPDATE_HEADER=1 cargo build` to generate it",
            p.display()
        )
    })
}

/// The C compiler: `$CC`, else `cc`.
pub fn cc() -> String {
    std::env::var("CC").unwrap_or_else(|_| "cc".to_owned())
}

/// The C++ compiler: `$CXX`, else `c++`.
pub fn cxx() -> String {
    std::env::var("CXX").unwrap_or_else(|_| "c++".to_owned())
}

/// `nm`: `$NM`, else `nm` (a cross build names its target's, e.g.
/// `aarch64-linux-gnu-nm`).
pub fn nm() -> String {
    std::env::var("NM").unwrap_or_else(|_| "nm".to_owned())
}

/// `readelf`: `$READELF`, else `readelf`.
pub fn readelf() -> String {
    std::env::var("READELF").unwrap_or_else(|_| "readelf".to_owned())
}

/// cargo's runner for the target these tests were built for
/// (`CARGO_TARGET_<TRIPLE>_RUNNER`, e.g. `qemu-aarch64 -L /` for a cross build),
/// split on whitespace; empty when unset.
pub fn runner() -> Vec<String> {
    let triple = env!("FWLIB32_TARGET")
        .to_uppercase()
        .replace(['-', '.'], "_");
    std::env::var(format!("CARGO_TARGET_{triple}_RUNNER"))
        .map(|r| r.split_whitespace().map(str::to_owned).collect())
        .unwrap_or_default()
}

/// A command running `exe`, a program built for the target (a C program the
/// test compiled, or one of the crate's binaries): directly, or through cargo's
/// runner for the target when one is set.
pub fn target_command(exe: impl AsRef<std::ffi::OsStr>) -> Command {
    let runner = runner();
    match runner.split_first() {
        None => Command::new(exe),
        Some((prog, args)) => {
            let mut cmd = Command::new(prog);
            cmd.args(args).arg(exe);
            cmd
        }
    }
}

/// `exe` as a shell command line, through cargo's runner for the target when
/// one is set (for script(1), which runs its command through the shell).
pub fn target_command_line(exe: &str) -> String {
    let mut words = runner();
    words.push(exe.to_owned());
    words.join(" ")
}

/// Runs a command to completion; panics with its output unless it succeeds.
/// A tool that cannot be started fails with a message naming it.
pub fn run(cmd: &mut Command) -> Output {
    let out = output(cmd);
    if !out.status.success() {
        panic!(
            "`{}` failed ({}):\n--- stdout ---\n{}\n--- stderr ---\n{}",
            describe(cmd),
            out.status,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
    out
}

/// Runs a command to completion, whatever its exit status. A tool that cannot
/// be started fails with a message naming it.
pub fn output(cmd: &mut Command) -> Output {
    cmd.output().unwrap_or_else(|e| {
        panic!(
            "cannot run `{}`: {e}.\nThese tests need a C toolchain on PATH: cc and c++ \
             (or $CC / $CXX), and binutils (nm, readelf). Install them, e.g. \
             `apt-get install build-essential binutils`.",
            cmd.get_program().to_string_lossy()
        )
    })
}

fn describe(cmd: &Command) -> String {
    let mut s = cmd.get_program().to_string_lossy().into_owned();
    for a in cmd.get_args() {
        s.push(' ');
        s.push_str(&a.to_string_lossy());
    }
    s
}

/// A fresh, empty scratch directory for one test under
/// `target/tmp/fwlib32-c-tests/NAME-PID`, removed when the value is dropped.
/// What a test left there and could not remove (a test that panicked while a
/// static held it, a killed run) goes at the next run: directories of
/// processes no longer alive are removed on the way in.
pub struct Scratch(PathBuf);

impl std::ops::Deref for Scratch {
    type Target = PathBuf;
    fn deref(&self) -> &PathBuf {
        &self.0
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<std::ffi::OsStr> for Scratch {
    fn as_ref(&self) -> &std::ffi::OsStr {
        self.0.as_os_str()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn scratch_root() -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join("fwlib32-c-tests")
}

/// Removes the scratch directories of earlier test processes that are gone.
fn prune_dead_scratch() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let Ok(entries) = std::fs::read_dir(scratch_root()) else {
            return;
        };
        for e in entries.flatten() {
            let name = e.file_name();
            let pid = name
                .to_str()
                .and_then(|n| n.rsplit_once('-'))
                .and_then(|(_, pid)| pid.parse::<u32>().ok());
            let alive = pid.is_some_and(|p| Path::new(&format!("/proc/{p}")).exists());
            if !alive {
                let _ = std::fs::remove_dir_all(e.path());
            }
        }
    });
}

pub fn scratch(name: &str) -> Scratch {
    prune_dead_scratch();
    let dir = scratch_root().join(format!("{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("create {}: {e}", dir.display()));
    Scratch(dir)
}

/// A fresh scratch directory holding the built library as `libfwlib32.so.1`
/// (the SONAME a program linked with `-lfwlib32` asks the loader for) and
/// `libfwlib32.so` -> it (the name `-lfwlib32` links): for `-L` and
/// `LD_LIBRARY_PATH`. `libfwlib32.so.1` is a link to the library cargo built,
/// not a copy (a debug build is about 46 MB).
pub fn lib_dir(name: &str) -> Scratch {
    let dir = scratch(name);
    let so = cdylib();
    let so = std::fs::canonicalize(&so).unwrap_or_else(|e| panic!("{}: {e}", so.display()));
    std::os::unix::fs::symlink(&so, dir.join("libfwlib32.so.1"))
        .unwrap_or_else(|e| panic!("link {}: {e}", so.display()));
    std::os::unix::fs::symlink("libfwlib32.so.1", dir.join("libfwlib32.so")).unwrap();
    dir
}

/// `(kind, name)` of every `typedef struct X {` / `typedef union X {` in a header.
pub fn header_typedefs(header: &str) -> Vec<(String, String)> {
    header
        .lines()
        .filter_map(|l| {
            let mut w = l.split_whitespace();
            match (w.next(), w.next(), w.next(), w.next()) {
                (Some("typedef"), Some(kind @ ("struct" | "union")), Some(name), Some("{")) => {
                    Some((kind.to_owned(), name.to_owned()))
                }
                _ => None,
            }
        })
        .collect()
}

/// Names of the functions a header declares (`short cnc_x(...);` prototypes,
/// possibly spread over several lines).
pub fn header_functions(header: &str) -> BTreeSet<String> {
    header
        .lines()
        .filter(|l| !l.starts_with(' ') && !l.starts_with('#') && !l.starts_with('/'))
        .filter_map(|l| {
            let before = l.split_once('(')?.0;
            let name = before.split_whitespace().last()?.trim_start_matches('*');
            (name.starts_with("cnc_") || name.starts_with("pmc_") || name.starts_with("fwlib_"))
                .then(|| name.to_owned())
        })
        .collect()
}

/// Names of the `pub ... extern "C" fn` items of src/ffi/*.rs and of the
/// functions described in src/spec/table/ (build.rs writes their exports).
pub fn ffi_functions() -> BTreeSet<String> {
    let dir = manifest_dir().join("src").join("ffi");
    let mut names = BTreeSet::new();
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("read {}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .collect();
    files.sort();
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        for line in text.lines() {
            let t = line.trim_start();
            if !t.starts_with("pub ") {
                continue;
            }
            if let Some((_, rest)) = t.split_once("extern \"C\" fn ") {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                names.insert(name);
            }
        }
    }
    // The functions described as data, and those not on Ethernet: build.rs
    // writes their exports.
    names.extend(fwlib32::spec::FUNCS.iter().map(|f| f.name.to_string()));
    let absent = fwlib32::spec::table::absent::ROWS.iter().copied().flatten();
    names.extend(absent.map(|(name, _)| name.to_string()));
    names
}

/// The library cargo built for this test run, found from this test's own path
/// (`target/<profile>/deps/artifacts-<hash>`).
///
/// `cargo test` compiles the library with all its crate types, cdylib
/// included, into `deps/`, but copies it up to `target/<profile>/` only on
/// `cargo build`: the copy there may be stale, so `deps/libfwlib32.so` comes
/// first. Without either, the library is built here.
pub fn cdylib() -> PathBuf {
    let exe = std::env::current_exe().expect("current_exe");
    let deps = exe.parent().expect("test executable directory");
    let profile_dir = if deps.file_name().is_some_and(|n| n == "deps") {
        deps.parent().unwrap()
    } else {
        deps
    };
    let fresh = deps.join("libfwlib32.so");
    if fresh.exists() {
        return fresh;
    }
    let lib = profile_dir.join("libfwlib32.so");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_owned());
    let mut cmd = Command::new(cargo);
    cmd.args(["build", "--lib", "--manifest-path"])
        .arg(manifest_dir().join("Cargo.toml"));
    if profile_dir.file_name().is_some_and(|n| n == "release") {
        cmd.arg("--release");
    }
    run(&mut cmd);
    assert!(
        lib.exists(),
        "neither {} nor {} found after `cargo build --lib`",
        fresh.display(),
        lib.display()
    );
    lib
}
