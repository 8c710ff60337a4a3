//! Modal codes other than G (cnc_modal types 100 to 126): the F, S, T ...
//! in effect.

use super::batch::{Batch, Ticket};
use super::cnc::Cnc;
use super::error::{Error, Ew, Result};
use super::part::{Part, Ready, via};
use crate::proto::program::{Modal, ModalCall, ModalKind, modal_kind};

const CALL: &str = "cnc_modal";

/// The part reading code type `kind` of the block executing, or the
/// refusal (no traffic) of a type that is not one code.
fn part(kind: i16) -> std::result::Result<impl Part<Out = i32> + Send + 'static, Ready<i32>> {
    match modal_kind(kind) {
        Some(k @ ModalKind::Aux(_)) if (100..=126).contains(&kind) => {
            // One 8-byte record.
            Ok(via(CALL, ModalCall { kind: k, block: 0 }, 8, |m| match m {
                Modal::Aux(a) => {
                    a.0.first().map(|c| c.value).ok_or_else(|| {
                        Error::invalid(CALL, Ew::NUMBER, "no such code in the answer")
                    })
                }
                Modal::G(_) => Err(Error::invalid(CALL, Ew::NUMBER, "a G-code answer")),
            }))
        }
        _ => Err(Ready(Err(Error::invalid(
            CALL,
            Ew::NUMBER,
            "types 100 to 126 are the codes other than G (103 F, 107 S, 108 T ...)",
        )))),
    }
}

impl Cnc {
    /// The modal code of cnc_modal type `kind` (100 to 126: 103 F, 107 S,
    /// 108 T ...) in the block executing.
    ///
    /// ```
    /// use fwlib32::native::Cnc;
    /// use fwlib32::sim::{Profile, Simulator};
    /// use std::time::Duration;
    ///
    /// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
    /// sim.set_elapsed(Duration::ZERO);
    /// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
    /// assert_eq!(cnc.modal_code(107)?, 12000); // S
    /// assert!(cnc.modal_code(5).is_err()); // a G-code group
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn modal_code(&self, kind: i16) -> Result<i32> {
        match part(kind) {
            Ok(p) => self.run(p),
            Err(r) => self.run(r),
        }
    }
}

impl Batch<'_> {
    /// [`Cnc::modal_code`] in the batch.
    pub fn modal_code(&mut self, kind: i16) -> Ticket<i32> {
        match part(kind) {
            Ok(p) => self.push(p),
            Err(r) => self.push(r),
        }
    }
}
