//! Where a described function's records and payload lie in the caller's
//! memory, and the one place reply integers are written into C members.

use crate::ffi::put;
use crate::spec::{Field, Int};
use std::os::raw::{c_char, c_short};

/// Where a described function's records go: the byte offset of the array
/// in its output, the size of one element, and the offset of each record
/// field's member in the element.
pub(crate) struct RecordsAt<'a> {
    pub base: usize,
    pub stride: usize,
    pub offsets: &'a [usize],
    /// Where the number of records goes (a `short`), if anywhere.
    pub count: Option<usize>,
    /// The caller's in-out count (`short *`,
    /// [`Param::Count`](crate::spec::Param::Count)); NULL for a function
    /// without one.
    pub asked: *mut c_short,
    /// The caller's numbers by pointer
    /// ([`Param::Io`](crate::spec::Param::Io)), in order.
    pub io: &'a [*mut c_short],
}

/// Where a write's payload records are read from: the caller's array (NULL
/// for a function without payload), one element's size, and the offset of
/// each payload field's member in the element.
pub(crate) struct PayloadAt<'a> {
    pub input: *const u8,
    /// Where the records start in the input ([`Func::payload_in`]'s
    /// member; 0: the input is their array).
    pub base: usize,
    pub stride: usize,
    pub offsets: &'a [usize],
    /// The offset in the first element of each input member a request
    /// word carries ([`Func::inputs`], in order).
    pub words: &'a [usize],
    /// The C strings of the text parameters ([`Func::texts`], in order).
    pub texts: &'a [*const c_char],
}

/// Writes `fields`' integers, field k's elements from byte `at(k)` of its
/// output on, each converted as a C cast converts it.
///
/// # Safety
/// Every element written must lie in writable memory of its output.
pub(super) unsafe fn write_fields(
    fields: &[Field],
    outs: &[*mut u8],
    at: impl Fn(usize) -> usize,
    v: &mut impl Iterator<Item = i64>,
) {
    for (k, field) in fields.iter().enumerate() {
        for e in 0..field.n as usize {
            // A reply cut short by a later subpacket's error: the fields
            // before it only.
            let Some(x) = v.next() else {
                return;
            };
            if field.to.is_none() {
                continue;
            }
            unsafe {
                let p = outs[field.out as usize].add(at(k) + e * field.c.size());
                match field.c {
                    Int::I8 | Int::IdChar => put(p.cast::<i8>(), x as i8),
                    Int::U8 | Int::Char => put(p, x as u8),
                    Int::I16 => put(p.cast::<i16>(), x as i16),
                    Int::U16 => put(p.cast::<u16>(), x as u16),
                    Int::I32 => put(p.cast::<i32>(), x as i32),
                    Int::U32 => put(p.cast::<u32>(), x as u32),
                    // The double of these bits, native.
                    Int::F64 => put(p.cast::<f64>(), f64::from_bits(x as u64)),
                    // A C member is never of this wire kind (places are I16).
                    Int::BaseExp => put(p.cast::<i16>(), x as i16),
                }
            }
        }
    }
}
