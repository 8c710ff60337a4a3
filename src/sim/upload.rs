//! Program upload on connection 1: what the CNC pushes for a request.

use super::Machine;
use super::service::{CncError, Reply};
use super::store::Program;
use crate::ew::{EW_ATTRIB, EW_DATA};

impl Machine {
    /// What the CNC pushes for an upload request (0x1501): the stored
    /// programs of the O-number range ("O`<s>`-O`<e>`") or of the name
    /// ("N:`<name>`": a program's name, "O`<number>`" or the last part of its
    /// path name) as a CNC punches them. Errors (the CNC's error frame; a
    /// real CNC's codes are not known): data type other than 0 (NC
    /// program) EW_ATTRIB, no such path EW_PATH, a range with start > end
    /// EW_NUMBER, no program found or a name not understood EW_DATA.
    pub fn upload_text(&self, req: &crate::proto::upload::StartReq) -> Reply<Vec<u8>> {
        if req.dtype != 0 {
            return Err(CncError::new(EW_ATTRIB));
        }
        if req.path == 0 || usize::from(req.path) > self.profile.paths.len() {
            return Err(CncError::PATH);
        }
        let progs = self.store.iter(req.path);
        let start = req.start_text();
        let found: Vec<&Program> = if let Some(name) = start.strip_prefix("N:") {
            progs
                .filter(|p| !name.is_empty() && p.answers_to(name, req.path))
                .collect()
        } else {
            let (s, e) = req.range().ok_or(CncError::new(EW_DATA))?;
            if s > e {
                return Err(CncError::NUMBER);
            }
            progs
                .filter(|p| (s..=e).contains(&i64::from(p.number)))
                .collect()
        };
        if found.is_empty() {
            return Err(CncError::new(EW_DATA));
        }
        Ok(crate::proto::upload::punch(found.iter().map(|p| &*p.text)))
    }
}
