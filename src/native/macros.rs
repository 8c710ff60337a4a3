//! Custom macro variables (cnc_rdmacro, cnc_wrmacro).

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::decimal::Decimal;
use super::error::{Error, Ew, Result};
use super::part::{Failed, Part, via};
use crate::proto::macros::{FIRST_WRITABLE, ReadMacros, VACANT_DEC, WriteMacros};

const READ: &str = "cnc_rdmacro";
const WRITE: &str = "cnc_wrmacro";

fn number(call: &'static str, n: u32) -> Result<i32> {
    i32::try_from(n).map_err(|_| Error::invalid(call, Ew::NUMBER, "variable number too large"))
}

fn read_part(n: i32) -> impl Part<Out = Option<Decimal>> + Send + 'static {
    via(READ, ReadMacros { s: n, e: n }, 8, |recs| {
        let r = recs.first().ok_or_else(|| {
            Error::of(
                READ,
                crate::error::Error::short("macro reply carries no record"),
            )
        })?;
        let (value, decimals) = r.to_decimal();
        Ok((decimals != VACANT_DEC).then_some(Decimal::new(value, decimals)))
    })
}

impl Cnc {
    /// Custom macro variable `#number` of the current path; `None` when it is
    /// vacant (`<null>`).
    ///
    /// ```
    /// use fwlib32::native::{Cnc, Decimal};
    /// use fwlib32::sim::{Profile, Simulator};
    /// use std::time::Duration;
    ///
    /// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
    /// assert_eq!(cnc.macro_var(501)?, Some("-0.125".parse()?));
    /// assert_eq!(cnc.macro_var(102)?, None); // vacant
    ///
    /// cnc.set_macro_var(102, Decimal::new(15, 1))?;
    /// assert_eq!(cnc.macro_var(102)?.unwrap().to_string(), "1.5");
    /// cnc.set_macro_var(102, None)?; // vacant again
    /// assert_eq!(cnc.macro_var(102)?, None);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn macro_var(&self, number: u32) -> Result<Option<Decimal>> {
        self.run(read_part(self::number(READ, number)?))
    }

    /// Sets `#number` (100 and up) to `value`, or makes it vacant with `None`.
    pub fn set_macro_var(&self, number: u32, value: impl Into<Option<Decimal>>) -> Result<()> {
        let n = self::number(WRITE, number)?;
        if n < i32::from(FIRST_WRITABLE) {
            let msg = "local variables #1..#99 cannot be written";
            return Err(Error::invalid(WRITE, Ew::NUMBER, msg));
        }
        let v = value
            .into()
            .map_or((0, VACANT_DEC), |d| (d.value, d.decimals));
        let c = WriteMacros {
            s: n,
            values: vec![v],
        };
        self.run(via(WRITE, c, 0, Ok))
    }
}

impl Batch<'_> {
    /// [`Cnc::macro_var`] in the batch.
    pub fn macro_var(&mut self, number: u32) -> Ticket<Option<Decimal>> {
        match self::number(READ, number) {
            Ok(n) => self.push(read_part(n)),
            Err(e) => self.push(Failed::new(e)),
        }
    }
}
