//! §4.2: the layer stack (Eq. 1–4) as a function of the world seed, and veins and caves (Eq. 5–6)
//! on world lattices.
//!
//! Why one file of about 690 lines (40 of tests): the layer stack and the vein and cave elements
//! are all drawn by `SubsurfacePlan` from the seed's numbered `Draws` streams, and the geometry
//! helpers at the end (`outline`, `border_distance`, `inside`) serve only those elements.

use super::config::{Range, SubsurfaceConfig};
use crate::terrain::hash::{hash2, mix32, stream, unit};
use crate::terrain::noise::{fade, lattice_cell};

/// Stream purposes of the subsurface (disjoint from `terrain::hash::purpose`).
pub mod purpose {
    /// The layer stack (`index` = layer).
    pub const STACK: u32 = 0x5b_0001;
    /// Layer-surface noise (`index` = layer).
    pub const SURFACE: u32 = 0x5b_0002;
    /// The vein lattice.
    pub const VEINS: u32 = 0x5b_0003;
    /// The cave lattice.
    pub const CAVES: u32 = 0x5b_0004;
    /// Direction noise of the material flow (`index` = layer).
    pub const FLOW: u32 = 0x5b_0005;
}

/// Most layers in a stack (bounds a column's work).
pub const MAX_LAYERS: usize = 64;
/// Recursion depth of the midpoint-displacement outline (§4.2.2: "limited to 5").
pub const OUTLINE_DEPTH: u32 = 5;
/// Vertices of an outline: 4 corners, doubled at every depth.
pub const OUTLINE_VERTICES: usize = 4 << OUTLINE_DEPTH;

/// A material composition: `(material id, concentration)`, concentrations summing to 1.
pub type Composition = Vec<(u32, f32)>;

/// Numbered draws from one hash stream: draw `i` is `mix32(seed ^ i·φ)`, a pure function of the
/// seed and `i` (no generator state beyond the counter).
#[derive(Clone, Copy, Debug)]
pub struct Draws {
    seed: u32,
    next: u32,
}

impl Draws {
    /// Draws from the stream `seed`.
    pub fn new(seed: u32) -> Draws {
        Draws { seed, next: 0 }
    }
    /// The next draw, uniform in `[0, 1)`.
    pub fn u(&mut self) -> f32 {
        self.next = self.next.wrapping_add(1);
        unit(mix32(self.seed ^ self.next.wrapping_mul(0x9e37_79b9)))
    }
}

/// One layer of the stack with its Eq. 3 properties in absolute units.
#[derive(Clone, Debug, PartialEq)]
pub struct Layer {
    /// Materials and concentrations (main material first).
    pub composition: Composition,
    /// Mean thickness, voxels.
    pub thickness: f32,
    /// Eq. 4 similarity to the layer below.
    pub similarity: f32,
    /// Fraction of the layer that blends with the one below (§4.3).
    pub blend: f32,
    /// Noise amplitude of the surface, voxels.
    pub roughness: f32,
    /// Mean height of the layer's top, voxels (the stack's top is at 0).
    pub mean_top: f32,
    /// Seed of the surface noise.
    pub noise_seed: u32,
    /// Seed of the flow-direction noise.
    pub flow_seed: u32,
}

/// What kind of element a vein-lattice or cave-lattice cell holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ElementKind {
    /// A mineral vein.
    Vein,
    /// A cave.
    Cave,
}

/// A vein or a cave: a midpoint-displacement outline in a bounding square, lying on a host
/// layer, with the Eq. 6 height profile.
#[derive(Clone, Debug, PartialEq)]
pub struct Element {
    /// Vein or cave.
    pub kind: ElementKind,
    /// Lattice cell.
    pub cell: (i32, i32),
    /// The layer it lies on.
    pub host: usize,
    /// Materials and concentrations.
    pub composition: Composition,
    /// Lower x and z corner of the bounding square, voxels.
    pub origin: (f32, f32),
    /// Side of the bounding square, voxels.
    pub side: f32,
    /// Largest height (relative thickness × global thickness), voxels.
    pub height: f32,
    /// Outline in unit-square coordinates, `OUTLINE_VERTICES` points, within `[0, 1]²`.
    pub outline: Vec<(f32, f32)>,
    /// Distance from the square's centre to the outline (unit coordinates): Eq. 6 normaliser.
    pub norm: f32,
}

/// Everything a chunk needs that depends only on the seed and the configuration.
#[derive(Clone, Debug)]
pub struct SubsurfacePlan {
    /// The configuration.
    pub config: SubsurfaceConfig,
    /// World seed.
    pub seed: u64,
    /// Layers from the bottom (base) up.
    pub layers: Vec<Layer>,
    /// Id of the void material (the first one listed).
    pub void_id: u32,
    /// Materials' index by position: affinities, `[i][j]` = (same layer, next layer).
    affinity: Vec<Vec<(f32, f32)>>,
    /// Lowest and highest possible top of every layer (the lattice noise is bounded).
    bounds: Vec<(f32, f32)>,
    /// Whether the stack is anchored to the ground of a world ([`SubsurfacePlan::anchored`]):
    /// local height 0 is the ground, the top layer reaches it everywhere, the ground truncates
    /// every other layer, and everything at or above it is void.
    pub ground_anchored: bool,
}

/// Largest absolute value of `terrain::noise::lattice` (the byte-sum Gaussian's extreme).
const NOISE_BOUND: f32 = 3.451;

/// Eq. 1–2 selection of a main material and extras (probability 0.5, halving), with
/// concentrations (main 0.5–0.9 when mixed, summing to 1). `below` is the composition of the
/// layer underneath by material index; `allowed` filters candidates.
fn select(
    plan_aff: &[Vec<(f32, f32)>],
    config: &SubsurfaceConfig,
    below: &[(usize, f32)],
    allowed: &dyn Fn(usize) -> bool,
    single: bool,
    d: &mut Draws,
) -> Vec<(usize, f32)> {
    let mut chosen: Vec<usize> = Vec::new();
    let mut p_extra = 1.0f32;
    loop {
        let mut cands: Vec<(usize, f32)> = Vec::new();
        for (i, aff) in plan_aff.iter().enumerate() {
            if !allowed(i) || chosen.contains(&i) {
                continue;
            }
            if !chosen.is_empty() && config.materials[i].flags.alone {
                continue;
            }
            if below.iter().any(|&(j, _)| aff[j].1 < 0.0) || chosen.iter().any(|&j| aff[j].0 < 0.0)
            {
                continue;
            }
            // Eq. 1, with the already selected materials added to the last layer's.
            let mut a: f32 = below.iter().map(|&(j, c)| aff[j].1 * c).sum();
            a += chosen.iter().map(|&j| aff[j].0).sum::<f32>();
            cands.push((i, a));
        }
        if cands.is_empty() {
            break;
        }
        // Eq. 2; all-zero affinities fall back to a uniform choice.
        let total: f32 = cands.iter().map(|c| c.1).sum();
        let u = d.u();
        let pick = if total > 0.0 {
            let mut acc = 0.0;
            let mut pick = cands[cands.len() - 1].0;
            for &(i, a) in &cands {
                acc += a / total;
                if u < acc {
                    pick = i;
                    break;
                }
            }
            pick
        } else {
            cands[((u * cands.len() as f32) as usize).min(cands.len() - 1)].0
        };
        chosen.push(pick);
        if single || config.materials[pick].flags.alone {
            break;
        }
        p_extra *= 0.5;
        if d.u() >= p_extra {
            break;
        }
    }
    if chosen.len() <= 1 {
        return chosen.into_iter().map(|i| (i, 1.0)).collect();
    }
    let main = 0.5 + 0.4 * d.u();
    let weights: Vec<f32> = (1..chosen.len()).map(|_| 0.05 + d.u()).collect();
    let wsum: f32 = weights.iter().sum();
    let mut out = vec![(chosen[0], main)];
    let mut rest = 1.0 - main;
    for (k, &i) in chosen[1..].iter().enumerate() {
        let c = if k + 2 == chosen.len() {
            rest
        } else {
            (1.0 - main) * weights[k] / wsum
        };
        rest -= c;
        out.push((i, c));
    }
    out
}

/// Eq. 3 over a range-valued property: each material draws its value, weighted by concentration.
fn property(
    config: &SubsurfaceConfig,
    comp: &[(usize, f32)],
    get: fn(&super::config::Material) -> Range,
    d: &mut Draws,
) -> f32 {
    comp.iter()
        .map(|&(i, c)| get(&config.materials[i]).draw(d.u()) * c)
        .sum()
}

fn scalar(
    config: &SubsurfaceConfig,
    comp: &[(usize, f32)],
    get: fn(&super::config::Material) -> f32,
) -> f32 {
    comp.iter()
        .map(|&(i, c)| get(&config.materials[i]) * c)
        .sum()
}

impl SubsurfacePlan {
    /// Builds the layer stack of a world (§4.2.1): base layer, then layers chosen by affinity with
    /// the one below until the terrain depth is reached. Expects a validated configuration.
    pub fn new(seed: u64, config: SubsurfaceConfig) -> SubsurfacePlan {
        let n = config.materials.len();
        let mut affinity = vec![vec![(0.0f32, 0.0f32); n]; n];
        for a in &config.affinities {
            let i = config.materials.iter().position(|m| m.id == a.a);
            let j = config.materials.iter().position(|m| m.id == a.b);
            if let (Some(i), Some(j)) = (i, j) {
                affinity[i][j] = (a.same_layer, a.next_layer);
                affinity[j][i] = (a.same_layer, a.next_layer);
            }
        }
        let void_id = config
            .materials
            .iter()
            .find(|m| m.flags.void)
            .map(|m| m.id)
            .unwrap_or(0);
        let g = config.general;
        let mut layers: Vec<Layer> = Vec::new();
        let mut below: Vec<(usize, f32)> = Vec::new();
        let mut height = 0.0f32;
        while layers.len() < MAX_LAYERS && (layers.is_empty() || height < g.terrain_depth) {
            let k = layers.len() as u32;
            let mut d = Draws::new(stream(seed, purpose::STACK, k));
            let depth = 1.0 - height / g.terrain_depth;
            let mats = &config.materials;
            let regular = |i: usize| {
                let f = mats[i].flags;
                !(f.void || f.base || f.vein || f.cave)
            };
            let comp = if k == 0 {
                select(
                    &affinity,
                    &config,
                    &[],
                    &|i| mats[i].flags.base,
                    false,
                    &mut d,
                )
            } else {
                let in_depth = |i: usize| {
                    regular(i) && (mats[i].depth.min..=mats[i].depth.max).contains(&depth)
                };
                let c = select(&affinity, &config, &below, &in_depth, false, &mut d);
                if c.is_empty() {
                    select(&affinity, &config, &below, &regular, false, &mut d)
                } else {
                    c
                }
            };
            if comp.is_empty() {
                break;
            }
            let thickness =
                (property(&config, &comp, |m| m.thickness, &mut d) * g.layer_thickness).max(0.5);
            let roughness = property(&config, &comp, |m| m.roughness, &mut d) * g.roughness;
            let similarity =
                (scalar(&config, &comp, |m| m.similarity) * g.similarity).clamp(0.0, 1.0);
            let blend = scalar(&config, &comp, |m| m.blend).clamp(0.0, 1.0);
            height += thickness;
            layers.push(Layer {
                composition: comp.iter().map(|&(i, c)| (mats[i].id, c)).collect(),
                thickness,
                similarity,
                blend,
                roughness,
                mean_top: height,
                noise_seed: stream(seed, purpose::SURFACE, k),
                flow_seed: stream(seed, purpose::FLOW, k),
            });
            below = comp;
        }
        for l in &mut layers {
            l.mean_top -= height;
        }
        let mut bounds: Vec<(f32, f32)> = Vec::with_capacity(layers.len());
        let mut amp = 0.0f32;
        for (k, l) in layers.iter().enumerate() {
            let own = NOISE_BOUND * l.roughness;
            amp = if k == 0 {
                own
            } else {
                amp * l.similarity + own * (1.0 - l.similarity)
            };
            let (mut lo, mut hi) = (l.mean_top - amp, l.mean_top + amp);
            if let Some(&(plo, phi)) = bounds.last() {
                lo = lo.max(plo);
                hi = hi.max(phi);
            }
            bounds.push((lo, hi));
        }
        SubsurfacePlan {
            bounds,
            config,
            seed,
            layers,
            void_id,
            affinity,
            ground_anchored: false,
        }
    }

    /// [`SubsurfacePlan::new`] anchored to a world's ground (the `strata` scene element): local
    /// height `y = 0` is the ground surface at every column. The paper's stack has its mean top
    /// at 0 and noisy layer surfaces, which under a real ground would leave void pockets below
    /// the ground and layers sticking out of it; anchored, every layer top is clamped to at
    /// most 0 (the ground truncates the layers it cuts, as erosion does), the top layer's top is
    /// 0 itself, and veins, caves and layers at or above 0 give way to the void (the air).
    pub fn anchored(seed: u64, config: SubsurfaceConfig) -> SubsurfacePlan {
        let mut plan = SubsurfacePlan::new(seed, config);
        plan.ground_anchored = true;
        let last = plan.bounds.len().saturating_sub(1);
        for (k, b) in plan.bounds.iter_mut().enumerate() {
            *b = if k == last {
                (0.0, 0.0)
            } else {
                (b.0.min(0.0), b.1.min(0.0))
            };
        }
        plan
    }

    /// The lowest and highest height any layer top can take (voxels): below the first is the
    /// base material only.
    pub fn depth_range(&self) -> (f32, f32) {
        let lo = self.bounds.first().map_or(0.0, |b| b.0);
        let hi = self.bounds.last().map_or(0.0, |b| b.1);
        (lo, hi)
    }

    /// The lowest and highest height the top of layer `k` can take (voxels), or `None` past the
    /// stack.
    pub fn top_range(&self, k: usize) -> Option<(f32, f32)> {
        self.bounds.get(k).copied()
    }

    fn index(&self, id: u32) -> usize {
        self.config
            .materials
            .iter()
            .position(|m| m.id == id)
            .unwrap_or(0)
    }

    /// Tops of every layer at world point `(x, z)` (voxels), bottom first, non-decreasing
    /// (Eq. 4: `h = h₋₁·s + n·(1 − s)`, plus the layer's mean top; a layer thinner than zero
    /// pinches out), and their gradients `(∂/∂x, ∂/∂z)`.
    pub fn tops(&self, x: f32, z: f32, out: &mut Vec<f32>, grads: &mut Vec<(f32, f32)>) {
        out.clear();
        grads.clear();
        let scale = self.config.general.scale;
        let (sx, sz) = (x * scale, z * scale);
        let mut h_prev = 0.0f32;
        let mut g_prev = (0.0f32, 0.0f32);
        let mut top_prev = f32::NEG_INFINITY;
        let mut tg_prev = (0.0f32, 0.0f32);
        for (k, l) in self.layers.iter().enumerate() {
            let (n, nx, nz) = lattice_grad(sx, sz, l.noise_seed);
            let a = l.roughness * scale;
            let (n, nx, nz) = (n * l.roughness, nx * a, nz * a);
            let (h, g) = if k == 0 {
                (n, (nx, nz))
            } else {
                let s = l.similarity;
                (
                    h_prev * s + n * (1.0 - s),
                    (g_prev.0 * s + nx * (1.0 - s), g_prev.1 * s + nz * (1.0 - s)),
                )
            };
            let top = l.mean_top + h;
            let (top, tg) = if top >= top_prev {
                (top, g)
            } else {
                (top_prev, tg_prev)
            };
            out.push(top);
            grads.push(tg);
            h_prev = h;
            g_prev = g;
            top_prev = top;
            tg_prev = tg;
        }
        if self.ground_anchored {
            let last = out.len().saturating_sub(1);
            for (k, (t, g)) in out.iter_mut().zip(grads.iter_mut()).enumerate() {
                if k == last || *t >= 0.0 {
                    *t = 0.0;
                    *g = (0.0, 0.0);
                }
            }
        }
    }

    /// §4.2.1's material flow of layer `k` at `(x, z)`: the unit vector tangent to the layer's
    /// surface (gradient `grad`) whose horizontal direction turns about the y axis by a 2D noise.
    pub fn layer_flow(&self, k: usize, x: f32, z: f32, grad: (f32, f32)) -> [f32; 3] {
        let scale = self.config.general.scale;
        let (n, _, _) = lattice_grad(x * scale, z * scale, self.layers[k].flow_seed);
        let (sin, cos) = libm::sincosf(n * std::f32::consts::PI);
        let dy = grad.0 * cos + grad.1 * sin;
        let inv = 1.0 / (1.0 + dy * dy).sqrt();
        [cos * inv, dy * inv, sin * inv]
    }

    /// Side of the lattice cells of one element kind, voxels.
    pub fn cell_side(&self, kind: ElementKind) -> f32 {
        let g = &self.config.general;
        match kind {
            ElementKind::Vein => g.vein_area,
            ElementKind::Cave => g.cave_area,
        }
        .ceil()
    }

    /// The element of a lattice cell, if the cell holds one (§4.2.2–4.2.3). Its bounding square
    /// lies inside the cell, so a chunk only looks at the cells its footprint meets.
    pub fn element(&self, kind: ElementKind, cell: (i32, i32)) -> Option<Element> {
        self.element_within(kind, cell, None)
    }

    /// [`Self::element`], or `None` early (before the outline) when the element cannot meet the
    /// box `region = [x0, x1) × [y0, y1) × [z0, z1)` (voxels): a conservative cull by its
    /// bounding square and the host layer's height bounds, so what it keeps is unchanged.
    pub fn element_within(
        &self,
        kind: ElementKind,
        cell: (i32, i32),
        region: Option<[(f32, f32); 3]>,
    ) -> Option<Element> {
        let g = &self.config.general;
        let (purpose, density, area, thick) = match kind {
            ElementKind::Vein => (
                purpose::VEINS,
                g.vein_density,
                g.vein_area,
                g.vein_thickness,
            ),
            ElementKind::Cave => (
                purpose::CAVES,
                g.cave_density,
                g.cave_area,
                g.cave_thickness,
            ),
        };
        let h = hash2(cell.0, cell.1, stream(self.seed, purpose, 0));
        if unit(h) >= density || self.layers.len() < 2 {
            return None;
        }
        let mut d = Draws::new(mix32(h ^ 0x27d4_eb2d));
        // The host: any layer but the top one, so the element lies under the surface.
        let host = ((d.u() * (self.layers.len() - 1) as f32) as usize).min(self.layers.len() - 2);
        let below: Vec<(usize, f32)> = self.layers[host]
            .composition
            .iter()
            .map(|&(id, c)| (self.index(id), c))
            .collect();
        let mats = &self.config.materials;
        let comp = match kind {
            ElementKind::Vein => select(
                &self.affinity,
                &self.config,
                &below,
                &|i| mats[i].flags.vein,
                false,
                &mut d,
            ),
            ElementKind::Cave => select(
                &self.affinity,
                &self.config,
                &below,
                &|i| mats[i].flags.cave,
                true,
                &mut d,
            ),
        };
        if comp.is_empty() {
            return None;
        }
        let side_cell = self.cell_side(kind);
        let base_side = area * (0.5 + 0.5 * d.u());
        let side = (base_side * scalar(&self.config, &comp, |m| m.area)).clamp(1.0, side_cell);
        let origin = (
            cell.0 as f32 * side_cell + d.u() * (side_cell - side),
            cell.1 as f32 * side_cell + d.u() * (side_cell - side),
        );
        let rough = property(&self.config, &comp, |m| m.roughness, &mut d);
        let height = property(&self.config, &comp, |m| m.thickness, &mut d) * thick;
        if let Some([(x0, x1), (y0, y1), (z0, z1)]) = region {
            let (lo, hi) = self.bounds[host];
            if origin.0 + side < x0
                || origin.0 > x1
                || origin.1 + side < z0
                || origin.1 > z1
                || hi + height + 1.0 < y0
                || lo - 1.0 > y1
            {
                return None;
            }
        }
        let outline = outline(rough, &mut d);
        let norm = border_distance(&outline, 0.5, 0.5).max(1e-3);
        Some(Element {
            kind,
            cell,
            host,
            composition: comp.iter().map(|&(i, c)| (mats[i].id, c)).collect(),
            origin,
            side,
            height,
            outline,
            norm,
        })
    }

    /// Affinity `(same layer, next layer)` of two material ids (0 when not listed).
    pub fn affinity(&self, a: u32, b: u32) -> (f32, f32) {
        self.affinity[self.index(a)][self.index(b)]
    }
}

/// `terrain::noise::lattice` (same operations, same bits) with its partial derivatives in
/// lattice units.
pub fn lattice_grad(x: f32, z: f32, seed: u32) -> (f32, f32, f32) {
    let ([v00, v10, v01, v11], tx, tz) = lattice_cell(x, z, seed);
    let u = fade(tx);
    let v = fade(tz);
    let a = v00 + (v10 - v00) * u;
    let b = v01 + (v11 - v01) * u;
    let value = a + (b - a) * v;
    let dfade = |t: f32| 30.0 * t * t * (t * (t - 2.0) + 1.0);
    let dx = ((v10 - v00) + ((v11 - v01) - (v10 - v00)) * v) * dfade(tx);
    let dz = (b - a) * dfade(tz);
    (value, dx, dz)
}

/// §4.2.2's fractal outline in the unit square: a square whose corners move along its diagonals,
/// then, recursively to depth 5, a random point of every segment moved along the line to the
/// centre by at most `d_i = (d_{i−1}/SmoothConstant)/2` (Eq. 5) either way. `d_0 = 0.2·r` and
/// `SmoothConstant = 2 − r` come from the roughness `r`. Points are clamped to the square.
pub fn outline(r: f32, d: &mut Draws) -> Vec<(f32, f32)> {
    let c = 0.5f32;
    let half = 0.3f32;
    let mut dmax = 0.2 * r;
    let smooth = 2.0 - r;
    let clamp = |p: (f32, f32)| (p.0.clamp(0.0, 1.0), p.1.clamp(0.0, 1.0));
    let mut pts: Vec<(f32, f32)> = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .iter()
        .map(|&(sx, sz): &(f32, f32)| {
            let t = (d.u() * 2.0 - 1.0) * dmax * std::f32::consts::FRAC_1_SQRT_2;
            clamp((c + sx * (half + t), c + sz * (half + t)))
        })
        .collect();
    for _ in 0..OUTLINE_DEPTH {
        dmax = dmax / smooth / 2.0;
        let mut next = Vec::with_capacity(pts.len() * 2);
        for i in 0..pts.len() {
            let a = pts[i];
            let b = pts[(i + 1) % pts.len()];
            let t = 0.25 + 0.5 * d.u();
            let p = (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
            let (vx, vz) = (p.0 - c, p.1 - c);
            let len = (vx * vx + vz * vz).sqrt().max(1e-6);
            let disp = (d.u() * 2.0 - 1.0) * dmax;
            next.push(a);
            next.push(clamp((p.0 + vx / len * disp, p.1 + vz / len * disp)));
        }
        pts = next;
    }
    pts
}

/// Distance from `(x, z)` to the nearest segment of a closed polygon.
pub fn border_distance(poly: &[(f32, f32)], x: f32, z: f32) -> f32 {
    let mut best = f32::INFINITY;
    for i in 0..poly.len() {
        let a = poly[i];
        let b = poly[(i + 1) % poly.len()];
        let (ex, ez) = (b.0 - a.0, b.1 - a.1);
        let (px, pz) = (x - a.0, z - a.1);
        let len2 = ex * ex + ez * ez;
        let t = if len2 > 0.0 {
            ((px * ex + pz * ez) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let (dx, dz) = (px - ex * t, pz - ez * t);
        best = best.min(dx * dx + dz * dz);
    }
    best.sqrt()
}

/// Even-odd point-in-polygon test.
pub fn inside(poly: &[(f32, f32)], x: f32, z: f32) -> bool {
    let mut c = false;
    let mut j = poly.len() - 1;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[j]);
        if (a.1 > z) != (b.1 > z) && x < (b.0 - a.0) * (z - a.1) / (b.1 - a.1) + a.0 {
            c = !c;
        }
        j = i;
    }
    c
}

impl Element {
    /// Eq. 6 height of the element at world `(x, z)`, or `None` outside its outline:
    /// `h = √(1 − (d − 1)²)` with `d` the distance to the border normalised to 1 at the centre.
    pub fn height_at(&self, x: f32, z: f32) -> Option<f32> {
        let u = (x - self.origin.0) / self.side;
        let v = (z - self.origin.1) / self.side;
        if !(0.0..=1.0).contains(&u) || !(0.0..=1.0).contains(&v) || !inside(&self.outline, u, v) {
            return None;
        }
        let dn = (border_distance(&self.outline, u, v) / self.norm).min(1.0);
        let h = (1.0 - (dn - 1.0) * (dn - 1.0)).max(0.0).sqrt();
        Some(h * self.height)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::noise::lattice;

    #[test]
    fn lattice_grad_is_the_lattice_and_its_derivative() {
        for i in 0..200 {
            let (x, z) = (i as f32 * 0.137 - 9.0, i as f32 * 0.291 - 20.0);
            let (v, dx, dz) = lattice_grad(x, z, 11);
            assert_eq!(v.to_bits(), lattice(x, z, 11).to_bits());
            let e = 1e-2;
            let fx = (lattice(x + e, z, 11) - lattice(x - e, z, 11)) / (2.0 * e);
            let fz = (lattice(x, z + e, 11) - lattice(x, z - e, 11)) / (2.0 * e);
            assert!(
                (fx - dx).abs() < 2e-2 && (fz - dz).abs() < 2e-2,
                "{dx} {fx} {dz} {fz}"
            );
        }
    }

    #[test]
    fn layer_flow_is_a_unit_tangent() {
        let plan = SubsurfacePlan::new(5, SubsurfaceConfig::preset("B0").expect("preset"));
        let (mut tops, mut grads) = (Vec::new(), Vec::new());
        for i in 0..50 {
            let (x, z) = (i as f32 * 3.3, i as f32 * -1.7);
            plan.tops(x, z, &mut tops, &mut grads);
            for (k, g) in grads.iter().enumerate() {
                let f = plan.layer_flow(k, x, z, *g);
                let norm = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
                assert!((norm - 1.0).abs() < 1e-5);
                // Tangent: perpendicular to the surface normal (−∂x, 1, −∂z).
                let dot = -g.0 * f[0] + f[1] - g.1 * f[2];
                assert!(dot.abs() < 1e-5, "{dot}");
                let (lo, hi) = plan.bounds[k];
                assert!(tops[k] >= lo && tops[k] <= hi, "{lo} {} {hi}", tops[k]);
            }
            assert!(tops.windows(2).all(|w| w[0] <= w[1]));
        }
    }
}
