//! The open handshake (frame 0x0101 / 0x0102, SPEC.md §3.2).

use super::wire::{DecodeError, Reader, Writer};

/// Body of an open response. The frame version selects the layout:
/// version ≥ 3 is the 30i class (20 header words, 16 words per path),
/// version ≤ 2 the 16i class (8 header words, 4 words per path).
/// Words whose use is unknown are kept, so encode(decode(b)) == b.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum OpenBody {
    Series30 {
        header: [u16; 20],
        paths: Vec<[u16; 16]>,
    },
    Series16 {
        header: [u16; 8],
        paths: Vec<[u16; 4]>,
    },
}

/// The handle class FANUC's library derives from the open response (SPEC.md §3.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CncClass {
    /// 30i / 31i / 32i / 0i-F: 8-byte value records.
    Series30,
    /// 16i / 18i / 21i / 0i: 4-byte values. `kind` is header word 1 (2 = Series 15).
    Series16 { kind: u16 },
}

impl CncClass {
    /// True for the 16i class (open response frame version <= 2).
    pub fn is_16i(&self) -> bool {
        matches!(self, CncClass::Series16 { .. })
    }
}

impl OpenBody {
    pub fn encode(&self, w: &mut Writer) {
        match self {
            OpenBody::Series30 { header, paths } => {
                header.iter().for_each(|x| w.u16(*x));
                paths.iter().flatten().for_each(|x| w.u16(*x));
            }
            OpenBody::Series16 { header, paths } => {
                header.iter().for_each(|x| w.u16(*x));
                paths.iter().flatten().for_each(|x| w.u16(*x));
            }
        }
    }

    pub fn to_bytes(&self) -> Vec<u8> {
        let mut w = Writer::new();
        self.encode(&mut w);
        w.into_vec()
    }

    /// Decodes the body of a 0x0102 frame of the given frame version. The body
    /// must be exactly as long as its path count says.
    pub fn decode(version: u16, body: &[u8]) -> Result<OpenBody, DecodeError> {
        let mut r = Reader::new(body);
        if version >= 3 {
            let mut header = [0u16; 20];
            for x in &mut header {
                *x = r.u16()?;
            }
            let n = header[5] as usize;
            if body.len() != 40 + 32 * n {
                return Err(DecodeError::Invalid(
                    "open response size does not match its path count",
                ));
            }
            let mut paths = Vec::with_capacity(n);
            for _ in 0..n {
                let mut p = [0u16; 16];
                for x in &mut p {
                    *x = r.u16()?;
                }
                paths.push(p);
            }
            Ok(OpenBody::Series30 { header, paths })
        } else {
            let mut header = [0u16; 8];
            for x in &mut header {
                *x = r.u16()?;
            }
            let n = header[4] as usize;
            if body.len() != 16 + 8 * n {
                return Err(DecodeError::Invalid(
                    "open response size does not match its path count",
                ));
            }
            let mut paths = Vec::with_capacity(n);
            for _ in 0..n {
                let mut p = [0u16; 4];
                for x in &mut p {
                    *x = r.u16()?;
                }
                paths.push(p);
            }
            Ok(OpenBody::Series16 { header, paths })
        }
    }

    pub fn class(&self) -> CncClass {
        match self {
            OpenBody::Series30 { .. } => CncClass::Series30,
            OpenBody::Series16 { header, .. } => CncClass::Series16 { kind: header[1] },
        }
    }

    /// Number of path entries.
    pub fn path_count(&self) -> usize {
        match self {
            OpenBody::Series30 { paths, .. } => paths.len(),
            OpenBody::Series16 { paths, .. } => paths.len(),
        }
    }

    /// The first word of each path entry: non-zero when the path exists
    /// (and, in the 16i class, the machine type: 0x2054 " T" lathe).
    pub fn path_words(&self) -> Vec<u16> {
        match self {
            OpenBody::Series30 { paths, .. } => paths.iter().map(|p| p[0]).collect(),
            OpenBody::Series16 { paths, .. } => paths.iter().map(|p| p[0]).collect(),
        }
    }

    /// What cnc_sysinfo_ex reports, from the open response alone (FANUC's
    /// library sends nothing for it) \[oracle\]: max_axis, max_spdl, max_path,
    /// max_mchn, ctrl_axis, ctrl_srvo, ctrl_spdl, ctrl_path, ctrl_mchn,
    /// addinfo; then per path system, group, attrib, ctrl_axis, ctrl_srvo,
    /// ctrl_spdl, mchn_no. The 30i body has them all (a path's ctrl_srvo is
    /// its ctrl_axis word again, as FANUC's library reads it); the 16i body
    /// has no machine groups, the group is the path's number; a Series 15
    /// reports `axes15` (word 0 of its start-up 0x8c answer) as ctrl_axis.
    pub fn system_ex(&self, axes15: u16) -> ([u16; 10], Vec<[u16; 7]>) {
        match self {
            OpenBody::Series30 { header: h, paths } => (
                [
                    h[3], h[4], h[5], h[6], h[8], h[9], h[10], h[11], h[12], h[15],
                ],
                paths
                    .iter()
                    .map(|p| [p[0], p[1], p[2], p[3], p[3], p[5], p[6]])
                    .collect(),
            ),
            OpenBody::Series16 { header: h, paths } => (
                [h[2], h[3], h[4], 0, axes15, 0, 0, h[5], 0, 0],
                paths
                    .iter()
                    .zip(1..)
                    .map(|(p, k)| [p[0], k, p[1], p[2], p[2], p[3], 0])
                    .collect(),
            ),
        }
    }

    /// What `cnc_getpath` returns as `maxpath_no`.
    pub fn maxpath_no(&self) -> u16 {
        match self {
            OpenBody::Series30 { header, .. } => header[11],
            OpenBody::Series16 { header, .. } => header[5],
        }
    }

    /// Maximum axes per path (the record count of an all-axes answer).
    pub fn max_axes(&self, path: usize) -> u16 {
        match self {
            OpenBody::Series30 { header, .. } => header[3],
            OpenBody::Series16 { header, paths } => {
                paths.get(path.wrapping_sub(1)).map_or(header[2], |p| p[2])
            }
        }
    }

    pub fn max_spindles(&self) -> u16 {
        match self {
            OpenBody::Series30 { header, .. } => header[4],
            OpenBody::Series16 { header, .. } => header[3],
        }
    }

    /// 30i class: header word at offset 20 must be non-zero for spindle functions.
    pub fn has_spindle_info(&self) -> bool {
        match self {
            OpenBody::Series30 { header, .. } => header[10] != 0,
            OpenBody::Series16 { .. } => true,
        }
    }

    /// Frame version a CNC of this layout answers with.
    pub fn frame_version(&self) -> u16 {
        match self {
            OpenBody::Series30 { .. } => 3,
            OpenBody::Series16 { .. } => 2,
        }
    }
}
