//! The Rust API's error: which FOCAS function failed, its `EW_*` code and the
//! detail words `cnc_getdtailerr` would report.

use crate::error::Error as Internal;
use std::fmt;

/// Results of the Rust API.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// An `EW_*` result code of FANUC's library (`Ew::NUMBER` is `EW_NUMBER`, 3).
/// Its `Debug` names it too: `EW_NUMBER(3)`.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Ew(pub i16);

impl fmt::Debug for Ew {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}({})", self.name(), self.0)
    }
}

/// Defines the `Ew` constants and the table of meanings: each names its
/// code in src/ew.rs (where its value and the C header's name come from).
macro_rules! ew_table {
    ($($konst:ident = $ew:ident, $meaning:literal;)*) => {
        impl Ew {
            $(
                #[doc = concat!("`", stringify!($ew), "`: ", $meaning, ".")]
                pub const $konst: Ew = Ew(crate::ew::$ew);
            )*
        }
        /// (code, name, meaning); the first name of a shared code wins.
        const TABLE: &[(i16, &str, &str)] = &[$((crate::ew::$ew, stringify!($ew), $meaning)),*];
    };
}

ew_table! {
    PROTOCOL = EW_PROTOCOL, "protocol error: the CNC's answer is not valid FOCAS2";
    SOCKET = EW_SOCKET, "socket error: no connection, or it broke or timed out";
    NODLL = EW_NODLL, "library for this CNC not found";
    INIERR = EW_INIERR, "error in the library's initial value file";
    ITLOW = EW_ITLOW, "low temperature alarm of the intelligent terminal";
    ITHIGHT = EW_ITHIGHT, "high temperature alarm of the intelligent terminal";
    BUS = EW_BUS, "bus error";
    SYSTEM2 = EW_SYSTEM2, "system error";
    HSSB = EW_HSSB, "HSSB communication error";
    HANDLE = EW_HANDLE, "library handle error";
    VERSION = EW_VERSION, "CNC or PMC version mismatch: not available on this CNC";
    UNEXP = EW_UNEXP, "abnormal error";
    SYSTEM = EW_SYSTEM, "system error";
    PARITY = EW_PARITY, "shared RAM parity error";
    MMCSYS = EW_MMCSYS, "emm386 or mmcsys install error";
    RESET = EW_RESET, "reset or stop occurred";
    BUSY = EW_BUSY, "busy: the CNC or the connection is doing something else";
    OK = EW_OK, "no error";
    FUNC = EW_FUNC, "function not available on this CNC (command prepare error)";
    NOPMC = EW_NOPMC, "PMC does not exist";
    LENGTH = EW_LENGTH, "data block length error";
    NUMBER = EW_NUMBER, "data number error: no such number";
    RANGE = EW_RANGE, "address range error";
    ATTRIB = EW_ATTRIB, "data attribute error: wrong type or axis";
    TYPE = EW_TYPE, "data type error";
    DATA = EW_DATA, "data error";
    NOOPT = EW_NOOPT, "option not installed";
    PROT = EW_PROT, "write protected";
    OVRFLOW = EW_OVRFLOW, "memory overflow";
    PARAM = EW_PARAM, "CNC parameter not correct";
    BUFFER = EW_BUFFER, "buffer empty or full";
    PATH = EW_PATH, "no such path";
    MODE = EW_MODE, "not possible in the CNC's current mode";
    REJECT = EW_REJECT, "execution rejected by the CNC";
    DTSRVR = EW_DTSRVR, "data server error";
    ALARM = EW_ALARM, "the CNC is in alarm";
    STOP = EW_STOP, "the CNC is not running";
    PASSWD = EW_PASSWD, "protected: parameter write or password needed";
    PMC = EW_PMC, "error reported by the PMC";
    PMCHANDLE = EW_PMCHANDLE, "PMC handle error";
    RD_OVWSTP = EW_RD_OVWSTP, "overwrite stop in program read";
    RD_RSTFIN = EW_RD_RSTFIN, "reset interrupt in program read";
}

impl Ew {
    /// The code's name, e.g. `"EW_NUMBER"`; `"EW_?"` for a code FANUC's
    /// header does not define.
    pub fn name(self) -> &'static str {
        TABLE.iter().find(|e| e.0 == self.0).map_or("EW_?", |e| e.1)
    }

    /// What the code means, for people.
    pub fn meaning(self) -> &'static str {
        TABLE
            .iter()
            .find(|e| e.0 == self.0)
            .map_or("unknown result code", |e| e.2)
    }
}

impl fmt::Display for Ew {
    /// `EW_NUMBER (3)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({})", self.name(), self.0)
    }
}

/// The two detail words of an error, as `cnc_getdtailerr` (`pmc_getdtailerr`
/// for PMC reads) reports them after the call: the CNC's own words for a
/// code the CNC answered, the library's location codes for a socket or
/// protocol error, zeros for a check made before any traffic.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub struct Detail {
    /// `ODBERR.err_no`.
    pub err_no: i16,
    /// `ODBERR.err_dtno`.
    pub err_dtno: i16,
}

impl Detail {
    fn suffix(&self) -> String {
        if *self == Detail::default() {
            String::new()
        } else {
            format!(" [detail {}/{}]", self.err_no, self.err_dtno)
        }
    }
}

/// Why a call failed. Every variant names the FOCAS function (`call`, e.g.
/// `"cnc_rdparam"`); [`Error::code`] gives its `EW_*` code and
/// [`Error::detail`] the detail words.
///
/// Its `Debug` is the message (what `fn main() -> Result<..>` prints on an
/// error): `cnc_statinfo: EW_SOCKET (-16): socket error: ...`; `{:#?}` shows
/// the fields.
#[derive(Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// No connection: refused, unreachable, closed by the CNC, timed out
    /// (`EW_SOCKET`). The connection is closed; connect again.
    #[error("{call}: {}: {}: {msg}{}", Ew::SOCKET, Ew::SOCKET.meaning(), .detail.suffix())]
    Socket {
        call: &'static str,
        detail: Detail,
        msg: String,
    },
    /// The CNC sent something that is not FOCAS2 (`EW_PROTOCOL`).
    #[error("{call}: {}: {}: {msg}{}", Ew::PROTOCOL, Ew::PROTOCOL.meaning(), .detail.suffix())]
    Protocol {
        call: &'static str,
        detail: Detail,
        msg: String,
    },
    /// The CNC answered with an error code (no such number, write
    /// protected, not in this mode ...).
    #[error("{call}: {code}: {}{}", .code.meaning(), .detail.suffix())]
    Cnc {
        call: &'static str,
        code: Ew,
        detail: Detail,
    },
    /// Refused by the library before any traffic, or an answer that does not
    /// fit what was asked (a real parameter read as `i16` ...).
    #[error("{call}: {code}: {}: {msg}", .code.meaning())]
    Invalid {
        call: &'static str,
        code: Ew,
        msg: String,
    },
}

impl fmt::Debug for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !f.alternate() {
            return fmt::Display::fmt(self, f);
        }
        let mut s = f.debug_struct("Error");
        s.field("call", &self.call()).field("code", &self.code());
        s.field("detail", &self.detail());
        if let Error::Socket { msg, .. }
        | Error::Protocol { msg, .. }
        | Error::Invalid { msg, .. } = self
        {
            s.field("msg", msg);
        }
        s.finish()
    }
}

impl Error {
    /// The FOCAS function that failed.
    pub fn call(&self) -> &'static str {
        match self {
            Error::Socket { call, .. }
            | Error::Protocol { call, .. }
            | Error::Cnc { call, .. }
            | Error::Invalid { call, .. } => call,
        }
    }

    /// The `EW_*` code a C program would have got.
    pub fn code(&self) -> Ew {
        match self {
            Error::Socket { .. } => Ew::SOCKET,
            Error::Protocol { .. } => Ew::PROTOCOL,
            Error::Cnc { code, .. } | Error::Invalid { code, .. } => *code,
        }
    }

    /// The detail words `cnc_getdtailerr` reports after the call.
    pub fn detail(&self) -> Detail {
        match self {
            Error::Socket { detail, .. }
            | Error::Protocol { detail, .. }
            | Error::Cnc { detail, .. } => *detail,
            Error::Invalid { .. } => Detail::default(),
        }
    }

    /// An error found by this API before or after the exchange.
    pub(crate) fn invalid(call: &'static str, code: Ew, msg: impl Into<String>) -> Error {
        Error::Invalid {
            call,
            code,
            msg: msg.into(),
        }
    }

    /// The library's internal error, for `call`.
    pub(crate) fn of(call: &'static str, e: Internal) -> Error {
        let d = |(err_no, err_dtno): (i16, i16)| Detail { err_no, err_dtno };
        match e {
            Internal::Socket { detail, msg } => Error::Socket {
                call,
                detail: d(detail),
                msg,
            },
            Internal::Protocol { detail, msg } => Error::Protocol {
                call,
                detail: d(detail),
                msg,
            },
            Internal::Cnc {
                code,
                detail1,
                detail2,
            } => Error::Cnc {
                call,
                code: Ew(code),
                detail: d((detail1 as i16, detail2 as i16)),
            },
            Internal::Local { code, msg } => Error::invalid(call, Ew(code), msg),
            // The native API never batches C calls.
            Internal::Queued => Error::invalid(call, Ew(0), "queued in a batch"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `fn main() -> Result<..>` prints the Debug form: it names the call and
    /// the EW code, not `Ew(-16)`.
    #[test]
    fn debug_names_the_code() {
        let e = Error::Socket {
            call: "cnc_statinfo",
            detail: Detail::default(),
            msg: "connection refused".into(),
        };
        let plain = format!("{e:?}");
        assert!(
            plain.starts_with("cnc_statinfo: EW_SOCKET (-16): "),
            "{plain}"
        );
        assert!(plain.ends_with("connection refused"), "{plain}");
        let full = format!("{e:#?}");
        assert!(
            full.contains("EW_SOCKET(-16)") && full.contains("cnc_statinfo"),
            "{full}"
        );
        assert_eq!(format!("{:?}", Ew::NUMBER), "EW_NUMBER(3)");
    }

    /// Every code of src/ew.rs (the header's codes) has its meaning here,
    /// under its name and value, and nothing else is.
    #[test]
    fn the_table_is_the_headers() {
        for &(name, value, _) in crate::ew::CODES {
            assert!(
                TABLE.iter().any(|e| e.0 == value && e.1 == name),
                "{name} = {value} missing"
            );
        }
        assert_eq!(crate::ew::CODES.len(), TABLE.len());
    }

    #[test]
    fn messages_name_call_code_and_meaning() {
        let e = Error::of(
            "cnc_rdparam",
            Internal::Cnc {
                code: 3,
                detail1: 0,
                detail2: 0,
            },
        );
        assert_eq!(e.code(), Ew::NUMBER);
        assert_eq!(
            e.to_string(),
            "cnc_rdparam: EW_NUMBER (3): data number error: no such number"
        );
        let e = Error::of(
            "cnc_allclibhndl3",
            Internal::socket((1, 0), "connect: refused"),
        );
        assert_eq!(
            e.detail(),
            Detail {
                err_no: 1,
                err_dtno: 0
            }
        );
        assert!(
            e.to_string()
                .starts_with("cnc_allclibhndl3: EW_SOCKET (-16): ")
        );
        assert_eq!(Ew(99).name(), "EW_?");
    }
}
