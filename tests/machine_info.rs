//! Machine information through the C ABI against the simulator: each answer
//! equals the profile (values other than the built-in ones, so a constant
//! could not pass), NULL outputs and bad handles fail before any traffic.

mod sim;

use fwlib32::ew::*;
use fwlib32::sim::Profile;
use fwlib32::*;

#[test]
fn ether_info_is_the_profiles_board() {
    for (board, device) in [(2i16, 1i16), (0, 0)] {
        let text = fwlib32::sim::profile::DEFAULT_PROFILE
            .replacen("ether_type = 1", &format!("ether_type = {board}"), 1)
            .replacen("ether_device = 0", &format!("ether_device = {device}"), 1);
        let (_s, h) = sim::start_alloc(Profile::parse(&text).unwrap());
        let (mut t, mut d) = (-1i16, -1i16);
        assert_eq!(unsafe { cnc_rdetherinfo(h, &mut t, &mut d) }, EW_OK);
        assert_eq!((t, d), (board, device));
        assert_eq!(
            unsafe { cnc_rdetherinfo(h, std::ptr::null_mut(), &mut d) },
            EW_DATA
        );
        assert_eq!(
            unsafe { cnc_rdetherinfo(h, &mut t, std::ptr::null_mut()) },
            EW_DATA
        );
        assert_eq!(cnc_freelibhndl(h), EW_OK);
        assert_eq!(unsafe { cnc_rdetherinfo(h, &mut t, &mut d) }, EW_HANDLE);
    }
}
