//! The text of the block executing and of those after it (cnc_rdexecprog).

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::error::Result;
use super::part::{Part, via};
use crate::proto::program::rdexecprog;

fn part(length: u16) -> impl Part<Out = String> + Send + 'static {
    let n = usize::from(length).min(crate::proto::packet::MAX_ANSWER);
    via("cnc_rdexecprog", rdexecprog(length), 4 + n, |e| {
        Ok(String::from_utf8_lossy(&e.text).into_owned())
    })
}

impl Cnc {
    /// At most `length` bytes of the program text from the block executing
    /// on (cnc_rdexecprog): blocks end in a line feed.
    ///
    /// ```
    /// use fwlib32::native::Cnc;
    /// use fwlib32::sim::{Profile, Simulator};
    /// use std::time::Duration;
    ///
    /// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// sim.set_elapsed(Duration::from_secs(1));
    /// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
    /// let text = cnc.executing(256)?;
    /// assert!(text.lines().next().is_some_and(|b| b.starts_with('N')));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn executing(&self, length: u16) -> Result<String> {
        self.run(part(length))
    }
}

impl Batch<'_> {
    /// [`Cnc::executing`] in the batch.
    pub fn executing(&mut self, length: u16) -> Ticket<String> {
        self.push(part(length))
    }
}
