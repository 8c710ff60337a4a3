//! The path's axes, modes and settings of the long tail: the synchronous
//! errors, the `[MEASURE]` keys' availability, the tool interference check
//! and the coordinate rotation in force.

use serde::Deserialize;

/// `[path.sync_error]`: the synchronous error (cnc_rdsynerrsy) and the
/// rigid tap's (cnc_rdsynerrrg), in detection units.
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SyncError {
    pub synchronous: i32,
    pub rigid_tap: i32,
}

/// `[path.measure]`: whether the `[MEASURE]` key (cnc_rdenblinfo) and the
/// `[MEASURE] [CENTER]` key (cnc_rdcenblinfo) are available (1) or not (0).
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Measure {
    pub enabled: i8,
    pub center_enabled: i8,
}

/// `[path.interference]`: the two tools the tool interference check
/// compares (cnc_rdinterference).
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Interference {
    pub tools: [i16; 2],
}

/// `[path.rotation]`: the coordinate rotation in force (cnc_rdcdrotate):
/// its mode (G code, 69: none), the plane's axes (axis numbers), the
/// center in the axes' least input increments and the angle (0.001°).
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Rotation {
    pub mode: i16,
    pub plane_axes: [i16; 2],
    pub center: [i32; 2],
    pub angle: i32,
}
