//! The bottom layer: FOCAS functions described as data ([`Func`]), one
//! entry each in [`FUNCS`]. Everything above reads it; it reads nothing.

pub mod commands;
mod func;
pub mod reply;
pub mod rules;
pub mod table;
pub mod types;

pub use table::FUNCS;
pub use types::*;

/// The described function named `name`.
pub fn find(name: &str) -> Option<&'static Func> {
    FUNCS.iter().find(|f| f.name == name)
}

/// The described function whose request on `class` (a [`Classes`] other
/// than `All`) is command `cmd`.
pub fn by_cmd(cmd: u16, s16: bool, s15: bool) -> Option<&'static Func> {
    FUNCS
        .iter()
        .find(|f| f.form(s16, s15).is_some_and(|form| form.cmd == cmd))
}

impl Func {
    /// The request form for a CNC of the 16i class (`s16`) or Series 15 (`s15`).
    pub fn form(&self, s16: bool, s15: bool) -> Option<&'static Form> {
        self.forms.iter().find(|f| f.classes.matches(s16, s15))
    }
}
