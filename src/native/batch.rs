//! [`Batch`]: several reads in as few request frames as the protocol allows.

use super::cnc::Cnc;
use super::error::{Error, Ew, Result};
use super::part::{AnyPart, Part};
use crate::proto::frame::max_body_len;
use std::any::Any;
use std::marker::PhantomData;
use std::sync::atomic::{AtomicU64, Ordering};

static NEXT_BATCH: AtomicU64 = AtomicU64::new(1);

/// Reads collected to be sent together. Each method adds one read and
/// returns a [`Ticket`] for its typed result; [`Batch::send`] sends them,
/// packed into as few frames as fit (each frame at most as many
/// subpackets as FANUC's library puts in one on the CNC's class, and an
/// answer no larger than the CNC's frames allow), and [`Replies::take`] hands each result out by its ticket.
///
/// ```
/// use fwlib32::native::{Cnc, Decimal, Mode};
/// use fwlib32::sim::{Profile, Simulator};
/// use std::time::Duration;
///
/// let sim = Simulator::start(Profile::default(), "127.0.0.1:0")?;
/// let cnc = Cnc::connect(&sim.addr().to_string(), Duration::from_secs(5))?;
///
/// let mut batch = cnc.batch();
/// let status = batch.status();
/// let parts = batch.param::<i32>(6711, None);
/// let gauge = batch.macro_var(500);
/// let absent = batch.param::<i32>(9999, None);
/// let mut replies = batch.send()?;
/// assert_eq!(replies.frames(), 1);
///
/// assert_eq!(replies.take(status)?.mode, Mode::Mem);
/// assert_eq!(replies.take(parts)?, 1234);
/// assert_eq!(replies.take(gauge)?, Some(Decimal::new(25400, 3)));
/// // Each read fails on its own: the others are not affected.
/// assert!(replies.take(absent).is_err());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct Batch<'a> {
    cnc: &'a Cnc,
    id: u64,
    parts: Vec<Box<dyn AnyPart>>,
}

/// Where one read's result will be: give it to [`Replies::take`].
#[must_use = "a ticket is the only way to the result"]
pub struct Ticket<T> {
    batch: u64,
    index: usize,
    _out: PhantomData<fn() -> T>,
}

impl<T> std::fmt::Debug for Ticket<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Ticket({})", self.index)
    }
}

/// The results of a sent batch.
pub struct Replies {
    batch: u64,
    results: Vec<Option<Box<dyn Any + Send>>>,
    frames: usize,
}

impl Cnc {
    /// A new, empty batch on this connection and path.
    pub fn batch(&self) -> Batch<'_> {
        Batch {
            cnc: self,
            id: NEXT_BATCH.fetch_add(1, Ordering::Relaxed),
            parts: Vec::new(),
        }
    }
}

impl Batch<'_> {
    /// Adds a part; its ticket.
    pub(crate) fn push<P>(&mut self, p: P) -> Ticket<P::Out>
    where
        P: Part + Send + 'static,
        P::Out: Send + 'static,
    {
        self.parts.push(Box::new(p));
        Ticket {
            batch: self.id,
            index: self.parts.len() - 1,
            _out: PhantomData,
        }
    }

    /// The connection the batch reads from.
    pub(crate) fn cnc(&self) -> &Cnc {
        self.cnc
    }

    /// Reads added so far.
    pub fn len(&self) -> usize {
        self.parts.len()
    }

    pub fn is_empty(&self) -> bool {
        self.parts.is_empty()
    }

    /// Sends every read. `Err` only when an exchange failed as a whole (no
    /// connection, a broken frame): then no result is known. A read the CNC
    /// refused is an `Err` of its own ticket.
    pub fn send(self) -> Result<Replies> {
        let cx = self.cnc.ctx();
        let open = &self.cnc.handle().pair.info.open;
        let max_body = max_body_len(open.frame_version());
        // The most FANUC's library puts in one frame on this class.
        let max_subs = crate::client::batch::default_limits(open.class()).subpackets;
        let mut frames: Vec<Vec<Box<dyn AnyPart>>> = Vec::new();
        let (mut subs, mut body) = (0, 2);
        for p in self.parts {
            let (n, size) = (p.subs(&cx).len(), p.answer_max(&cx));
            let fits = subs + n <= max_subs && body + size <= max_body;
            match frames.last_mut() {
                Some(f) if fits || f.is_empty() => f.push(p),
                _ => {
                    (subs, body) = (0, 2);
                    frames.push(vec![p]);
                }
            }
            subs += n;
            body += size;
        }
        let mut results = Vec::new();
        for f in &frames {
            results.extend(self.cnc.run_frame(f)?.into_iter().map(Some));
        }
        Ok(Replies {
            batch: self.id,
            results,
            frames: frames.len(),
        })
    }
}

impl Replies {
    /// The result of the read `ticket` stands for.
    pub fn take<T: 'static>(&mut self, ticket: Ticket<T>) -> Result<T> {
        let other = || Error::invalid("batch", Ew::DATA, "a ticket of another batch");
        if ticket.batch != self.batch {
            return Err(other());
        }
        let r = self
            .results
            .get_mut(ticket.index)
            .and_then(Option::take)
            .ok_or_else(other)?;
        match r.downcast::<Result<T>>() {
            Ok(r) => *r,
            Err(_) => Err(other()),
        }
    }

    /// How many request frames the batch took.
    pub fn frames(&self) -> usize {
        self.frames
    }
}
