//! Volume chunks of a world with a subsurface (issue 6, "caves carve the world's solid"): the
//! heightfield solid of [`crate::volume::chunk`] with the caves of the `strata` elements in force
//! carved out, meshed, and each vertex given the subsurface material found there.
//!
//! Per padded column (global sample `(gx, gz)` at `(gx·s, gz·s)`) the ground `g` is recovered
//! from the tile height ([`super::world::ground_under`]) and the carved interval `(a, b)` of the
//! cave in force there, if any, turns every sample of the column into `max(S, d)`,
//! `d = min(y − g − a, g + b − y)` ([`super::world`] module docs). Both are pure functions of
//! the global column, so a sample shared by two chunks has the same value in both and the
//! same-LOD padding rule keeps seams exact: a cave crossing a chunk border is one closed
//! surface across the chunks (`tests/strata_world.rs`).
//!
//! **Vertex materials.** Vertex `p` with outward normal `n` takes the main material (largest
//! concentration, [`super::world::main_material`]) of the voxel holding `p − n·v·t/2` (`v` =
//! `voxel_m`) for the first `t = 1 …` [`MATERIAL_STEPS`] whose material is neither void nor cave:
//! the solid's material just inside the surface, so the ground shows its top layer and a cave
//! wall the rock around it. Voxels are whole cells while the carved surface is not, so the voxel
//! half a voxel in may still be the cave's; the steps look past it. The ground for a voxel is the
//! bilinear interpolation of the columns' ground at the voxel column's centre.

use super::chunk::ElementMemo;
use super::world::{carved_at, ground_under, in_force, main_material, memos, Geology};
use crate::volume::chunk::{
    chunk_sdf, mesh_sdf, ChunkKey, ChunkMesh, Columns, CHUNK_SAMPLES, NO_GEOLOGY,
};
use crate::volume::element::SolvedVolume;
use crate::volume::mesh::{MeshError, QuadMesh};
use crate::volume::offload::VolumeOffload;
use std::sync::Arc;

/// Half-voxel steps a vertex looks into the solid for its material.
pub const MATERIAL_STEPS: usize = 4;

/// Meshes chunk `key` of a world whose tiles gave `cols`: the heightfield solid, the volume
/// regions `volumes` blended in (in document order, [`SolvedVolume::blend`]), then the caves of
/// `geos` (the `strata` elements meeting the chunk, in document order) carved and vertex
/// materials set; the surface nets are offered to `dev`. With no element and
/// [`CpuOnly`](crate::volume::offload::CpuOnly) it
/// equals [`crate::volume::chunk::mesh_chunk`].
///
/// # Errors
/// [`MeshError`] if the mesher refuses the grid.
pub fn mesh_world_chunk(
    key: ChunkKey,
    spacing_m: f32,
    cols: &Columns,
    volumes: &[Arc<SolvedVolume>],
    geos: &[Arc<Geology>],
    scratch: &mut QuadMesh,
    dev: &dyn VolumeOffload,
) -> Result<ChunkMesh, MeshError> {
    let mut sdf = Vec::new();
    let mut mats = Vec::new();
    chunk_sdf(key, spacing_m, cols, &mut sdf, &mut mats);
    let n = CHUNK_SAMPLES;
    let [gx0, gy0, gz0] = key.first_cell().map(|c| c - 1);
    let s = f64::from(spacing_m);
    for v in volumes {
        blend_volume(v, [gx0, gy0, gz0], s, &mut sdf);
    }
    if geos.is_empty() {
        return mesh_sdf(key, spacing_m, &sdf, &mats, scratch, dev);
    }
    let mut memos = memos(geos);
    let mut ground = vec![0.0f32; n * n];
    for k in 0..n {
        let z = (gz0 + k as i64) as f64 * s;
        for i in 0..n {
            let x = (gx0 + i as i64) as f64 * s;
            let c = k * n + i;
            let g = ground_under(geos, &mut memos, x, z, cols.heights[c]);
            ground[c] = g;
            let Some((a, b)) = carved_at(geos, &mut memos, x, z) else {
                continue;
            };
            for j in 0..n {
                let y = (gy0 + j as i64) as f64 * s;
                let local = (y - f64::from(g)) as f32;
                let d = (local - a).min(b - local);
                let v = &mut sdf[(k * n + j) * n + i];
                if d > *v {
                    *v = d;
                }
            }
        }
    }
    let mut mesh = mesh_sdf(key, spacing_m, &sdf, &mats, scratch, dev)?;
    let origin = key.first_cell().map(|c| c as f64 * s);
    let frame = Frame {
        x0: gx0 as f64 * s,
        z0: gz0 as f64 * s,
        s,
        ground: &ground,
    };
    mesh.geology = mesh
        .positions
        .iter()
        .zip(&mesh.normals)
        .map(|(p, nrm)| {
            let p: [f64; 3] = std::array::from_fn(|a| origin[a] + f64::from(p[a]));
            vertex_material(geos, &mut memos, &frame, p, *nrm)
        })
        .collect();
    Ok(mesh)
}

/// Blends a volume region into the padded grid whose first sample is global `first`
/// ([`SolvedVolume::blend`]); samples outside the region's box keep their value.
fn blend_volume(v: &SolvedVolume, first: [i64; 3], s: f64, sdf: &mut [f32]) {
    let n = CHUNK_SAMPLES;
    let lo = first.map(|c| c as f64 * s);
    let hi = first.map(|c| (c + n as i64 - 1) as f64 * s);
    if !v.spec.meets(lo, hi) {
        return;
    }
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                let p = [
                    (first[0] + i as i64) as f64 * s,
                    (first[1] + j as i64) as f64 * s,
                    (first[2] + k as i64) as f64 * s,
                ];
                let c = (k * n + j) * n + i;
                sdf[c] = v.blend(p, sdf[c]);
            }
        }
    }
}

/// The padded column grid of a chunk and its ground, metres.
struct Frame<'a> {
    x0: f64,
    z0: f64,
    s: f64,
    ground: &'a [f32],
}

impl Frame<'_> {
    /// Bilinear ground at `(x, z)`, clamped to the padded grid.
    fn ground_at(&self, x: f64, z: f64) -> f64 {
        let n = CHUNK_SAMPLES;
        let (u, v) = ((x - self.x0) / self.s, (z - self.z0) / self.s);
        crate::terrain::lattice::bilinear_clamped(self.ground, n, n, u, v)
    }
}

fn vertex_material(
    geos: &[Arc<Geology>],
    memos: &mut [ElementMemo],
    frame: &Frame<'_>,
    p: [f64; 3],
    normal: [f32; 3],
) -> u32 {
    let Some(k) = in_force(geos, p[0], p[2]) else {
        return NO_GEOLOGY;
    };
    let g = &geos[k];
    let mut found = NO_GEOLOGY;
    for step in 1..=MATERIAL_STEPS {
        let depth = 0.5 * step as f64 * g.voxel_m();
        let q: [f64; 3] = std::array::from_fn(|a| p[a] - f64::from(normal[a]) * depth);
        let (cx, cz) = g.column_centre(q[0], q[2]);
        let ground = frame.ground_at(cx, cz);
        let (comp, _) = g.composition(q[0], q[1], q[2], ground, &mut memos[k]);
        found = main_material(&comp).unwrap_or(NO_GEOLOGY);
        if !g.is_hollow(found) {
            break;
        }
    }
    found
}
