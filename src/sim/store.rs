//! The CNC's program memory: a [`Store`] of programs per path, seeded from
//! the profile's `[[program]]`s and changed by the program functions
//! (download, delete, rename, copy ...). Upload, the directory reads and
//! the running machine read it, so a change shows at once.
//!
//! Refusals answer the CNC's error codes and change nothing: no such path
//! EW_PATH, no such program EW_DATA, a number already used EW_DATA, a
//! protected program EW_PROT, the program the path is executing EW_BUSY,
//! memory or directory full EW_OVRFLOW.

use super::profile::cycle::{DEFAULT_PROGRAM_DATE, StoredProgram, program_date};
use super::profile::{Path, Profile};
use super::service::{CncError, Reply};
use crate::ew;
use std::sync::Arc;

/// A date as year, month, day, hour, minute.
pub type Date = [u16; 5];

/// One stored program.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Program {
    /// O number (0: a 30i program known by its name alone).
    pub number: i32,
    /// Name as cnc_exeprgname2 reports it, e.g. "O1234" or a path like
    /// "//CNC_MEM/USER/PATH1/O1234"; empty = "O`<number>`".
    pub name: String,
    /// The comment of the first block, without its parentheses.
    pub comment: String,
    /// The program text as the CNC punches it, one block per line
    /// ("O1234 (DEMO);\nN10 G01 X10. F500;\n...%\n").
    pub text: Arc<str>,
    pub created: Date,
    pub modified: Date,
    /// Edit protection: delete, rename and overwrite answer EW_PROT.
    pub protect: bool,
}

impl Program {
    /// A program of `text` stored on `date`: number and comment from its
    /// first block ("O1234 (COMMENT);"; none: number 0, no comment).
    pub fn new(text: &str, date: Date) -> Program {
        let first = text
            .lines()
            .map(str::trim)
            .find(|l| !l.is_empty() && *l != "%");
        let first = first.unwrap_or("");
        let number = first
            .strip_prefix(['O', 'o', ':'])
            .map(|r| {
                r.chars()
                    .take_while(char::is_ascii_digit)
                    .collect::<String>()
            })
            .and_then(|d| d.parse().ok())
            .unwrap_or(0);
        let comment = first
            .split_once('(')
            .and_then(|(_, r)| r.split_once(')'))
            .map_or("", |(c, _)| c);
        Program {
            number,
            name: String::new(),
            comment: comment.to_string(),
            text: text.into(),
            created: date,
            modified: date,
            protect: false,
        }
    }

    /// A profile's `[[program]]` (its comment if it gives one, else the
    /// text's).
    pub fn from_profile(p: &StoredProgram) -> Program {
        let date = program_date(p).unwrap_or(DEFAULT_PROGRAM_DATE);
        let mut prog = Program::new(&p.text, date);
        prog.number = p.number;
        prog.name = p.name.clone();
        prog.protect = p.protect;
        if !p.comment.is_empty() {
            prog.comment = p.comment.clone();
        }
        prog
    }

    /// Bytes of memory the program takes (cnc_rdprogdir's length).
    pub fn size(&self) -> usize {
        self.text.len()
    }

    /// The name CNCs report: the profile's, or "O`<number>`".
    pub fn display_name(&self) -> String {
        if self.name.is_empty() {
            format!("O{:04}", self.number)
        } else {
            self.name.clone()
        }
    }

    /// The full path name cnc_exeprgname2 reports for it on `path`: the
    /// name if it is a path, else "//CNC_MEM/USER/PATH`<n>`/`<name>`".
    pub fn full_name(&self, path: u16) -> String {
        let name = self.display_name();
        if name.starts_with("//") {
            name
        } else {
            format!("//CNC_MEM/USER/PATH{path}/{name}")
        }
    }

    /// Whether an upload name ("N:" stripped) asked on `path` means this
    /// program: its name, "O`<number>`" / "O%04d", the last element of its
    /// path name, its full path name (what cnc_exeprgname2 reports), or its
    /// folder followed by "O`<number>`" / "O%04d".
    pub fn answers_to(&self, name: &str, path: u16) -> bool {
        let o_forms = [format!("O{:04}", self.number), format!("O{}", self.number)];
        let display = self.display_name();
        let full = self.full_name(path);
        let folder = &full[..full.rfind('/').map_or(0, |i| i + 1)];
        display == name
            || o_forms.iter().any(|o| o == name)
            || display.rsplit('/').next() == Some(name)
            || full == name
            || name
                .strip_prefix(folder)
                .is_some_and(|leaf| o_forms.iter().any(|o| o == leaf))
    }

    /// The program under number `to`: its first block's O number changed
    /// too (the name follows when it is an "O" name).
    pub fn renumbered(&self, to: i32) -> Program {
        let mut p = self.clone();
        let mut text = String::with_capacity(self.text.len() + 8);
        let mut done = false;
        for line in self.text.split_inclusive('\n') {
            let t = line.trim_start();
            let digits = t.get(1..).unwrap_or("");
            let n = digits.chars().take_while(char::is_ascii_digit).count();
            if !done && t.starts_with(['O', 'o']) && digits[..n].parse() == Ok(self.number) {
                text.push_str(&format!("O{to:04}{}", &digits[n..]));
                done = true;
            } else {
                done |= !t.trim().is_empty() && !t.starts_with('%');
                text.push_str(line);
            }
        }
        p.text = text.into();
        p.number = to;
        if p.name.starts_with('O') || p.name.is_empty() {
            p.name.clear();
        }
        p
    }
}

/// Program memory of a path when the profile gives no `[path.memory]`.
pub const DEFAULT_MEMORY: usize = 512 * 1024;
/// Programs a path holds at most when the profile does not say.
pub const DEFAULT_PROGRAMS: usize = 400;

/// The programs of one path, in number order.
#[derive(Debug, Clone, Default)]
pub struct PathStore {
    programs: Vec<Program>,
    /// Memory for programs, bytes (cnc_rdproginfo).
    pub capacity: usize,
    /// How many programs fit at most (directory entries).
    pub max_programs: usize,
    /// The program the path is executing (0: none): the run engine keeps it;
    /// changing it is EW_BUSY.
    pub running: i32,
    /// The main program selected (cnc_search; 0: none): what a start runs.
    pub main: i32,
    /// The MDI program's execution pointer (cnc_wrmdipntr, cnc_rdmdipntr).
    pub mdi_pntr: i32,
    /// The MDI program's text (cnc_wrmdiprog, cnc_rdmdiprog).
    pub mdi: Vec<u8>,
}

/// The program memory of every path.
#[derive(Debug, Clone, Default)]
pub struct Store {
    paths: Vec<PathStore>,
    /// The 30i folder tree, each folder's full name ending in '/'; the
    /// programs of "//CNC_MEM/USER/PATH`<n>`/" are path n's.
    pub folders: Vec<String>,
    /// The current folders (cnc_rdpdf_curdir types 1 and 2).
    pub curdir: [String; 2],
}

/// The folders of a new CNC (before the paths' own).
pub const FOLDERS: [&str; 5] = [
    "//CNC_MEM/",
    "//CNC_MEM/USER/",
    "//CNC_MEM/USER/LIBRARY/",
    "//CNC_MEM/SYSTEM/",
    "//CNC_MEM/MTB1/",
];

fn err<T>(code: i16) -> Reply<T> {
    Err(CncError::new(code))
}

impl Store {
    /// The store of a profile: each `[[program]]` on its path (path 0: on
    /// every path), capacities from `[path.memory]`, the main program of
    /// each path its `[path.cycle]` program.
    pub fn seed(profile: &Profile) -> Store {
        let paths = profile
            .paths
            .iter()
            .enumerate()
            .map(|(i, p): (usize, &Path)| {
                let mut programs: Vec<Program> = profile
                    .programs
                    .iter()
                    .filter(|s| s.path == 0 || usize::from(s.path) == i + 1)
                    .map(Program::from_profile)
                    .collect();
                programs.sort_by_key(|p| p.number);
                PathStore {
                    programs,
                    capacity: p.memory.bytes.unwrap_or(DEFAULT_MEMORY),
                    max_programs: p.memory.programs.unwrap_or(DEFAULT_PROGRAMS),
                    main: p.cycle.program,
                    ..PathStore::default()
                }
            });
        let paths: Vec<PathStore> = paths.collect();
        let own = (1..=paths.len()).map(|n| format!("//CNC_MEM/USER/PATH{n}/"));
        let folders = FOLDERS.iter().map(|f| f.to_string()).chain(own).collect();
        let home = "//CNC_MEM/USER/PATH1/".to_string();
        Store {
            paths,
            folders,
            curdir: [home.clone(), home],
        }
    }

    /// What a full name ("//CNC_MEM/USER/PATH1/O0100", a folder ending in
    /// '/'; a name without "//" is in the current folder) stands for: the
    /// folder's name, and the path whose memory it is with the program
    /// number (None: the folder itself; an unknown folder or a file name
    /// other than "O`<number>`": EW_DATA).
    pub fn locate(&self, name: &str) -> Reply<(String, Option<(u16, i32)>)> {
        let full = match name.starts_with("//") {
            true => name.to_string(),
            false => format!("{}{name}", self.curdir[0]),
        };
        let cut = full.rfind('/').map_or(0, |i| i + 1);
        let (folder, leaf) = full.split_at(cut);
        if !self.folders.iter().any(|f| f == folder) {
            return err(ew::EW_DATA);
        }
        if leaf.is_empty() {
            return Ok((folder.to_string(), None));
        }
        let path =
            (1..=self.paths.len() as u16).find(|n| folder == format!("//CNC_MEM/USER/PATH{n}/"));
        let number = leaf.strip_prefix('O').and_then(|d| d.parse::<i32>().ok());
        match (path, number) {
            (Some(p), Some(n)) if leaf[1..].bytes().all(|b| b.is_ascii_digit()) => {
                Ok((folder.to_string(), Some((p, n))))
            }
            _ => err(ew::EW_DATA),
        }
    }

    /// Path `path` (1-based); EW_PATH if there is none.
    pub fn path(&self, path: u16) -> Reply<&PathStore> {
        let i = usize::from(path).wrapping_sub(1);
        self.paths.get(i).ok_or(CncError::PATH)
    }

    /// Path `path` to change.
    pub fn path_mut(&mut self, path: u16) -> Reply<&mut PathStore> {
        let i = usize::from(path).wrapping_sub(1);
        self.paths.get_mut(i).ok_or(CncError::PATH)
    }

    /// The programs of `path` in number order (none for a path it lacks).
    pub fn iter(&self, path: u16) -> impl Iterator<Item = &Program> {
        self.path(path).into_iter().flat_map(PathStore::iter)
    }

    /// Program `number` of `path`.
    pub fn get(&self, path: u16, number: i32) -> Option<&Program> {
        self.iter(path).find(|p| p.number == number)
    }

    /// Stores `p` on `path`. Refused (nothing changes): a number already
    /// stored EW_DATA, memory or directory full EW_OVRFLOW.
    pub fn insert(&mut self, path: u16, p: Program) -> Reply<()> {
        let s = self.path_mut(path)?;
        if s.programs.iter().any(|q| q.number == p.number) {
            return err(ew::EW_DATA);
        }
        if s.programs.len() >= s.max_programs || s.used() + p.size() > s.capacity {
            return err(ew::EW_OVRFLOW);
        }
        let at = s.programs.partition_point(|q| q.number < p.number);
        s.programs.insert(at, p);
        Ok(())
    }

    /// Stores `p` on `path` in place of the program of its number, if any
    /// (a download over an existing program): refused as [`Store::insert`],
    /// and EW_PROT / EW_BUSY for a protected / executing one it replaces.
    pub fn replace(&mut self, path: u16, p: Program) -> Reply<()> {
        if self.get(path, p.number).is_some() {
            let s = self.path(path)?;
            let old = s.editable(p.number)?;
            if s.used() - old.size() + p.size() > s.capacity {
                return err(ew::EW_OVRFLOW);
            }
            self.remove(path, p.number)?;
        }
        self.insert(path, p)
    }

    /// Deletes program `number` of `path` and gives it back. Refused: no
    /// such program EW_DATA, protected EW_PROT, executing EW_BUSY.
    pub fn remove(&mut self, path: u16, number: i32) -> Reply<Program> {
        self.path(path)?.editable(number)?;
        let s = self.path_mut(path)?;
        let at = s.programs.iter().position(|p| p.number == number);
        Ok(s.programs.remove(at.expect("checked")))
    }

    /// Deletes every program of `path` that is neither protected, executing
    /// nor the main program (as a CNC deletes all): how many went.
    pub fn remove_all(&mut self, path: u16) -> Reply<usize> {
        let s = self.path_mut(path)?;
        let before = s.programs.len();
        let running = s.running;
        let main = s.main;
        s.programs
            .retain(|p| p.protect || p.number == running || p.number == main);
        Ok(before - s.programs.len())
    }

    /// Renumbers program `from` of `path` as `to` (its first block too),
    /// modified `date`. Refused: `from` as [`Store::remove`], `to` already
    /// stored EW_DATA.
    pub fn rename(&mut self, path: u16, from: i32, to: i32, date: Date) -> Reply<()> {
        let s = self.path(path)?;
        let mut p = s.editable(from)?.renumbered(to);
        if s.programs.iter().any(|q| q.number == to) {
            return err(ew::EW_DATA);
        }
        p.modified = date;
        self.remove(path, from)?;
        self.insert(path, p)
    }

    /// Copies program `from` of `path` to a new program `to` (created
    /// `date`, not protected). Refused: no `from` EW_DATA, as
    /// [`Store::insert`] for `to`.
    pub fn copy(&mut self, path: u16, from: i32, to: i32, date: Date) -> Reply<()> {
        let mut p = self.path(path)?.find(from)?.renumbered(to);
        (p.created, p.modified, p.protect) = (date, date, false);
        self.insert(path, p)
    }

    /// Program `number`'s lines as `f` changes them (modified `date`):
    /// refused as [`Store::remove`], or EW_OVRFLOW when they do not fit.
    pub fn edit_lines(
        &mut self,
        path: u16,
        number: i32,
        date: Date,
        f: impl FnOnce(&mut Vec<String>),
    ) -> Reply<()> {
        let s = self.path(path)?;
        let old = s.editable(number)?;
        let mut lines: Vec<String> = old.text.lines().map(String::from).collect();
        f(&mut lines);
        let mut p = old.clone();
        (p.text, p.modified) = ((lines.join("\n") + "\n").into(), date);
        if s.used() - old.size() + p.size() > s.capacity {
            return err(ew::EW_OVRFLOW);
        }
        let s = self.path_mut(path)?;
        let at = s.programs.iter().position(|q| q.number == number);
        s.programs[at.expect("editable")] = p;
        Ok(())
    }

    /// cnc_search: program `number` becomes the main program of `path`.
    /// No such program EW_DATA; the path executing a program EW_BUSY.
    pub fn select(&mut self, path: u16, number: i32) -> Reply<()> {
        let s = self.path_mut(path)?;
        if s.running != 0 {
            return err(ew::EW_BUSY);
        }
        s.find(number)?;
        s.main = number;
        Ok(())
    }

    /// cnc_condense: memory is never fragmented here, so nothing moves.
    /// `type` other than 0/1 EW_ATTRIB, a program (not 0) not stored EW_DATA.
    pub fn condense(&self, path: u16, kind: i32, number: i32) -> Reply<()> {
        let s = self.path(path)?;
        if !(0..=1).contains(&kind) {
            return err(ew::EW_ATTRIB);
        }
        if number != 0 {
            s.find(number)?;
        }
        Ok(())
    }

    /// Sets program `number`'s protection.
    pub fn protect(&mut self, path: u16, number: i32, on: bool) -> Reply<()> {
        let s = self.path_mut(path)?;
        let p = s.programs.iter_mut().find(|p| p.number == number);
        p.ok_or(CncError::new(ew::EW_DATA))?.protect = on;
        Ok(())
    }
}

impl PathStore {
    /// Bytes the programs take.
    pub fn used(&self) -> usize {
        self.programs.iter().map(Program::size).sum()
    }

    /// The programs in number order.
    pub fn iter(&self) -> std::slice::Iter<'_, Program> {
        self.programs.iter()
    }

    /// How many programs are stored.
    pub fn count(&self) -> usize {
        self.programs.len()
    }

    /// Program `number`; EW_DATA if there is none.
    pub fn find(&self, number: i32) -> Reply<&Program> {
        let p = self.programs.iter().find(|p| p.number == number);
        p.ok_or(CncError::new(ew::EW_DATA))
    }

    /// Program `number` if it may change: no such program EW_DATA,
    /// protected EW_PROT, executing or selected as the main program EW_BUSY
    /// (FANUC's sample for cnc_delete reads EW_BUSY as "rejected": the
    /// main program cannot be deleted).
    pub fn editable(&self, number: i32) -> Reply<&Program> {
        let p = self.find(number)?;
        if p.protect {
            return err(ew::EW_PROT);
        }
        if number == self.running || number == self.main {
            return err(ew::EW_BUSY);
        }
        Ok(p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn store() -> Store {
        Store::seed(&Profile::default())
    }

    #[test]
    fn seeded_from_the_profile_in_number_order() {
        let s = store();
        let n: Vec<i32> = s.iter(1).map(|p| p.number).collect();
        assert_eq!(n, vec![100, 1234]);
        assert_eq!(s.get(1, 1234).unwrap().comment, "POCKET DEMO");
        assert_eq!(s.path(1).unwrap().main, 1234);
        assert!(s.path(9).is_err());
    }

    #[test]
    fn refusals_change_nothing() {
        let mut s = store();
        let d = [2026, 1, 2, 3, 4];
        let before: Vec<Program> = s.iter(1).cloned().collect();
        let dup = Program::new("O0100 (X);\nM30;\n%\n", d);
        assert_eq!(s.insert(1, dup).unwrap_err().code, ew::EW_DATA);
        assert_eq!(s.remove(1, 7).unwrap_err().code, ew::EW_DATA);
        s.protect(1, 100, true).unwrap();
        assert_eq!(s.remove(1, 100).unwrap_err().code, ew::EW_PROT);
        assert_eq!(s.rename(1, 100, 5, d).unwrap_err().code, ew::EW_PROT);
        s.protect(1, 100, false).unwrap();
        assert_eq!(
            s.remove(1, 1234).unwrap_err().code,
            ew::EW_BUSY,
            "the main program"
        );
        s.path_mut(1).unwrap().running = 100;
        assert_eq!(s.remove(1, 100).unwrap_err().code, ew::EW_BUSY);
        assert_eq!(s.select(1, 100).unwrap_err().code, ew::EW_BUSY);
        s.path_mut(1).unwrap().running = 0;
        assert_eq!(s.select(1, 7).unwrap_err().code, ew::EW_DATA);
        assert_eq!(s.rename(1, 100, 1234, d).unwrap_err().code, ew::EW_DATA);
        s.path_mut(1).unwrap().capacity = s.path(1).unwrap().used();
        let big = Program::new("O0001;\nM30;\n%\n", d);
        assert_eq!(s.insert(1, big).unwrap_err().code, ew::EW_OVRFLOW);
        assert_eq!(s.iter(1).cloned().collect::<Vec<_>>(), before);
    }

    #[test]
    fn rename_copy_and_delete() {
        let mut s = store();
        let d = [2026, 1, 2, 3, 4];
        s.rename(1, 100, 200, d).unwrap();
        let p = s.get(1, 200).unwrap();
        assert!(p.text.starts_with("O0200 (WARM UP);\n"), "{}", p.text);
        assert_eq!(p.modified, d);
        s.copy(1, 200, 300, d).unwrap();
        assert!(s.get(1, 300).unwrap().text.starts_with("O0300 (WARM UP);"));
        assert_eq!(s.remove(1, 200).unwrap().number, 200);
        assert_eq!(s.remove_all(1).unwrap(), 1, "the main program stays");
        s.select(1, 1234).unwrap();
        let p = Program::new("%\nO0042 (NEW PART);\nM30;\n%\n", d);
        assert_eq!((p.number, p.comment.as_str()), (42, "NEW PART"));
    }
}
