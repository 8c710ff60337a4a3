//! Every function the library exports, and how each is made: the table
//! build.rs writes from src/ffi/exported.rs (the functions written by hand,
//! which a test checks against src/ffi/*.rs) and src/spec/table/ (the
//! described ones, which build.rs exports itself). COMPATIBILITY.md
//! (tests/recorded/compat.rs) and `focas compat` read it; tests/artifacts/artifacts.rs
//! checks it against the built library's symbols.

/// How an exported function is made.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum How {
    /// Written by hand in `src/ffi/<area>.rs`.
    Written { area: &'static str },
    /// Described as data in src/spec/table/ (its export written by build.rs).
    Described,
    /// Declared by FANUC's header, implemented by none of FANUC's Ethernet
    /// libraries: exported so that programs link and run, answering this
    /// code without traffic as FANUC's Ethernet library does (table entries
    /// of src/spec/table/absent.rs; cnc_allclibhndl, src/ffi/absent.rs).
    NotOnEthernet { code: i16, ew: &'static str },
    /// One of our `fwlib_*` extensions (src/ffi/ext.rs, `fwlib32_ext.h`).
    Extension,
}

/// One exported function.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Export {
    pub name: &'static str,
    pub how: How,
}

include!(concat!(env!("OUT_DIR"), "/exports.rs"));

/// The exported function `name`, if the library has it.
pub fn export(name: &str) -> Option<&'static Export> {
    EXPORTS
        .binary_search_by(|e| e.name.cmp(name))
        .ok()
        .map(|i| &EXPORTS[i])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sorted_and_found() {
        assert!(EXPORTS.windows(2).all(|w| w[0].name < w[1].name));
        assert_eq!(
            export("cnc_statinfo").map(|e| e.how),
            Some(How::Written { area: "status" })
        );
        assert_eq!(
            export("cnc_rdexecpt").map(|e| e.how),
            Some(How::NotOnEthernet {
                code: crate::ew::EW_VERSION,
                ew: "EW_VERSION"
            })
        );
        assert_eq!(
            export("cnc_allclibhndl").map(|e| e.how),
            Some(How::NotOnEthernet {
                code: crate::ew::EW_MMCSYS,
                ew: "EW_MMCSYS"
            })
        );
        assert_eq!(
            export("fwlib_set_reconnect").map(|e| e.how),
            Some(How::Extension)
        );
        assert!(export("cnc_no_such_function").is_none());
        assert!(
            EXPORTS
                .iter()
                .any(|e| e.how == How::Described && e.name == crate::spec::FUNCS[0].name)
        );
    }
}
