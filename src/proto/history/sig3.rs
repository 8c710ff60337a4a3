//! The operation history's signal table (cnc_wrhissgnl3).

use super::records::be32;
use crate::error::Result;
use crate::proto::call::{Call, Ctx, sub};
use crate::proto::cmd::WRHISSGNL3;
use crate::proto::packet::{ReqSub, RespSub};

/// One entry of the signal table on the wire: i32 entry number, i32 PMC
/// number, i32 byte number, the address type an i16 at 12 (its low
/// byte 13 read), byte 14 the mask.
pub const SIG3_REC: usize = 16;

/// One entry of the operation history's signal table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Sig3 {
    pub ent_no: i16,
    pub pmc_no: i16,
    pub sig_no: i16,
    pub sig_name: u8,
    pub mask_pat: u8,
}

impl Sig3 {
    pub fn to_wire(&self) -> [u8; SIG3_REC] {
        let mut b = [0u8; SIG3_REC];
        b[0..4].copy_from_slice(&i32::from(self.ent_no).to_be_bytes());
        b[4..8].copy_from_slice(&i32::from(self.pmc_no).to_be_bytes());
        b[8..12].copy_from_slice(&i32::from(self.sig_no).to_be_bytes());
        // FANUC's library sends the char sign-extended to a short.
        b[12..14].copy_from_slice(&i16::from(self.sig_name as i8).to_be_bytes());
        b[14] = self.mask_pat;
        b
    }
    /// An entry of a request's payload (the simulator): the full i32
    /// words, which it checks.
    pub fn from_wire(b: &[u8]) -> (i32, i32, i32, u8, u8) {
        (be32(b, 0), be32(b, 4), be32(b, 8), b[13], b[14])
    }
}

/// cnc_wrhissgnl3's request: the entries, their number the argument word.
pub struct WriteSig3 {
    pub entries: Vec<Sig3>,
}

impl Call for WriteSig3 {
    type Output = ();
    fn request(&self, _: &Ctx) -> Vec<ReqSub> {
        let n = self.entries.len() as i32;
        let sub = ReqSub::cnc(WRHISSGNL3, &[n]);
        if n == 0 {
            return vec![sub];
        }
        let data = self.entries.iter().flat_map(Sig3::to_wire).collect();
        vec![sub.with_payload(data)]
    }
    fn decode(&self, _: &Ctx, resp: &[RespSub]) -> Result<()> {
        sub(resp, 0).map(|_| ())
    }
}
