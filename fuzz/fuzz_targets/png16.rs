//! The PNG heightmap imports of authored regions (`authoring::exchange`): a 16-bit greyscale
//! heightmap and the gradient map, as `POST …/regions/{rid}/heightmap.png` reads them. Any
//! bytes are refused with an error or decoded to an image of the size its header states.
#![no_main]

use libfuzzer_sys::fuzz_target;
use strata::authoring::exchange::{import_gradient_map, import_png16};

fuzz_target!(|data: &[u8]| {
    if let Ok(image) = import_png16(data, -100.0, 1000.0) {
        assert_eq!(image.values.len(), image.width * image.height);
        assert!(image.values.iter().all(|h| (-100.0..=1000.0).contains(h)));
    }
    if let Ok(image) = import_gradient_map(data, 1.0) {
        let (gx, gz) = &image.values;
        assert_eq!(gx.len(), image.width * image.height);
        assert_eq!(gz.len(), image.width * image.height);
    }
});
