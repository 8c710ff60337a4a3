//! Program download into the simulated CNC's memory (connection 1, frames
//! in src/proto/download.rs): the text a download brought, checked as a
//! CNC checks it, stored in the path's program store (src/sim/store.rs).
//!
//! The text is punch format: an optional leading "%" (or LF) line, then
//! one or more programs each starting with its "O`<number>`" block, blocks
//! one per line (a ';' end of block is dropped), up to a "%" line. The
//! whole download is checked before anything is stored, so a refused one
//! changes nothing: not ASCII or a block that is not a run of address
//! words (a letter and its value, comments in parentheses) EW_DATA, a
//! program without an O number EW_DATA, then the store's own refusals (a
//! number in use EW_DATA, memory full EW_OVRFLOW).

use super::Machine;
use super::service::{CncError, Reply};
use super::store::Program;
use crate::ew::{EW_ATTRIB, EW_DATA};
use crate::proto::upload::StartReq;

/// Whether a block is a run of address words, as a CNC parses it: a
/// letter, then its value (digits, sign, point, or a macro expression in
/// brackets or after '#'); comments in parentheses; "/" block skip.
fn block_ok(line: &str) -> bool {
    let mut depth = 0i32;
    let mut prev_letter = false;
    for c in line.chars() {
        match c {
            '(' => depth += 1,
            ')' if depth > 0 => depth -= 1,
            ')' => return false,
            _ if depth > 0 => {}
            c if c.is_ascii_alphabetic() => prev_letter = true,
            c if c.is_ascii_digit() || "+-.#[]=*/, \t;".contains(c) => {}
            _ => return false,
        }
    }
    depth == 0 && (prev_letter || line.trim_matches([' ', '\t', ';', '/']).is_empty())
}

/// The programs of a downloaded text, in order; EW_DATA if it is not
/// punch format.
pub fn programs(text: &[u8]) -> Reply<Vec<String>> {
    let text = std::str::from_utf8(text)
        .ok()
        .filter(|t| t.is_ascii())
        .ok_or(CncError::new(EW_DATA))?;
    let mut out: Vec<Vec<&str>> = Vec::new();
    let lines = text.split(['\n', '\r']).map(str::trim);
    // A leading "%" opens the text; a later one ends it.
    for l in lines {
        if l.starts_with('%') {
            if out.is_empty() {
                continue;
            }
            break;
        }
        if l.is_empty() {
            continue;
        }
        let l = l.strip_suffix(';').unwrap_or(l).trim_end();
        if !block_ok(l) {
            return Err(CncError::new(EW_DATA));
        }
        let header = l.starts_with(['O', 'o']) && l[1..].starts_with(|c: char| c.is_ascii_digit());
        match out.last_mut() {
            Some(p) if !header => p.push(l),
            _ => out.push(vec![l]),
        }
    }
    Ok(out.into_iter().map(|p| p.join("\n")).collect())
}

impl Machine {
    /// A finished download of the data type and path `req` names.
    pub(crate) fn download(&mut self, req: &StartReq, text: &[u8]) -> Reply<()> {
        if req.dtype != 0 {
            return Err(CncError::new(EW_ATTRIB));
        }
        let today = self.today();
        let new: Vec<Program> = programs(text)?
            .iter()
            .map(|t| Program::new(t, today))
            .collect();
        if new.is_empty() || new.iter().any(|p| p.number <= 0) {
            return Err(CncError::new(EW_DATA));
        }
        // All or nothing: a copy takes them, then replaces the store.
        let mut store = self.store.clone();
        for p in new {
            store.insert(req.path, p)?;
        }
        self.store = store;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn punch_text_splits_into_programs() {
        let t = b"%\nO1234(DEMO)\nG0X1.;\n\nM30\nO2(B)\nM30\n%\ngarbage";
        assert_eq!(
            programs(t).unwrap(),
            ["O1234(DEMO)\nG0X1.\nM30", "O2(B)\nM30"]
        );
        assert_eq!(programs(b"\nO1\nM30\n%").unwrap(), ["O1\nM30"]);
    }

    #[test]
    fn bad_blocks_are_refused() {
        for t in [
            &b"%\nO1\nG0X1.(open\n%"[..],
            b"%\nO1\n\xff\n%",
            b"%\nO1\n12\n%",
            b"%\nO1\nG0 ? X1\n%",
        ] {
            assert_eq!(programs(t).map_err(|e| e.code), Err(EW_DATA), "{t:?}");
        }
    }
}
