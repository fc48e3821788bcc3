//! River pieces and the carve: the valley profile every sample is cut to, and the water over it
//! (module docs of [`super`], step 6).

use super::super::super::hash::{hash2, signed_unit};
use super::super::super::noise::lattice;
use super::super::EarthPlan;
use super::network::{LongPiece, Network, Node};
use super::shores::Sill;
use super::{
    channel, kind, RiverPlan, CARVE_MAX_M, FLOODPLAIN, FLOODPLAIN_MIN_M, LOD_FLOOR, MIN_VALLEY_Q,
    PIECE_BLOCK, Q_MAX, REACH, RELIEF_SOURCE_FROM, RELIEF_SOURCE_Q, RELIEF_WALLS_MIN, SMALL_BEND,
    VALLEY_MIN, WALL_NOISE_CLAMP, WALL_NOISE_INV_M,
};
use rustc_hash::FxHashSet as HashSet;

/// One piece of a river's centre line, with the profile of its valley: the cubic
/// `a + t·(b − a) + t·(1 − t)·((1 − t)·sa + t·sb)`, `t ∈ [0, 1]`, whose offset from the chord
/// leaves `a` with slope `sa` and reaches `b` with slope `−sb` (metres per unit `t`), so its
/// tangents at the ends are the river curve's (straight where both are zero, as in every world
/// before `valleys: 3`). The floodplain's half-width and the walls' mean slope are linear in
/// `t` between their values at the ends (equal ends before `valleys: 4`), and so is the walls'
/// spur value (0 before `valleys: 5`). Twenty-two `f32`, the layout of the WGSL twin's storage
/// array.
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
#[repr(C)]
pub struct Piece {
    /// Upstream end, metres.
    pub ax: f32,
    /// Upstream end, metres.
    pub az: f32,
    /// Downstream end, metres.
    pub bx: f32,
    /// Downstream end, metres.
    pub bz: f32,
    /// Water level at the upstream end, metres.
    pub wa: f32,
    /// Water level at the downstream end, metres.
    pub wb: f32,
    /// Channel half-width, metres (0: a dry valley).
    pub half_width: f32,
    /// Channel depth below the water, metres.
    pub depth: f32,
    /// Half-width of the valley, metres: beyond it the piece changes nothing.
    pub valley: f32,
    /// 1 when the channel holds water.
    pub wet: f32,
    /// Reach of the piece, metres: the widest its valley gets, and where it stops changing
    /// anything.
    pub reach: f32,
    /// `1 / (|b − a|² + 10⁻⁶)`, 1/m².
    pub inv_len2: f32,
    /// Half-width of the flat floodplain at the upstream end, metres (`valleys: 2`; 0 in
    /// `valleys: 1` worlds, whose walls rise from the channel's edge): the valley floor is the
    /// water level out to the larger of the floodplain and the channel's half-width.
    pub floodplain: f32,
    /// Slope `sa` of the offset at `a`, metres per unit `t`, normal to the chord (`valleys: 3`;
    /// 0 before).
    pub sax: f32,
    /// Slope `sa`, second component.
    pub saz: f32,
    /// Slope `sb` of the offset at `b` (with the sign that makes the offset `t·(1 − t)·sb` near
    /// `b`), metres per unit `t`, normal to the chord.
    pub sbx: f32,
    /// Slope `sb`, second component.
    pub sbz: f32,
    /// Half-width of the floodplain at the downstream end, metres (`floodplain` before
    /// `valleys: 4`).
    pub floodplain_b: f32,
    /// Mean slope of the walls at the upstream end, rise over run ([`super::WALL_SLOPE`] before
    /// `valleys: 4`).
    pub slope_a: f32,
    /// Mean slope of the walls at the downstream end, rise over run.
    pub slope_b: f32,
    /// The walls' spur value at the upstream end ([`super::SPUR`]; 0 before `valleys: 5`).
    pub spur_a: f32,
    /// The walls' spur value at the downstream end.
    pub spur_b: f32,
}

impl Piece {
    /// Farthest the piece's curve strays from its chord, metres (`max(|sa|, |sb|) / 4`; 0 for a
    /// straight piece): the distances the carve measures ([`foot`]) are at least the chord's
    /// less this.
    pub fn bulge(&self) -> f32 {
        let a = (self.sax * self.sax + self.saz * self.saz).sqrt();
        let b = (self.sbx * self.sbx + self.sbz * self.sbz).sqrt();
        0.25 * a.max(b)
    }
}

/// The rivers and lakes that can touch a rectangle of samples: pieces binned on a grid, and the
/// lake levels of the nodes around it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RiverJob {
    /// Pieces.
    pub pieces: Vec<Piece>,
    /// West edge of the bin grid, metres.
    pub x0: f32,
    /// North edge of the bin grid, metres.
    pub z0: f32,
    /// East edge of the samples' rectangle, metres.
    pub x1: f32,
    /// South edge of the samples' rectangle, metres.
    pub z1: f32,
    /// Bin side, metres.
    pub bin_m: f32,
    /// Bins per row.
    pub bins_w: usize,
    /// Bin rows.
    pub bins_h: usize,
    /// `bins_w · bins_h + 1` offsets into `bin_pieces` (CSR).
    pub bin_start: Vec<u32>,
    /// Piece indices of each bin, in piece order.
    pub bin_pieces: Vec<u32>,
    /// Node spacing, metres.
    pub spacing_m: f32,
    /// First node column of `lakes`.
    pub li0: i64,
    /// First node row of `lakes`.
    pub lk0: i64,
    /// Node columns of `lakes`.
    pub lakes_w: usize,
    /// Lake level of each node of the window (NaN: none), row-major.
    pub lakes: Vec<f32>,
    /// Node height of each lake node of the window (NaN where no lake), as `lakes`: empty
    /// unless [`RiverJob::sink`].
    pub floors: Vec<f32>,
    /// Whether the shores sink the ground inside a lake towards its nodes' heights
    /// (`RiverPlan::sink`, `lakes: 8`).
    pub sink: bool,
    /// `RiverPlan::wall_noise`: amplitude of the walls' width noise, metres (0: none).
    pub wall_noise: f32,
    /// `RiverPlan::wall_seed`.
    pub wall_seed: u32,
    /// Whether the lakes have shaped shores (`lakes: 2`, [`super::shores`]).
    pub shores: bool,
    /// Whether the carve keeps a sill under the land beside a lake (`lakes: 4`,
    /// [`super::shores`] step 5).
    pub sills: bool,
    /// `RiverPlan::shore_seeds`: the shores' two noise octaves and the warp's x and z.
    pub shore_seeds: [u32; 4],
    /// Scale of the shores' warp, metres (`SHORE_WARP` node spacings).
    pub shore_warp_m: f32,
    /// `1 / (SHORE_WARP_WAVE` node spacings`)`, 1/m: the warp's noise is read at `(x, z)·this`.
    pub shore_warp_inv_m: f32,
    /// Scales of the shoreline's two noise octaves' clamped values: [`super::SHORE_N1`] and
    /// [`super::SHORE_N2`], faded by the tile's vertex spacing in `lakes: 7` worlds
    /// ([`RiverPlan::shore_noise`]).
    pub shore_n: [f32; 2],
}

/// The projection of `(x, z)` on piece `p`'s chord, clamped to `[0, 1]`, and the chord `b − a`.
#[inline(always)]
pub(super) fn chord_t(p: &Piece, x: f32, z: f32) -> (f32, f32, f32) {
    let (abx, abz) = (p.bx - p.ax, p.bz - p.az);
    let t = (((x - p.ax) * abx + (z - p.az) * abz) * p.inv_len2).clamp(0.0, 1.0);
    (t, abx, abz)
}

/// The foot of the point `(x, z)` on piece `p`: its parameter `t` in `[0, 1]`, the projection of
/// the point on the chord, and the squared distance to the curve's point at `t`, m². For a
/// straight piece that is the distance to the segment; for a bent one the distance along the
/// chord's normal to the curve (close to the true distance for the gentle bends of a piece),
/// which is at least the distance to the segment less [`Piece::bulge`] and, as the pieces'
/// tangents agree where they meet, joins the next piece's without a crease. With zero slopes
/// the added term is `+0`, so straight pieces give the bits they gave before bends existed.
#[inline(always)]
pub(super) fn foot(p: &Piece, x: f32, z: f32) -> (f32, f32) {
    let (t, abx, abz) = chord_t(p, x, z);
    let (dx, dz) = (
        x - curve_at(p.ax, abx, p.sax, p.sbx, t),
        z - curve_at(p.az, abz, p.saz, p.sbz, t),
    );
    (t, dx * dx + dz * dz)
}

/// One coordinate of a piece's curve at `t`: the chord's `a + t·ab` plus the offset
/// `t(1 − t)²·sa + t²(1 − t)·sb` across it, in this order of operations (the carve's feet and
/// the river lines' points, [`super::lines`], give the same bits).
#[inline(always)]
pub(super) fn curve_at(a: f32, ab: f32, sa: f32, sb: f32, t: f32) -> f32 {
    let k = t * (1.0 - t);
    a + t * ab + (k * (1.0 - t) * sa + k * t * sb)
}

/// The smoothstep from `e0` to `e1` at `x` with its place bent by the spur value `s`
/// ([`super::SPUR`]): `t = clamp((x − e0) / (e1 − e0), 0, 1)`, `t' = t + s·t·(1 − t)`,
/// `t'²·(3 − 2t')`. With `s = 0` the bits of [`smoothstep`].
#[inline(always)]
pub fn spur_step(e0: f32, e1: f32, x: f32, s: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    let t = t + s * (t * (1.0 - t));
    t * t * (3.0 - 2.0 * t)
}

/// Distance from piece `p`'s chord (the segment from `a` to `b`) to the point `(x, z)`, metres.
fn point_distance(p: &Piece, x: f32, z: f32) -> f32 {
    let (t, abx, abz) = chord_t(p, x, z);
    let (dx, dz) = (x - (p.ax + t * abx), z - (p.az + t * abz));
    (dx * dx + dz * dz).sqrt()
}

/// A lower bound of the distance from piece `p`'s chord to the rectangle `[x0, x1] × [z0, z1]`:
/// the distance between their bounding boxes.
fn rect_distance(p: &Piece, x0: f32, z0: f32, x1: f32, z1: f32) -> f32 {
    let dx = (x0 - p.ax.max(p.bx)).max(p.ax.min(p.bx) - x1).max(0.0);
    let dz = (z0 - p.az.max(p.bz)).max(p.az.min(p.bz) - z1).max(0.0);
    (dx * dx + dz * dz).sqrt()
}

/// Derivative by `t` of [`catmull_rom`] at `t`.
fn catmull_rom_tangent(p: [(f32, f32); 4], t: f32) -> (f32, f32) {
    let f = |a: f32, b: f32, c: f32, d: f32| {
        0.5 * ((c - a)
            + 2.0 * (2.0 * a - 5.0 * b + 4.0 * c - d) * t
            + 3.0 * (3.0 * b - a - 3.0 * c + d) * t * t)
    };
    (
        f(p[0].0, p[1].0, p[2].0, p[3].0),
        f(p[0].1, p[1].1, p[2].1, p[3].1),
    )
}

/// Catmull–Rom point of the uniform spline through `p0..p3` at `t`.
fn catmull_rom(p: [(f32, f32); 4], t: f32) -> (f32, f32) {
    let (t2, t3) = (t * t, t * t * t);
    let f = |a: f32, b: f32, c: f32, d: f32| {
        0.5 * (2.0 * b
            + (c - a) * t
            + (2.0 * a - 5.0 * b + 4.0 * c - d) * t2
            + (3.0 * b - a - 3.0 * c + d) * t3)
    };
    (
        f(p[0].0, p[1].0, p[2].0, p[3].0),
        f(p[0].1, p[1].1, p[2].1, p[3].1),
    )
}

/// One river edge of the network: from a node to its downstream neighbour.
#[derive(Clone, Debug, PartialEq)]
pub struct Edge {
    /// The upstream node.
    pub from: Node,
    /// The downstream node.
    pub to: Node,
    /// The centre line, `RiverPlan::pieces + 1` points (x, z, water level), metres.
    pub points: Vec<[f32; 3]>,
    /// The offset slopes `[sa, sb]` of each piece between consecutive points, metres per unit
    /// `t` ([`Piece::sax`]): zero before `valleys: 3`, whose pieces are straight.
    pub bends: Vec<[f32; 4]>,
}

impl Network<'_> {
    /// The edge out of node `(i, k)`, if it drains somewhere.
    pub fn edge(&mut self, i: i64, k: i64) -> Option<Edge> {
        let from = self.node(i, k);
        let (pi, pk) = from.down?;
        let to = self.node(pi, pk);
        let main = self.main_upstream(i, k).map(|u| (self.q(u.0, u.1), u));
        // The fine network of `lakes: 6`, both of `lakes: 7`: a spilling lake's edge starts at
        // its saddle
        // (`Network::saddle`), and the curves before and after it read that point instead of
        // the pit.
        let saddle = self.saddle(i, k);
        let p1 = saddle.map_or((from.x, from.z), |(a, b)| self.plan.position(a, b));
        let p2 = (to.x, to.z);
        let p0 = match main {
            Some((_, (a, b))) if saddle.is_none() => self.edge_start(a, b),
            _ => (2.0 * p1.0 - p2.0, 2.0 * p1.1 - p2.1),
        };
        let p3 = match to.down {
            Some((a, b)) if self.saddle(pi, pk).is_none() => self.plan.position(a, b),
            _ => (2.0 * p2.0 - p1.0, 2.0 * p2.1 - p1.1),
        };
        // A valley begins at a node no carved edge enters: its water starts at the node's
        // height, so the valley fades in instead of starting as a step.
        let source = main.is_none_or(|(mq, _)| mq < MIN_VALLEY_Q);
        let w0 = if source { from.h.max(from.w) } else { from.w };
        // A hashed bend across the edge, largest at its middle and nil at the nodes, so valleys
        // wander off the lattice's directions between confluences.
        let (ex, ez) = (p2.0 - p1.0, p2.1 - p1.1);
        // `valleys: 8`: a smaller river bends less (`SMALL_BEND`).
        let share = if self.plan.sized_valleys {
            SMALL_BEND + (1.0 - SMALL_BEND) * self.plan.size_of(from.q)
        } else {
            1.0
        };
        let bend = share
            * self.plan.meander
            * signed_unit(hash2(i as i32, k as i32, self.plan.seed ^ 0x7c15_9e3d));
        let pieces = self.plan.pieces;
        // `valleys: 3` bends with `16·t²·(1 − t)²`, flat at the nodes, so the centre line keeps
        // the Catmull–Rom curve's tangent there instead of turning a corner at every node.
        let smooth_bend = self.plan.valleys >= 3;
        let curve = |t: f32| {
            let (cx, cz) = catmull_rom([p0, p1, p2, p3], t);
            // Before `valleys: 3` the bend is `bend·4·t·(1 − t)`, evaluated in that order.
            let b = if smooth_bend {
                let u = 4.0 * t * (1.0 - t);
                bend * u * u
            } else {
                bend * 4.0 * t * (1.0 - t)
            };
            (cx - ez * b, cz + ex * b)
        };
        // The direction of `curve` at `t` (`valleys: 3` only).
        let tangent = |t: f32| {
            let (cx, cz) = catmull_rom_tangent([p0, p1, p2, p3], t);
            let u = 4.0 * t * (1.0 - t);
            let db = bend * 8.0 * u * (1.0 - 2.0 * t);
            (cx - ez * db, cz + ex * db)
        };
        let points: Vec<[f32; 3]> = (0..=pieces)
            .map(|j| {
                let t = j as f32 / pieces as f32;
                let (x, z) = if j == 0 {
                    p1
                } else if j == pieces {
                    p2
                } else {
                    curve(t)
                };
                [x, z, w0 + (to.w - w0) * t]
            })
            .collect();
        // `valleys: 3`: each piece's offset from its chord leaves and reaches its ends along
        // the curve's tangents there (at most 45° off the chord), so consecutive pieces meet
        // without a corner. The offset is across the chord only: then the foot of a point of
        // the piece on its chord is the piece's own parameter, and the carve's distance
        // ([`foot`]) is nil along the whole centre line.
        let bends = (0..pieces)
            .map(|j| {
                if self.plan.valleys < 3 {
                    return [0.0; 4];
                }
                let (a, b) = (points[j], points[j + 1]);
                let (abx, abz) = (b[0] - a[0], b[1] - a[1]);
                let len = (abx * abx + abz * abz).sqrt();
                if len < 1e-3 {
                    return [0.0; 4];
                }
                let (ux, uz) = (abx / len, abz / len);
                let (nx, nz) = (-uz, ux);
                // Metres across the chord per unit `t` of a curve heading along `(tx, tz)`.
                let slope = |(tx, tz): (f32, f32)| {
                    let (along, across) = (tx * ux + tz * uz, tx * nx + tz * nz);
                    if along <= 0.0 {
                        len * across.signum()
                    } else {
                        len * (across / along).clamp(-1.0, 1.0)
                    }
                };
                let sa = slope(tangent(j as f32 / pieces as f32));
                let sb = -slope(tangent((j + 1) as f32 / pieces as f32));
                [sa * nx, sa * nz, sb * nx, sb * nz]
            })
            .collect();
        Some(Edge {
            from,
            to,
            points,
            bends,
        })
    }

    /// Whether the edge out of node `(i, k)`, of discharge `q`, carves a valley: `q` at least
    /// [`MIN_VALLEY_Q`], and with `valleys: 7` at least `1 + RELIEF_SOURCE_Q · a²`, `a` the
    /// relief above [`RELIEF_SOURCE_FROM`] ([`RELIEF_SOURCE_Q`]), or out of or into a lake.
    pub(super) fn carves(&mut self, i: i64, k: i64, q: u32) -> bool {
        if q < MIN_VALLEY_Q {
            return false;
        }
        if !self.plan.relief_sources {
            return true;
        }
        let r = self.relief(i, k) * self.earth.inv_relief_max;
        let above = ((r - RELIEF_SOURCE_FROM) / (1.0 - RELIEF_SOURCE_FROM)).max(0.0);
        if q as f32 >= 1.0 + RELIEF_SOURCE_Q * above * above {
            return true;
        }
        // The edges out of and into a lake carve whatever their discharge: a lake among
        // uncarved mountains met them along the edge of its shores' reach, as a wall up to
        // `SHORE_MAX_M` high a node spacing from its water.
        self.lake(i, k).is_some()
            || self
                .down(i, k)
                .is_some_and(|(a, b)| self.lake(a, b).is_some())
    }

    /// The pieces of the edges out of the nodes of piece block `b` ([`PIECE_BLOCK`] nodes a
    /// side), in node order (rows, then columns) and along each edge.
    pub(super) fn block_pieces(&mut self, (bx, bz): (i64, i64)) -> Vec<Piece> {
        let mut pieces = Vec::new();
        for k in bz * PIECE_BLOCK..(bz + 1) * PIECE_BLOCK {
            for i in bx * PIECE_BLOCK..(bx + 1) * PIECE_BLOCK {
                self.node_pieces(i, k, &mut pieces);
            }
        }
        pieces
    }

    /// Appends the pieces of the edge out of node `(i, k)` to `pieces`, along the edge (none
    /// when the edge carves nothing).
    fn node_pieces(&mut self, i: i64, k: i64, pieces: &mut Vec<Piece>) {
        let s = self.plan.spacing_m;
        let q = self.q(i, k);
        if !self.carves(i, k, q) {
            return;
        }
        let Some(edge) = self.edge(i, k) else {
            return;
        };
        if edge.from.sea {
            return;
        }
        let wet = q >= self.plan.wet_q;
        let (hw, depth) = if wet {
            channel(q * self.plan.q_scale)
        } else {
            (0.0, 0.0)
        };
        // Valleys widen with the discharge, from VALLEY_MIN to the reach, and may widen
        // further where they are deep: up to three times that in plains, more where the
        // relief is high (at most the reach).
        let grow = libm::log2f(q as f32) / libm::log2f(Q_MAX as f32);
        let max_reach = REACH * s;
        let valley = VALLEY_MIN + (max_reach - VALLEY_MIN) * grow;
        let relief = self.relief(i, k) * self.earth.inv_relief_max;
        let reach = (3.0 * valley * (1.0 + 3.0 * relief)).min(max_reach);
        // `valleys: 2`: a flat floodplain, then walls as wide as the height they climb
        // (`profile`); the land beyond keeps its own shape.
        let (floodplain, valley) = if self.plan.valleys >= 2 {
            // `valleys: 8`: the smallest floodplains are narrower (`RiverPlan::size_of`).
            let f = (FLOODPLAIN * hw + FLOODPLAIN_MIN_M * self.plan.size_of(q)).min(0.5 * reach);
            (f, 2.0 * f)
        } else {
            (0.0, valley)
        };
        // `valleys: 4`: the floodplain's width and the walls' slope at a point of the
        // centre line, scaled by value noise (one value at a point shared by the pieces
        // that meet there, so they agree).
        // `valleys: 6`: gentler walls where the relief is lower (one factor an edge).
        let walls = self.plan.relief_walls.then(|| {
            (RELIEF_WALLS_MIN + (1.0 - RELIEF_WALLS_MIN) * relief.max(0.0).sqrt()).min(1.0)
        });
        let shape = |x: f32, z: f32| {
            let (f, slope) = self.plan.valley_shape(x, z, floodplain);
            (f, walls.map_or(slope, |w| slope * w))
        };
        for (p, bend) in edge.points.windows(2).zip(&edge.bends) {
            let (abx, abz) = (p[1][0] - p[0][0], p[1][1] - p[0][1]);
            let (fa, sa) = shape(p[0][0], p[0][1]);
            let (fb, sb) = shape(p[1][0], p[1][1]);
            pieces.push(Piece {
                ax: p[0][0],
                az: p[0][1],
                bx: p[1][0],
                bz: p[1][1],
                wa: p[0][2],
                wb: p[1][2],
                half_width: hw,
                depth,
                valley,
                wet: if wet { 1.0 } else { 0.0 },
                reach,
                inv_len2: 1.0 / (abx * abx + abz * abz + PIECE_LEN2_EPS),
                sax: bend[0],
                saz: bend[1],
                sbx: bend[2],
                sbz: bend[3],
                floodplain: fa,
                floodplain_b: fb,
                slope_a: sa,
                slope_b: sb,
                spur_a: self.plan.spur_at(p[0][0], p[0][1]),
                spur_b: self.plan.spur_at(p[1][0], p[1][1]),
            });
        }
    }

    /// The pieces of the long edges that can reach piece block `(bx, bz)` (the nodes' cells
    /// `bx·PIECE_BLOCK..` × `bz·PIECE_BLOCK..`), with their pits and indices along the edge: a
    /// breached pit or a spilling lake drains to its outlet, up to the flood's radius (plus
    /// one) away, and its edge runs over the nodes between, farther from its pit's block than
    /// the blocks a job reads for the edges between lattice neighbours (plans with
    /// [`RiverPlan::long_edges`]; [`Network::long_pieces`] caches them).
    pub(super) fn block_long_pieces(&mut self, (bx, bz): (i64, i64)) -> Vec<LongPiece> {
        let s = self.plan.spacing_m;
        let side = PIECE_BLOCK as f32 * s;
        let (x0, z0) = (bx as f32 * side, bz as f32 * side);
        let (x1, z1) = (x0 + side, z0 + side);
        // An edge's curve stays within a spacing or two of the segment between its nodes.
        let margin = self.plan.lake_radius + 1 + REACH.ceil() as i64 + 3;
        let is = bx * PIECE_BLOCK - margin..(bx + 1) * PIECE_BLOCK + margin;
        let ks = bz * PIECE_BLOCK - margin..(bz + 1) * PIECE_BLOCK + margin;
        let mut out = Vec::new();
        for (i, k) in self.sinks(is, ks) {
            let Some((di, dk)) = self.down(i, k) else {
                continue;
            };
            if (di - i).abs() <= 1 && (dk - k).abs() <= 1 {
                continue;
            }
            let mut pieces = Vec::new();
            self.node_pieces(i, k, &mut pieces);
            for (j, p) in pieces.into_iter().enumerate() {
                let reach = p.reach.max(p.half_width + 1.0);
                if rect_distance(&p, x0, z0, x1, z1) < reach + p.bulge() {
                    out.push(((i, k), j as u32, p));
                }
            }
        }
        out
    }

    /// The rivers and lakes that can touch samples in `[x0, x1] × [z0, z1]` (metres), binned on
    /// a grid of `bin_m` squares.
    pub fn job(&mut self, x0: f32, z0: f32, x1: f32, z1: f32, bin_m: f32) -> RiverJob {
        self.job_within(x0, z0, x1, z1, bin_m, |p| p.reach)
    }

    /// The wet channels that can hold samples of `[x0, x1] × [z0, z1]` (metres), and the lakes:
    /// the job of [`water_at`], whose river level reads only the pieces within a channel
    /// half-width of a sample. `water_at` gives the same answer for it as for [`Network::job`]'s,
    /// bit for bit (a margin of 1 m keeps rounding on the side of keeping a piece), and most
    /// tiles have no such piece at all.
    pub fn water_job(&mut self, x0: f32, z0: f32, x1: f32, z1: f32, bin_m: f32) -> RiverJob {
        self.job_within(x0, z0, x1, z1, bin_m, |p| {
            if p.wet > 0.0 {
                p.half_width + 1.0
            } else {
                0.0
            }
        })
    }

    /// The job of the lakes alone over a rectangle (no river pieces): what tiles too coarse to
    /// carve read to show the lakes over their uncarved heights (`lakes: 5`), and the lake
    /// window and settings every job starts from.
    pub fn lake_job(&mut self, x0: f32, z0: f32, x1: f32, z1: f32) -> RiverJob {
        let (li0, lk0, lakes_w, lakes, floors) = self.lake_window(x0, z0, x1, z1);
        let s = self.plan.spacing_m;
        RiverJob {
            x0,
            z0,
            x1,
            z1,
            bin_m: (x1 - x0).max(z1 - z0).max(s),
            spacing_m: s,
            li0,
            lk0,
            lakes_w,
            lakes,
            floors,
            sink: self.plan.sink,
            wall_noise: self.plan.wall_noise,
            wall_seed: self.plan.wall_seed,
            shores: self.plan.lakes >= 2,
            sills: self.plan.lakes >= 4,
            shore_seeds: self.plan.shore_seeds,
            shore_warp_m: super::SHORE_WARP * s,
            shore_warp_inv_m: 1.0 / (super::SHORE_WARP_WAVE * s),
            shore_n: [super::SHORE_N1, super::SHORE_N2],
            ..RiverJob::default()
        }
    }

    /// The lake levels of the nodes a sample of the rectangle can read (the four around it,
    /// after the shores' warp): the window's first node column and row, its width and the
    /// levels (NaN where no lake), empty when no lake is readable; then the lake nodes' heights
    /// in the same layout where the plan sinks the ground inside lakes, else empty.
    fn lake_window(&mut self, x0: f32, z0: f32, x1: f32, z1: f32) -> LakeWindow {
        let s = self.plan.spacing_m;
        // Lake levels of the nodes around the rectangle (a vertex reads the four around it).
        let li0 = ((x0 / s) - 0.5).floor() as i64 - 1;
        let li1 = ((x1 / s) - 0.5).floor() as i64 + 2;
        let lk0 = ((z0 / s) - 0.5).floor() as i64 - 1;
        let lk1 = ((z1 / s) - 0.5).floor() as i64 + 2;
        let lakes_w = (li1 - li0 + 1) as usize;
        let mut lakes = Vec::with_capacity(lakes_w * (lk1 - lk0 + 1) as usize);
        let mut floors = Vec::new();
        for k in lk0..=lk1 {
            for i in li0..=li1 {
                let lake = self.lake(i, k);
                lakes.push(lake.unwrap_or(f32::NAN));
                if self.plan.sink {
                    floors.push(lake.map_or(f32::NAN, |_| self.height(i, k)));
                }
            }
        }
        // No lake that a sample of the rectangle can read (the four nodes around it, after the
        // shores' warp of less than half a spacing): an empty window, so `lake_level` and
        // `lake_field` answer at once.
        let reach = |i: i64, k: i64| {
            let (ri0, ri1) = ((x0 / s - 1.0).floor() as i64, (x1 / s).floor() as i64 + 1);
            let (rk0, rk1) = ((z0 / s - 1.0).floor() as i64, (z1 / s).floor() as i64 + 1);
            (ri0..=ri1).contains(&i) && (rk0..=rk1).contains(&k)
        };
        let readable = (lk0..=lk1)
            .flat_map(|k| (li0..=li1).map(move |i| (i, k)))
            .zip(&lakes)
            .any(|((i, k), l)| !l.is_nan() && reach(i, k));
        if !readable {
            lakes.clear();
            floors.clear();
        }
        (li0, lk0, lakes_w, lakes, floors)
    }

    /// The job of the pieces that come within `reach_of(piece)` metres of the rectangle, each in
    /// the bins whose centre is within that plus half a bin's diagonal.
    fn job_within(
        &mut self,
        x0: f32,
        z0: f32,
        x1: f32,
        z1: f32,
        bin_m: f32,
        reach_of: impl Fn(&Piece) -> f32,
    ) -> RiverJob {
        let s = self.plan.spacing_m;
        // Nodes whose edges can come within reach: the curve stays within a spacing of its
        // nodes' cells (jitter and Catmull–Rom overshoot are both below half a spacing).
        let margin = REACH * s + 2.0 * s;
        let block = |v: f32| ((v / s).floor() as i64).div_euclid(PIECE_BLOCK);
        let (bx0, bx1) = (block(x0 - margin), block(x1 + margin));
        let (bz0, bz1) = (block(z0 - margin), block(z1 + margin));
        let mut pieces: Vec<Piece> = Vec::new();
        for bz in bz0..=bz1 {
            for bx in bx0..=bx1 {
                let cached = self.pieces((bx, bz));
                pieces.extend(cached.iter().filter(|p| {
                    // A piece that reaches nowhere (a dry one, for the water job) stays
                    // out however far it bends.
                    let reach = reach_of(p);
                    reach > 0.0 && rect_distance(p, x0, z0, x1, z1) < reach + p.bulge()
                }));
            }
        }
        if self.plan.long_edges {
            // The long edges of pits beyond the blocks read (those of pits inside them are
            // among the blocks' pieces), each piece once.
            let mut seen = HashSet::default();
            for bz in bz0..=bz1 {
                for bx in bx0..=bx1 {
                    for (pit, j, p) in self.long_pieces((bx, bz)).iter() {
                        let (pb, pk) =
                            (pit.0.div_euclid(PIECE_BLOCK), pit.1.div_euclid(PIECE_BLOCK));
                        if (bx0..=bx1).contains(&pb) && (bz0..=bz1).contains(&pk) {
                            continue;
                        }
                        let reach = reach_of(p);
                        if reach > 0.0
                            && rect_distance(p, x0, z0, x1, z1) < reach + p.bulge()
                            && seen.insert((*pit, *j))
                        {
                            pieces.push(*p);
                        }
                    }
                }
            }
        }
        // A piece goes into every bin it can reach: the distance from the piece to the bin's
        // centre is below its reach plus half the bin's diagonal.
        let bins_w = (((x1 - x0) / bin_m).floor() as usize) + 1;
        let bins_h = (((z1 - z0) / bin_m).floor() as usize) + 1;
        let half_diag = bin_m * std::f32::consts::FRAC_1_SQRT_2;
        // (bin, piece) pairs in piece order, then sorted by bin with a stable counting sort.
        let mut pairs: Vec<(u32, u32)> = Vec::new();
        for (pi, p) in pieces.iter().enumerate() {
            // A bent piece reaches as far beyond its chord's reach as it strays from the chord.
            let reach = reach_of(p) + p.bulge();
            let bx0 = ((p.ax.min(p.bx) - reach - x0) / bin_m).floor();
            let bx1 = ((p.ax.max(p.bx) + reach - x0) / bin_m).floor();
            let bz0 = ((p.az.min(p.bz) - reach - z0) / bin_m).floor();
            let bz1 = ((p.az.max(p.bz) + reach - z0) / bin_m).floor();
            if bx1 < 0.0 || bz1 < 0.0 || bx0 >= bins_w as f32 || bz0 >= bins_h as f32 {
                continue;
            }
            for bz in bz0.max(0.0) as usize..=(bz1 as usize).min(bins_h - 1) {
                for bx in bx0.max(0.0) as usize..=(bx1 as usize).min(bins_w - 1) {
                    let cx = x0 + (bx as f32 + 0.5) * bin_m;
                    let cz = z0 + (bz as f32 + 0.5) * bin_m;
                    if point_distance(p, cx, cz) < reach + half_diag {
                        pairs.push(((bz * bins_w + bx) as u32, pi as u32));
                    }
                }
            }
        }
        let mut bin_start = vec![0u32; bins_w * bins_h + 1];
        for &(b, _) in &pairs {
            bin_start[b as usize + 1] += 1;
        }
        for b in 0..bins_w * bins_h {
            bin_start[b + 1] += bin_start[b];
        }
        let mut fill = bin_start.clone();
        let mut bin_pieces = vec![0u32; pairs.len()];
        for &(b, pi) in &pairs {
            bin_pieces[fill[b as usize] as usize] = pi;
            fill[b as usize] += 1;
        }
        RiverJob {
            pieces,
            bin_m,
            bins_w,
            bins_h,
            bin_start,
            bin_pieces,
            ..self.lake_job(x0, z0, x1, z1)
        }
    }
}

/// A lake window ([`Network::lake_window`]): first node column and row, node columns, the
/// levels and the lake nodes' heights.
type LakeWindow = (i64, i64, usize, Vec<f32>, Vec<f32>);

/// Margin of [`RiverJob::carve_pruned`]'s test that a piece cannot lower a sample further, metres:
/// far above the rounding of a water level interpolated between a piece's ends (below a
/// millimetre at the heights a world reaches).
pub(super) const SKIP_MARGIN_M: f32 = 0.01;

/// Added to a piece's squared length before the division that projects a sample onto it, so a
/// piece of zero length divides by a positive number (the WGSL twin reads it from its preamble).
pub const PIECE_LEN2_EPS: f32 = 1e-6;

#[inline(always)]
pub(super) fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Piece `p` applied to a sample at `(x, z)` of height `h`: the height lowered towards the
/// valley (at most `h`) and, when the sample lies in a wet channel, the water level there.
///
/// With `W` the water level, `b` the channel half-width, `F = max(b, floodplain)`, `V` the
/// valley half-width and `d` the distance to the piece: above `W` the height keeps its excess
/// scaled by `g = smoothstep(F, V', d)`, so the valley keeps the terrain's detail and its floor
/// is flat at `W` out to `F`; `V' = clamp(F + (h − W) / k, V, R)` widens the valley where it is
/// deep, so its walls average no more than `k` (`R` is the piece's reach). The floodplain and
/// the slope `k` are linear in `t` between the piece's ends ([`Piece::floodplain`],
/// [`Piece::floodplain_b`], [`Piece::slope_a`], [`Piece::slope_b`]; `k` is [`super::WALL_SLOPE`]
/// before `valleys: 4`); neither depends on `h`, so the slope of the result in `h` stays in
/// [−¼, 1] (the smoothstep's `g − u·g'` is at least −¼; with a spur `s`, `valleys: 5`, the
/// bent place `u' = u + s·u·(1 − u)` gives `g(u') − u·g'(u')·(1 + s·(1 − 2u))`, which stays
/// above −1 for `|s| < 1`). In `valleys: 1` worlds the floodplain is 0, so `F = b`. Below
/// `W` nothing changes. Inside the channel the ground is cut to the parabola
/// `W − c·(1 − (d/b)²)`. Beyond `V'` the height is `h`, bit for bit.
#[inline(always)]
pub fn profile(p: &Piece, x: f32, z: f32, h: f32) -> (f32, Option<f32>) {
    let (t, d2) = foot(p, x, z);
    profile_at_foot(p, t, d2, h, 0.0, Sill::NONE)
}

/// [`profile`] given the sample's foot on the piece ([`foot`]), the walls' added width at
/// the sample ([`RiverJob::wall_width`], metres; 0 where the world has no wall noise, which
/// leaves every bit as it was) and the lake sill there ([`RiverJob::shore_sill`]; outside the
/// channel the valley is cut no lower than the sill, and [`Sill::NONE`] leaves every bit as it
/// was). The walls' spur value is linear along the piece between [`Piece::spur_a`] and
/// [`Piece::spur_b`] (0 at both ends leaves every bit as it was).
#[inline(always)]
fn profile_at_foot(
    p: &Piece,
    t: f32,
    d2: f32,
    h: f32,
    wall: f32,
    sill: Sill,
) -> (f32, Option<f32>) {
    if d2 >= p.reach * p.reach {
        return (h, None);
    }
    let d = d2.sqrt();
    let w = p.wa + (p.wb - p.wa) * t;
    let mut c = h;
    if h > w {
        let floor = p
            .half_width
            .max(p.floodplain + (p.floodplain_b - p.floodplain) * t);
        let slope = p.slope_a + (p.slope_b - p.slope_a) * t;
        let v = (floor + (h - w) / slope + wall).clamp(p.valley, p.reach);
        if d < v {
            let spur = p.spur_a + (p.spur_b - p.spur_a) * t;
            let g = spur_step(floor, v, d, spur);
            c = w + (h - w) * g;
        }
    }
    let mut water = None;
    if d < p.half_width {
        let r = d / p.half_width;
        c = c.min(w - p.depth * (1.0 - r * r));
        if p.wet > 0.0 {
            water = Some(w);
        }
    } else if sill.s > 0.0 {
        c = c + (c.max(h.min(sill.level)) - c) * sill.s;
    }
    (c, water)
}

/// The pieces of each bin of a [`RiverJob`] that can change its samples, each with the squared
/// distance beyond which it changes none of them ([`RiverJob::pruned`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PrunedBins {
    /// `bins + 1` offsets into `entries` (CSR).
    pub start: Vec<u32>,
    /// Piece index and squared radius, m², of each bin's pieces, in piece order.
    pub entries: Vec<(u32, f32)>,
}

impl RiverJob {
    /// The bin of a sample at `(x, z)`, if it lies on the grid.
    pub(super) fn bin_index(&self, x: f32, z: f32) -> Option<usize> {
        if self.bin_start.is_empty() {
            return None;
        }
        let bx = ((x - self.x0) / self.bin_m).floor();
        let bz = ((z - self.z0) / self.bin_m).floor();
        // Written so that NaN lands outside too.
        let inside = |b: f32, n: usize| b >= 0.0 && b < n as f32;
        if !(inside(bx, self.bins_w) && inside(bz, self.bins_h)) {
            return None;
        }
        Some(bz as usize * self.bins_w + bx as usize)
    }

    fn bin(&self, x: f32, z: f32) -> &[u32] {
        match self.bin_index(x, z) {
            Some(b) => &self.bin_pieces[self.bin_start[b] as usize..self.bin_start[b + 1] as usize],
            None => &[],
        }
    }

    fn pieces_at(&self, x: f32, z: f32) -> impl Iterator<Item = &Piece> {
        self.bin(x, z).iter().map(|&i| &self.pieces[i as usize])
    }

    /// The width added to the walls at `(x, z)`, metres: `wall_noise·(n + WALL_NOISE_CLAMP)`,
    /// `n` the value noise of [`super::WALL_NOISE_M`] clamped to ±[`super::WALL_NOISE_CLAMP`],
    /// so at least 0; exactly 0 in worlds without wall noise.
    #[inline(always)]
    pub fn wall_width(&self, x: f32, z: f32) -> f32 {
        if self.wall_noise == 0.0 {
            return 0.0;
        }
        let n = lattice(x * WALL_NOISE_INV_M, z * WALL_NOISE_INV_M, self.wall_seed);
        self.wall_noise * (n.clamp(-WALL_NOISE_CLAMP, WALL_NOISE_CLAMP) + WALL_NOISE_CLAMP)
    }

    /// The largest [`RiverJob::wall_width`] anywhere, metres (0 without wall noise).
    fn wall_width_max(&self) -> f32 {
        self.wall_noise * (2.0 * WALL_NOISE_CLAMP)
    }

    /// The carved height of a sample at `(x, z)` with height `h`: the lowest of the pieces'
    /// carves ([`profile`], with the walls' added width there) of the height shaped by the lake
    /// shores ([`RiverJob::shore`]), removing at most [`CARVE_MAX_M`] of that.
    pub fn carve_one(&self, x: f32, z: f32, h: f32) -> f32 {
        let (h, sill) = self.shore_sill(x, z, h);
        let wall = self.wall_width(x, z);
        let mut c = h;
        for p in self.pieces_at(x, z) {
            let (t, d2) = foot(p, x, z);
            c = c.min(profile_at_foot(p, t, d2, h, wall, sill).0);
        }
        c.max(h - CARVE_MAX_M)
    }

    /// The river level over a sample at `(x, z)` whose carved height is `carved`, if it lies in
    /// a wet channel below the water (the highest such level).
    pub fn river_level(&self, x: f32, z: f32, carved: f32) -> Option<f32> {
        let mut best: Option<f32> = None;
        for p in self.pieces_at(x, z).filter(|p| p.wet > 0.0) {
            let (t, d2) = foot(p, x, z);
            if d2 < p.half_width * p.half_width {
                let w = p.wa + (p.wb - p.wa) * t;
                if carved < w {
                    best = Some(best.map_or(w, |o| o.max(w)));
                }
            }
        }
        best
    }

    /// The pieces of each bin that can change its samples, given the samples' heights
    /// `(x, z, h)`: a piece reaches no farther than its valley widened for the bin's highest
    /// sample (`profile`'s `V'`, with a margin for rounding) or its channel, and that distance
    /// is kept with it. [`RiverJob::carve_pruned`] then gives every sample the carve of
    /// [`RiverJob::carve_one`], bit for bit: a piece left out, or farther from a sample than its
    /// radius, would have returned the height unchanged, and the lowest of the rest does not
    /// depend on their order. In mountains a bin's highest sample is far below the tile's, so
    /// this keeps a few pieces of the many within reach. The heights are taken as the lake
    /// shores shape them ([`RiverJob::shore`]), as the carve reads them.
    pub fn pruned(&self, samples: impl Iterator<Item = (f32, f32, f32)>) -> PrunedBins {
        let bins = self.bin_start.len().saturating_sub(1);
        let mut h_max = vec![f32::NEG_INFINITY; bins];
        for (x, z, h) in samples {
            if let Some(b) = self.bin_index(x, z) {
                h_max[b] = h_max[b].max(self.shore(x, z, h));
            }
        }
        self.pruned_for(&h_max)
    }

    /// [`RiverJob::pruned`] given each bin's highest sample, `h_max[b]` (−∞: no sample).
    pub(super) fn pruned_for(&self, h_max: &[f32]) -> PrunedBins {
        let bins = h_max.len();
        let mut start = Vec::with_capacity(bins + 1);
        let mut entries = Vec::new();
        let wall_max = self.wall_width_max();
        for (b, &top) in h_max.iter().enumerate() {
            start.push(entries.len() as u32);
            if top == f32::NEG_INFINITY {
                continue;
            }
            let (bx, bz) = ((b % self.bins_w) as f32, (b / self.bins_w) as f32);
            let rx0 = self.x0 + bx * self.bin_m;
            let rz0 = self.z0 + bz * self.bin_m;
            let (rx1, rz1) = (rx0 + self.bin_m, rz0 + self.bin_m);
            let range = self.bin_start[b] as usize..self.bin_start[b + 1] as usize;
            for &i in &self.bin_pieces[range] {
                let p = &self.pieces[i as usize];
                let w_min = p.wa.min(p.wb);
                let v = if top > w_min {
                    let floor = p.half_width.max(p.floodplain.max(p.floodplain_b));
                    let slope = p.slope_a.min(p.slope_b);
                    (floor + (top - w_min) / slope + wall_max).clamp(p.valley, p.reach)
                } else {
                    p.half_width
                };
                let r = v.max(p.half_width) * 1.001 + 1.0;
                if rect_distance(p, rx0, rz0, rx1, rz1) < r + p.bulge() {
                    entries.push((i, r * r));
                }
            }
        }
        start.push(entries.len() as u32);
        PrunedBins { start, entries }
    }

    /// [`RiverJob::carve_one`] through the pruned bins of [`RiverJob::pruned`] (the same bits
    /// for every sample whose height is at most its bin's highest).
    pub fn carve_pruned(&self, pruned: &PrunedBins, x: f32, z: f32, h: f32) -> f32 {
        let (h, sill) = self.shore_sill(x, z, h);
        let Some(b) = self.bin_index(x, z) else {
            return h.max(h - CARVE_MAX_M);
        };
        let mut c = h;
        let range = pruned.start[b] as usize..pruned.start[b + 1] as usize;
        let wall = if range.is_empty() {
            0.0
        } else {
            self.wall_width(x, z)
        };
        for &(i, r2) in &pruned.entries[range] {
            let p = &self.pieces[i as usize];
            let (t, d2) = foot(p, x, z);
            // Outside its channel a piece lowers a sample to its water level at most, which is
            // no lower than its ends' lower level (less a centimetre for rounding): a sample
            // already carved below that keeps its height, as `min` would keep it. The channel
            // test is widened by a thousandth, so rounding in `profile`'s own test (on the
            // distance, not its square) never finds a sample in the channel that this does not.
            let in_channel = d2 <= p.half_width * p.half_width * 1.001;
            if d2 < r2 && (in_channel || c > p.wa.min(p.wb) - SKIP_MARGIN_M) {
                c = c.min(profile_at_foot(p, t, d2, h, wall, sill).0);
            }
        }
        c.max(h - CARVE_MAX_M)
    }

    /// Lake level over `(x, z)`: the highest of the four nodes around it.
    pub fn lake_level(&self, x: f32, z: f32) -> Option<f32> {
        if self.lakes.is_empty() {
            return None;
        }
        let i = ((x / self.spacing_m) - 0.5).floor() as i64;
        let k = ((z / self.spacing_m) - 0.5).floor() as i64;
        [(0, 0), (1, 0), (0, 1), (1, 1)]
            .into_iter()
            .filter_map(|(di, dk)| self.node_lake(i + di, k + dk))
            .reduce(f32::max)
    }
}

/// The world rectangle `(x0, z0, x1, z1)`, metres, of the `w × h` samples
/// `(gx0 + i, gz0 + j)·spacing_m` of a field.
fn field_rect(spacing_m: f32, gx0: i64, gz0: i64, w: usize, h: usize) -> (f32, f32, f32, f32) {
    (
        gx0 as f32 * spacing_m,
        gz0 as f32 * spacing_m,
        (gx0 + w as i64 - 1) as f32 * spacing_m,
        (gz0 + h as i64 - 1) as f32 * spacing_m,
    )
}

/// The bin side of a field's job over the rectangle `(x0, z0, x1, z1)`: about 8 × 8 bins over
/// it, at least 8 m and at most a node spacing, metres.
fn field_bin_m(plan: &RiverPlan, (x0, z0, x1, z1): (f32, f32, f32, f32)) -> f32 {
    ((x1 - x0).max(z1 - z0) / 8.0).clamp(8.0, plan.spacing_m)
}

/// The job of the samples `(gx0 + i, gz0 + j)·spacing` of a field (its world rectangle).
pub fn job_for(
    earth: &EarthPlan,
    plan: &RiverPlan,
    spacing_m: f32,
    gx0: i64,
    gz0: i64,
    w: usize,
    h: usize,
) -> RiverJob {
    let (x0, z0, x1, z1) = field_rect(spacing_m, gx0, gz0, w, h);
    let bin_m = field_bin_m(plan, (x0, z0, x1, z1));
    let mut job = Network::new(earth, plan).job(x0, z0, x1, z1, bin_m);
    widen_floors(plan, spacing_m, &mut job);
    job.shore_n = plan.shore_noise(spacing_m);
    job
}

/// In `valleys: 8` worlds, widens every floodplain of `job` to at least [`LOD_FLOOR`] vertex
/// spacings each side, so a tile of `spacing_m` samples each valley floor on every row and
/// column that crosses it. Tiles of spacings up to 16 m keep their pieces (the narrowest
/// floodplain, a source's, is 8.3 m each side); a coarser tile's floors are wider than LOD 0's
/// by at most a vertex spacing, within its LOD bound ([`super::widened_floor_bound_m`]).
fn widen_floors(plan: &RiverPlan, spacing_m: f32, job: &mut RiverJob) {
    if !plan.sized_valleys {
        return;
    }
    let floor = LOD_FLOOR * spacing_m;
    for p in &mut job.pieces {
        p.floodplain = p.floodplain.max(floor);
        p.floodplain_b = p.floodplain_b.max(floor);
    }
}

/// The water job ([`Network::water_job`]) of the same samples as [`job_for`]'s.
pub fn water_job_for(
    earth: &EarthPlan,
    plan: &RiverPlan,
    spacing_m: f32,
    gx0: i64,
    gz0: i64,
    w: usize,
    h: usize,
) -> RiverJob {
    let (x0, z0, x1, z1) = field_rect(spacing_m, gx0, gz0, w, h);
    let bin_m = field_bin_m(plan, (x0, z0, x1, z1));
    let mut job = Network::new(earth, plan).water_job(x0, z0, x1, z1, bin_m);
    widen_floors(plan, spacing_m, &mut job);
    job.shore_n = plan.shore_noise(spacing_m);
    job
}

/// The lakes alone over the samples `(gx0 + i, gz0 + j)·spacing` of a field (its world
/// rectangle): the water of tiles too coarse to carve in worlds with `lakes: 5`.
pub fn lake_job_for(
    earth: &EarthPlan,
    plan: &RiverPlan,
    spacing_m: f32,
    gx0: i64,
    gz0: i64,
    w: usize,
    h: usize,
) -> RiverJob {
    let (x0, z0, x1, z1) = field_rect(spacing_m, gx0, gz0, w, h);
    let mut job = Network::new(earth, plan).lake_job(x0, z0, x1, z1);
    job.shore_n = plan.shore_noise(spacing_m);
    job
}

/// Water of one sample: its surface (metres) and kind (`kind::*`), given its carved height
/// (the highest of the sea, a lake and a river over it; inside a shaped lake shore, the lake
/// over a river).
pub fn water_at(job: &RiverJob, sea_level_m: f32, x: f32, z: f32, carved: f32) -> (f32, u8) {
    water_at_lake(job, sea_level_m, x, z, carved, job.lake_surface(x, z))
}

/// [`water_at`] of a sample whose lake level [`RiverJob::lake_surface`] is `lake`.
pub fn water_at_lake(
    job: &RiverJob,
    sea_level_m: f32,
    x: f32,
    z: f32,
    carved: f32,
    lake: Option<f32>,
) -> (f32, u8) {
    let river = job.river_level(x, z, carved);
    let mut surface = carved;
    let mut k = kind::NONE;
    if carved < sea_level_m {
        surface = sea_level_m;
        k = kind::SEA;
    }
    if let Some(w) = river {
        if w > surface {
            surface = w;
            k = kind::RIVER;
        }
    }
    if let Some(l) = lake {
        // Inside a shaped shore the lake holds the rivers that reach it: their water levels,
        // which fall to the lake's only at its node, do not stand above it.
        if l > carved && (l > surface || (job.shores && k == kind::RIVER)) {
            surface = l;
            k = kind::LAKE;
        }
    }
    (surface, k)
}
