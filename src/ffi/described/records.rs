//! A described write's payload records checked, exchanged for and computed
//! one by one before its request ([`Func::rules`], [`Func::each`],
//! [`Func::codes`]): cnc_sdtsetchnl's channels.

use crate::client::handles;
use crate::error::{Error, Result};
use crate::proto::described::{EachCall, each_value};
use crate::spec::{Func, Of};

/// For each of `payload`'s records (its fields' integers as read from the
/// caller's array), in order: its [`Rule`](crate::spec::Rule)s (the first
/// refusing one returns its code, its detail set for cnc_getdtailerr), its
/// [`Each`](crate::spec::Each) exchange (an error answer ends the call),
/// then its
/// [`Code`](crate::spec::Code)s applied in place. `class`: the CNC is of
/// the 16i class, of Series 15.
pub(super) fn prepare(
    f: &'static Func,
    h: &handles::Handle,
    args: &[i32],
    payload: &mut [i64],
    class: (bool, bool),
) -> Result<()> {
    let per: usize = f
        .payload
        .map_or(0, |p| p.fields.iter().map(|x| usize::from(x.n)).sum());
    // The path's controlled axes, as the connect answer gives them.
    let path = usize::from(h.ctx().path);
    let (_, paths) = h.pair.info.open.system_ex(0);
    let axes = paths
        .get(path.wrapping_sub(1))
        .map_or(0, |p| i64::from(p[3]));
    for rec in payload.chunks_mut(per.max(1)) {
        let read = rec.to_vec();
        let at = |k: u8| read.get(usize::from(k)).copied().unwrap_or(0);
        let field = |of: Of| match of {
            Of::Field(k) => Some(at(k)),
            Of::Arg(_) => None,
        };
        if let Some((code, detail)) = f.rule_refusal(field, at, class.0, class.1, axes) {
            h.set_detail(detail);
            return Err(Error::local(code, "a record's member out of range"));
        }
        let value = match f.each_of(&read, class.0, class.1) {
            Some(e) => {
                let ask = || {
                    h.call(&EachCall {
                        each: e,
                        key: at(e.when.0),
                    })
                    .map_err(|x| match (x, e.error) {
                        (Error::Cnc { .. }, Some(code)) => {
                            Error::local(code, "an error answer to the record's exchange")
                        }
                        (x, _) => x,
                    })
                };
                each_value(e, &ask()?, at(e.when.0))
            }
            None => None,
        };
        f.coded(rec, args, value)
            .map_err(|c| Error::local(c, "a record's member outside its code table"))?;
    }
    Ok(())
}
