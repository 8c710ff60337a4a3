//! Reading a response frame as FANUC's library reads it: whole entries
//! only, fixed fields zero-extended, every subpacket present, middle
//! payloads long enough.

use crate::error::{Error, Result};
use crate::proto::call::sub;
use crate::proto::packet::RespSub;
use crate::proto::value::Value;
use crate::proto::wire::Wire;

/// The whole value records of subpacket `i`, at least `need` of them: a
/// ragged tail is ignored, as FANUC's library counts them (payload / 8)
/// [fuzz, rddynamic `s8Tlong`: a 9-byte position answer].
pub(super) fn records(resp: &[RespSub], i: usize, need: usize) -> Result<Vec<Value>> {
    let v = whole_records(resp, i)?;
    if v.len() < need {
        return Err(Error::short("fewer value records than the function needs"));
    }
    Ok(v)
}

/// The low 16 bits of a word, sign-extended (FANUC's reading of alarm and
/// program numbers).
pub fn low16(v: i32) -> i32 {
    i32::from(v as i16)
}

/// The whole `size`-byte entries of a payload: a ragged tail is no entry,
/// as FANUC's library counts them (payload / size).
pub fn whole<T: Wire>(p: &[u8], size: usize) -> Result<Vec<T>> {
    Ok(Vec::<T>::from_bytes(&p[..p.len() / size * size])?)
}

/// The first `N` bytes of a payload, zero-extended when it is shorter: FANUC's
/// library reads fixed fields of the last subpacket of a frame that way
/// (its receive buffer is zero past the frame; recorded with an earlier call
/// leaving other bytes there).
pub fn zext<const N: usize>(p: &[u8]) -> [u8; N] {
    let mut b = [0u8; N];
    let n = p.len().min(N);
    b[..n].copy_from_slice(&p[..n]);
    b
}

/// The subpackets of a frame must all be there: a missing one (the later
/// ones shifted) is EW_PROTOCOL with detail 3, as FANUC's library reports it.
pub fn expect_subs(resp: &[RespSub], n: usize) -> Result<()> {
    if resp.len() < n {
        return Err(Error::protocol(
            crate::error::detail::COUNT_ZERO,
            format!("response has {} subpackets, expected {n}", resp.len()),
        ));
    }
    Ok(())
}

/// The whole value records of subpacket `i`: a ragged tail (fewer than 8
/// bytes) is no record, as FANUC's library counts them (payload / 8).
pub fn whole_records(resp: &[RespSub], i: usize) -> Result<Vec<Value>> {
    whole(&sub(resp, i)?.payload, 8)
}

/// The first `n` bytes of a middle subpacket's payload: FANUC's library
/// reads what a shorter one lacks from the next subpacket (ours:
/// EW_PROTOCOL).
pub(super) fn need(p: &[u8], n: usize, what: &str) -> Result<()> {
    if p.len() < n {
        return Err(Error::short(format!(
            "{what}: {} bytes, {n} needed",
            p.len()
        )));
    }
    Ok(())
}

pub(super) fn be16(p: &[u8], at: usize) -> u16 {
    u16::from_be_bytes([p[at], p[at + 1]])
}
