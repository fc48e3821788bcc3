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
//!
//! **The seam rule for materials.** A vertex on a chunk border belongs to both chunks (the
//! padding rule of [`crate::volume::chunk`]), and its probes reach sideways past the chunk's
//! padded columns: a probe point lies at most `MATERIAL_STEPS·v/2` from `p` along x and z, and
//! the centre of its voxel column at most `v/2` from it, so the ground is read at most
//! `r = (MATERIAL_STEPS + 1)·v/2` metres (`2.5·v`), `r/s` columns, beyond the cell holding `p`.
//! How a world reads it is its `chunk_geology` setting
//! ([`crate::terrain::WorldParams::chunk_geology`]):
//!
//! - `1` (worlds stored before `2`, which keep their bytes): the ground of the chunk's 34 × 34
//!   padded columns, clamped to them, at the vertex position the chunk's `f32` positions give.
//!   A probe that leaves one chunk's padded columns but not its neighbour's reads different
//!   grounds in the two, so a shared vertex can get different materials in them.
//! - `2` (new worlds): the vertex is placed at `(cell + offset)·s` from its global cell and
//!   in-cell offset (the same bits in every chunk), and the ground is read from the wide window
//!   of [`Columns::wide_heights`], the columns of the chunk and its eight neighbours:
//!   [`WIDE_MARGIN`] (31) columns beyond the padded grid, so at least 31 beyond the cell of any
//!   vertex the chunk holds. The bilinear position is world-anchored (`x/s` split into a global
//!   column and a fraction) and clamped to 31 columns around the vertex's cell, a window every
//!   chunk holding the vertex holds whole, so every chunk reads the same four columns with the
//!   same fractions and gives the vertex the same material bits. The clamp changes nothing while
//!   `r/s ≤ 31`, that is `v/s ≤ 12.4`: at every LOD of a world with `cell_m ≥ 0.33` for the
//!   largest voxel ([`super::spec::MAX_VOXEL_M`], 4 m); in finer worlds a probe farther than that
//!   reads the ground at the window's edge, in every chunk alike. The window's ground is
//!   computed only where a probe reads it beyond the padded grid, and the chunk takes the
//!   `strata` elements meeting the window, so the ground there is the one its neighbours
//!   compute.

use super::chunk::ElementMemo;
use super::world::{carved_at, ground_under, in_force, main_material, memos, Geology};
use crate::element::Rect;
use crate::terrain::lattice::lerp2;
use crate::terrain::WorldPlan;
use crate::volume::chunk::{
    chunk_sdf, mesh_sdf, ChunkKey, ChunkMesh, Columns, CHUNK_CELLS, CHUNK_SAMPLES, NO_GEOLOGY,
    WIDE_MARGIN, WIDE_SAMPLES,
};
use crate::volume::element::SolvedVolume;
use crate::volume::mesh::{MeshError, QuadMesh};
use crate::volume::offload::VolumeOffload;
use std::sync::Arc;

/// Half-voxel steps a vertex looks into the solid for its material.
pub const MATERIAL_STEPS: usize = 4;

/// Meshes chunk `key` of the world `plan` whose tiles gave `cols`: the heightfield solid, the
/// volume regions `volumes` blended in (in document order, [`SolvedVolume::blend`]), then the
/// caves of `geos` carved and vertex materials set (module docs); the surface nets are offered
/// to `dev`. `geos` are the `strata` elements, in document order, meeting the chunk's padded
/// columns ([`ground_rect`] with `chunk_geology: 1`) or the wide window ([`ground_rect`] with
/// `2`). With no element and [`CpuOnly`](crate::volume::offload::CpuOnly) it equals
/// [`crate::volume::chunk::mesh_chunk`].
///
/// # Errors
/// [`MeshError`] if the mesher refuses the grid.
pub fn mesh_world_chunk(
    key: ChunkKey,
    plan: &WorldPlan,
    cols: &Columns,
    volumes: &[Arc<SolvedVolume>],
    geos: &[Arc<Geology>],
    scratch: &mut QuadMesh,
    dev: &dyn VolumeOffload,
) -> Result<ChunkMesh, MeshError> {
    let spacing_m = plan.lods[key.lod as usize].spacing_m;
    let wide = plan.params.chunk_geology >= 2;
    let mut sdf = Vec::new();
    let mut mats = Vec::new();
    chunk_sdf(key, spacing_m, cols, &mut sdf, &mut mats);
    let n = CHUNK_SAMPLES;
    let [gx0, gy0, gz0] = key.first_cell().map(|c| c - 1);
    let s = f64::from(spacing_m);
    for v in volumes {
        blend_volume(v, [gx0, gy0, gz0], s, &mut sdf);
    }
    // With the wide window `geos` may hold elements that only meet the neighbours' columns:
    // the chunk carries materials when one meets its own padded columns.
    let padded = ground_rect(key, spacing_m, 1);
    if geos.is_empty() || (wide && !geos.iter().any(|g| g.meets(padded))) {
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
    if wide {
        let mut window = WideGround::new(key, s, cols, &ground);
        mesh.geology = (0..mesh.positions.len())
            .map(|v| {
                let (cell, off) = (mesh.global_cells[v], mesh.offsets[v]);
                let p: [f64; 3] = std::array::from_fn(|a| (cell[a] as f64 + f64::from(off[a])) * s);
                let mut read = |memos: &mut [ElementMemo], cx: f64, cz: f64| {
                    window.ground_at(geos, memos, [cell[0], cell[2]], cx, cz)
                };
                vertex_material(geos, &mut memos, &mut read, p, mesh.normals[v])
            })
            .collect();
        return Ok(mesh);
    }
    let origin = key.first_cell().map(|c| c as f64 * s);
    let frame = Frame {
        x0: gx0 as f64 * s,
        z0: gz0 as f64 * s,
        s,
        ground: &ground,
    };
    let mut read = |_: &mut [ElementMemo], cx: f64, cz: f64| frame.ground_at(cx, cz);
    mesh.geology = mesh
        .positions
        .iter()
        .zip(&mesh.normals)
        .map(|(p, nrm)| {
            let p: [f64; 3] = std::array::from_fn(|a| origin[a] + f64::from(p[a]));
            vertex_material(geos, &mut memos, &mut read, p, *nrm)
        })
        .collect();
    Ok(mesh)
}

/// The ground-plane rectangle (metres, closed) of the columns chunk `key` reads the ground of
/// with `chunk_geology` (the world's setting): its padded columns `32·x − 1 … 32·x + 32` with
/// `1`, the wide window `32·x − 32 … 32·x + 63` with `2` (module docs). The `strata` elements
/// meeting it are the ones [`mesh_world_chunk`] needs.
pub fn ground_rect(key: ChunkKey, spacing_m: f32, chunk_geology: u32) -> Rect {
    let s = f64::from(spacing_m);
    let margin = if chunk_geology >= 2 { WIDE_MARGIN } else { 0 } as i64;
    let [gx, _, gz] = key.first_cell();
    let (lo, hi) = (-1 - margin, CHUNK_CELLS as i64 + margin);
    Rect {
        min: [(gx + lo) as f64 * s, (gz + lo) as f64 * s],
        max: [(gx + hi) as f64 * s, (gz + hi) as f64 * s],
    }
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

/// The ground of a chunk's wide window ([`Columns::wide_heights`]) for `chunk_geology: 2`: the
/// padded columns' ground as the carve computed it, the others computed where a probe first
/// reads them (NaN until then).
struct WideGround<'a> {
    heights: &'a [f32],
    ground: Vec<f32>,
    /// Global column of the window's first column and row.
    gx0: i64,
    gz0: i64,
    s: f64,
}

impl<'a> WideGround<'a> {
    /// The window of chunk `key`, whose padded columns' ground is `padded` (34 × 34).
    fn new(key: ChunkKey, s: f64, cols: &'a Columns, padded: &[f32]) -> Self {
        let (n, w, m) = (CHUNK_SAMPLES, WIDE_SAMPLES, WIDE_MARGIN);
        let mut ground = vec![f32::NAN; w * w];
        for k in 0..n {
            let row = (k + m) * w + m;
            ground[row..row + n].copy_from_slice(&padded[k * n..(k + 1) * n]);
        }
        let [gx, _, gz] = key.first_cell();
        let first = -1 - m as i64;
        WideGround {
            heights: &cols.wide_heights,
            ground,
            gx0: gx + first,
            gz0: gz + first,
            s,
        }
    }

    /// The ground of global column `(gx, gz)`, which lies in the window.
    fn column(
        &mut self,
        geos: &[Arc<Geology>],
        memos: &mut [ElementMemo],
        gx: i64,
        gz: i64,
    ) -> f64 {
        let c = (gz - self.gz0) as usize * WIDE_SAMPLES + (gx - self.gx0) as usize;
        if self.ground[c].is_nan() {
            let (x, z) = (gx as f64 * self.s, gz as f64 * self.s);
            self.ground[c] = ground_under(geos, memos, x, z, self.heights[c]);
        }
        f64::from(self.ground[c])
    }

    /// Bilinear ground at `(x, z)` for a vertex in global cell `cell` (x, z): world-anchored,
    /// clamped to [`WIDE_MARGIN`] columns around the cell (module docs).
    fn ground_at(
        &mut self,
        geos: &[Arc<Geology>],
        memos: &mut [ElementMemo],
        cell: [i64; 2],
        x: f64,
        z: f64,
    ) -> f64 {
        let (i, tx) = window_axis(x / self.s, cell[0]);
        let (k, tz) = window_axis(z / self.s, cell[1]);
        let c00 = self.column(geos, memos, i, k);
        let c10 = self.column(geos, memos, i + 1, k);
        let c01 = self.column(geos, memos, i, k + 1);
        let c11 = self.column(geos, memos, i + 1, k + 1);
        lerp2(c00, c10, c01, c11, tx, tz)
    }
}

/// The first of the two global columns a bilinear read at column coordinate `u` blends, and
/// the fraction of the second, for a vertex whose cell is `c`: `u` clamped to
/// `[c − 31, c + 32]` ([`WIDE_MARGIN`]), so both columns lie in every window holding the cell.
fn window_axis(u: f64, c: i64) -> (i64, f64) {
    let m = WIDE_MARGIN as i64;
    let u = u.clamp((c - m) as f64, (c + 1 + m) as f64);
    let i = (u.floor() as i64).min(c + m);
    (i, u - i as f64)
}

/// The subsurface material of vertex `p` with normal `normal` (module docs); `ground` gives the
/// ground at a voxel column's centre.
fn vertex_material(
    geos: &[Arc<Geology>],
    memos: &mut [ElementMemo],
    ground: &mut dyn FnMut(&mut [ElementMemo], f64, f64) -> f64,
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
        let ground = ground(memos, cx, cz);
        let (comp, _) = g.composition(q[0], q[1], q[2], ground, &mut memos[k]);
        found = main_material(&comp).unwrap_or(NO_GEOLOGY);
        if !g.is_hollow(found) {
            break;
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::subsurface::spec::MAX_VOXEL_M;

    #[test]
    fn window_reads_are_world_anchored_and_stay_in_every_window_holding_the_cell() {
        let m = WIDE_MARGIN as i64;
        for c in [-1000i64, -33, -1, 0, 31, 32, 63, 4095] {
            // Every chunk holding cell `c` has it among its cells `32·x − 1 … 32·x + 31`.
            let holders: Vec<i64> = (c.div_euclid(32) - 1..=c.div_euclid(32) + 1)
                .filter(|x| (32 * x - 1..=32 * x + 31).contains(&c))
                .collect();
            assert!(!holders.is_empty());
            for step in 0..=2000 {
                let u = c as f64 - 60.0 + step as f64 * 0.0605;
                let (i, t) = window_axis(u, c);
                assert!((0.0..=1.0).contains(&t), "{u} {c}: {t}");
                for x in &holders {
                    let first = 32 * x - 32;
                    assert!(i >= first && i + 1 < first + WIDE_SAMPLES as i64, "{u} {c}");
                }
                if u >= (c - m) as f64 && u <= (c + 1 + m) as f64 {
                    assert_eq!(i as f64 + t, u, "unclamped reads are where the probe is");
                }
            }
        }
    }

    #[test]
    fn the_window_holds_every_probe_at_cells_of_a_third_of_a_metre_and_more() {
        // A probe's column centre lies at most (MATERIAL_STEPS + 1)·v/2 from its vertex along
        // x and z, so at most that many columns, over the spacing, beyond the vertex's cell.
        let reach = (MATERIAL_STEPS + 1) as f64 * MAX_VOXEL_M / 2.0;
        assert!(reach / 0.33 <= WIDE_MARGIN as f64, "{reach} m");
        assert!(reach / 0.3 > WIDE_MARGIN as f64, "finer cells clamp");
    }
}
