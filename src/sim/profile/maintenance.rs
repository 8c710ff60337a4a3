//! `[maintenance]`: the periodic maintenance screen's items
//! (cnc_rdpm_item, cnc_wrpm_item) and item names (cnc_rdpm_cncitem,
//! cnc_rdpm_mcnitem, cnc_wrpm_mcnitem). Pure data; the counting is in
//! src/sim/maintenance.rs.

use serde::Deserialize;

/// Maintenance item slots (cnc_rdpm_item 1..=ITEMS).
pub const ITEMS: usize = 10;
/// Machine-specific item name slots (cnc_rdpm_mcnitem 1..=MCN_ITEMS).
pub const MCN_ITEMS: usize = 20;
/// Bytes of an item name.
pub const NAME_LEN: usize = 62;
/// The highest life count type: 0 not counted, 1 power-on time, 2
/// operating time, 3 cutting time (cnc_rdtimer 0, 1, 2).
pub const TYPE_MAX: i32 = 3;

/// One maintenance item.
#[derive(Debug, Clone, Default, Deserialize, PartialEq, Eq)]
#[serde(deny_unknown_fields, default)]
pub struct Item {
    pub name: String,
    /// Life count type (see [`TYPE_MAX`]).
    pub r#type: i32,
    /// The life, in minutes.
    pub total: i32,
    /// Minutes left when the item was last set (at power-on: the profile's).
    pub remain: i32,
    /// The counter's value (ms) when `remain` was set; None: the profile's
    /// timers at power-on.
    #[serde(skip)]
    pub base: Option<i64>,
}

/// `[maintenance]`.
#[derive(Debug, Clone, Default, Deserialize, PartialEq, Eq)]
#[serde(deny_unknown_fields, default)]
pub struct Maintenance {
    /// The CNC's item names (read only).
    pub cnc_items: Vec<String>,
    /// The machine tool builder's item names (MCN_ITEMS slots).
    pub machine_items: Vec<String>,
    /// The items (ITEMS slots; the rest empty).
    #[serde(rename = "item")]
    pub items: Vec<Item>,
}

impl Maintenance {
    /// The profile's limits.
    pub fn validate(&self) -> Result<(), String> {
        if self.items.len() > ITEMS || self.machine_items.len() > MCN_ITEMS {
            return Err(format!(
                "[maintenance]: at most {ITEMS} items and {MCN_ITEMS} machine_items"
            ));
        }
        let long = |n: &String| n.len() > NAME_LEN;
        if self.cnc_items.iter().chain(&self.machine_items).any(long)
            || self.items.iter().any(|i| long(&i.name))
        {
            return Err(format!("[maintenance]: names of at most {NAME_LEN} bytes"));
        }
        for i in &self.items {
            if !(0..=TYPE_MAX).contains(&i.r#type)
                || i.total < 0
                || !(0..=i.total).contains(&i.remain)
            {
                return Err(format!(
                    "[[maintenance.item]] {:?}: type 0 to {TYPE_MAX}, 0 <= remain <= total",
                    i.name
                ));
            }
        }
        Ok(())
    }
}
