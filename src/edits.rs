//! The edits a height tile applies to the procedural field, in this order: the displacements
//! of the authored regions it meets (issue 4, added by world position), then the cave breaches
//! of the `strata` elements it meets (issue 6, the column lowered to the cave's floor where a
//! cave reaches the ground; [`crate::subsurface::world`]). Both are pure functions of the world
//! position of a lattice sample, so tiles that share an edge agree on it bit for bit and seam
//! strips of the coarser LOD get the same edits. A finished tile then marks the vertices the
//! volume regions it meets override (issue 5) and, where a `strata` element asks for it, the
//! vertices where its caves breach the ground (issue 19, [`TileEdits::mark`]).
//!
//! Pure: no tokio, axum or wgpu.

use crate::authoring::Displacement;
use crate::subsurface::world::{breach_lattice, in_force, memos};
use crate::subsurface::{ElementMemo, Geology};
use crate::terrain::lattice::Window;
use crate::terrain::plan::TILE_VERTS;
use crate::terrain::tile::{apply_snap, field, finish, snap_strip, Edge, Field, FieldJob};
use crate::terrain::{Tile, TileKey, WorldPlan};
use crate::volume::chunk::MAX_CHUNK_LOD;
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
    /// The world version's Ptex materials and decals, for exported pages (`None`: the default
    /// set of the world's seed). Tiles do not read it.
    pub materials: Option<Arc<crate::ptex::MaterialSet>>,
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

    /// Marks the vertices of a finished tile that volume chunks override: those whose ground
    /// lies inside a volume region's box (`x`, `z` within its bbox, the height within its
    /// `y_m`) and, in tiles of LOD 0 to [`MAX_CHUNK_LOD`], those where a cave of a `strata`
    /// element with `mark_openings` breaches the ground (the element in force there,
    /// [`crate::subsurface::world::in_force`]). Leaves [`Tile::volume_override`] empty when no
    /// vertex is marked.
    pub fn mark(&self, tile: &mut Tile) {
        let caves = tile.key.lod <= MAX_CHUNK_LOD
            && self
                .strata
                .iter()
                .any(|g| g.spec.carve && g.spec.mark_openings);
        if self.volumes.is_empty() && !caves {
            return;
        }
        let mut memos = memos(&self.strata);
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
                u8::from(inside || (caves && self.opening(&mut memos, x, z)))
            })
            .collect();
        if marks.contains(&1) {
            tile.volume_override = marks;
        }
    }

    /// Whether a cave of the `strata` element in force at `(x, z)` breaches the ground there
    /// and the element has `mark_openings`.
    fn opening(&self, memos: &mut [ElementMemo], x: f64, z: f64) -> bool {
        let Some(k) = in_force(&self.strata, x, z) else {
            return false;
        };
        let g = &self.strata[k];
        g.spec.mark_openings && g.carved(x, z, &mut memos[k]).is_some_and(|(_, b)| b > 0.0)
    }
}

/// The ground under a volume region is the ground tiles have.
impl GroundEdits for TileEdits {
    fn apply(&self, window: Window, heights: &mut [f32]) {
        TileEdits::apply(self, window, heights);
    }
}

/// The lattice jobs tile `key` needs, in order: its field with the one-vertex margin, then one
/// strip of the coarser lattice per edge whose `seams` flag is set (`n, e, s, w`; none at the
/// coarsest LOD). [`assemble`] takes their fields in the same order.
pub fn tile_jobs(
    plan: &WorldPlan,
    key: TileKey,
    seams: [bool; 4],
) -> Vec<(Option<Edge>, FieldJob)> {
    let mut jobs = vec![(None, FieldJob::with_margin(key))];
    if (key.lod as usize) + 1 < plan.lods.len() {
        for (edge, _) in Edge::ALL.iter().zip(seams).filter(|(_, c)| *c) {
            jobs.push((Some(*edge), snap_strip(key, *edge)));
        }
    }
    jobs
}

/// Applies `edits` to the field a job of [`tile_jobs`] produced.
pub fn edit_field(plan: &WorldPlan, job: FieldJob, edits: &TileEdits, field: &mut Field) {
    edits.apply(job.window(plan), &mut field.heights);
}

/// The one tile synthesis after the fields: `fields` are those of [`tile_jobs`] (same order),
/// already edited by [`edit_field`]. Finishes the tile (normals, materials, water, skirts),
/// snaps the seam edges to the coarser strips (so the edits reach the seams too) and marks the
/// vertices volume regions override.
pub fn assemble(
    plan: &WorldPlan,
    key: TileKey,
    fields: &[(Option<Edge>, Field)],
    edits: &TileEdits,
) -> Tile {
    let mut t = finish(plan, key, &fields[0].1);
    for (edge, strip) in &fields[1..] {
        if let Some(edge) = edge {
            apply_snap(&mut t, *edge, &strip.heights);
        }
    }
    edits.mark(&mut t);
    t
}

/// Synthesises tile `key` of the world `plan` with `edits` and no seams on the CPU (the tiles
/// of batch exports): [`synthesize_with_seams`].
pub fn synthesize(plan: &WorldPlan, key: TileKey, edits: &TileEdits) -> Tile {
    synthesize_with_seams(plan, key, [false; 4], edits)
}

/// Synthesises tile `key` of the world `plan` with `seams` and `edits` on the CPU: the jobs of
/// [`tile_jobs`] by [`field`], then [`assemble`]. The compute front door runs the same jobs on
/// the device when it has one, and the same [`assemble`].
pub fn synthesize_with_seams(
    plan: &WorldPlan,
    key: TileKey,
    seams: [bool; 4],
    edits: &TileEdits,
) -> Tile {
    let fields: Vec<(Option<Edge>, Field)> = tile_jobs(plan, key, seams)
        .into_iter()
        .map(|(edge, job)| {
            let mut f = field(plan, job);
            edit_field(plan, job, edits, &mut f);
            (edge, f)
        })
        .collect();
    assemble(plan, key, &fields, edits)
}
