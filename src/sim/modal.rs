//! The modal state a running program sets (cnc_modal): the G codes of the
//! groups the simulator follows and the other codes (F, S, M, T ...), per
//! block as the program leaves them. What a program never sets is the
//! profile's `[path.modal]` table (src/sim/program.rs answers).

/// G codes the simulator follows: (G number, cnc_modal type = group − 1,
/// code within the group). Group 01 motion, 02 plane, 03 absolute /
/// incremental, 05 feed per minute / per revolution (G95 = 1, as FANUC's
/// library reads it for cnc_rdspeed on the 16i), 06 inch / metric, 07
/// cutter compensation.
const G_CODES: [(i32, usize, u8); 16] = [
    (0, 0, 0),
    (1, 0, 1),
    (2, 0, 2),
    (3, 0, 3),
    (17, 1, 0),
    (18, 1, 1),
    (19, 1, 2),
    (90, 2, 0),
    (91, 2, 1),
    (94, 4, 0),
    (95, 4, 1),
    (20, 5, 0),
    (21, 5, 1),
    (40, 6, 0),
    (41, 6, 1),
    (42, 6, 2),
];
/// G-code groups followed (cnc_modal types 0..G_GROUPS).
const G_GROUPS: usize = 7;
/// The other codes by cnc_modal type − 100 (FANUC's order: B D E F H L M S
/// T); E and L are not modal in a program and are not followed.
const AUX_LETTERS: [char; 9] = ['B', 'D', '-', 'F', 'H', '-', 'M', 'S', 'T'];
pub(crate) const F: usize = 3;
pub(crate) const S: usize = 7;

/// Modal codes set by a program (None: not set).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ProgramModal {
    /// Code within the group, by cnc_modal type (0 = group 01 ...).
    pub g: [Option<u8>; G_GROUPS],
    /// Value by cnc_modal type − 100 (3 F, 6 M, 7 S, 8 T ...).
    pub aux: [Option<i32>; AUX_LETTERS.len()],
}

impl ProgramModal {
    /// After a block's G code `g`.
    pub(crate) fn set_g(&mut self, g: i32) {
        if let Some(&(_, group, code)) = G_CODES.iter().find(|x| x.0 == g)
            && let Some(slot) = self.g.get_mut(group)
        {
            *slot = Some(code);
        }
    }

    /// After a block's word `letter` with `value` (an integer value:
    /// F and S as cnc_actf / cnc_acts show them).
    pub(crate) fn set_word(&mut self, letter: char, value: &str) {
        if let Some(k) = AUX_LETTERS.iter().position(|c| *c == letter)
            && let Ok(v) = value.parse::<f64>()
        {
            self.aux[k] = Some(v as i32);
        }
    }

    /// What this state leaves unset taken from `earlier`.
    pub(crate) fn or(self, earlier: ProgramModal) -> ProgramModal {
        let mut m = self;
        for (a, b) in m.g.iter_mut().zip(earlier.g) {
            *a = a.or(b);
        }
        for (a, b) in m.aux.iter_mut().zip(earlier.aux) {
            *a = a.or(b);
        }
        m
    }

    /// The code of group type `t` the program set.
    pub fn g_code(&self, t: usize) -> Option<u8> {
        self.g.get(t).copied().flatten()
    }

    /// The address letters of the values cnc_modal types `100 + k`
    /// follow, with their k (cnc_rdcommand's addresses).
    pub fn letters() -> impl Iterator<Item = (usize, char)> {
        AUX_LETTERS
            .iter()
            .copied()
            .enumerate()
            .filter(|(_, c)| *c != '-')
    }

    /// The value of cnc_modal type `100 + k` the program set.
    pub fn aux_value(&self, k: usize) -> Option<i32> {
        self.aux.get(k).copied().flatten()
    }
}
