//! NC programs: the program directory (cnc_rdprogdir3), upload
//! (cnc_upstart3, cnc_upload3, cnc_upend3) and download (cnc_dwnstart3,
//! cnc_download3, cnc_dwnend3) on connection 1, deletion (cnc_delete).

use super::alarm::Timestamp;
use super::cnc::Cnc;
use super::error::{Error, Result};
use crate::ew::{EW_BUFFER, EW_RESET};
use crate::proto::described::Described;
use crate::proto::download::DOWNLOAD;
use crate::proto::program::{DirEntry, PROGDIR_CHUNK, progdir, progdir3_code};
use crate::proto::upload::{StartReq, range_name};

/// A program in the CNC's memory.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct ProgramEntry {
    /// The O number.
    pub number: u32,
    /// Size in bytes, as the CNC counts it.
    pub length: i32,
    /// The comment, without its parentheses ("" for none).
    pub comment: String,
    /// Last modified, when the CNC says.
    pub modified: Option<Timestamp>,
}

pub(super) fn entry(e: &DirEntry) -> ProgramEntry {
    let c = String::from_utf8_lossy(e.comment_text()).trim().to_string();
    let comment = c
        .strip_prefix('(')
        .and_then(|c| c.strip_suffix(')'))
        .map_or(c.clone(), str::to_string);
    let [year, month, day, hour, minute, _] = e.date;
    let modified = (year > 0 && (1..=12).contains(&month)).then_some(Timestamp {
        year,
        month: month as u8,
        day: day as u8,
        hour: hour as u8,
        minute: minute as u8,
        second: 0,
    });
    ProgramEntry {
        number: e.number.max(0) as u32,
        length: e.length,
        comment,
        modified,
    }
}

impl Cnc {
    /// The programs stored for the current path, by number, with size,
    /// comment and date (cnc_rdprogdir3 type 2, 19 programs an exchange).
    ///
    /// ```
    /// use fwlib32::native::Cnc;
    /// use fwlib32::sim::{Profile, Simulator};
    /// use std::time::Duration;
    ///
    /// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
    /// let progs = cnc.programs()?;
    /// assert_eq!(progs[1].number, 1234);
    /// assert_eq!(progs[1].comment, "POCKET DEMO");
    ///
    /// let text = cnc.program(1234)?;
    /// assert!(text.starts_with("%\nO1234 (POCKET DEMO)\n"));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn programs(&self) -> Result<Vec<ProgramEntry>> {
        const CALL: &str = "cnc_rdprogdir3";
        let code = progdir3_code(2).unwrap_or(3);
        let mut out: Vec<ProgramEntry> = Vec::new();
        let mut top = 0;
        loop {
            let c = progdir(top, PROGDIR_CHUNK, code);
            let d = self.run(super::part::via(CALL, c, 72 * 19, Ok))?;
            let n = d.0.len().min(PROGDIR_CHUNK as usize);
            out.extend(d.0[..n].iter().map(entry));
            // Numbers must grow from one exchange to the next.
            match d.0[..n].last() {
                Some(l)
                    if n == PROGDIR_CHUNK as usize && l.number >= top && l.number < i32::MAX =>
                {
                    top = l.number + 1
                }
                _ => return Ok(out),
            }
        }
    }

    /// Uploads program O`number` of the current path: its text as the CNC
    /// punches it ("%", the blocks one per line, "%").
    pub fn program(&self, number: u32) -> Result<String> {
        self.program_with(number, |_| {})
    }

    /// As [`Cnc::program`], calling `progress` with the bytes received so
    /// far as they arrive (compare with [`ProgramEntry::length`]).
    pub fn program_with(&self, number: u32, mut progress: impl FnMut(usize)) -> Result<String> {
        let (h, me) = (self.handle(), self.number());
        let (path, timeout) = {
            let s = h.state.lock();
            (s.path, s.timeout)
        };
        let n = number.min(i32::MAX as u32) as i32;
        let req = StartReq {
            dtype: 0,
            path,
            start: range_name(n, n),
            end: Vec::new(),
        };
        h.upload_start(me, &req, timeout)
            .map_err(|e| Error::of("cnc_upstart3", e))?;
        let mut text = Vec::new();
        let mut buf = vec![0u8; 4096];
        loop {
            match h.upload_read(me, &mut buf, timeout) {
                Ok(k) => {
                    text.extend_from_slice(&buf[..k]);
                    progress(text.len());
                }
                Err(e) if e.ew() == EW_BUFFER => h
                    .upload_wait(me, timeout)
                    .map_err(|e| Error::of("cnc_upload3", e))?,
                Err(e) if e.ew() == EW_RESET => break,
                Err(e) => {
                    let _ = h.upload_end(me, timeout);
                    return Err(Error::of("cnc_upload3", e));
                }
            }
        }
        h.upload_end(me, timeout)
            .map_err(|e| Error::of("cnc_upend3", e))?;
        Ok(String::from_utf8_lossy(&text).into_owned())
    }

    /// Downloads program text in punch format ("%", the "O`<number>`" block
    /// and its blocks one per line, "%") into the CNC's memory, calling
    /// `progress` with the bytes sent so far. The CNC's refusal (a number in
    /// use EW_DATA, memory full EW_OVRFLOW, protected EW_PROT ...) is the
    /// error of cnc_dwnend3; a refused program is not stored.
    pub fn put_program(&self, text: &[u8], mut progress: impl FnMut(usize)) -> Result<()> {
        let (h, me) = (self.handle(), self.number());
        let (path, timeout) = {
            let s = h.state.lock();
            (s.path, s.timeout)
        };
        let req = StartReq {
            dtype: 0,
            path,
            start: Vec::new(),
            end: Vec::new(),
        };
        h.send_start(me, DOWNLOAD, &req, false, timeout)
            .map_err(|e| Error::of("cnc_dwnstart3", e))?;
        let mut sent = 0;
        for chunk in text.chunks(DOWNLOAD.chunk * 8) {
            if let Err(e) = h.send_data(me, DOWNLOAD, chunk, timeout) {
                let _ = h.send_end(me, DOWNLOAD, timeout);
                return Err(Error::of("cnc_download3", e));
            }
            sent += chunk.len();
            progress(sent);
        }
        h.send_end(me, DOWNLOAD, timeout)
            .map_err(|e| Error::of("cnc_dwnend3", e))
    }

    /// Deletes program `number` (cnc_delete): EW_DATA when there is none,
    /// EW_PROT when it is protected, EW_BUSY when it runs or is selected.
    /// cnc_delete takes numbers up to 32767: a larger one is EW_DATA
    /// before any traffic.
    pub fn delete_program(&self, number: u32) -> Result<()> {
        const CALL: &str = "cnc_delete";
        let Ok(n) = i16::try_from(number) else {
            return Err(Error::invalid(
                CALL,
                super::error::Ew::DATA,
                format!("O{number}: cnc_delete takes program numbers up to 32767"),
            ));
        };
        let f = crate::spec::find(CALL).expect("a described function");
        let args = [i32::from(n)];
        self.handle()
            .call(&Described::new(f, &args))
            .map(|_| ())
            .map_err(|e| Error::of(CALL, e))
    }
}
