//! Periodic maintenance (class 1): item names and items, read and written
//! as fixed records (docs/protocol/machine.md, "Periodic maintenance"). The
//! functions are described as data (src/spec/table/maintenance.rs); this is
//! the wire layout the simulator answers in.

/// Bytes of an item name.
pub const NAME_LEN: usize = 62;
pub use super::cmd::{RDPM_CNCITEM, RDPM_ITEM, RDPM_MCNITEM, WRPM_ITEM, WRPM_MCNITEM};
/// Bytes of an item on the wire: name, 2 bytes, i32 type, total, remain,
/// stat (IODBPMAINTE's layout, big-endian).
pub const ITEM_LEN: usize = 80;
/// Most names FANUC's library asks for at once (23 × 62 fit one answer).
pub const NAMES_MAX: i16 = 23;
/// Most items FANUC's library asks for at once (17 × 80).
pub const ITEMS_MAX: i16 = 17;

/// A maintenance item as on the wire.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PmItem {
    pub name: [u8; NAME_LEN],
    pub r#type: i32,
    pub total: i32,
    pub remain: i32,
    pub stat: i32,
}

impl PmItem {
    pub fn from_wire(b: &[u8]) -> PmItem {
        let word = |i: usize| i32::from_be_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
        let mut name = [0; NAME_LEN];
        name.copy_from_slice(&b[..NAME_LEN]);
        PmItem {
            name,
            r#type: word(64),
            total: word(68),
            remain: word(72),
            stat: word(76),
        }
    }
    /// The 80 wire bytes (the two after the name zero).
    pub fn to_wire(&self) -> Vec<u8> {
        let mut b = self.name.to_vec();
        b.extend([0, 0]);
        for v in [self.r#type, self.total, self.remain, self.stat] {
            b.extend(v.to_be_bytes());
        }
        b
    }
}
