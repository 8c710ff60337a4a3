//! The 30i program data folders on the program store (src/sim/store.rs):
//! "//CNC_MEM/USER/PATH`<n>`/" holds path n's programs; other folders hold
//! folders only. Names are NUL-padded fields of the request's payload
//! (256 bytes; a rename's new name 36). Refusals: an unknown folder or a
//! name that is not "O`<number>`" EW_DATA, then the store's (EW_DATA, EW_PROT,
//! EW_BUSY, EW_OVRFLOW); a type other than 1/2 EW_ATTRIB.

use super::Machine;
use super::route::{Asked, Route, none};
use super::service::{CncError, Reply};
use super::store::{FOLDERS, Program};
use crate::ew;
use crate::proto::packet::ReqSub;
use crate::proto::program as pp;
use crate::proto::wire::Writer;

pub(super) const ROUTES: &[Route] = &[
    Route::table(pp::PDF_DRIVE, |_, _| Ok(bytes(b"CNC_MEM\0\0\0\0\0"))),
    Route::table(pp::PDF_INF, |m, _| m.pdf_inf()),
    Route::table(pp::PDF_RDCURDIR, |m, q| {
        Ok(bytes(&name256(&m.store.curdir[curdir(q.arg(0))?])))
    }),
    Route::table(pp::PDF_WRCURDIR, |m, q| {
        none(m.pdf_wrcurdir(q.arg(0), &q.text(0)))
    }),
    Route::table(pp::PDF_SUBDIRN, |m, q| m.pdf_subdirn(&q.text(0))),
    Route::table(pp::PDF_ADD, |m, q| none(m.pdf_add(&q.text(0)))),
    Route::table(pp::PDF_DEL, |m, q| none(m.pdf_del(&q.text(0)))),
    Route::table(pp::PDF_RENAME, |m, q| {
        none(m.pdf_rename(&q.text(0), &q.text(1)))
    }),
    Route::table(pp::PDF_RDMAIN, |m, q| {
        let main = m.store.path(q.path)?.main;
        let name = format!("//CNC_MEM/USER/PATH{}/O{main:04}", q.path);
        Ok(bytes(&name256(&name)))
    }),
    Route::table(pp::PDF_SLCTMAIN, |m, q| none(m.pdf_slctmain(&q.text(0)))),
    Route::table(pp::PDF_COPY, |m, q| {
        none(m.pdf_copy(&q.text(0), &q.text(1), false))
    }),
    Route::table(pp::PDF_MOVE, |m, q| {
        none(m.pdf_copy(&q.text(0), &q.text(1), true))
    }),
    Route::cnc(pp::PDF_SUBDIR, Machine::folder_request),
    Route::cnc(pp::PDF_ALLDIR, Machine::folder_request),
    Route::cnc(pp::PDF_RDLINE, Machine::line_request),
    Route::cnc(pp::PDF_WRLINE, Machine::line_request),
    Route::table(pp::PDF_DELLINE, |m, q| none(m.pdf_delline(q))),
    Route::table(pp::PDF_DELALL, |m, q| none(m.pdf_delall(&q.text(0)))),
    Route::cnc(pp::PDF_RDACTPT, Machine::folder_request),
    Route::cnc(pp::PDF_WRACTPT, Machine::folder_request),
];

/// A NUL-padded field as text.
fn field(b: &[u8]) -> String {
    let n = b.iter().position(|&c| c == 0).unwrap_or(b.len());
    String::from_utf8_lossy(&b[..n]).into_owned()
}

/// A name answered in a 256-byte NUL-padded field.
fn name256(s: &str) -> Vec<u8> {
    let mut b = s.as_bytes()[..s.len().min(255)].to_vec();
    b.resize(256, 0);
    b
}

/// A text's characters as a described answer's integers.
fn bytes(b: &[u8]) -> Vec<i64> {
    b.iter().map(|&c| i64::from(c)).collect()
}

fn err<T>(code: i16) -> Reply<T> {
    Err(CncError::new(code))
}

impl Machine {
    /// The path and number of program `a` ("<folder>O<n>"), else EW_DATA.
    fn program(&self, a: &str) -> Reply<(u16, i32)> {
        self.store.locate(a)?.1.ok_or(CncError::new(ew::EW_DATA))
    }

    /// Folder `a`, else (a program, or no such folder) EW_DATA.
    fn folder(&self, a: &str) -> Reply<String> {
        match self.store.locate(a)? {
            (f, None) => Ok(f),
            _ => err(ew::EW_DATA),
        }
    }

    /// The path whose programs folder `f` holds, if any.
    fn path_of(&self, f: &str) -> Option<u16> {
        (1..=self.run.len() as u16).find(|n| f == format!("//CNC_MEM/USER/PATH{n}/"))
    }

    /// The folders right inside folder `f`.
    fn subfolders(&self, f: &str) -> Vec<&String> {
        let inside = |g: &&String| {
            g.strip_prefix(f)
                .is_some_and(|r| !r.is_empty() && r.find('/') == Some(r.len() - 1))
        };
        self.store.folders.iter().filter(inside).collect()
    }

    /// The request's name: the payload's 256-byte field.
    fn name(sub: &ReqSub) -> String {
        let p = &sub.payload;
        field(p.get(..256).unwrap_or(p))
    }

    /// A folder command: its name and arguments.
    fn folder_request(&mut self, sub: &ReqSub) -> Reply<Vec<u8>> {
        let a = Self::name(sub);
        self.folder_answer(sub.cmd, sub.path, sub.args, &a)
    }

    /// A line command: the program's name and the arguments.
    fn line_request(&mut self, sub: &ReqSub) -> Reply<Vec<u8>> {
        let a = Self::name(sub);
        self.line_answer(sub, &a)
    }

    /// Deletes every program of a path's folder (cnc_pdf_delall).
    fn pdf_delall(&mut self, name: &str) -> Reply<()> {
        let (folder, _) = self.store.locate(name)?;
        let p = self.path_of(&folder).ok_or(CncError::new(ew::EW_DATA))?;
        self.store.remove_all(p).map(drop)
    }

    /// Deletes `count` lines of a program ("<folder>O<n>") from line
    /// `line_no` (1 the first; cnc_pdf_delline).
    fn pdf_delline(&mut self, q: &Asked<'_>) -> Reply<()> {
        let today = self.today();
        let (from, n) = (q.arg(0).max(0) as usize, q.arg(1).max(0) as usize);
        let at = from.saturating_sub(1);
        let (p, number) = self.program(&q.text(0))?;
        self.store.edit_lines(p, number, today, |l| {
            let end = (at + n).min(l.len());
            l.drain(at.min(end)..end);
        })
    }

    /// Creates a program or (a name ending in '/') a folder.
    fn pdf_add(&mut self, a: &str) -> Reply<()> {
        let today = self.today();
        if let Some(inner) = a.strip_suffix('/') {
            let parent = &a[..inner.rfind('/').map_or(0, |i| i + 1)];
            let st = &mut self.store;
            if st.folders.iter().any(|f| f == a) || !st.folders.iter().any(|f| f == parent) {
                return err(ew::EW_DATA);
            }
            st.folders.push(a.to_string());
            return Ok(());
        }
        let (p, n) = self.program(a)?;
        self.store
            .insert(p, Program::new(&format!("O{n:04};\n%\n"), today))
    }

    /// Deletes a program or an empty folder of the user's.
    fn pdf_del(&mut self, a: &str) -> Reply<()> {
        let st = &mut self.store;
        match st.locate(a)? {
            (_, Some((p, n))) => st.remove(p, n).map(drop),
            (f, None) => {
                // The CNC's own folders stay, and a folder with folders in it.
                let at = st.folders.iter().position(|g| *g == f);
                let full = st
                    .folders
                    .iter()
                    .any(|g| g.len() > f.len() && g.starts_with(&f));
                if full || at < Some(FOLDERS.len() + self.run.len()) {
                    return err(ew::EW_DATA);
                }
                st.folders.retain(|g| *g != f);
                Ok(())
            }
        }
    }

    /// Selects a program as the main program.
    fn pdf_slctmain(&mut self, a: &str) -> Reply<()> {
        let (p, n) = self.program(a)?;
        self.store.select(p, n)
    }

    /// The line commands on a program ("<folder>O<n>"): read `args[1]`
    /// lines from line `args[0]` (1 the first), write the bytes after the
    /// name after line `args[0]`.
    fn line_answer(&mut self, sub: &ReqSub, name: &str) -> Reply<Vec<u8>> {
        let today = self.today();
        let (from, n) = (sub.args[0].max(0) as usize, sub.args[1].max(0) as usize);
        let at = from.saturating_sub(1);
        let (p, number) = self.program(name)?;
        let st = &mut self.store;
        match sub.cmd {
            pp::PDF_RDLINE => {
                let text = st.path(p)?.find(number)?.text.clone();
                let lines = text.split_inclusive('\n').skip(at).take(n);
                Ok(lines.collect::<String>().into_bytes())
            }
            _ => {
                let add = sub.payload.get(256..).unwrap_or(&[]);
                let add = String::from_utf8_lossy(add).into_owned();
                st.edit_lines(p, number, today, |l| {
                    let at = from.min(l.len());
                    l.splice(at..at, add.lines().map(String::from));
                })
                .map(|()| Vec::new())
            }
        }
    }

    fn folder_answer(&mut self, cmd: u16, path: u16, args: [i32; 5], a: &str) -> Reply<Vec<u8>> {
        let (word, block) = (args[0], args[1]);
        let mut w = Writer::new();
        match cmd {
            pp::PDF_SUBDIR | pp::PDF_ALLDIR => {
                let f = self.folder(a)?;
                let (from, n) = (word.max(0) as usize, block.max(0) as usize);
                let subs = self.subfolders(&f);
                let st = &self.store;
                let progs: Vec<&Program> = self
                    .path_of(&f)
                    .map_or(Vec::new(), |p| st.iter(p).collect());
                let fixed = |s: &str, n: usize| {
                    let mut b = s.as_bytes()[..s.len().min(n - 1)].to_vec();
                    b.resize(n, 0);
                    b
                };
                let leaf = |g: &String| g[f.len()..g.len() - 1].to_string();
                if cmd == pp::PDF_SUBDIR {
                    for g in subs.iter().skip(from).take(n) {
                        w.i32(i32::from(
                            st.folders
                                .iter()
                                .any(|h| h.len() > g.len() && h.starts_with(g.as_str())),
                        ));
                        w.bytes(&fixed(&leaf(g), 36));
                    }
                } else {
                    let entries = subs
                        .iter()
                        .map(|g| (0, leaf(g), String::new(), [0u16; 5], 0))
                        .chain(progs.iter().map(|p| {
                            (
                                1,
                                p.display_name(),
                                format!("({})", p.comment),
                                p.modified,
                                p.size(),
                            )
                        }));
                    for (kind, name, comment, d, size) in entries.skip(from).take(n) {
                        w.i16(kind);
                        for v in d {
                            w.i16(v as i16);
                        }
                        w.bytes(&[0; 8]);
                        w.i32(size as i32);
                        w.i32(0);
                        w.bytes(&fixed(&name, 36));
                        w.bytes(&fixed(if kind == 1 { &comment } else { "" }, 52));
                        w.bytes(&[0; 12]);
                    }
                }
            }
            pp::PDF_RDACTPT => {
                let (number, name) = self.shown_program(path)?;
                let blk = self.run.get(usize::from(path) - 1).map_or(0, |r| r.block);
                w.i32(blk as i32);
                w.bytes(&name256(&format!("//CNC_MEM/USER/PATH{path}/{name}")));
                let _ = number;
            }
            pp::PDF_WRACTPT => {
                let (p, n) = self.program(a)?;
                self.store.path(p)?.find(n)?;
                w.i32(block);
            }
            _ => return Err(CncError::FUNC),
        }
        Ok(w.into_vec())
    }

    /// The drives' used and total pages (256 bytes each), the folders,
    /// and room for 1000 (cnc_rdpdf_inf).
    fn pdf_inf(&mut self) -> Reply<Vec<i64>> {
        let (mut used, mut all) = (0, 0);
        for n in 1..=self.run.len() as u16 {
            let s = self.store.path(n)?;
            (used, all) = (used + s.used(), all + s.capacity);
        }
        let dirs = self.store.folders.len();
        Ok([used.div_ceil(256), all / 256, dirs, 1000]
            .map(|v| v as i64)
            .to_vec())
    }

    /// Sets the current folder of `type` (1 foreground, 2 background).
    fn pdf_wrcurdir(&mut self, word: i32, a: &str) -> Reply<()> {
        let k = curdir(word)?;
        self.store.curdir[k] = self.folder(a)?;
        Ok(())
    }

    /// The folders and the programs a folder holds.
    fn pdf_subdirn(&mut self, a: &str) -> Reply<Vec<i64>> {
        let f = self.folder(a)?;
        let files = self.path_of(&f).map_or(0, |n| self.store.iter(n).count());
        Ok(vec![self.subfolders(&f).len() as i64, files as i64])
    }

    /// Renames a program to "O`<number>`".
    fn pdf_rename(&mut self, a: &str, b: &str) -> Reply<()> {
        let today = self.today();
        let (Ok((p, n)), Some(to)) = (self.program(a), new_number(b)) else {
            return err(ew::EW_DATA);
        };
        self.store.rename(p, n, to, today)
    }

    /// Copies (or, `moved`, moves) a program to a program, or into a
    /// folder.
    fn pdf_copy(&mut self, a: &str, b: &str, moved: bool) -> Reply<()> {
        let today = self.today();
        let (p, n) = self.program(a)?;
        let st = &mut self.store;
        let (q, m) = match st.locate(b)? {
            (_, Some(to)) => to,
            (f, None) => match st.locate(&format!("{f}O{n:04}"))? {
                (_, Some(to)) => to,
                _ => return err(ew::EW_DATA),
            },
        };
        let mut prog = st.path(p)?.find(n)?.clone();
        if moved {
            st.path(p)?.editable(n)?;
        } else {
            (prog.created, prog.modified, prog.protect) = (today, today, false);
        }
        st.insert(q, prog.renumbered(m))?;
        if moved {
            st.remove(p, n)?;
        }
        Ok(())
    }
}

/// The current folder's index of a `type` (1 or 2; else EW_ATTRIB).
fn curdir(word: i32) -> Reply<usize> {
    let k = usize::try_from(word - 1).ok().filter(|k| *k < 2);
    k.ok_or(CncError::new(ew::EW_ATTRIB))
}

/// The program number of a new name "O<number>".
fn new_number(name: &str) -> Option<i32> {
    let d = name.strip_prefix('O')?;
    d.bytes()
        .all(|b| b.is_ascii_digit())
        .then(|| d.parse().ok())?
}
