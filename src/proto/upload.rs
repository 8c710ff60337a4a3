//! Program upload over connection 1 (SPEC.md §2, §5.3): sans-IO pieces
//! shared by the client (src/client/pair.rs) and the simulator.
//!
//! The client sends 0x1501 (body [`START_BODY_LEN`] bytes: u16 data type,
//! u16 path, the start name and the end name, 256 bytes each, NUL padded)
//! and waits for any 0x15xx answer. The CNC then pushes the text in 0x1604
//! frames and ends with an empty 0x1701, which the client acknowledges with
//! an empty 0x1702. The client aborts an unfinished upload with 0x1804 and
//! 8 zero bytes, awaiting no answer. A CNC-side failure during the upload
//! comes as a 0x18xx frame whose body words 1..3 are the error code and
//! its two detail words (read from FANUC's library, \[dis\]; never seen from
//! a real CNC).

/// Body length of the 0x1501 upload start frame.
pub const START_BODY_LEN: usize = 0x204;
/// Size of each of the two names in the start body.
pub const NAME_LEN: usize = 256;
/// Body of the 0x1804 abort frame.
pub const ABORT_BODY: [u8; 8] = [0; 8];
/// The text a CNC pushes in one 0x1604 frame (the simulator's; a frame
/// of 1460 bytes, a 1500-byte Ethernet MTU's TCP payload). FANUC's
/// library overruns its buffer and crashes on a data body of more than
/// 1470 bytes \[oracle\], whatever the frame version allows.
pub const DATA_CHUNK: usize = 1450;
/// Frame kinds (high byte of the type word) of the upload traffic.
pub const KIND_START: u8 = 0x15;
pub const KIND_DATA: u8 = 0x16;
pub const KIND_END: u8 = 0x17;
pub const KIND_ERROR: u8 = 0x18;
/// cnc_upload3 and relatives need room for this many bytes (FANUC: a
/// `*length` of 255 or less is EW_LENGTH), and keep filling the caller's
/// buffer from further frames while more than this much room is left.
pub const MIN_READ: usize = 256;

/// The start request: what to upload.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StartReq {
    /// Data type (0 = NC program; 1.. tool offsets, parameters, ... on a CNC).
    pub dtype: i16,
    /// The handle's path (FANUC's library puts its path word here, \[dis\];
    /// recorded only with path 1).
    pub path: u16,
    /// `O<s>-O<e>` (cnc_upstart, cnc_upstart3) or `N:<name>` (cnc_upstart4):
    /// bytes, sent as the caller gave them (FANUC's library copies the C
    /// string unchanged, whatever its encoding).
    pub start: Vec<u8>,
    /// Empty for every function above.
    pub end: Vec<u8>,
}

/// The start name cnc_upstart / cnc_upstart3 send: `O<s>-O<e>` (C's "%d").
pub fn range_name(start: i32, end: i32) -> Vec<u8> {
    format!("O{start}-O{end}").into_bytes()
}

/// The start name cnc_upstart4 sends: `N:<name>` (the name's bytes as
/// given), or "N:" for NULL.
pub fn name4(name: Option<&[u8]>) -> Vec<u8> {
    [b"N:", name.unwrap_or_default()].concat()
}

fn put_name(out: &mut [u8], b: &[u8]) {
    let n = b.len().min(NAME_LEN - 1);
    out[..n].copy_from_slice(&b[..n]);
}

fn get_name(b: &[u8]) -> Vec<u8> {
    let end = b.iter().position(|c| *c == 0).unwrap_or(b.len());
    b[..end].to_vec()
}

impl StartReq {
    pub fn encode(&self) -> Vec<u8> {
        let mut b = vec![0u8; START_BODY_LEN];
        b[0..2].copy_from_slice(&self.dtype.to_be_bytes());
        b[2..4].copy_from_slice(&self.path.to_be_bytes());
        put_name(&mut b[4..4 + NAME_LEN], &self.start);
        put_name(&mut b[4 + NAME_LEN..], &self.end);
        b
    }

    /// The simulator's reading of a start body (a short body reads as zeros).
    pub fn decode(body: &[u8]) -> StartReq {
        let mut b = body.to_vec();
        b.resize(START_BODY_LEN, 0);
        StartReq {
            dtype: i16::from_be_bytes([b[0], b[1]]),
            path: u16::from_be_bytes([b[2], b[3]]),
            start: get_name(&b[4..4 + NAME_LEN]),
            end: get_name(&b[4 + NAME_LEN..]),
        }
    }

    /// The start name as text (bytes that are not UTF-8 read as U+FFFD).
    pub fn start_text(&self) -> String {
        String::from_utf8_lossy(&self.start).into_owned()
    }

    /// The O-number range of an `O<s>-O<e>` or `O<n>` start name.
    pub fn range(&self) -> Option<(i64, i64)> {
        let num = |s: &str| s.strip_prefix('O')?.trim().parse::<i64>().ok();
        let start = self.start_text();
        match start.split_once("-O") {
            Some((a, b)) => Some((num(a)?, num(&format!("O{b}"))?)),
            None => num(&start).map(|n| (n, n)),
        }
    }
}

/// Body of a CNC error frame (0x18xx): the code and detail words FANUC's
/// library reads from words 1, 2, 3.
pub fn error_body(code: i16, detail1: u16, detail2: u16) -> Vec<u8> {
    let mut b = vec![0u8; 8];
    b[2..4].copy_from_slice(&code.to_be_bytes());
    b[4..6].copy_from_slice(&detail1.to_be_bytes());
    b[6..8].copy_from_slice(&detail2.to_be_bytes());
    b
}

/// (code, detail1, detail2) of a CNC error frame body; missing bytes read as 0.
pub fn decode_error(body: &[u8]) -> (i16, u16, u16) {
    let w = |i: usize| {
        body.get(i..i + 2)
            .map_or(0, |x| u16::from_be_bytes([x[0], x[1]]))
    };
    (w(2) as i16, w(4), w(6))
}

/// Program texts as a CNC punches them: "%", then each program's blocks
/// one per line (end of block ';' dropped, LF as end of block), then "%".
/// Lines of the stored text that are empty or '%' are left out.
pub fn punch<'a>(programs: impl IntoIterator<Item = &'a str>) -> Vec<u8> {
    let mut out = String::from("%\n");
    for text in programs {
        for line in text.lines() {
            let l = line.trim();
            let l = l.strip_suffix(';').unwrap_or(l).trim_end();
            if l.is_empty() || l.starts_with('%') {
                continue;
            }
            out.push_str(l);
            out.push('\n');
        }
    }
    out.push('%');
    out.into_bytes()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn start_body_round_trips() {
        let r = StartReq {
            dtype: 1,
            path: 2,
            start: range_name(1, 9999),
            end: Vec::new(),
        };
        let b = r.encode();
        assert_eq!(b.len(), START_BODY_LEN);
        assert_eq!(&b[..14], b"\x00\x01\x00\x02O1-O9999\x00\x00");
        assert_eq!(StartReq::decode(&b), r);
        assert_eq!(r.range(), Some((1, 9999)));
        let r = StartReq {
            start: "O-5-O-5".into(),
            ..r
        };
        assert_eq!(r.range(), Some((-5, -5)));
        // A Latin-1 name goes as its bytes and comes back as them.
        let r = StartReq {
            start: name4(Some(b"\xc4RGER")),
            ..r
        };
        assert_eq!(&r.encode()[4..12], b"N:\xc4RGER\0");
        assert_eq!(StartReq::decode(&r.encode()), r);
    }

    #[test]
    fn punch_shape() {
        assert_eq!(punch(["O0001;\nM30;\n%\n"]), b"%\nO0001\nM30\n%".to_vec());
        assert_eq!(punch([]), b"%\n%".to_vec());
    }

    #[test]
    fn error_words() {
        assert_eq!(decode_error(&error_body(-2, 3, 4)), (-2, 3, 4));
        assert_eq!(decode_error(&[]), (0, 0, 0));
    }
}
