//! Height tiles: the 65×65-vertex product of the procedural world.
//!
//! Vertex `(i, j)` of tile `(lod, x, z)` has global lattice index `(x·64 + i, z·64 + j)` and sits
//! at world `(gx·δ, gz·δ)` with `δ = cell_m · 2^lod`; `i` runs east along +X, `j` south along +Z,
//! and the vertex index is `j·65 + i`. Every per-vertex value is a pure function of `(seed,
//! settings, lod, gx, gz)`:
//!
//! 1. biome map on the lattice with a margin of `r` (blur radius) + 1 samples ([`super::biome`]);
//! 2. biome weights by separable Gaussian blur ([`super::blur`]);
//! 3. height `h = Σ_b w_b · H_b(x)` over the biomes with nonzero weight ([`super::fractal`]);
//! 4. normals by central differences over the one-vertex margin, so edge normals match too;
//! 5. proto-texturing material and water depth ([`super::texture`]).
//!
//! Hence same-LOD neighbours share their edge vertices bit for bit. Across LODs a tile carries
//! skirts, and [`snap_edges`] replaces an edge by the coarser neighbour's edge (even vertices take
//! the coarser lattice's heights, odd ones the midpoint) so the mesh is watertight.

use super::biome::biome_grid;
use super::blur::blur_weights;
use super::fractal::fbm_batch;
use super::lattice::Window;
use super::plan::{WorldPlan, TILE_QUADS, TILE_VERTEX_COUNT, TILE_VERTS};
use super::texture::{proto_texture_batch, surface_inputs as surface_inputs_at, SURFACE_INPUTS};

/// Address of a height tile.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TileKey {
    /// Level of detail: vertex spacing is `cell_m · 2^lod`.
    pub lod: u32,
    /// Tile column (east is +x).
    pub x: i64,
    /// Tile row (south is +z).
    pub z: i64,
}

/// Heights and biome weights of a rectangle of one LOD's lattice.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// Columns.
    pub w: usize,
    /// Rows.
    pub h: usize,
    /// Heights, metres, row-major.
    pub heights: Vec<f32>,
    /// Biome weights, `weights[v * k + b]`.
    pub weights: Vec<f32>,
    /// The sea-level climate's snow line at each sample, metres, row-major (`earth-1` worlds
    /// with `snow_lines: 2`, [`super::earth::climate::sea_snow_lines`]); empty otherwise.
    pub snow_line: Vec<f32>,
    /// The lake field at each sample, row-major, where the CPU carve computed it (`earth-1`
    /// worlds with shaped shores and a lake near, [`super::earth::rivers::LakeField`]); the
    /// tile's water reads them instead of computing them again. Empty otherwise.
    pub lake_fields: Vec<Option<super::earth::rivers::LakeField>>,
}

/// One field job: the lattice samples `(gx0 + i, gz0 + j)`, `i < w`, `j < h`, of LOD `lod`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FieldJob {
    /// Level of detail: an index into `WorldPlan::lods`.
    pub lod: u32,
    /// Lattice x of the first sample (lattice units of the LOD).
    pub gx0: i64,
    /// Lattice z of the first sample (lattice units of the LOD).
    pub gz0: i64,
    /// Samples per row (along x).
    pub w: usize,
    /// Rows (along z).
    pub h: usize,
}

impl FieldJob {
    /// The job of the `w × h` samples from lattice point `(gx0, gz0)` of LOD `lod`.
    pub fn new(lod: u32, gx0: i64, gz0: i64, w: usize, h: usize) -> Self {
        Self {
            lod,
            gx0,
            gz0,
            w,
            h,
        }
    }

    /// The job of tile `key`'s vertices with a one-sample margin on every side (the margin gives
    /// the normals their central differences): `TILE_VERTS + 2` square from lattice point
    /// `(64·x − 1, 64·z − 1)`.
    pub fn with_margin(key: TileKey) -> Self {
        let n = TILE_VERTS + 2;
        Self::new(
            key.lod,
            key.x * TILE_QUADS - 1,
            key.z * TILE_QUADS - 1,
            n,
            n,
        )
    }

    /// The job's rectangle of the world lattice of `plan` (for the edits applied to its heights).
    pub fn window(self, plan: &WorldPlan) -> Window {
        Window {
            spacing_m: plan.lods[self.lod as usize].spacing_m,
            gx0: self.gx0,
            gz0: self.gz0,
            w: self.w,
            h: self.h,
        }
    }
}

/// The biome ids of a job's biome grid: its rectangle grown by the blur radius
/// `r = kernel.len() / 2` on every side, `(w + 2r) × (h + 2r)` row-major, with that width and
/// height ([`biome_grid`] over the grid).
pub fn job_biome_ids(plan: &WorldPlan, job: FieldJob) -> (Vec<u8>, usize, usize) {
    let lp = &plan.lods[job.lod as usize];
    let r = lp.kernel.len() / 2;
    let (bw, bh) = (job.w + 2 * r, job.h + 2 * r);
    let mut ids = vec![0u8; bw * bh];
    biome_grid(
        &plan.biome_map,
        lp.spacing_m,
        job.gx0 - r as i64,
        job.gz0 - r as i64,
        bw,
        bh,
        &mut ids,
    );
    (ids, bw, bh)
}

/// Synthesises heights and weights of the job's lattice samples: the CPU reference of the
/// field (the WGSL twin is `gpu::TileKernels::field`). An `earth-1` world's field is
/// [`super::earth::field`].
pub fn field(plan: &WorldPlan, job: FieldJob) -> Field {
    if let Some(earth) = &plan.earth {
        return super::earth::field(earth, plan.lods[job.lod as usize].spacing_m, job);
    }
    let FieldJob {
        lod,
        gx0,
        gz0,
        w,
        h,
    } = job;
    let lp = &plan.lods[lod as usize];
    let k = plan.biome_count();
    let (ids, bw, bh) = job_biome_ids(plan, job);
    let mut weights = vec![0.0f32; w * h * k];
    let single = blur_weights(&ids, bw, bh, &lp.kernel, k, &mut weights);

    let mut heights = vec![0.0f32; w * h];
    let row: Vec<f32> = (0..w)
        .map(|i| (gx0 + i as i64) as f32 * lp.spacing_m)
        .collect();
    let mut xs = Vec::with_capacity(w * h);
    let mut zs = Vec::with_capacity(w * h);
    for j in 0..h {
        xs.extend_from_slice(&row);
        zs.resize(zs.len() + w, (gz0 + j as i64) as f32 * lp.spacing_m);
    }
    // One biome everywhere (most tiles): every weight is exactly 1, so `0 + 1·H = H`.
    if let Some(b) = single {
        fbm_batch(&lp.fractals[b as usize], &xs, &zs, &mut heights);
        return Field {
            w,
            h,
            heights,
            weights,
            snow_line: Vec::new(),
            lake_fields: Vec::new(),
        };
    }
    let mut idx = Vec::with_capacity(w * h);
    let mut bx = Vec::with_capacity(w * h);
    let mut bz = Vec::with_capacity(w * h);
    let mut gs = Vec::new();
    for (b, fractal) in lp.fractals.iter().enumerate() {
        idx.clear();
        bx.clear();
        bz.clear();
        for v in 0..w * h {
            if weights[v * k + b] > 0.0 {
                idx.push(v);
                bx.push(xs[v]);
                bz.push(zs[v]);
            }
        }
        gs.resize(idx.len(), 0.0);
        fbm_batch(fractal, &bx, &bz, &mut gs);
        for (n, &v) in idx.iter().enumerate() {
            heights[v] += weights[v * k + b] * gs[n];
        }
    }
    Field {
        w,
        h,
        heights,
        weights,
        snow_line: Vec::new(),
        lake_fields: Vec::new(),
    }
}

/// A 65×65-vertex height tile.
#[derive(Clone, Debug, PartialEq)]
pub struct Tile {
    /// Address.
    pub key: TileKey,
    /// Vertex spacing, metres.
    pub spacing_m: f32,
    /// Number of biomes `k`.
    pub biome_count: usize,
    /// Heights, metres, index `j·65 + i`.
    pub heights: Vec<f32>,
    /// Unit normals (x, y, z), y up.
    pub normals: Vec<[f32; 3]>,
    /// Biome weights, `weights[v·k + b]`, each vertex summing to 1.
    pub weights: Vec<f32>,
    /// Proto-texturing material id per vertex (index into `MATERIALS`).
    pub materials: Vec<u8>,
    /// Depth of water above the ground, metres (0 on land): sea, lake or river.
    pub water_depth: Vec<f32>,
    /// Kind of the water over each vertex (`earth::rivers::kind`: 0 none, 1 sea, 2 lake,
    /// 3 river); empty in worlds without rivers, where all water is the sea.
    pub water_kind: Vec<u8>,
    /// Depth of the skirts hanging from the four edges, metres.
    pub skirt_depth_m: f32,
    /// 1 where a volume region's box holds the vertex's ground, so volume chunks, not this
    /// heightfield, give the surface there (issue 5); empty when no vertex is (`edits`).
    pub volume_override: Vec<u8>,
}

impl Tile {
    /// World X of the tile's west edge, metres.
    pub fn origin_x_m(&self) -> f64 {
        (self.key.x * TILE_QUADS) as f64 * self.spacing_m as f64
    }

    /// World Z of the tile's north edge, metres.
    pub fn origin_z_m(&self) -> f64 {
        (self.key.z * TILE_QUADS) as f64 * self.spacing_m as f64
    }
}

/// Synthesises one tile on the CPU (the reference implementation).
pub fn synthesize(plan: &WorldPlan, key: TileKey) -> Tile {
    let f = field(plan, FieldJob::with_margin(key));
    finish(plan, key, &f)
}

/// The tile's vertices of a per-sample field of a 67×67 job (the one-vertex margin dropped),
/// row-major; empty when `v` is.
fn crop<T: Clone>(v: &[T]) -> Vec<T> {
    let n = TILE_VERTS + 2;
    if v.is_empty() {
        return Vec::new();
    }
    let mut out = Vec::with_capacity(TILE_VERTEX_COUNT);
    for j in 0..TILE_VERTS {
        let row = (j + 1) * n + 1;
        out.extend_from_slice(&v[row..row + TILE_VERTS]);
    }
    out
}

/// Turns a 67×67 field (the tile plus a one-vertex margin) into a tile: normals, materials,
/// water and skirts. The GPU path produces the field and calls this too.
pub fn finish(plan: &WorldPlan, key: TileKey, f: &Field) -> Tile {
    let n = TILE_VERTS + 2;
    assert!(f.w == n && f.h == n, "finish: field must be 67×67");
    let k = plan.biome_count();
    let spacing = plan.lods[key.lod as usize].spacing_m;
    let mut heights = vec![0.0f32; TILE_VERTEX_COUNT];
    let mut normals = vec![[0.0f32; 3]; TILE_VERTEX_COUNT];
    let mut normal_y = vec![0.0f32; TILE_VERTEX_COUNT];
    let mut weights = vec![0.0f32; TILE_VERTEX_COUNT * k];
    let inv2d = 1.0 / (2.0 * spacing);
    for j in 0..TILE_VERTS {
        let row = (j + 1) * n + 1;
        let dst = j * TILE_VERTS;
        heights[dst..dst + TILE_VERTS].copy_from_slice(&f.heights[row..row + TILE_VERTS]);
        weights[dst * k..(dst + TILE_VERTS) * k]
            .copy_from_slice(&f.weights[row * k..(row + TILE_VERTS) * k]);
        let (up, mid, down) = (
            &f.heights[row - n..],
            &f.heights[row - 1..],
            &f.heights[row + n..],
        );
        let (up, mid, down) = (
            &up[..TILE_VERTS],
            &mid[..TILE_VERTS + 2],
            &down[..TILE_VERTS],
        );
        for i in 0..TILE_VERTS {
            let dx = (mid[i + 2] - mid[i]) * inv2d;
            let dz = (down[i] - up[i]) * inv2d;
            let inv = 1.0 / (dx * dx + 1.0 + dz * dz).sqrt();
            normals[dst + i] = [-dx * inv, inv, -dz * inv];
            normal_y[dst + i] = inv;
        }
    }
    let mut materials = vec![0u8; TILE_VERTEX_COUNT];
    let snow_shift = match &plan.earth {
        Some(e) => super::earth::snow_shift(e, key, spacing, &normals),
        None => Vec::new(),
    };
    // New `earth-1` worlds' sea-level snow lines, cropped to the tile like the weights.
    let snow_line = crop(&f.snow_line);
    proto_texture_batch(
        &plan.texture,
        &heights,
        &normal_y,
        &weights,
        &snow_line,
        &snow_shift,
        &mut materials,
    );
    let sea = plan.params.sea_level_m;
    let (surface, water_kind) = match &plan.earth {
        // The carve's lake fields of the tile's vertices, cropped like the heights.
        Some(e) => super::earth::tile_water(e, key, spacing, sea, &heights, &crop(&f.lake_fields)),
        None => (Vec::new(), Vec::new()),
    };
    let water_depth = if surface.is_empty() {
        heights.iter().map(|h| (sea - h).max(0.0)).collect()
    } else {
        surface
            .iter()
            .zip(&heights)
            .map(|(s, h)| (s - h).max(0.0))
            .collect()
    };
    let skirt_depth_m = skirt_depth(&heights, spacing);
    Tile {
        key,
        spacing_m: spacing,
        biome_count: k,
        heights,
        normals,
        weights,
        materials,
        water_depth,
        water_kind,
        skirt_depth_m,
        volume_override: Vec::new(),
    }
}

/// The inputs of the texel weighting function at every vertex of `tile`
/// ([`super::texture::surface_inputs`], vertex order), for the Ptex bake of worlds with
/// `texturing.ptex_blend: 2`; `None` in other worlds, whose bake blends the vertices' dominant
/// materials. The snow line's shift is the one [`finish`] gave the vertex (a function of its
/// position and normal).
pub fn surface_inputs(plan: &WorldPlan, tile: &Tile) -> Option<Vec<[f32; SURFACE_INPUTS]>> {
    if plan.params.texturing.ptex_blend != 2 {
        return None;
    }
    let k = tile.biome_count;
    let (shift, sea) = match &plan.earth {
        Some(e) => (
            super::earth::snow_shift(e, tile.key, tile.spacing_m, &tile.normals),
            super::earth::tile_sea_snow_lines(e, tile.key, tile.spacing_m),
        ),
        None => (Vec::new(), Vec::new()),
    };
    Some(
        tile.heights
            .iter()
            .enumerate()
            .map(|(v, &h)| {
                let w = &tile.weights[v * k..(v + 1) * k];
                surface_inputs_at(
                    &plan.texture,
                    h,
                    w,
                    sea.get(v).copied(),
                    shift.get(v).copied().unwrap_or(0.0),
                )
            })
            .collect(),
    )
}

/// Skirt depth: deep enough to hide the largest crack against a neighbour one LOD coarser, which
/// is bounded by the height change between adjacent edge vertices plus the dropped octaves.
fn skirt_depth(heights: &[f32], spacing: f32) -> f32 {
    let v = |i: usize, j: usize| heights[j * TILE_VERTS + i];
    let mut step = 0.0f32;
    for t in 0..TILE_VERTS - 1 {
        for (a, b) in [
            (v(t, 0), v(t + 1, 0)),
            (v(t, TILE_VERTS - 1), v(t + 1, TILE_VERTS - 1)),
            (v(0, t), v(0, t + 1)),
            (v(TILE_VERTS - 1, t), v(TILE_VERTS - 1, t + 1)),
        ] {
            step = step.max((a - b).abs());
        }
    }
    2.0 * step + 4.0 * spacing
}

/// Tile edges, in `?seams=n,e,s,w` order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edge {
    /// `j = 0` (−Z).
    North,
    /// `i = 64` (+X).
    East,
    /// `j = 64` (+Z).
    South,
    /// `i = 0` (−X).
    West,
}

impl Edge {
    /// All edges in `n, e, s, w` order.
    pub const ALL: [Edge; 4] = [Edge::North, Edge::East, Edge::South, Edge::West];

    /// Vertex index of position `t` (0..65) along the edge.
    pub fn vertex(self, t: usize) -> usize {
        let last = TILE_VERTS - 1;
        match self {
            Edge::North => t,
            Edge::South => last * TILE_VERTS + t,
            Edge::West => t * TILE_VERTS,
            Edge::East => t * TILE_VERTS + last,
        }
    }
}

/// The rectangle of the next coarser LOD's lattice that an edge snaps to, 33 samples along the
/// edge.
pub fn snap_strip(key: TileKey, edge: Edge) -> FieldJob {
    // Global lattice index of the edge's first vertex at this LOD; both are even because a tile
    // spans 64 quads, so they lie on the coarser lattice.
    let (gx0, gz0, along_x) = match edge {
        Edge::North => (key.x * TILE_QUADS, key.z * TILE_QUADS, true),
        Edge::South => (key.x * TILE_QUADS, (key.z + 1) * TILE_QUADS, true),
        Edge::West => (key.x * TILE_QUADS, key.z * TILE_QUADS, false),
        Edge::East => ((key.x + 1) * TILE_QUADS, key.z * TILE_QUADS, false),
    };
    let half = TILE_VERTS / 2 + 1;
    let (w, h) = if along_x { (half, 1) } else { (1, half) };
    FieldJob::new(key.lod + 1, gx0 / 2, gz0 / 2, w, h)
}

/// Replaces an edge by the coarser lattice's heights `coarse` (33 values from [`snap_strip`]):
/// even vertices take them bit for bit, odd vertices the midpoint of their even neighbours, so the
/// shared edge is watertight against the coarser neighbour.
pub fn apply_snap(tile: &mut Tile, edge: Edge, coarse: &[f32]) {
    assert_eq!(coarse.len(), TILE_VERTS / 2 + 1, "apply_snap: strip length");
    for t in 0..TILE_VERTS {
        let v = edge.vertex(t);
        tile.heights[v] = if t % 2 == 0 {
            coarse[t / 2]
        } else {
            (coarse[t / 2] + coarse[t / 2 + 1]) * 0.5
        };
    }
}

/// Snaps the edges whose flag is set (`n, e, s, w` order) on the CPU.
pub fn snap_edges(plan: &WorldPlan, tile: &mut Tile, coarser: [bool; 4]) {
    if tile.key.lod as usize + 1 >= plan.lods.len() {
        return;
    }
    for (edge, _) in Edge::ALL.iter().zip(coarser).filter(|(_, c)| *c) {
        let coarse = field(plan, snap_strip(tile.key, *edge));
        apply_snap(tile, *edge, &coarse.heights);
    }
}
