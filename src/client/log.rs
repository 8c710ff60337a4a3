//! The library's own log: a readable text file (or stderr), never stdout,
//! never the process-global `log` facade. Failures to log are swallowed.
//!
//! Levels follow FANUC's `cnc_startupprocess`: 0 off, 1 errors, 2 every
//! call, 3 every byte sent and received. `FWLIB32_LOG_LEVEL` (and
//! `FWLIB32_LOG_FILE`, default stderr) turn it on for programs that never
//! call `cnc_startupprocess`.

use parking_lot::Mutex;
use std::fs::File;
use std::io::Write;
use std::sync::OnceLock;
use std::sync::atomic::{AtomicU8, Ordering};
use std::time::SystemTime;

static LEVEL: AtomicU8 = AtomicU8::new(0);
static SINK: Mutex<Option<Sink>> = Mutex::new(None);
static ENV: OnceLock<()> = OnceLock::new();

enum Sink {
    File(File),
    Stderr,
}

pub const ERRORS: u8 = 1;
pub const CALLS: u8 = 2;
pub const BYTES: u8 = 3;

fn init_from_env() {
    ENV.get_or_init(|| {
        let Some(level) = std::env::var("FWLIB32_LOG_LEVEL")
            .ok()
            .and_then(|v| v.trim().parse::<u8>().ok())
        else {
            return;
        };
        let sink = match std::env::var_os("FWLIB32_LOG_FILE") {
            Some(p) => match std::fs::OpenOptions::new()
                .create(true)
                .append(true)
                .open(p)
            {
                Ok(f) => Sink::File(f),
                Err(_) => Sink::Stderr,
            },
            None => Sink::Stderr,
        };
        *SINK.lock() = Some(sink);
        LEVEL.store(level.min(BYTES), Ordering::Relaxed);
    });
}

/// Opens `path` (truncating it) and logs at `level` from now on.
pub fn start(level: u8, path: Option<&std::path::Path>) -> std::io::Result<()> {
    init_from_env();
    let sink = match path {
        Some(p) => Sink::File(File::create(p)?),
        None => Sink::Stderr,
    };
    *SINK.lock() = Some(sink);
    LEVEL.store(level.min(BYTES), Ordering::Relaxed);
    Ok(())
}

/// Flushes and closes the log (cnc_exitprocess).
pub fn stop() {
    LEVEL.store(0, Ordering::Relaxed);
    if let Some(Sink::File(mut f)) = SINK.lock().take() {
        let _ = f.flush();
    }
}

pub fn enabled(level: u8) -> bool {
    init_from_env();
    LEVEL.load(Ordering::Relaxed) >= level
}

pub fn write(level: u8, msg: std::fmt::Arguments<'_>) {
    if !enabled(level) {
        return;
    }
    let line = format!("{} pid {} {}\n", utc_now(), std::process::id(), msg);
    match SINK.lock().as_mut() {
        Some(Sink::File(f)) => {
            let _ = f.write_all(line.as_bytes());
        }
        Some(Sink::Stderr) => {
            let _ = std::io::stderr().write_all(line.as_bytes());
        }
        None => {}
    }
}

/// Now, RFC 3339 in UTC to the millisecond ("2026-11-28T11:22:06.123Z").
/// By libc's gmtime_r, not a date crate: jiff here added 185 KB to the
/// stripped library (1.16 MB to 1.35 MB, over tests/artifacts/install.rs's guard)
/// for one time stamp.
fn utc_now() -> String {
    let now = SystemTime::now()
        .duration_since(SystemTime::UNIX_EPOCH)
        .unwrap_or_default();
    let secs = now.as_secs() as libc::time_t;
    // SAFETY: plain out-parameter; gmtime_r is reentrant.
    let mut tm: libc::tm = unsafe { std::mem::zeroed() };
    if unsafe { libc::gmtime_r(&secs, &mut tm) }.is_null() {
        return format!("{}.{:03}", now.as_secs(), now.subsec_millis());
    }
    format!(
        "{:04}-{:02}-{:02}T{:02}:{:02}:{:02}.{:03}Z",
        tm.tm_year + 1900,
        tm.tm_mon + 1,
        tm.tm_mday,
        tm.tm_hour,
        tm.tm_min,
        tm.tm_sec,
        now.subsec_millis()
    )
}

/// Hex dump of a frame at level 3.
pub fn bytes(dir: &str, conn: u8, peer: &str, b: &[u8]) {
    if enabled(BYTES) {
        let mut hex = String::with_capacity(b.len() * 2);
        for x in b {
            use std::fmt::Write as _;
            let _ = write!(hex, "{x:02x}");
        }
        write(
            BYTES,
            format_args!("{dir} conn{conn} {peer} {} bytes: {hex}", b.len()),
        );
    }
}

#[macro_export]
macro_rules! log_at {
    ($level:expr, $($arg:tt)*) => {
        if $crate::client::log::enabled($level) {
            $crate::client::log::write($level, format_args!($($arg)*));
        }
    };
}
