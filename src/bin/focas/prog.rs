//! `prog ls | get N [FILE] | put FILE | rm N`.

use crate::out::{Fail, Table, json_line, print, to_json};
use fwlib32::native::{Cnc, Error, Ew, Run};
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::json;
use std::path::PathBuf;

#[derive(clap::Subcommand)]
pub enum Prog {
    /// The program directory: numbers, sizes, dates, comments
    Ls,
    /// Upload program N, to FILE or stdout
    Get { number: u32, file: Option<PathBuf> },
    /// Download FILE (punch format: %, `O<number>` ..., %) to the CNC's memory.
    #[command(about = "Download FILE (punch format: %, O<number> ..., %) to the CNC's memory")]
    Put {
        #[arg(value_parser = read_program)]
        file: ProgFile,
    },
    /// Delete program N
    Rm { number: u32 },
}

/// A program file to download, read before connecting.
#[derive(Debug, Clone)]
pub struct ProgFile {
    pub path: PathBuf,
    pub text: Vec<u8>,
    /// The O number of its first block, if it has one.
    pub number: Option<u32>,
}

/// Reads FILE (a usage error when it cannot be read).
fn read_program(s: &str) -> Result<ProgFile, String> {
    let path = PathBuf::from(s);
    let text = std::fs::read(&path).map_err(|e| format!("{s}: {e}"))?;
    let number = program_number(&text);
    Ok(ProgFile { path, text, number })
}

/// The number of `O1234 (...)` (or ISO `:1234`), the first block after
/// the leading `%`.
pub fn program_number(text: &[u8]) -> Option<u32> {
    let text = String::from_utf8_lossy(text);
    let first = text
        .lines()
        .map(str::trim)
        .find(|l| !l.is_empty() && *l != "%")?;
    let rest = first.strip_prefix(['O', 'o', ':'])?;
    let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
    digits.parse().ok()
}

pub fn run(cnc: &Cnc, p: Prog, json: bool) -> Result<(), Fail> {
    match p {
        Prog::Ls => ls(cnc, json),
        Prog::Get { number, file } => get(cnc, number, file, json),
        Prog::Put { file } => put(cnc, &file, json),
        Prog::Rm { number } => {
            cnc.delete_program(number)
                .map_err(|e| explain(cnc, e, Some(number), Op::Rm))?;
            if json {
                json_line(&json!({ "deleted": number }))
            } else {
                print(&format!("O{number} deleted\n"))
            }
        }
    }
}

/// A transfer's bar on stderr (only on a terminal): bytes of the total,
/// rate, time left.
const BAR: &str = "{msg} [{bar:30}] {bytes}/{total_bytes} {bytes_per_sec} ETA {eta}";

fn progress(total: u64, msg: String) -> ProgressBar {
    let bar = ProgressBar::new(total);
    bar.set_style(
        ProgressStyle::with_template(BAR)
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    bar.set_message(msg);
    bar
}

/// What was refused.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Op {
    Get,
    Put,
    Rm,
}

/// `O0012`, as the CNC shows it.
fn o(n: u32) -> String {
    format!("O{n:04}")
}

/// The CNC's refusal `e` of `op` on program `number`, in words where the
/// call and what the CNC says now tell what happened (the directory, what
/// runs); else the bare error. The EW code stays in the message.
fn explain(cnc: &Cnc, e: Error, number: Option<u32>, op: Op) -> Fail {
    let Some(n) = number else {
        return Fail::Api(e);
    };
    let code = e.code();
    // Is O`n` in the directory? (None: the directory cannot be read.)
    let stored = || {
        cnc.programs()
            .ok()
            .map(|ps| ps.iter().any(|p| p.number == n))
    };
    let why = match (op, code) {
        (Op::Put, Ew::DATA) if stored() == Some(true) => Some(format!(
            "{} already in memory (focas prog rm {n} first)",
            o(n)
        )),
        (Op::Put, Ew::OVRFLOW) => Some(format!("no room for {} in the CNC's memory", o(n))),
        (Op::Put, Ew::PROT) => Some("the CNC's program memory is protected".to_string()),
        (Op::Get | Op::Rm, Ew::DATA | Ew::NUMBER) if stored() == Some(false) => {
            Some(format!("{} not found", o(n)))
        }
        (Op::Rm, Ew::PROT) => Some(format!("{} is protected", o(n))),
        (Op::Rm, Ew::BUSY) => {
            let mut b = cnc.batch();
            let (st, ex) = (b.status(), b.execution());
            b.send().ok().and_then(|mut r| {
                let (s, x) = (r.take(st).ok()?, r.take(ex).ok()?);
                let runs = s.run != Run::Reset;
                if x.program == n {
                    Some(if runs {
                        format!("{} is running", o(n))
                    } else {
                        format!("{} is selected", o(n))
                    })
                } else if x.main_program == n {
                    Some(if runs {
                        format!("{} is running (the main program)", o(n))
                    } else {
                        format!("{} is selected (the main program)", o(n))
                    })
                } else {
                    None
                }
            })
        }
        _ => None,
    };
    match why {
        Some(w) => Fail::Refused(w, e),
        None => Fail::Api(e),
    }
}

fn put(cnc: &Cnc, f: &ProgFile, json: bool) -> Result<(), Fail> {
    let (file, text) = (&f.path, &f.text);
    let bar = progress(text.len() as u64, file.display().to_string());
    let r = cnc.put_program(text, |n| {
        bar.set_position(n as u64);
        if n == text.len() {
            // All sent: the CNC may still be taking it in.
            bar.set_message(format!("{}: sent, waiting for the CNC", file.display()));
        }
    });
    bar.finish_and_clear();
    r.map_err(|e| explain(cnc, e, f.number, Op::Put))?;
    if json {
        json_line(&json!({ "file": file, "number": f.number, "bytes": text.len() }))
    } else {
        print(&format!(
            "{}: {} bytes downloaded\n",
            file.display(),
            text.len()
        ))
    }
}

fn ls(cnc: &Cnc, json: bool) -> Result<(), Fail> {
    let progs = cnc.programs()?;
    if json {
        return json_line(&json!({ "programs": to_json(&progs) }));
    }
    if progs.is_empty() {
        return print("no program\n");
    }
    let mut t = Table::new(&[false, true, false, false]);
    for p in &progs {
        let m = p.modified.map_or(String::new(), |t| {
            let s = t.to_string();
            s[..s.len().saturating_sub(3)].to_string()
        });
        t.row([
            format!("O{:04}", p.number),
            p.length.to_string(),
            m,
            p.comment.clone(),
        ]);
    }
    print(&t.render())
}

fn get(cnc: &Cnc, number: u32, file: Option<PathBuf>, json: bool) -> Result<(), Fail> {
    // The directory's size of the program, for the bar (the upload's text
    // differs a little: the CNC punches it).
    let total = cnc
        .programs()
        .ok()
        .and_then(|ps| ps.into_iter().find(|p| p.number == number))
        .map_or(0, |p| p.length.max(0) as u64);
    let bar = progress(total, o(number));
    let text = cnc.program_with(number, |n| {
        let n = n as u64;
        if n > bar.length().unwrap_or(0) {
            bar.set_length(n);
        }
        bar.set_position(n);
    });
    bar.finish_and_clear();
    let text = text.map_err(|e| explain(cnc, e, Some(number), Op::Get))?;
    match (file, json) {
        (Some(f), json) => {
            std::fs::write(&f, &text).map_err(|e| Fail::Other(format!("{}: {e}", f.display())))?;
            if json {
                json_line(&json!({ "number": number, "bytes": text.len(), "file": f }))
            } else {
                print(&format!(
                    "O{number}: {} bytes to {}\n",
                    text.len(),
                    f.display()
                ))
            }
        }
        (None, true) => json_line(&json!({ "number": number, "bytes": text.len(), "text": text })),
        (None, false) => {
            let nl = if text.ends_with('\n') { "" } else { "\n" };
            print(&format!("{text}{nl}"))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bar_template_is_valid() {
        assert!(ProgressStyle::with_template(BAR).is_ok());
    }

    #[test]
    fn program_numbers() {
        assert_eq!(program_number(b"%\nO4242 (X)\nM30\n%"), Some(4242));
        assert_eq!(program_number(b"\r\n%\r\n:0012\r\n%"), Some(12));
        assert_eq!(program_number(b"O1"), Some(1));
        assert_eq!(program_number(b"%\nG00 X1.\n%"), None);
        assert_eq!(program_number(b""), None);
    }
}
