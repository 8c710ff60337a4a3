//! Axes and spindles: names, positions, speeds, loads, dynamic data, figures.

use crate::wire_struct;

// Shared with cnc_rddynamic2 (one copy is kept at merge): the payloads of
// 0x1a (alarm bits), 0x1c (program numbers) and 0x1d (sequence number).

wire_struct! {
    /// Payload of 0x001a (cnc_alarm, cnc_alarm2, rddynamic2): the alarm bit map.
    pub struct AlarmBits {
        pub bits: u32,
    }
}

wire_struct! {
    /// Payload of 0x001c (cnc_rdprgnum, rddynamic2): running and main program numbers.
    pub struct ProgNums {
        pub data: i32,
        pub mdata: i32,
    }
}

wire_struct! {
    /// Payload of 0x001d (cnc_rdseqnum, rddynamic2): the sequence number.
    pub struct SeqNum {
        pub data: i32,
    }
}

// --- position ---
