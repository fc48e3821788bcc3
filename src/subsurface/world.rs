//! The subsurface of a world (issue 6, "Integration"): a `strata` element ([`StrataSpec`]) bound
//! to the world's seed and anchored to its ground.
//!
//! # Coordinates
//!
//! A world point `(x, y, z)` (metres) lies in voxel column `(⌊x / v⌋, ⌊z / v⌋)` (`v` =
//! `voxel_m`) at **local height** `y − g`, where `g` is the world's ground at the point — the
//! heights of the world's tiles with authored regions applied, before any cave breach. The
//! layer stack is anchored there ([`SubsurfacePlan::anchored`]): the top layer reaches the
//! ground everywhere and everything at or above it is air. For a voxel query the ground is read
//! at the column's centre `((i + ½)·v, (k + ½)·v)`, so the voxel `(i, j, k)` with
//! `j = ⌊(y − g_c) / v⌋` is the voxel of the stack as [`super::Chunk`]s store it.
//!
//! # Caves carve the solid
//!
//! Over a column a cave occupies the local heights `(lo, hi)` of its Eq. 6 profile on its host
//! layer. The carved interval is that span shrunk by [`CAVE_SHRINK_VOXELS`] at both ends, so a
//! cave closes before its outline, where the profile thins to nothing, instead of leaving
//! slivers thinner than a voxel. A volume chunk's solid becomes `max(S, d)` with
//! `d = min(y − g − a, g + b − y)` for the carved interval `(a, b)` (metres, negative below the
//! ground) — positive inside the cave. Where a cave reaches the ground (`a < 0 < b`) it
//! **breaches**: the column is air from the cave's floor up, so height tiles lower their vertex
//! to `g + a` ([`breach_lattice`]); the breach depends only on the column, so a chunk recovers
//! the ground as `g = h − a` ([`ground_under`]).
//!
//! # Where an element is in force
//!
//! A `strata` element has effect inside its bbox; where several cover a column the last one
//! (document order) is in force ([`in_force`]). Its veins and caves are those whose bounding
//! square lies inside its bbox.

use super::chunk::ElementMemo;
use super::plan::{Composition, SubsurfacePlan};
use super::spec::StrataSpec;
use crate::element::Rect;
use crate::terrain::lattice::Window;
use std::sync::Arc;

/// How far a cave's carved interval stays inside its Eq. 6 span at each end, voxels.
pub const CAVE_SHRINK_VOXELS: f32 = 0.25;

/// A `strata` element bound to a world seed.
#[derive(Clone, Debug)]
pub struct Geology {
    /// The element.
    pub spec: StrataSpec,
    /// Its layer stack, veins and caves, anchored to the ground.
    pub plan: SubsurfacePlan,
    /// The bbox in voxels, `[x0, z0, x1, z1]`.
    bounds: [f32; 4],
}

impl Geology {
    /// Binds `spec` to the world seed `seed`.
    pub fn new(seed: u64, spec: StrataSpec) -> Geology {
        let v = spec.voxel_m;
        let bounds = [
            (spec.min[0] / v) as f32,
            (spec.min[1] / v) as f32,
            (spec.max[0] / v) as f32,
            (spec.max[1] / v) as f32,
        ];
        Geology {
            plan: SubsurfacePlan::anchored(seed, spec.config.clone()),
            spec,
            bounds,
        }
    }

    /// The bbox in voxels, `[x0, z0, x1, z1]` (the bounds of [`SubsurfacePlan::chunk_within`]).
    pub fn bounds(&self) -> [f32; 4] {
        self.bounds
    }

    /// Voxel side, metres.
    pub fn voxel_m(&self) -> f64 {
        self.spec.voxel_m
    }

    /// Whether the element's bbox meets the closed rectangle `r` (metres).
    pub fn meets(&self, r: Rect) -> bool {
        Rect {
            min: self.spec.min,
            max: self.spec.max,
        }
        .intersects(&r)
    }

    /// Whether the column at `(x, z)` (metres) is inside the element's bbox.
    pub fn covers(&self, x: f64, z: f64) -> bool {
        let (a, b) = (self.spec.min, self.spec.max);
        x >= a[0] && x <= b[0] && z >= a[1] && z <= b[1]
    }

    /// A memo of this element's veins and caves (only those inside its bbox).
    pub fn memo(&self) -> ElementMemo {
        ElementMemo::within(self.bounds)
    }

    /// The carved interval `(a, b)` over the column at `(x, z)` (metres), in local metres
    /// (negative below the ground), if a cave carves there.
    pub fn carved(&self, x: f64, z: f64, memo: &mut ElementMemo) -> Option<(f32, f32)> {
        if !self.spec.carve {
            return None;
        }
        let v = self.spec.voxel_m;
        let (lo, hi) = self.plan.cave_at((x / v) as f32, (z / v) as f32, memo)?;
        let (a, b) = (lo + CAVE_SHRINK_VOXELS, hi - CAVE_SHRINK_VOXELS);
        let v = v as f32;
        (a < b && a < 0.0).then_some((a * v, b * v))
    }

    /// The voxel of the world point `(x, y, z)` (metres) given the ground `ground_m` at its
    /// column's centre ([`Geology::column_centre`]).
    pub fn voxel_of(&self, x: f64, y: f64, z: f64, ground_m: f64) -> [i32; 3] {
        let v = self.spec.voxel_m;
        [
            (x / v).floor() as i32,
            ((y - ground_m) / v).floor() as i32,
            (z / v).floor() as i32,
        ]
    }

    /// Whether material `id` is the void or a cave material (not solid rock).
    pub fn is_hollow(&self, id: u32) -> bool {
        self.plan
            .config
            .materials
            .iter()
            .any(|m| m.id == id && (m.flags.void || m.flags.cave))
    }

    /// The centre `(x, z)` (metres) of the voxel column holding `(x, z)`.
    pub fn column_centre(&self, x: f64, z: f64) -> (f64, f64) {
        let v = self.spec.voxel_m;
        (((x / v).floor() + 0.5) * v, ((z / v).floor() + 0.5) * v)
    }

    /// Composition and flow at the world point `(x, y, z)` given the ground at its column's
    /// centre: the voxel's, as the stored limits give it.
    pub fn composition(
        &self,
        x: f64,
        y: f64,
        z: f64,
        ground_m: f64,
        memo: &mut ElementMemo,
    ) -> (Composition, [f32; 3]) {
        let [i, j, k] = self.voxel_of(x, y, z, ground_m);
        self.plan.voxel_memo(i, j, k, memo)
    }
}

/// The material id with the largest concentration (the lowest id on a tie).
pub fn main_material(c: &Composition) -> Option<u32> {
    c.iter()
        .fold(None, |best: Option<(u32, f32)>, &(id, w)| match best {
            Some((bid, bw)) if bw > w || (bw == w && bid < id) => Some((bid, bw)),
            _ => Some((id, w)),
        })
        .map(|(id, _)| id)
}

/// Index of the element in force at column `(x, z)`: the last of `geos` whose bbox covers it.
pub fn in_force(geos: &[Arc<Geology>], x: f64, z: f64) -> Option<usize> {
    geos.iter().rposition(|g| g.covers(x, z))
}

/// One memo per element of `geos`.
pub fn memos(geos: &[Arc<Geology>]) -> Vec<ElementMemo> {
    geos.iter().map(|g| g.memo()).collect()
}

/// The carved interval in force over column `(x, z)`.
pub fn carved_at(
    geos: &[Arc<Geology>],
    memos: &mut [ElementMemo],
    x: f64,
    z: f64,
) -> Option<(f32, f32)> {
    let k = in_force(geos, x, z)?;
    geos[k].carved(x, z, &mut memos[k])
}

/// Lowers the heights of a lattice `window` where a cave breaches the ground (module docs): the
/// height `g` of a vertex becomes `g + a` when the carved interval `(a, b)` there has
/// `a < 0 < b`.
pub fn breach_lattice(geos: &[Arc<Geology>], window: Window, heights: &mut [f32]) {
    if geos.iter().all(|g| !g.spec.carve) {
        return;
    }
    let mut memos = memos(geos);
    window.visit_mut(heights, |x, z, h| {
        if let Some((a, b)) = carved_at(geos, &mut memos, x, z) {
            if b > 0.0 {
                *h += a;
            }
        }
    });
}

/// The ground under column `(x, z)` whose (possibly breached) height is `height`: the inverse
/// of [`breach_lattice`] for one sample.
pub fn ground_under(
    geos: &[Arc<Geology>],
    memos: &mut [ElementMemo],
    x: f64,
    z: f64,
    height: f32,
) -> f32 {
    match carved_at(geos, memos, x, z) {
        Some((a, b)) if b > 0.0 => height - a,
        _ => height,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::subsurface::SubsurfaceConfig;

    fn geology(preset: &str, carve: bool) -> Geology {
        Geology::new(
            11,
            StrataSpec {
                id: "g".into(),
                min: [-2000.0, -2000.0],
                max: [2000.0, 2000.0],
                config: SubsurfaceConfig::preset(preset).expect("preset"),
                voxel_m: 1.0,
                carve,
                mark_openings: false,
            },
        )
    }

    #[test]
    fn the_anchored_stack_has_no_void_below_the_ground_and_only_void_above() {
        let g = geology("B3", true);
        let mut memo = g.memo();
        let void = g.plan.void_id;
        for i in 0..400 {
            let (x, z) = (i as f64 * 7.3 - 1400.0, i as f64 * -3.1 + 600.0);
            let (above, _) = g.composition(x, 0.3, z, 0.0, &mut memo);
            assert_eq!(above, vec![(void, 1.0)], "air above the ground at {x} {z}");
            for depth in [0.5, 3.0, 12.0, 60.0] {
                let (below, _) = g.composition(x, -depth, z, 0.0, &mut memo);
                let is_cave = below.iter().any(|&(id, _)| {
                    g.plan
                        .config
                        .materials
                        .iter()
                        .any(|m| m.id == id && m.flags.cave)
                });
                assert!(
                    is_cave || below.iter().all(|&(id, _)| id != void),
                    "void {depth} m below the ground at {x} {z}: {below:?}"
                );
            }
        }
    }

    #[test]
    fn breaches_invert_and_carved_intervals_lie_in_their_caves() {
        let geos = vec![Arc::new(geology("B2", true))];
        let mut memos = memos(&geos);
        let (mut carved, mut breached) = (0, 0);
        for j in 0..300i64 {
            for i in 0..300i64 {
                let (gx, gz) = (i * 2 - 250, j - 200);
                let (x, z) = (gx as f64, gz as f64);
                let mut h = [37.5f32];
                let window = Window {
                    spacing_m: 1.0,
                    gx0: gx,
                    gz0: gz,
                    w: 1,
                    h: 1,
                };
                breach_lattice(&geos, window, &mut h);
                let g = ground_under(&geos, &mut memos, x, z, h[0]);
                assert!(
                    (g - 37.5).abs() < 1e-4,
                    "ground {g} recovered from {}",
                    h[0]
                );
                let Some((a, b)) = carved_at(&geos, &mut memos, x, z) else {
                    assert_eq!(h[0], 37.5, "no cave, no breach");
                    continue;
                };
                carved += 1;
                assert!(a < b && a < 0.0);
                if b > 0.0 {
                    breached += 1;
                    assert_eq!(h[0], 37.5 + a, "the breach lowers to the floor");
                } else {
                    assert_eq!(h[0], 37.5, "a cave under the ground leaves it");
                }
            }
        }
        assert!(carved > 100, "B2 carves caves: {carved} columns");
        assert!(breached < carved, "{breached} of {carved}");
        let off = vec![Arc::new(geology("B2", false))];
        let mut m = super::memos(&off);
        assert!((0..2000).all(|i| carved_at(&off, &mut m, i as f64 * 0.7, 3.0).is_none()));
    }

    #[test]
    fn the_last_element_covering_a_column_is_in_force() {
        let a = Arc::new(geology("A0", true));
        let mut spec = a.spec.clone();
        spec.min = [0.0, 0.0];
        spec.max = [10.0, 10.0];
        let b = Arc::new(Geology::new(11, spec));
        let geos = vec![a, b];
        assert_eq!(in_force(&geos, 5.0, 5.0), Some(1));
        assert_eq!(in_force(&geos, -5.0, 5.0), Some(0));
        assert_eq!(in_force(&geos, 5000.0, 5.0), None);
        assert_eq!(
            main_material(&vec![(3, 0.25), (1, 0.5), (2, 0.25)]),
            Some(1)
        );
        assert_eq!(main_material(&vec![(3, 0.5), (1, 0.5)]), Some(1));
        assert_eq!(main_material(&vec![]), None);
    }
}
