//! The records: the operation history record kinds FANUC's library
//! decodes, and each record as the CNC sends it (built by the simulator).

use super::records::{ALM5_REC, ALM5_TEXT, OM_TEXT, OP_REC};

/// The kinds of operation history record FANUC's library decodes, by the
/// record type the CNC sends (other types: the type alone).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OpKind {
    Mdi,
    Signal,
    Alarm,
    Date,
    Time,
    Other,
}

impl OpKind {
    pub fn of(rec_type: i16) -> OpKind {
        match rec_type {
            0 | 5 | 10 => OpKind::Mdi,
            1 | 6 | 11 => OpKind::Signal,
            2 | 7 | 12 => OpKind::Alarm,
            3 => OpKind::Date,
            4 => OpKind::Time,
            _ => OpKind::Other,
        }
    }
}

/// One operation history record as the CNC sends it (simulator side):
/// type at 2, then six words from byte 4. MDI: key, power-on flag; signal:
/// i32 number, name, old << 8 | new; alarm: i32 number, 0, group, i32
/// axis; date: year, month, day, power-on flag; time: hour, minute,
/// second, power-on flag.
pub fn op_record(rec_type: i16, words: [i32; 4]) -> Vec<u8> {
    let mut b = vec![0u8; OP_REC];
    b[2..4].copy_from_slice(&rec_type.to_be_bytes());
    let w16 =
        |b: &mut [u8], at: usize, v: i32| b[at..at + 2].copy_from_slice(&(v as i16).to_be_bytes());
    let w32 = |b: &mut [u8], at: usize, v: i32| b[at..at + 4].copy_from_slice(&v.to_be_bytes());
    match OpKind::of(rec_type) {
        OpKind::Signal => {
            w32(&mut b, 4, words[0]);
            w16(&mut b, 8, words[1]);
            w16(&mut b, 10, words[2] << 8 | (words[3] & 0xff));
        }
        OpKind::Alarm => {
            w32(&mut b, 4, words[0]);
            w16(&mut b, 10, words[1]);
            w32(&mut b, 12, words[2]);
        }
        _ => {
            for (k, v) in words.iter().enumerate() {
                w16(&mut b, 4 + 2 * k, *v);
            }
        }
    }
    b
}

/// The time stamp of a history record: year, month, day, hour, minute, second.
pub type Stamp = [u16; 6];

fn text<const N: usize>(msg: &str) -> [u8; N] {
    let mut t = [0u8; N];
    let b = msg.as_bytes();
    let n = b.len().min(N);
    t[..n].copy_from_slice(&b[..n]);
    t
}

fn stamp_words(t: &Stamp) -> Vec<u8> {
    t.iter().flat_map(|v| v.to_be_bytes()).collect()
}

/// One cnc_rdomhistry record (simulator side): om_no at 2, the time stamp
/// from 4, the text from 20.
pub fn om_record(number: i16, t: &Stamp, msg: &str) -> Vec<u8> {
    let mut b = vec![0u8; 2];
    b.extend(number.to_be_bytes());
    b.extend(stamp_words(t));
    b.extend([0u8; 4]);
    b.extend(text::<OM_TEXT>(msg));
    b
}

/// One cnc_rdomhistry2 record (simulator side): display flag, number, the
/// time stamp, the text.
pub fn om2_record(shown: bool, number: i16, t: &Stamp, msg: &str) -> Vec<u8> {
    let mut b = i16::from(shown).to_be_bytes().to_vec();
    b.extend(number.to_be_bytes());
    b.extend(stamp_words(t));
    b.extend(text::<OM_TEXT>(msg));
    b
}

/// The fields of an alarm history 5 record.
#[derive(Debug, Clone, Default)]
pub struct Alm5 {
    pub number: i32,
    pub group: i32,
    pub axis: i32,
    pub time: Stamp,
    pub path: i16,
    pub axes: i16,
    pub message: String,
}

/// One cnc_rdalmhistry5 record (simulator side): i32 number, group, axis;
/// six i16 of time; i32 message length; i16 path, system alarm, display
/// flag, number of axes; 64 text bytes; then the modal and position blocks
/// (zeros here: the simulator keeps no snapshot); 528 bytes in all.
pub fn alm5_record(a: &Alm5) -> Vec<u8> {
    let mut b = Vec::with_capacity(ALM5_REC);
    for v in [a.number, a.group, a.axis] {
        b.extend(v.to_be_bytes());
    }
    b.extend(stamp_words(&a.time));
    b.extend((a.message.len().min(ALM5_TEXT) as i32).to_be_bytes());
    for v in [a.path, 0, 1, a.axes] {
        b.extend(v.to_be_bytes());
    }
    b.extend(text::<ALM5_TEXT>(&a.message));
    b.resize(ALM5_REC, 0);
    b
}
