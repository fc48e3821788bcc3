//! The numeric path parameters and queries of product URLs (`server::params`, the chunk and
//! river keys): the input is `seg/seg/…[?query]`, and every parser is given the segments it
//! takes. Each answers a value within the world's bounds or a 400 error naming a field.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::sync::OnceLock;
use strata::server::chunks::parse_chunk;
use strata::server::params::{
    check_bounds, parse_coord, parse_lod, parse_seams, parse_seed, parse_tile_path,
    parse_tile_version,
};
use strata::server::rivers::parse_key;
use strata::terrain::{WorldParams, WorldPlan, MAX_LOD};

fn plan() -> &'static WorldPlan {
    static PLAN: OnceLock<WorldPlan> = OnceLock::new();
    PLAN.get_or_init(|| WorldPlan::new(42, WorldParams::default()).expect("the default plan"))
}

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let (path, query) = match text.split_once('?') {
        Some((p, q)) => (p, Some(q)),
        None => (text, None),
    };
    let s: Vec<&str> = path.split('/').collect();
    let at = |i: usize| s.get(i).copied().unwrap_or("");
    let refused = |e: strata::server::AppError| assert!(e.status.is_client_error(), "{e:?}");
    let _ = parse_seed(at(0)).map_err(refused);
    if let Ok(lod) = parse_lod(at(1)).map_err(refused) {
        assert!(lod <= MAX_LOD);
    }
    let _ = parse_coord(at(2), "x").map_err(refused);
    match parse_tile_path(plan(), at(1), at(2), at(3)) {
        Ok((key, format)) => {
            assert!(check_bounds(plan(), key).is_ok());
            let _ = parse_seams(query).map_err(refused);
            let _ = parse_tile_version(query, format).map_err(refused);
        }
        Err(e) => refused(e),
    }
    let _ = parse_chunk(plan(), at(1), at(2), at(3), at(4)).map_err(refused);
    let _ = parse_key(at(1), at(2), at(3)).map_err(refused);
});
