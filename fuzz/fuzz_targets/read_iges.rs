//! The IGES reader on arbitrary bytes: never a panic or a huge allocation.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        if let Ok(surfaces) = pde_bezier::read_iges(text) {
            for s in surfaces {
                assert!(s.validate().is_ok());
                let _ = s.eval(0.5, 0.5);
            }
        }
    }
});
