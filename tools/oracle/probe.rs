//! Building and driving tools/oracle/probe.c: one process per case, one
//! command line in, one JSON line out.

use serde_json::Value;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};

/// Compiles the probe against our header into `dir`; returns its path.
pub fn build(root: &Path, dir: &Path) -> PathBuf {
    std::fs::create_dir_all(dir).expect("probe directory");
    let exe = dir.join("focas-probe");
    let src = root.join("tools/oracle/probe.c");
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".to_string());
    let out = Command::new(&cc)
        .args([
            "-std=gnu11",
            "-O1",
            "-Wall",
            "-Werror",
            "-Wno-unused-parameter",
            "-I",
        ])
        .arg(root.join("include"))
        .arg(&src)
        .arg("-o")
        .arg(&exe)
        .args(["-ldl", "-lpthread"])
        .output()
        .unwrap_or_else(|e| panic!("cannot run {cc}: {e}"));
    assert!(
        out.status.success(),
        "compiling {} failed:\n{}",
        src.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

/// What one probe command did.
#[derive(Debug, Clone, PartialEq)]
pub enum Answer {
    Done {
        ret: i64,
        /// In-out counts by name (h, num, length ...).
        fields: Vec<(String, i64)>,
        /// The two 0xCC-filled buffers up to their last written byte.
        b0: Vec<u8>,
        b1: Vec<u8>,
    },
    /// The library does not export this function.
    Missing(String),
    /// The probe died (the library crashed) or said something unreadable.
    Crashed(String),
}

pub struct Probe {
    child: Child,
    stdin: Option<ChildStdin>,
    stdout: BufReader<ChildStdout>,
    dead: bool,
}

impl Probe {
    /// Starts the probe: `cmd` runs its executable (directly, or through a
    /// runner such as qemu for another target).
    pub fn spawn(mut cmd: Command, lib: &Path, port: u16) -> Probe {
        let mut child = cmd
            .arg(lib)
            .arg("127.0.0.1")
            .arg(port.to_string())
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap_or_else(|e| panic!("cannot start the probe {cmd:?}: {e}"));
        let stdin = child.stdin.take();
        let stdout = BufReader::new(child.stdout.take().unwrap());
        Probe {
            child,
            stdin,
            stdout,
            dead: false,
        }
    }

    pub fn call(&mut self, cmd: &str) -> Answer {
        if self.dead {
            return Answer::Crashed("probe already dead".into());
        }
        let sent = self
            .stdin
            .as_mut()
            .map(|s| writeln!(s, "{cmd}").and_then(|_| s.flush()));
        let mut line = String::new();
        if !matches!(sent, Some(Ok(()))) || self.stdout.read_line(&mut line).unwrap_or(0) == 0 {
            self.dead = true;
            let status = self.child.wait().map(|s| s.to_string()).unwrap_or_default();
            return Answer::Crashed(format!("probe ended: {status}"));
        }
        parse(&line)
    }

    /// Closes the probe's input and waits for it to end.
    pub fn finish(mut self) {
        self.stdin.take();
        let _ = self.child.wait();
    }
}

impl Drop for Probe {
    fn drop(&mut self) {
        self.stdin.take();
        if !self.dead && self.child.try_wait().ok().flatten().is_none() {
            let _ = self.child.kill();
        }
        let _ = self.child.wait();
    }
}

fn unhex(s: &str) -> Vec<u8> {
    (0..s.len() / 2)
        .map(|i| u8::from_str_radix(&s[2 * i..2 * i + 2], 16).unwrap_or(0))
        .collect()
}

fn parse(line: &str) -> Answer {
    let v: Value = match serde_json::from_str(line) {
        Ok(v) => v,
        Err(e) => return Answer::Crashed(format!("unreadable probe line {line:?}: {e}")),
    };
    if let Some(m) = v["missing"].as_str() {
        return Answer::Missing(m.to_string());
    }
    if let Some(u) = v["unknown"].as_str() {
        return Answer::Crashed(format!("the probe has no word {u:?}"));
    }
    let fields = v["fields"]
        .as_object()
        .map(|o| {
            o.iter()
                .map(|(k, x)| (k.clone(), x.as_i64().unwrap_or(0)))
                .collect()
        })
        .unwrap_or_default();
    Answer::Done {
        ret: v["return"].as_i64().unwrap_or(i64::MIN),
        fields,
        b0: unhex(v["b0"].as_str().unwrap_or("")),
        b1: unhex(v["b1"].as_str().unwrap_or("")),
    }
}

/// The names the vector format gives a word's two buffers.
pub fn buffer_names(word: &str) -> (&'static str, &'static str) {
    match word {
        "getpath" => ("path_no", "maxpath_no"),
        "rdactpt" => ("prog_no", "blk_no"),
        "getfigure" => ("dec_fig_in", "dec_fig_out"),
        _ => ("out", "out2"),
    }
}
