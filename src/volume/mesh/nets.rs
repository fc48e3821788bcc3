//! The surface-nets pass: vertices, normals, attributes and quads in one sweep over the cells
//! (see the module docs of [`super`] for the rules), then [`super::ptex::adjacency`].
//!
//! Only two z-slices of the cell→vertex table are kept (a quad at cell `p` joins cells at `z` and
//! `z − 1`), so the scratch memory is `O(nx·ny)` and nothing is allocated per cell.

use super::{
    MeshError, MeshOptions, QuadClass, QuadMesh, SampleAttributes, CELL_CORNERS, CELL_EDGES,
    MAX_SAMPLES, NONE,
};

/// Meshes the zero set of `sdf` into `out` (cleared first; its allocations are reused).
///
/// `attrs` are optional per-sample inputs carried into the vertex data. Fails without touching
/// `out` when a dimension is below 2, the grid exceeds [`MAX_SAMPLES`], the spacing is not
/// positive or a slice length differs from the sample count.
pub fn surface_nets(
    sdf: &[f32],
    attrs: SampleAttributes<'_>,
    opts: &MeshOptions,
    out: &mut QuadMesh,
) -> Result<(), MeshError> {
    validate(sdf, attrs, opts)?;
    out.clear();
    emit(sdf, attrs, opts, out);
    super::ptex::adjacency(out);
    Ok(())
}

/// [`surface_nets`] with the geometry offered to `dev` (the WGSL twin,
/// [`crate::volume::offload::VolumeOffload::surface_nets`]); the vertex attributes are then
/// computed here from the sample attributes by the CPU's rule, so only positions and normals
/// can differ from [`surface_nets`] (within the twin's tolerance), and a material pick where an
/// offset lies within rounding of ½.
///
/// # Errors
/// As [`surface_nets`].
pub fn surface_nets_on(
    sdf: &[f32],
    attrs: SampleAttributes<'_>,
    opts: &MeshOptions,
    out: &mut QuadMesh,
    dev: &dyn crate::volume::offload::VolumeOffload,
) -> Result<(), MeshError> {
    validate(sdf, attrs, opts)?;
    match dev.surface_nets(sdf, opts) {
        Some(mesh) if mesh.cells.len() == mesh.offsets.len() => {
            *out = mesh;
            let [nx, ny, _] = opts.dims;
            let offs = corner_offsets(nx, nx * ny);
            let (materials, noise) = (&mut out.materials, &mut out.noise);
            materials.clear();
            noise.clear();
            for (c, f) in out.cells.iter().zip(&out.offsets) {
                let i = c[0] as usize + nx * (c[1] as usize + ny * c[2] as usize);
                let (m, n) = vertex_attributes(attrs, i, &offs, *f);
                materials.push(m);
                noise.push(n);
            }
            Ok(())
        }
        _ => {
            out.clear();
            emit(sdf, attrs, opts, out);
            super::ptex::adjacency(out);
            Ok(())
        }
    }
}

fn validate(sdf: &[f32], attrs: SampleAttributes<'_>, opts: &MeshOptions) -> Result<(), MeshError> {
    let d = opts.dims;
    let n = d
        .iter()
        .try_fold(1usize, |acc, &v| acc.checked_mul(v))
        .unwrap_or(usize::MAX);
    if d.iter().any(|&v| v < 2) || n > MAX_SAMPLES {
        return Err(MeshError::BadDims(d));
    }
    if !(opts.spacing_m.is_finite() && opts.spacing_m > 0.0) {
        return Err(MeshError::BadSpacing(opts.spacing_m));
    }
    let check = |field, got| {
        if got == n {
            Ok(())
        } else {
            Err(MeshError::Length {
                field,
                got,
                want: n,
            })
        }
    };
    check("sdf", sdf.len())?;
    if let Some(m) = attrs.materials {
        check("materials", m.len())?;
    }
    if let Some(m) = attrs.noise {
        check("noise", m.len())?;
    }
    Ok(())
}

/// Sample offsets of the eight cell corners for row stride `sy` and slice stride `sz`.
fn corner_offsets(sy: usize, sz: usize) -> [usize; 8] {
    CELL_CORNERS.map(|c| c[0] as usize + c[1] as usize * sy + c[2] as usize * sz)
}

/// Vertex placement, normal, attributes and quad emission (module docs of [`super`], steps 1–4).
pub(crate) fn emit(
    sdf: &[f32],
    attrs: SampleAttributes<'_>,
    opts: &MeshOptions,
    out: &mut QuadMesh,
) {
    let [nx, ny, nz] = opts.dims;
    let (sy, sz) = (nx, nx * ny);
    let (cnx, cny) = (nx - 1, ny - 1);
    let slice = cnx * cny;
    let offs = corner_offsets(sy, sz);
    let spacing = opts.spacing_m as f64;
    let (qmin, qmax) = (opts.quad_min, opts.quad_max);
    let mut ring = std::mem::take(&mut out.cell_vertex);
    ring.clear();
    ring.resize(2 * slice, NONE);
    // Sign bits (`S < 0`) of two sample slices, 64 samples per word: cells whose eight corners
    // agree are skipped a word at a time.
    let words = nx.div_ceil(64);
    let plane = ny * words;
    let mut signs = std::mem::take(&mut out.signs);
    signs.clear();
    signs.resize(2 * plane, 0);
    fill_signs(&sdf[..sz], nx, &mut signs[..plane]);
    for cz in 0..nz - 1 {
        let cur = (cz & 1) * slice;
        let prev = slice - cur;
        ring[cur..cur + slice].fill(NONE);
        let (lo, hi) = ((cz & 1) * plane, ((cz + 1) & 1) * plane);
        fill_signs(
            &sdf[(cz + 1) * sz..(cz + 2) * sz],
            nx,
            &mut signs[hi..hi + plane],
        );
        for cy in 0..cny {
            let row = cy * sy + cz * sz;
            let rows = [
                lo + cy * words,
                lo + (cy + 1) * words,
                hi + cy * words,
                hi + (cy + 1) * words,
            ];
            let word = |w: usize| -> (u64, u64) {
                if w == words {
                    return (0, u64::MAX);
                }
                let r = rows.map(|b| signs[b + w]);
                (r[0] | r[1] | r[2] | r[3], r[0] & r[1] & r[2] & r[3])
            };
            let mut next = word(0);
            for w in 0..words {
                let (any0, all0) = next;
                next = word(w + 1);
                let any = any0 | (any0 >> 1) | (next.0 << 63);
                let all = all0 & ((all0 >> 1) | (next.1 << 63));
                let valid = cnx - 64 * w;
                let mut mixed = (any & !all)
                    & if valid >= 64 {
                        u64::MAX
                    } else {
                        (1u64 << valid) - 1
                    };
                while mixed != 0 {
                    let cx = 64 * w + mixed.trailing_zeros() as usize;
                    mixed &= mixed - 1;
                    let i = row + cx;
                    let v: [f32; 8] = offs.map(|o| sdf[i + o]);
                    let mut mask = 0u32;
                    for (k, &s) in v.iter().enumerate() {
                        mask |= u32::from(s < 0.0) << k;
                    }
                    if mask == 0 || mask == 0xff {
                        continue;
                    }
                    let vi = out.positions.len() as u32;
                    ring[cur + cy * cnx + cx] = vi;
                    push_vertex(out, &v, mask, [cx, cy, cz], i, &offs, attrs, spacing);
                    // Quads of the three grid edges leaving corner 0 (sample p = this cell's corner).
                    let p = [cx as u32, cy as u32, cz as u32];
                    if (0..3).any(|k| p[k] < qmin[k] || p[k] >= qmax[k]) {
                        continue;
                    }
                    let solid0 = mask & 1 != 0;
                    let at = |x: usize, y: usize, slice_base: usize| slice_base + y * cnx + x;
                    // Edge along X (corner 1): cells p − Y − Z, p − Z, p, p − Y.
                    if cy > 0 && cz > 0 && ((mask >> 1) & 1 != 0) != solid0 {
                        let c = [
                            ring[at(cx, cy - 1, prev)],
                            ring[at(cx, cy, prev)],
                            vi,
                            ring[at(cx, cy - 1, cur)],
                        ];
                        push_quad(out, 0, solid0, c, p);
                    }
                    // Edge along Y (corner 2): b = Z, c = X: cells p − Z − X, p − X, p, p − Z.
                    if cz > 0 && cx > 0 && ((mask >> 2) & 1 != 0) != solid0 {
                        let c = [
                            ring[at(cx - 1, cy, prev)],
                            ring[at(cx - 1, cy, cur)],
                            vi,
                            ring[at(cx, cy, prev)],
                        ];
                        push_quad(out, 1, solid0, c, p);
                    }
                    // Edge along Z (corner 4): b = X, c = Y: cells p − X − Y, p − Y, p, p − X.
                    if cx > 0 && cy > 0 && ((mask >> 4) & 1 != 0) != solid0 {
                        let c = [
                            ring[at(cx - 1, cy - 1, cur)],
                            ring[at(cx, cy - 1, cur)],
                            vi,
                            ring[at(cx - 1, cy, cur)],
                        ];
                        push_quad(out, 2, solid0, c, p);
                    }
                }
            }
        }
    }
    out.cell_vertex = ring;
    out.signs = signs;
}

/// Sign bits of one sample slice: bit `x % 64` of word `y·words + x / 64` is `S(x, y) < 0`.
fn fill_signs(slice: &[f32], nx: usize, out: &mut [u64]) {
    let words = nx.div_ceil(64);
    for (row, dst) in slice.chunks_exact(nx).zip(out.chunks_exact_mut(words)) {
        for (chunk, word) in row.chunks(64).zip(dst.iter_mut()) {
            let mut bits = 0u64;
            for (b, &v) in chunk.iter().enumerate() {
                bits |= u64::from(v < 0.0) << b;
            }
            *word = bits;
        }
    }
}

/// Appends the vertex of a surface cell: position, normal, attributes, empty quad slots.
#[allow(clippy::too_many_arguments)]
#[inline]
fn push_vertex(
    out: &mut QuadMesh,
    v: &[f32; 8],
    mask: u32,
    cell: [usize; 3],
    i: usize,
    offs: &[usize; 8],
    attrs: SampleAttributes<'_>,
    spacing: f64,
) {
    let mut sum = [0.0f32; 3];
    let mut n = 0u32;
    for e in CELL_EDGES {
        let (a, b) = (e[0], e[1]);
        if ((mask >> a) ^ (mask >> b)) & 1 == 0 {
            continue;
        }
        let t = v[a] / (v[a] - v[b]);
        let (ca, cb) = (CELL_CORNERS[a], CELL_CORNERS[b]);
        for k in 0..3 {
            sum[k] += ca[k] as f32 + t * (cb[k] as f32 - ca[k] as f32);
        }
        n += 1;
    }
    let inv = 1.0 / n as f32;
    let f = sum.map(|s| (s * inv).clamp(0.0, 1.0));
    let normal = trilinear_gradient(v, f);
    out.cells.push(cell.map(|c| c as u32));
    out.offsets.push(f);
    out.positions.push(std::array::from_fn(|k| {
        ((cell[k] as f64 + f[k] as f64) * spacing) as f32
    }));
    out.normals.push(normal);
    let (material, noise) = vertex_attributes(attrs, i, offs, f);
    out.materials.push(material);
    out.noise.push(noise);
    out.slots.push([NONE; 12]);
    out.masks.push(mask as u8);
}

/// The material (of the corner nearest to the vertex) and the noise parameters (trilinear in
/// the cell) of a vertex at in-cell offset `f` of the cell whose first sample is `i`.
#[inline]
fn vertex_attributes(
    attrs: SampleAttributes<'_>,
    i: usize,
    offs: &[usize; 8],
    f: [f32; 3],
) -> (u8, [f32; 4]) {
    let nearest =
        usize::from(f[0] >= 0.5) | usize::from(f[1] >= 0.5) << 1 | usize::from(f[2] >= 0.5) << 2;
    let material = attrs.materials.map_or(0, |m| m[i + offs[nearest]]);
    let noise = match attrs.noise {
        None => [0.0; 4],
        Some(noise) => {
            let w = trilinear_weights(f);
            let mut acc = [0.0f32; 4];
            for (c, wc) in w.iter().enumerate() {
                let s = noise[i + offs[c]];
                for k in 0..4 {
                    acc[k] += wc * s[k];
                }
            }
            acc
        }
    };
    (material, noise)
}

/// Trilinear weights of the eight corners at in-cell offset `f`.
#[inline]
fn trilinear_weights(f: [f32; 3]) -> [f32; 8] {
    let g = f.map(|x| 1.0 - x);
    std::array::from_fn(|c| {
        let pick = |k: usize| if (c >> k) & 1 == 1 { f[k] } else { g[k] };
        pick(0) * pick(1) * pick(2)
    })
}

/// `∇S / |∇S|` of the trilinear interpolant of the corners `v` at offset `f` (`+Y` if zero).
#[inline]
pub(crate) fn trilinear_gradient(v: &[f32; 8], f: [f32; 3]) -> [f32; 3] {
    let [fx, fy, fz] = f;
    let [gx, gy, gz] = [1.0 - fx, 1.0 - fy, 1.0 - fz];
    let dx = gy * gz * (v[1] - v[0])
        + fy * gz * (v[3] - v[2])
        + gy * fz * (v[5] - v[4])
        + fy * fz * (v[7] - v[6]);
    let dy = gx * gz * (v[2] - v[0])
        + fx * gz * (v[3] - v[1])
        + gx * fz * (v[6] - v[4])
        + fx * fz * (v[7] - v[5]);
    let dz = gx * gy * (v[4] - v[0])
        + fx * gy * (v[5] - v[1])
        + gx * fy * (v[6] - v[2])
        + fx * fy * (v[7] - v[3]);
    let len = (dx * dx + dy * dy + dz * dz).sqrt();
    if len > 0.0 && len.is_finite() {
        [dx / len, dy / len, dz / len]
    } else {
        [0.0, 1.0, 0.0]
    }
}

/// Appends the quad of the grid edge along `axis` at sample `p`; `cells` are the vertices of the
/// cells `c00, c10, c11, c01` (module docs of [`super`]).
#[inline]
pub(crate) fn push_quad(
    out: &mut QuadMesh,
    axis: usize,
    solid_low: bool,
    cells: [u32; 4],
    p: [u32; 3],
) {
    let q = out.quads.len() as u32;
    let [c00, c10, c11, c01] = cells;
    out.quads.push(if solid_low {
        [c00, c10, c11, c01]
    } else {
        [c00, c01, c11, c10]
    });
    out.classes.push(QuadClass::new(axis, solid_low));
    out.edges.push(p);
    // In cell c(j_b, j_c) the edge sits at offsets (1 − j_b, 1 − j_c): slot 4a + o_b + 2·o_c.
    let base = 4 * axis;
    for (c, slot) in [(c00, 3), (c10, 2), (c11, 0), (c01, 1)] {
        out.slots[c as usize][base + slot] = q;
    }
}
