//! §3 and §4.3: chunks of columns of stacked limits, with blend zones between layers, and a
//! voxel's composition and flow by interpolation between the limits around it.

use super::plan::{Composition, Element, ElementKind, SubsurfacePlan};

/// Largest chunk side (limits store their height in a byte).
pub const MAX_CHUNK: u32 = 64;

/// Chunk coordinates: the chunk covers voxels `[x·size, (x+1)·size)` on each axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ChunkKey {
    /// Chunk x.
    pub x: i32,
    /// Chunk y (0 holds the voxels just above and below the mean surface at y = 0).
    pub y: i32,
    /// Chunk z.
    pub z: i32,
}

/// A mixture of two palette entries: `(1 − t)·palette[lo] + t·palette[hi]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mix {
    /// First palette entry.
    pub lo: u16,
    /// Second palette entry.
    pub hi: u16,
    /// Weight of `hi`.
    pub t: f32,
}

impl Mix {
    fn pure(i: u16) -> Mix {
        Mix {
            lo: i,
            hi: i,
            t: 0.0,
        }
    }
    fn weight(&self, i: u16) -> f32 {
        let mut w = 0.0;
        if self.lo == i {
            w += 1.0 - self.t;
        }
        if self.hi == i {
            w += self.t;
        }
        w
    }
}

/// A limit: the volume's properties at voxel height `y` of its column (§3).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limit {
    /// Voxel height within the column, `0..size`.
    pub y: u8,
    /// Composition, as a mixture of palette entries.
    pub mix: Mix,
    /// Material flow: the mixture of its entries' flows (§4.2.1; zero in the void).
    pub flow: [f32; 3],
}

/// A chunk: `size × size` columns of stacked limits; each column has its bottom and top limits
/// and at most `size` limits.
#[derive(Clone, Debug, PartialEq)]
pub struct Chunk {
    /// Where it is.
    pub key: ChunkKey,
    /// Voxels per side.
    pub size: u32,
    /// Compositions the limits mix: the void, then every layer bottom up, then the chunk's
    /// veins and caves.
    pub palette: Vec<Composition>,
    /// Limits per column; column `(i, k)` (x, z) is number `k·size + i`.
    pub counts: Vec<u8>,
    /// All limits, column after column, bottom up.
    pub limits: Vec<Limit>,
    starts: Vec<u32>,
}

struct Placed {
    element: Element,
    palette: u16,
}

/// Flow of every palette entry a column uses: layers by [`SubsurfacePlan::layer_flow`], veins and
/// caves the flow of their host layer, the void none. Computed only for the entries used.
struct Flows {
    flows: Vec<Option<[f32; 3]>>,
}

impl Flows {
    fn clear(&mut self, n: usize) {
        self.flows.clear();
        self.flows.resize(n, None);
    }

    #[allow(clippy::too_many_arguments)]
    fn of(
        &mut self,
        plan: &SubsurfacePlan,
        hosts: &[usize],
        layers: usize,
        grads: &[(f32, f32)],
        x: f32,
        z: f32,
        p: u16,
    ) -> [f32; 3] {
        if let Some(f) = self.flows[p as usize] {
            return f;
        }
        let p = p as usize;
        let f = if p == 0 {
            [0.0; 3]
        } else {
            let k = if p <= layers {
                p - 1
            } else {
                hosts[p - layers - 1]
            };
            plan.layer_flow(k, x, z, grads[k])
        };
        self.flows[p] = Some(f);
        f
    }

    #[allow(clippy::too_many_arguments)]
    fn mix(
        &mut self,
        plan: &SubsurfacePlan,
        hosts: &[usize],
        grads: &[(f32, f32)],
        x: f32,
        z: f32,
        m: Mix,
    ) -> [f32; 3] {
        let layers = plan.layers.len();
        let a = self.of(plan, hosts, layers, grads, x, z, m.lo);
        if m.lo == m.hi {
            return a;
        }
        let b = self.of(plan, hosts, layers, grads, x, z, m.hi);
        let t = m.t;
        [
            a[0] * (1.0 - t) + b[0] * t,
            a[1] * (1.0 - t) + b[1] * t,
            a[2] * (1.0 - t) + b[2] * t,
        ]
    }
}

/// Composition of a voxel centre at height `y` of a column with layer tops `tops`: the layer it
/// lies in, the blend zone at a layer's bottom (§4.3: blend × local thickness, mixing linearly
/// from the layer below), void above the top layer, and veins then caves over both; anchored to
/// a ground ([`SubsurfacePlan::anchored`]), void at and above local height 0.
fn sample(plan: &SubsurfacePlan, tops: &[f32], spans: &[(f32, f32, u16)], y: f32) -> Mix {
    if plan.ground_anchored && y >= 0.0 {
        return Mix::pure(0);
    }
    for &(lo, hi, p) in spans.iter().rev() {
        if y >= lo && y < hi {
            return Mix::pure(p);
        }
    }
    let Some(k) = tops.iter().position(|&t| y < t) else {
        return Mix::pure(0);
    };
    let layer = (k + 1) as u16;
    if k > 0 {
        let bottom = tops[k - 1];
        let zone = plan.layers[k].blend * (tops[k] - bottom);
        if y < bottom + zone {
            return Mix {
                lo: layer - 1,
                hi: layer,
                t: (y - bottom) / zone,
            };
        }
    }
    Mix::pure(layer)
}

/// Whether `m` equals the interpolation of `a` and `b` at fraction `f`, for every palette entry.
fn on_line(a: Mix, b: Mix, m: Mix, f: f32) -> bool {
    if a == m && m == b {
        return true;
    }
    [a.lo, a.hi, b.lo, b.hi, m.lo, m.hi].iter().all(|&i| {
        let w = a.weight(i) * (1.0 - f) + b.weight(i) * f;
        (w - m.weight(i)).abs() <= 1e-5
    })
}

impl SubsurfacePlan {
    /// The elements (veins first, then caves) that may meet the box `[x0, x0+size)` ×
    /// `[y0, y0+size)` × `[z0, z0+size)`.
    fn elements_near(&self, x0: f32, y0: f32, z0: f32, size: f32) -> Vec<Element> {
        let region = [(x0, x0 + size), (y0, y0 + size), (z0, z0 + size)];
        let mut out = Vec::new();
        for kind in [ElementKind::Vein, ElementKind::Cave] {
            let side = self.cell_side(kind);
            let (i0, i1) = (
                (x0 / side).floor() as i32,
                ((x0 + size) / side).floor() as i32,
            );
            let (k0, k1) = (
                (z0 / side).floor() as i32,
                ((z0 + size) / side).floor() as i32,
            );
            for k in k0..=k1 {
                for i in i0..=i1 {
                    if let Some(e) = self.element_within(kind, (i, k), Some(region)) {
                        out.push(e);
                    }
                }
            }
        }
        out
    }

    /// Generates one chunk from the plan alone: the same bytes whatever else was generated,
    /// in whatever order, on whatever thread.
    pub fn chunk(&self, key: ChunkKey, size: u32) -> Chunk {
        self.chunk_within(key, size, None)
    }

    /// [`Self::chunk`] keeping only the veins and caves whose bounding square lies inside
    /// `bounds = [x0, z0, x1, z1]` (voxels), as a `strata` element's bbox does.
    pub fn chunk_within(&self, key: ChunkKey, size: u32, bounds: Option<[f32; 4]>) -> Chunk {
        let size = size.clamp(1, MAX_CHUNK);
        let s = size as f32;
        let (x0, y0, z0) = (key.x as f32 * s, key.y as f32 * s, key.z as f32 * s);
        let mut palette: Vec<Composition> = vec![vec![(self.void_id, 1.0)]];
        palette.extend(self.layers.iter().map(|l| l.composition.clone()));
        let placed: Vec<Placed> = self
            .elements_near(x0, y0, z0, s)
            .into_iter()
            .filter(|e| square_within(e, bounds))
            .map(|element| {
                palette.push(element.composition.clone());
                Placed {
                    element,
                    palette: (palette.len() - 1) as u16,
                }
            })
            .collect();
        let n = size as usize;
        let mut counts = Vec::with_capacity(n * n);
        let mut limits = Vec::with_capacity(n * n * 3);
        let mut starts = Vec::with_capacity(n * n);
        let mut tops = Vec::with_capacity(self.layers.len());
        let mut grads = Vec::with_capacity(self.layers.len());
        let hosts: Vec<usize> = placed.iter().map(|p| p.element.host).collect();
        let mut flows = Flows { flows: Vec::new() };
        let mut spans = Vec::with_capacity(placed.len());
        let mut column = vec![Mix::pure(0); n];
        for k in 0..n {
            for i in 0..n {
                let (x, z) = (x0 + i as f32 + 0.5, z0 + k as f32 + 0.5);
                self.tops(x, z, &mut tops, &mut grads);
                flows.clear(palette.len());
                spans.clear();
                for p in &placed {
                    if let Some(h) = p.element.height_at(x, z) {
                        let lo = tops[p.element.host];
                        spans.push((lo, lo + h, p.palette));
                    }
                }
                for (j, m) in column.iter_mut().enumerate() {
                    *m = sample(self, &tops, &spans, y0 + j as f32 + 0.5);
                }
                starts.push(limits.len() as u32);
                let before = limits.len();
                let mut a = 0usize;
                limits.push(Limit {
                    y: 0,
                    mix: column[0],
                    flow: flows.mix(self, &hosts, &grads, x, z, column[0]),
                });
                while a + 1 < n {
                    let mut b = a + 1;
                    while b + 1 < n {
                        let c = b + 1;
                        let ok = (a + 1..c).all(|j| {
                            on_line(
                                column[a],
                                column[c],
                                column[j],
                                (j - a) as f32 / (c - a) as f32,
                            )
                        });
                        if !ok {
                            break;
                        }
                        b = c;
                    }
                    limits.push(Limit {
                        y: b as u8,
                        mix: column[b],
                        flow: flows.mix(self, &hosts, &grads, x, z, column[b]),
                    });
                    a = b;
                }
                counts.push((limits.len() - before) as u8);
            }
        }
        Chunk {
            key,
            size,
            palette,
            counts,
            limits,
            starts,
        }
    }

    /// Composition and flow of the world voxel `(x, y, z)` evaluated directly, without chunks.
    pub fn voxel(&self, x: i32, y: i32, z: i32) -> (Composition, [f32; 3]) {
        let near = self.elements_near(x as f32, y as f32, z as f32, 1.0);
        self.voxel_among(x, y, z, near.iter())
    }

    /// [`Self::voxel`] with the lattice elements taken from `memo`, which keeps them for the
    /// next query nearby and drops those outside its bounds ([`ElementMemo::within`]).
    pub fn voxel_memo(
        &self,
        x: i32,
        y: i32,
        z: i32,
        memo: &mut ElementMemo,
    ) -> (Composition, [f32; 3]) {
        let near = memo.near(self, x as f32, z as f32, 1.0);
        self.voxel_among(x, y, z, near.iter().map(|e| e.as_ref()))
    }

    /// The cave over world column `(x, z)` (voxels): the lowest and highest local height of its
    /// Eq. 6 profile on its host layer, `(top of host, top of host + height)`, if a cave of
    /// `memo`'s bounds covers the column.
    pub fn cave_at(&self, x: f32, z: f32, memo: &mut ElementMemo) -> Option<(f32, f32)> {
        let side = self.cell_side(ElementKind::Cave);
        let cell = ((x / side).floor() as i32, (z / side).floor() as i32);
        let e = memo.get(self, ElementKind::Cave, cell)?;
        let h = e.height_at(x, z)?;
        let (mut tops, mut grads) = (Vec::new(), Vec::new());
        self.tops(x, z, &mut tops, &mut grads);
        let lo = tops[e.host];
        Some((lo, lo + h))
    }

    fn voxel_among<'a>(
        &self,
        x: i32,
        y: i32,
        z: i32,
        near: impl Iterator<Item = &'a Element>,
    ) -> (Composition, [f32; 3]) {
        let (xc, zc) = (x as f32 + 0.5, z as f32 + 0.5);
        let mut palette: Vec<Composition> = vec![vec![(self.void_id, 1.0)]];
        palette.extend(self.layers.iter().map(|l| l.composition.clone()));
        let (mut tops, mut grads) = (Vec::new(), Vec::new());
        self.tops(xc, zc, &mut tops, &mut grads);
        let mut spans = Vec::new();
        let mut hosts = Vec::new();
        for e in near {
            if let Some(h) = e.height_at(xc, zc) {
                palette.push(e.composition.clone());
                hosts.push(e.host);
                let lo = tops[e.host];
                spans.push((lo, lo + h, (palette.len() - 1) as u16));
            }
        }
        let m = sample(self, &tops, &spans, y as f32 + 0.5);
        let mut flows = Flows { flows: Vec::new() };
        flows.clear(palette.len());
        let flow = flows.mix(self, &hosts, &grads, xc, zc, m);
        (materials(&palette, &[(m.lo, 1.0 - m.t), (m.hi, m.t)]), flow)
    }
}

/// The lattice elements already built, for many queries in one neighbourhood (a volume chunk's
/// vertices, a batch of points). It caches a pure function, so answers do not depend on what
/// was asked before; elements whose bounding square leaves the bounds count as absent.
#[derive(Debug, Default)]
pub struct ElementMemo {
    bounds: Option<[f32; 4]>,
    cells: std::collections::BTreeMap<(bool, i32, i32), Option<std::sync::Arc<Element>>>,
}

impl ElementMemo {
    /// A memo keeping only elements whose bounding square lies inside `[x0, x1] × [z0, z1]`
    /// (voxels), given as `[x0, z0, x1, z1]`.
    pub fn within(bounds: [f32; 4]) -> ElementMemo {
        ElementMemo {
            bounds: Some(bounds),
            cells: Default::default(),
        }
    }

    fn get(
        &mut self,
        plan: &SubsurfacePlan,
        kind: ElementKind,
        cell: (i32, i32),
    ) -> Option<std::sync::Arc<Element>> {
        let bounds = self.bounds;
        self.cells
            .entry((kind == ElementKind::Cave, cell.0, cell.1))
            .or_insert_with(|| {
                let e = plan.element(kind, cell)?;
                square_within(&e, bounds).then(|| std::sync::Arc::new(e))
            })
            .clone()
    }

    /// Veins, then caves, of the cells the square `[x0, x0+size)` × `[z0, z0+size)` meets.
    fn near(
        &mut self,
        plan: &SubsurfacePlan,
        x0: f32,
        z0: f32,
        size: f32,
    ) -> Vec<std::sync::Arc<Element>> {
        let mut out = Vec::new();
        for kind in [ElementKind::Vein, ElementKind::Cave] {
            let side = plan.cell_side(kind);
            let cells = |a: f32| (a / side).floor() as i32..=((a + size) / side).floor() as i32;
            for k in cells(z0) {
                for i in cells(x0) {
                    out.extend(self.get(plan, kind, (i, k)));
                }
            }
        }
        out
    }
}

/// Whether the element's bounding square lies inside `bounds = [x0, z0, x1, z1]` (voxels);
/// always without bounds.
fn square_within(e: &Element, bounds: Option<[f32; 4]>) -> bool {
    bounds.is_none_or(|[x0, z0, x1, z1]| {
        e.origin.0 >= x0
            && e.origin.1 >= z0
            && e.origin.0 + e.side <= x1
            && e.origin.1 + e.side <= z1
    })
}

/// Expands weighted palette entries into materials, merged by id and sorted.
fn materials(palette: &[Composition], weights: &[(u16, f32)]) -> Composition {
    let mut out: Composition = Vec::new();
    for &(p, w) in weights {
        if w == 0.0 {
            continue;
        }
        for &(id, c) in &palette[p as usize] {
            match out.iter_mut().find(|e| e.0 == id) {
                Some(e) => e.1 += w * c,
                None => out.push((id, w * c)),
            }
        }
    }
    out.sort_by_key(|e| e.0);
    out
}

impl Chunk {
    /// The limits of column `(i, k)`.
    pub fn column(&self, i: u32, k: u32) -> &[Limit] {
        let c = (k * self.size + i) as usize;
        let s = self.starts[c] as usize;
        &self.limits[s..s + self.counts[c] as usize]
    }

    /// The limits of column `(i, k)` around voxel height `j`. `hi` is the column's first limit at
    /// or above `j` (its last limit when none is). The result is `(hi, None)` when `hi` is at
    /// height `j` or is the column's first limit; otherwise it is `(hi, Some((lo, f)))` with `lo`
    /// the limit before `hi` and `f = (j − lo.y) / (hi.y − lo.y)` the fraction of the way from
    /// `lo` to `hi` (above 1 when `j` lies above the column's last limit).
    fn bracket(&self, i: u32, j: u32, k: u32) -> (Limit, Option<(Limit, f32)>) {
        let col = self.column(i, k);
        let above = col
            .iter()
            .position(|l| u32::from(l.y) >= j)
            .unwrap_or(col.len() - 1);
        let hi = col[above];
        if u32::from(hi.y) == j || above == 0 {
            return (hi, None);
        }
        let lo = col[above - 1];
        let f = (j - u32::from(lo.y)) as f32 / (u32::from(hi.y) - u32::from(lo.y)) as f32;
        (hi, Some((lo, f)))
    }

    /// Composition of voxel `(i, j, k)` of the chunk (local coordinates): the limit's when a limit
    /// is at that height, otherwise linear interpolation between the limits below and above.
    pub fn voxel(&self, i: u32, j: u32, k: u32) -> Composition {
        match self.bracket(i, j, k) {
            (hi, None) => materials(
                &self.palette,
                &[(hi.mix.lo, 1.0 - hi.mix.t), (hi.mix.hi, hi.mix.t)],
            ),
            (hi, Some((lo, f))) => materials(
                &self.palette,
                &[
                    (lo.mix.lo, (1.0 - lo.mix.t) * (1.0 - f)),
                    (lo.mix.hi, lo.mix.t * (1.0 - f)),
                    (hi.mix.lo, (1.0 - hi.mix.t) * f),
                    (hi.mix.hi, hi.mix.t * f),
                ],
            ),
        }
    }

    /// Material flow of voxel `(i, j, k)`: the limit's, or linear interpolation between the limits
    /// below and above.
    pub fn flow(&self, i: u32, j: u32, k: u32) -> [f32; 3] {
        match self.bracket(i, j, k) {
            (hi, None) => hi.flow,
            (hi, Some((lo, f))) => [0, 1, 2].map(|c| lo.flow[c] * (1.0 - f) + hi.flow[c] * f),
        }
    }

    /// Voxels in the chunk.
    pub fn voxel_count(&self) -> usize {
        (self.size * self.size * self.size) as usize
    }

    /// Canonical little-endian bytes: key, size, palette, limit counts, limits (height, mixture,
    /// flow).
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut b = Vec::with_capacity(16 + self.limits.len() * 11 + self.counts.len());
        for v in [self.key.x, self.key.y, self.key.z] {
            b.extend_from_slice(&v.to_le_bytes());
        }
        b.extend_from_slice(&self.size.to_le_bytes());
        b.extend_from_slice(&(self.palette.len() as u32).to_le_bytes());
        for comp in &self.palette {
            b.extend_from_slice(&(comp.len() as u32).to_le_bytes());
            for &(id, c) in comp {
                b.extend_from_slice(&id.to_le_bytes());
                b.extend_from_slice(&c.to_bits().to_le_bytes());
            }
        }
        b.extend_from_slice(&self.counts);
        for l in &self.limits {
            b.push(l.y);
            b.extend_from_slice(&l.mix.lo.to_le_bytes());
            b.extend_from_slice(&l.mix.hi.to_le_bytes());
            b.extend_from_slice(&l.mix.t.to_bits().to_le_bytes());
            for c in l.flow {
                b.extend_from_slice(&c.to_bits().to_le_bytes());
            }
        }
        b
    }
}
