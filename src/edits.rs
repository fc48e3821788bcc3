//! The edits a height tile applies to the procedural field, in this order: the displacements
//! of the authored regions it meets (issue 4, added by world position), then the cave breaches
//! of the `strata` elements it meets (issue 6, the column lowered to the cave's floor where a
//! cave reaches the ground; [`crate::subsurface::world`]). Both are pure functions of the world
//! position of a lattice sample, so tiles that share an edge agree on it bit for bit and seam
//! strips of the coarser LOD get the same edits. A finished tile then marks the vertices the
//! volume regions it meets override (issue 5, [`TileEdits::mark`]).
//!
//! Pure: no tokio, axum or wgpu.

use crate::authoring::Displacement;
use crate::subsurface::world::breach_lattice;
use crate::subsurface::Geology;
use crate::terrain::lattice::Window;
use crate::terrain::plan::TILE_VERTS;
use crate::terrain::tile::{field, finish, FieldJob};
use crate::terrain::{Tile, TileKey, WorldPlan};
use crate::volume::element::{GroundEdits, VolumeSpec};
use std::sync::Arc;

/// What a tile applies on top of the procedural field.
#[derive(Clone, Debug, Default)]
pub struct TileEdits {
    /// Solved authored regions meeting the tile, in document order.
    pub displacements: Vec<Arc<Displacement>>,
    /// `strata` elements meeting the tile, in document order.
    pub strata: Vec<Arc<Geology>>,
    /// Volume regions meeting the tile: their boxes mark the vertices they override.
    pub volumes: Vec<Arc<VolumeSpec>>,
}

impl TileEdits {
    /// Applies the edits to the heights of a lattice `window` (row-major).
    pub fn apply(&self, window: Window, heights: &mut [f32]) {
        for d in &self.displacements {
            d.add_to_lattice(window, heights);
        }
        if !self.strata.is_empty() {
            breach_lattice(&self.strata, window, heights);
        }
    }

    /// Marks the vertices of a finished tile whose ground lies inside a volume region's box
    /// (`x`, `z` within its bbox, the height within its `y_m`): volume chunks give the surface
    /// there. Leaves [`Tile::volume_override`] empty when no vertex is marked.
    pub fn mark(&self, tile: &mut Tile) {
        if self.volumes.is_empty() {
            return;
        }
        let s = f64::from(tile.spacing_m);
        let (x0, z0) = (tile.origin_x_m(), tile.origin_z_m());
        let marks: Vec<u8> = tile
            .heights
            .iter()
            .enumerate()
            .map(|(v, &h)| {
                let (x, z) = (
                    x0 + (v % TILE_VERTS) as f64 * s,
                    z0 + (v / TILE_VERTS) as f64 * s,
                );
                let inside = self.volumes.iter().any(|b| {
                    x >= b.min[0]
                        && x <= b.max[0]
                        && z >= b.min[1]
                        && z <= b.max[1]
                        && h >= b.y_m[0]
                        && h <= b.y_m[1]
                });
                u8::from(inside)
            })
            .collect();
        if marks.contains(&1) {
            tile.volume_override = marks;
        }
    }
}

/// The ground under a volume region is the ground tiles have.
impl GroundEdits for TileEdits {
    fn apply(&self, window: Window, heights: &mut [f32]) {
        TileEdits::apply(self, window, heights);
    }
}

/// Synthesises tile `key` of the world `plan` with `edits` (the CPU path of the tile routes, for
/// batch exports): the field with its margin, the edits, then normals, materials and skirts.
pub fn synthesize(plan: &WorldPlan, key: TileKey, edits: &TileEdits) -> Tile {
    let job = FieldJob::with_margin(key);
    let mut f = field(plan, job);
    edits.apply(job.window(plan), &mut f.heights);
    let mut t = finish(plan, key, &f);
    edits.mark(&mut t);
    t
}
