//! What every connection of one simulated CNC shares: the CNC behind its
//! lock, the session count, the clock (frozen in tests), the machine's
//! faults and trace, and its listener's state (refusing or not).

use super::faults::FaultPlan;
use super::service::CncService;
use super::trace::Trace;
use parking_lot::Mutex;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::time::Instant;
use tokio::sync::watch;

/// What a machine's network side is given besides its CNC.
pub struct Net {
    /// Time zero of the faults' schedules (and of the trace's clock).
    pub zero: Instant,
    pub faults: FaultPlan,
    pub trace: Option<Arc<Trace>>,
    /// The machine's name in trace lines ("m1", "m2" ...).
    pub label: String,
}

impl Net {
    /// No faults, no trace.
    pub fn plain() -> Net {
        Net {
            zero: Instant::now(),
            faults: FaultPlan::default(),
            trace: None,
            label: "m1".into(),
        }
    }
}

/// Shared by every connection of one simulated CNC.
pub struct Shared {
    pub cnc: Mutex<Box<dyn CncService>>,
    pub(crate) sessions: AtomicUsize,
    /// A frozen clock (tests): frames are answered as at this instant.
    pub(crate) clock: watch::Sender<Option<Instant>>,
    pub net: Net,
    /// Bumped each time the machine drops off the network: connections
    /// opened before are gone.
    epoch: AtomicU64,
    /// Connection numbers, for the trace.
    pub(crate) next_conn: AtomicU64,
    /// The listener's socket (once serving) and whether it listens: set
    /// under this lock from the clock read under it, by the accept loop
    /// and by [`Shared::set_clock`], so the last clock set always decides.
    pub(crate) listener: Mutex<Option<(std::os::fd::RawFd, bool)>>,
    /// How many times it listened again: the accept loop registers the
    /// socket anew with the runtime after each (a socket shut down has
    /// reported a hang-up, and the runtime keeps that for good).
    pub(crate) relistens: AtomicU64,
    /// Data request frames (0x2101) answered: round trips.
    pub(crate) data_frames: AtomicU64,
}

impl Shared {
    pub fn new(cnc: Box<dyn CncService>) -> Arc<Shared> {
        Shared::with_net(cnc, Net::plain())
    }

    pub fn with_net(cnc: Box<dyn CncService>, net: Net) -> Arc<Shared> {
        Arc::new(Shared {
            cnc: Mutex::new(cnc),
            sessions: AtomicUsize::new(0),
            clock: watch::Sender::new(None),
            net,
            epoch: AtomicU64::new(0),
            next_conn: AtomicU64::new(1),
            listener: Mutex::new(None),
            relistens: AtomicU64::new(0),
            data_frames: AtomicU64::new(0),
        })
    }

    /// Freezes the clock data frames are answered at (None: real time again).
    /// A machine refusing connections at that instant has stopped
    /// listening when this returns.
    pub fn set_clock(&self, at: Option<std::time::Instant>) {
        self.clock.send_replace(at);
        self.apply_listening();
    }
    /// Listens or not, as the faults say for now; whether it refuses.
    pub(crate) fn apply_listening(&self) -> bool {
        let mut l = self.listener.lock();
        let refusing = self.net.faults.refusing(self.fault_time(self.now()));
        if let Some((fd, listening)) = l.as_mut()
            && *listening == refusing
        {
            // SAFETY: the listener's own socket, open while it is set here.
            unsafe {
                if refusing {
                    // Linux: a listening socket shut down for reading
                    // is closed but keeps its port; `listen` reopens it.
                    libc::shutdown(*fd, libc::SHUT_RD);
                } else {
                    libc::listen(*fd, 1024);
                    self.relistens.fetch_add(1, Ordering::AcqRel);
                }
            }
            *listening = !refusing;
            let what = if refusing { "refusing" } else { "accepting" };
            self.trace(0, || format!("!! {what} connections"));
        }
        refusing
    }
    /// The instant a data frame is answered at.
    pub fn now(&self) -> std::time::Instant {
        self.clock.borrow().unwrap_or_else(std::time::Instant::now)
    }
    pub(crate) fn frozen(&self) -> bool {
        self.clock.borrow().is_some()
    }
    /// Seconds since the faults' time zero at `now`.
    pub fn fault_time(&self, now: Instant) -> f64 {
        now.saturating_duration_since(self.net.zero).as_secs_f64()
    }
    /// FOCAS sessions open now (connection-1 opens not yet closed).
    pub fn sessions(&self) -> usize {
        self.sessions.load(Ordering::Relaxed)
    }
    /// Data request frames answered so far (round trips on connection 2).
    pub fn data_frames(&self) -> u64 {
        self.data_frames.load(Ordering::Relaxed)
    }
    pub(crate) fn epoch(&self) -> u64 {
        self.epoch.load(Ordering::Acquire)
    }
    /// The machine drops off the network: every open connection is gone.
    pub(crate) fn drop_off(&self) {
        self.epoch.fetch_add(1, Ordering::AcqRel);
    }
    pub(crate) fn trace(&self, conn: u64, text: impl FnOnce() -> String) {
        if let Some(t) = &self.net.trace {
            t.line(&self.net.label, conn, &text());
        }
    }
}
