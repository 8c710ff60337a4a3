//! What the repository ships, checked: the built library (soname, exports,
//! size), the header (fresh, usable from C and C++, struct layouts), `make
//! install`, the C examples and those in other languages, src/'s layering,
//! and the documentation's function table.

#[path = "../toolchain/mod.rs"]
mod toolchain;

mod abi;
mod artifacts;
mod c_examples;
mod examples;
mod header;
mod install;
mod layers;
mod readme;
