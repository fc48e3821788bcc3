//! Where a world's caves open to the ground or come near it (issue 19): the sites a stream
//! streams volume chunks for, found from the `strata` elements' bounded data alone.
//!
//! A cave lies on its host layer, whose top stays within the layer's bounds
//! ([`SubsurfacePlan::top_range`]), and rises at most its Eq. 6 height above it. So without
//! evaluating a single column, a cave whose highest possible carved top stays more than
//! [`NEAR_GROUND_M`] below the ground is never near it, and every other cave is a **site**: its
//! bounding square and the deepest local height its carved floor can take. The test is
//! conservative (a site may stay below the ground everywhere), never the reverse: every column
//! where a cave breaches the ground ([`super::world::breach_lattice`]) lies in a site.
//!
//! **Cost.** The caves live on a lattice whose cells hold at most one cave each
//! ([`SubsurfacePlan::element`]); a search looks at no more than [`MAX_CAVE_CELLS`] cells in all,
//! those of the searched area nearest its centre when the area holds more, and a cell costs a
//! hash and a few draws (the outline is drawn only for caves that pass the depth test).

use super::plan::ElementKind;
use super::world::{Geology, CAVE_SHRINK_VOXELS};
use std::sync::Arc;

/// How close below the ground a cave's carved top must be able to come for the cave to be a
/// site, metres.
pub const NEAR_GROUND_M: f64 = 16.0;
/// Most cave-lattice cells one search looks at, over all elements.
pub const MAX_CAVE_CELLS: usize = 16_384;

/// A cave that breaches the ground or may come within [`NEAR_GROUND_M`] of it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaveSite {
    /// `[x, z]` of the west-north corner of the cave's bounding square, metres.
    pub min: [f64; 2],
    /// `[x, z]` of the east-south corner, metres.
    pub max: [f64; 2],
    /// The lowest local height its carved floor can take, metres (negative: below the ground).
    pub floor_m: f64,
}

/// The sites of `geos` (the `strata` elements that carve) whose bounding square meets the area
/// `[x0, z0, x1, z1]` (metres), looking at no more than [`MAX_CAVE_CELLS`] lattice cells: when
/// the area holds more, the square of cells around `centre` (metres) that fits the budget left.
/// Elements come in document order, cells row by row.
pub fn cave_sites(geos: &[Arc<Geology>], area: [f64; 4], centre: [f64; 2]) -> Vec<CaveSite> {
    let mut budget = MAX_CAVE_CELLS;
    let mut out = Vec::new();
    for g in geos.iter().filter(|g| g.spec.carve) {
        sites_of(g, area, centre, &mut budget, &mut out);
    }
    out
}

fn sites_of(
    g: &Geology,
    area: [f64; 4],
    centre: [f64; 2],
    budget: &mut usize,
    out: &mut Vec<CaveSite>,
) {
    let v = g.voxel_m();
    let plan = &g.plan;
    let side = f64::from(plan.cell_side(ElementKind::Cave)) * v;
    let (lo, hi) = (g.spec.min, g.spec.max);
    let x0 = area[0].max(lo[0]);
    let z0 = area[1].max(lo[1]);
    let x1 = area[2].min(hi[0]);
    let z1 = area[3].min(hi[1]);
    if x0 > x1 || z0 > z1 || *budget == 0 {
        return;
    }
    let cell = |m: f64| (m / side).floor() as i64;
    let (mut i0, mut i1, mut k0, mut k1) = (cell(x0), cell(x1), cell(z0), cell(z1));
    let count = (i1 - i0 + 1) as f64 * (k1 - k0 + 1) as f64;
    if count > *budget as f64 {
        // The square of cells around the centre that fits the budget.
        let half = (((*budget as f64).sqrt() - 1.0) / 2.0).floor().max(0.0) as i64;
        let (ci, ck) = (cell(centre[0]).clamp(i0, i1), cell(centre[1]).clamp(k0, k1));
        (i0, i1) = ((ci - half).max(i0), (ci + half).min(i1));
        (k0, k1) = ((ck - half).max(k0), (ck + half).min(k1));
    }
    let looked = ((i1 - i0 + 1) * (k1 - k0 + 1)) as usize;
    *budget = budget.saturating_sub(looked);
    let bounds = g.bounds();
    let shrink = f64::from(CAVE_SHRINK_VOXELS);
    // Local heights in voxels: the cull keeps a cave whose top can reach this height.
    let near = (-NEAR_GROUND_M / v) as f32;
    let region = |a: f64, b: f64| ((a / v) as f32, (b / v) as f32);
    let cull = Some([region(x0, x1), (near, f32::MAX), region(z0, z1)]);
    for k in k0..=k1 {
        for i in i0..=i1 {
            let (Ok(ci), Ok(ck)) = (i32::try_from(i), i32::try_from(k)) else {
                continue;
            };
            let Some(e) = plan.element_within(ElementKind::Cave, (ci, ck), cull) else {
                continue;
            };
            let inside = e.origin.0 >= bounds[0]
                && e.origin.1 >= bounds[1]
                && e.origin.0 + e.side <= bounds[2]
                && e.origin.1 + e.side <= bounds[3];
            let Some((host_lo, host_hi)) = plan.top_range(e.host) else {
                continue;
            };
            let top_m = (f64::from(host_hi) + f64::from(e.height) - shrink) * v;
            if !inside || top_m <= -NEAR_GROUND_M {
                continue;
            }
            out.push(CaveSite {
                min: [f64::from(e.origin.0) * v, f64::from(e.origin.1) * v],
                max: [
                    f64::from(e.origin.0 + e.side) * v,
                    f64::from(e.origin.1 + e.side) * v,
                ],
                floor_m: ((f64::from(host_lo) + shrink) * v).min(0.0),
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::subsurface::world::{carved_at, memos};
    use crate::subsurface::{StrataSpec, SubsurfaceConfig};

    fn geology(preset: &str) -> Arc<Geology> {
        Arc::new(Geology::new(
            11,
            StrataSpec {
                id: "g".into(),
                min: [-300.0, -300.0],
                max: [300.0, 300.0],
                config: SubsurfaceConfig::preset(preset).expect("preset"),
                voxel_m: 1.0,
                carve: true,
                mark_openings: false,
            },
        ))
    }

    #[test]
    fn every_breached_or_near_column_lies_in_a_site_and_deep_caves_are_left_out() {
        let geos = vec![geology("B2")];
        let sites = cave_sites(&geos, [-300.0, -300.0, 300.0, 300.0], [0.0, 0.0]);
        let mut memos = memos(&geos);
        let (mut near, mut carved) = (0, 0);
        for j in 0..300 {
            for i in 0..300 {
                let (x, z) = (i as f64 * 2.0 - 299.5, j as f64 * 2.0 - 299.5);
                let Some((a, b)) = carved_at(&geos, &mut memos, x, z) else {
                    continue;
                };
                carved += 1;
                if f64::from(b) <= -NEAR_GROUND_M {
                    continue;
                }
                near += 1;
                let site = sites
                    .iter()
                    .find(|s| x >= s.min[0] && x <= s.max[0] && z >= s.min[1] && z <= s.max[1]);
                let Some(s) = site else {
                    panic!("the cave at ({x}, {z}), carved {a}..{b}, is in no site");
                };
                assert!(f64::from(a) >= s.floor_m, "floor {a} below {}", s.floor_m);
            }
        }
        assert!(near > 0, "B2 has caves near the ground: {near} of {carved}");
        assert!(near < carved, "some caves are deep: {near} of {carved}");
        let covered: f64 = sites
            .iter()
            .map(|s| (s.max[0] - s.min[0]) * (s.max[1] - s.min[1]))
            .sum();
        assert!(covered < 600.0 * 600.0 * 0.5, "sites cover {covered} m²");
    }

    #[test]
    fn the_search_looks_at_a_bounded_number_of_cells_around_the_centre() {
        let mut config = SubsurfaceConfig::preset("B2").expect("preset");
        config.general.cave_area = 1.0;
        config.general.cave_density = 1.0;
        let spec = StrataSpec {
            id: "g".into(),
            min: [-1e5, -1e5],
            max: [1e5, 1e5],
            config,
            voxel_m: 1.0,
            carve: true,
            mark_openings: false,
        };
        let geos = vec![Arc::new(Geology::new(3, spec))];
        let sites = cave_sites(&geos, [-1e5, -1e5, 1e5, 1e5], [500.0, -200.0]);
        assert!(sites.len() <= MAX_CAVE_CELLS);
        assert!(sites
            .iter()
            .all(|s| (s.min[0] - 500.0).abs() <= 64.0 && (s.min[1] + 200.0).abs() <= 64.0));
    }
}
