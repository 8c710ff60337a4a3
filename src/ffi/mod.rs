//! The C ABI: one module per API area. Every exported body runs inside
//! `ffi_boundary!`, so a panic becomes `EW_UNEXP` instead of crossing into C.

pub mod absent;
pub mod alarm;
pub mod axisdata;
pub mod described;
pub mod download;
pub mod dynamic;
pub mod exported;
pub mod exports;
pub mod ext;
pub mod folder;
pub mod handle;
pub mod history;
pub mod machine;
pub mod macros;
pub mod memory;
pub mod offset;
pub mod param;
pub mod paraminfo;
pub mod pmc;
pub mod position;
pub mod program;
pub mod spindle;
pub mod status;
pub mod tool;
pub mod upload;

use crate::client::log;
use crate::error::{Error, Result};
use crate::ew::{EW_OK, EW_UNEXP};
use std::os::raw::{c_char, c_short};

/// Runs an exported function's body: `Result<()>` becomes an `EW_*` code,
/// a panic becomes `EW_UNEXP`. The signature stays outside, for cbindgen.
macro_rules! ffi_boundary {
    ($name:literal, $body:block) => {{ $crate::ffi::boundary($name, &mut || -> $crate::error::Result<()> { $body }) }};
}
pub(crate) use ffi_boundary;

/// [`ffi_boundary`] for a read that may join a batch (fwlib_batch_begin):
/// while its handle batches, the call is queued and its body (a `move`
/// closure: its arguments by value) kept to run again at fwlib_batch_end
/// (src/client/batch.rs). Every other export answers EW_REJECT then.
macro_rules! ffi_read {
    ($name:literal, $body:block) => {{
        let mut body = move || -> $crate::error::Result<()> { $body };
        if $crate::client::batch::active() {
            $crate::ffi::read_boundary($name, Box::new(body))
        } else {
            $crate::ffi::boundary($name, &mut body)
        }
    }};
}
pub(crate) use ffi_read;

/// Runs an export's body: a panic is caught (never crosses the C
/// boundary), the result becomes its `EW_*` code. One function for every
/// export (a trait object, not a copy each).
pub(crate) fn boundary(name: &str, body: &mut dyn FnMut() -> Result<()>) -> c_short {
    crate::client::begin_call();
    finish(
        name,
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(body)),
    )
}

/// [`boundary`] while some handle batches: a call queued in its handle's
/// batch keeps its body and answers EW_OK.
pub(crate) fn read_boundary(
    name: &'static str,
    mut body: Box<dyn FnMut() -> Result<()>>,
) -> c_short {
    crate::client::begin_call();
    let r = crate::client::batch::batchable(|| {
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(&mut body))
    });
    match r {
        Ok(Err(Error::Queued)) => {
            crate::client::end_call(None);
            crate::client::handles::defer(name, body)
        }
        r => {
            crate::client::handles::forget();
            finish(name, r)
        }
    }
}

pub(crate) fn finish(name: &str, r: std::thread::Result<Result<()>>) -> c_short {
    crate::client::end_call(match &r {
        Ok(Err(e)) => Some(e),
        _ => None,
    });
    match r {
        Ok(Ok(())) => {
            crate::log_at!(log::CALLS, "{name} -> 0");
            EW_OK
        }
        Ok(Err(e)) => {
            let code = e.ew();
            crate::log_at!(log::ERRORS, "{name} -> {code}: {e}");
            code
        }
        Err(p) => {
            let msg = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            crate::log_at!(log::ERRORS, "{name} -> {EW_UNEXP}: internal panic: {msg}");
            EW_UNEXP
        }
    }
}

/// A required pointer argument, checked before any traffic.
pub(crate) fn nonnull<T>(p: *mut T) -> Result<*mut T> {
    if p.is_null() {
        Err(Error::null())
    } else {
        Ok(p)
    }
}

/// Writes a finished result to the caller (only ever on success).
///
/// # Safety
/// `p` must be non-null and point to writable memory for a `T`.
pub(crate) unsafe fn put<T>(p: *mut T, v: T) {
    unsafe { p.write_unaligned(v) }
}

/// Writes `v` at byte offset `off` of the caller's buffer.
///
/// # Safety
/// `base + off .. + size_of::<T>()` must be writable.
pub(crate) unsafe fn put_at<T>(base: *mut u8, off: usize, v: T) {
    unsafe { put(base.add(off).cast::<T>(), v) }
}

/// Writes `v` to member `$m` of the `$ty` whose bytes start at `$base` (a
/// `*mut u8`), unaligned: at the member's offset (`offset_of!`), and `v`
/// must have the member's type, both checked when the crate compiles.
/// `$m[k]` writes element `k` of an array member (`k` may pass the
/// array's declared length where the caller's buffer holds more records).
/// Use in an `unsafe` block: the member's bytes must be writable.
macro_rules! put_member {
    ($base:expr, $ty:ty, $m:ident [$k:expr], $v:expr) => {
        $crate::ffi::put_at(
            $base,
            ::std::mem::offset_of!($ty, $m) + $k * $crate::ffi::elem_size(|s: &$ty| &s.$m),
            $crate::ffi::of_member(|s: &$ty| &s.$m[0], $v),
        )
    };
    ($base:expr, $ty:ty, $m:ident, $v:expr) => {
        $crate::ffi::put_at(
            $base,
            ::std::mem::offset_of!($ty, $m),
            $crate::ffi::of_member(|s: &$ty| &s.$m, $v),
        )
    };
}
pub(crate) use put_member;

/// Where element `k` of array member `$m` of the `$ty` at `$base` (a
/// `*mut u8`) starts: a record of a caller's array of records, which
/// `put_member!` then writes. Use in an `unsafe` block.
macro_rules! element {
    ($base:expr, $ty:ty, $m:ident [$k:expr]) => {
        $base.add(::std::mem::offset_of!($ty, $m) + $k * $crate::ffi::elem_size(|s: &$ty| &s.$m))
    };
}
pub(crate) use element;

/// `v`, whose type is that of the member `_member` projects: the type
/// check of `put_member!`.
pub(crate) fn of_member<S, T>(_member: fn(&S) -> &T, v: T) -> T {
    v
}

/// The size of an element of the array member `_member` projects.
pub(crate) fn elem_size<S, T, const N: usize>(_member: fn(&S) -> &[T; N]) -> usize {
    size_of::<T>()
}

/// The caller's `length` as a byte count (negative counts as 0).
pub(crate) fn len_of(length: c_short) -> usize {
    length.max(0) as usize
}

/// A C string argument's bytes, without its NUL: passed on unchanged,
/// whatever their encoding, as FANUC's library does (a Latin-1 folder name
/// or comment works).
///
/// # Safety
/// `p` must be NULL or point to a NUL-terminated string.
pub(crate) unsafe fn cstr<'a>(p: *const c_char) -> Result<&'a [u8]> {
    if p.is_null() {
        return Err(Error::null());
    }
    Ok(unsafe { std::ffi::CStr::from_ptr(p) }.to_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ew::{EW_HANDLE, EW_OK, EW_UNEXP};

    fn run(f: impl Fn() -> Result<()> + 'static) -> c_short {
        ffi_boundary!("test", { f() })
    }

    #[test]
    fn a_panic_becomes_ew_unexp() {
        assert_eq!(run(|| panic!("bug")), EW_UNEXP);
        assert_eq!(run(|| panic!("{}", String::from("bug"))), EW_UNEXP);
    }

    #[test]
    fn results_become_codes() {
        assert_eq!(run(|| Ok(())), EW_OK);
        assert_eq!(run(|| Err(Error::handle())), EW_HANDLE);
    }
}
