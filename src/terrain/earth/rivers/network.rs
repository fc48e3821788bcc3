//! The drainage network: node heights, flow, discharge and lakes, memoised per world in
//! bounded block caches (module docs of [`super`], steps 1–5).
//!
//! Why one file of about 630 lines: steps 1–5 are methods of one `Network`, each reading the block
//! caches that the earlier steps fill, in the order the module docs of [`super`] give.

use super::super::super::hash::{hash2, unit};
use super::super::kernel::{self, LANES};
use super::super::EarthPlan;
use super::carve::Piece;
use super::{RiverPlan, BLOCK, BREACH_DEPTH_M, LAKE_WALK, NONE, OFFSETS, Q_MAX, ROUTE_NOISE};
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};
use std::collections::BinaryHeap;
use std::sync::Arc;

/// A node's lattice index `(i, k)`.
pub type NodeId = (i64, i64);

/// A lake: its level (metres), the nodes it floods and its outlet, if the flood found one.
pub type Lake = (f32, Vec<NodeId>, Option<NodeId>);

/// Where flows end and in how many steps, by node.
type Ends = HashMap<NodeId, (NodeId, usize)>;

/// A frame of the upstream count: the node, its upstream neighbours, the next to visit and the
/// count so far.
type Frame = (NodeId, Vec<NodeId>, usize, u32);

/// Empties every cache of every world's network (the results stay the same: tests use it to
/// compute a tile from nothing, `strata bench tiles` to time cold tiles). The invalidated
/// entries are removed at once (moka otherwise drops them in its housekeeping, and until then
/// they count against the byte budget).
pub fn clear_caches() {
    fn clear<V: Send + Sync + 'static>(c: &BlockCache<V>) {
        c.invalidate_all();
        c.run_pending_tasks();
    }
    clear(&CACHES.heights);
    clear(&CACHES.routes);
    clear(&CACHES.spills);
    clear(&CACHES.flow);
    clear(&CACHES.pieces);
    clear(&CACHES.long);
    clear(&CACHES.floods);
    clear(&CACHES.lakes);
}

/// Floods that end within this many nodes are not kept in the process cache
/// ([`Network::flood`]).
const SMALL_FLOOD_NODES: usize = 16;

/// A call's memo of one kind of block, by block index.
type Memo<V> = HashMap<(i64, i64), Arc<V>>;

/// A piece of a long edge (a breached pit's or a spilling lake's, to an outlet beyond its
/// lattice neighbours): the pit, the piece's index along the edge and the piece.
pub(super) type LongPiece = ((i64, i64), u32, Piece);

/// A block of one world's network: the world's fingerprint ([`RiverPlan::fingerprint`]) and
/// the block's index.
type BlockKey = (u64, (i64, i64));

/// A process cache of one kind of block. Keys hash with foldhash (seeded per process): moka's
/// default SipHash was a tenth of the time of cold coarse tiles, whose floods insert an entry
/// per pit.
type BlockCache<V> = moka::sync::Cache<BlockKey, Arc<V>, foldhash::fast::RandomState>;

/// The block caches of every world's network in the process, each bounded in bytes (so many
/// worlds and versions share one budget; versions of a world with the same settings share
/// their blocks).
struct Caches {
    heights: BlockCache<HeightBlock>,
    routes: BlockCache<RouteBlock>,
    spills: BlockCache<RouteBlock>,
    flow: BlockCache<FlowBlock>,
    pieces: BlockCache<Vec<Piece>>,
    /// The long edges' pieces that can reach each piece block ([`LongPiece`]).
    long: BlockCache<Vec<LongPiece>>,
    /// The lakes of pits, by the world's fingerprint and the pit: the blocks around a pit
    /// within a flood's radius all ask for its lake.
    floods: BlockCache<Lake>,
    /// The lake levels of blocks, apart from their flow (coarse tiles read these alone).
    lakes: BlockCache<LakeBlock>,
}

/// Byte budgets of the caches.
const HEIGHTS_BYTES: u64 = 64 << 20;
const ROUTES_BYTES: u64 = 8 << 20;
const FLOW_BYTES: u64 = 64 << 20;
const PIECES_BYTES: u64 = 64 << 20;
const FLOODS_BYTES: u64 = 16 << 20;

fn cache<V: Send + Sync + 'static>(bytes: u64, weigh: fn(&V) -> usize) -> BlockCache<V> {
    moka::sync::Cache::builder()
        .max_capacity(bytes)
        .weigher(move |_, v: &Arc<V>| (64 + weigh(v)).min(u32::MAX as usize) as u32)
        .build_with_hasher(foldhash::fast::RandomState::default())
}

static CACHES: std::sync::LazyLock<Caches> = std::sync::LazyLock::new(|| Caches {
    heights: cache(HEIGHTS_BYTES, |b: &HeightBlock| {
        4 * b.h.len() + b.down.len() + 4 * b.relief.len()
    }),
    routes: cache(ROUTES_BYTES, RouteBlock::weight),
    spills: cache(ROUTES_BYTES, RouteBlock::weight),
    flow: cache(FLOW_BYTES, |b: &FlowBlock| 4 * (b.q.len() + b.w.len())),
    pieces: cache(PIECES_BYTES, |p: &Vec<Piece>| {
        std::mem::size_of::<Piece>() * p.len()
    }),
    long: cache(FLOODS_BYTES, |p: &Vec<LongPiece>| {
        std::mem::size_of::<LongPiece>() * p.len()
    }),
    floods: cache(FLOODS_BYTES, |l: &Lake| 16 * l.1.len()),
    lakes: cache(ROUTES_BYTES, |b: &LakeBlock| 4 * b.lake.len()),
});

/// The breached pits of one block (shallow pits that drain over their saddle to the outlet
/// beyond it instead of holding a lake), or in `lakes: 3` worlds its spilling lakes (pits that
/// hold a lake and drain from it to its outlet, [`Network::spill`]).
#[derive(Default)]
struct RouteBlock {
    /// Pits of the block and their outlets.
    out: HashMap<(i64, i64), (i64, i64)>,
    /// Outlets in the block and the pits that drain into each, in index order.
    into: HashMap<(i64, i64), Vec<(i64, i64)>>,
}

impl RouteBlock {
    /// Bytes the block's cache entry is weighed at.
    fn weight(&self) -> usize {
        48 * self.out.len() + self.into.values().map(|v| 48 + 16 * v.len()).sum::<usize>()
    }
}

/// Heights (a one-node ring included) and flow directions of one block of nodes.
struct HeightBlock {
    /// `(BLOCK + 2)²` heights, metres, from node `(bx·BLOCK − 1, bz·BLOCK − 1)`.
    h: Vec<f32>,
    /// `BLOCK²` indices into [`OFFSETS`] of the downstream neighbour, or `NONE`.
    down: Vec<u8>,
    /// `BLOCK²` relief amplitudes of the macro fields, metres.
    relief: Vec<f32>,
}

/// Discharge and water levels of one block of nodes.
struct FlowBlock {
    /// `BLOCK²` discharges, nodes.
    q: Vec<u32>,
    /// `BLOCK²` water levels, metres.
    w: Vec<f32>,
}

/// Lake levels of one block of nodes (apart from the flow: tiles too coarse to carve read the
/// lakes alone).
struct LakeBlock {
    /// `BLOCK²` levels of the highest lake covering each node, metres (NaN: none).
    lake: Vec<f32>,
}

/// One node of the network as the products see it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    /// Lattice index.
    pub i: i64,
    /// Lattice index.
    pub k: i64,
    /// World position, metres.
    pub x: f32,
    /// World position, metres.
    pub z: f32,
    /// Height of the world function at the node LOD, metres.
    pub h: f32,
    /// Discharge, nodes (capped at [`Q_MAX`]).
    pub q: u32,
    /// Water level of the river through the node, metres.
    pub w: f32,
    /// The downstream neighbour, if any.
    pub down: Option<(i64, i64)>,
    /// Whether the node is below sea level.
    pub sea: bool,
    /// The lake level covering the node, if any.
    pub lake: Option<f32>,
}

/// Read access to the network with a per-call memo of blocks.
pub struct Network<'a> {
    pub(super) earth: &'a EarthPlan,
    pub(super) plan: &'a RiverPlan,
    heights: Memo<HeightBlock>,
    /// The height block read last, and its index.
    last_heights: Option<((i64, i64), Arc<HeightBlock>)>,
    routes: Memo<RouteBlock>,
    spills: Memo<RouteBlock>,
    flows: Memo<FlowBlock>,
    lakes: Memo<LakeBlock>,
    /// The lakes of the pits asked for, by pit (the blocks around a pit each ask for it).
    floods: Memo<Lake>,
}

impl std::fmt::Debug for Network<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Network").finish_non_exhaustive()
    }
}

fn block_of(i: i64) -> (i64, usize) {
    (i.div_euclid(BLOCK), i.rem_euclid(BLOCK) as usize)
}

impl<'a> Network<'a> {
    /// The network of `earth`'s rivers (`earth.rivers` must be set).
    pub fn new(earth: &'a EarthPlan, plan: &'a RiverPlan) -> Self {
        Self {
            earth,
            plan,
            heights: HashMap::default(),
            last_heights: None,
            routes: HashMap::default(),
            spills: HashMap::default(),
            flows: HashMap::default(),
            lakes: HashMap::default(),
            floods: HashMap::default(),
        }
    }

    fn height_block(&mut self, b: (i64, i64)) -> Arc<HeightBlock> {
        if let Some(hb) = self.heights.get(&b) {
            return hb.clone();
        }
        let (earth, plan) = (self.earth, self.plan);
        let hb = CACHES.heights.get_with((plan.fingerprint, b), || {
            Arc::new(compute_heights(earth, plan, b))
        });
        self.heights.insert(b, hb.clone());
        hb
    }

    /// `read` of height block `b`: the block of the last call without a lookup (walks and
    /// floods read node after node of one block), else [`Network::height_block`]'s.
    #[inline]
    fn with_heights<R>(&mut self, b: (i64, i64), read: impl FnOnce(&HeightBlock) -> R) -> R {
        match &self.last_heights {
            Some((last, hb)) if *last == b => read(hb),
            _ => {
                let hb = self.height_block(b);
                let r = read(&hb);
                self.last_heights = Some((b, hb));
                r
            }
        }
    }

    /// Height of node `(i, k)`, metres.
    pub fn height(&mut self, i: i64, k: i64) -> f32 {
        let ((bx, li), (bz, lk)) = (block_of(i), block_of(k));
        self.with_heights((bx, bz), |hb| {
            hb.h[(lk + 1) * (BLOCK as usize + 2) + li + 1]
        })
    }

    /// Relief amplitude of the macro fields at node `(i, k)`, metres.
    pub fn relief(&mut self, i: i64, k: i64) -> f32 {
        let ((bx, li), (bz, lk)) = (block_of(i), block_of(k));
        self.with_heights((bx, bz), |hb| hb.relief[lk * BLOCK as usize + li])
    }

    fn down_index(&mut self, i: i64, k: i64) -> u8 {
        let ((bx, li), (bz, lk)) = (block_of(i), block_of(k));
        self.with_heights((bx, bz), |hb| hb.down[lk * BLOCK as usize + li])
    }

    /// The downstream neighbour of node `(i, k)` on the lattice (a pit has none).
    fn lattice_down(&mut self, i: i64, k: i64) -> Option<(i64, i64)> {
        match self.down_index(i, k) {
            NONE => None,
            d => {
                let (di, dk) = OFFSETS[d as usize];
                Some((i + di, k + dk))
            }
        }
    }

    /// Block `b` from this call's memo (`memo`), else from the process cache, else computed by
    /// `compute` and put in both.
    fn block<V: Send + Sync + 'static>(
        &mut self,
        b: (i64, i64),
        memo: fn(&mut Self) -> &mut Memo<V>,
        cache: &BlockCache<V>,
        compute: fn(&mut Self, (i64, i64)) -> V,
    ) -> Arc<V> {
        if let Some(v) = memo(self).get(&b) {
            return v.clone();
        }
        let key = (self.plan.fingerprint, b);
        if let Some(v) = cache.get(&key) {
            memo(self).insert(b, v.clone());
            return v;
        }
        let v = Arc::new(compute(self, b));
        cache.insert(key, v.clone());
        memo(self).insert(b, v.clone());
        v
    }

    fn route_block(&mut self, b: (i64, i64)) -> Arc<RouteBlock> {
        self.block(b, |n| &mut n.routes, &CACHES.routes, Self::compute_routes)
    }

    /// Whether `(i, k)` is a pit: land with no lower neighbour.
    fn is_pit(&mut self, i: i64, k: i64) -> bool {
        self.down_index(i, k) == NONE && self.height(i, k) >= self.plan.sea_level_m
    }

    /// The outlet a shallow pit drains to: the first node below the lake's level beyond its
    /// saddle, when that node is lower than the pit itself (so heights fall strictly along every
    /// chain of breaches and no flow can cycle) and the lake would be shallower than
    /// [`BREACH_DEPTH_M`].
    fn breach(&mut self, i: i64, k: i64) -> Option<(i64, i64)> {
        let lake = self.flood(i, k);
        let (level, outlet) = (lake.0, lake.2);
        let h = self.height(i, k);
        let o = outlet?;
        (self.height(o.0, o.1) < h && level - h < BREACH_DEPTH_M).then_some(o)
    }

    fn compute_routes(&mut self, b: (i64, i64)) -> RouteBlock {
        self.compute_outlets(b, |net, i, k| {
            if net.is_pit(i, k) {
                net.breach(i, k)
            } else {
                None
            }
        })
    }

    /// The nodes in `is × ks` without a lattice neighbour below them (pits, and sea nodes
    /// with no lower neighbour), in row order (`k`, then `i`): each height block of the range
    /// is scanned for them, instead of asking every node.
    pub(super) fn sinks(
        &mut self,
        is: std::ops::Range<i64>,
        ks: std::ops::Range<i64>,
    ) -> Vec<(i64, i64)> {
        let mut found = Vec::new();
        for hz in block_of(ks.start).0..=block_of(ks.end - 1).0 {
            for hx in block_of(is.start).0..=block_of(is.end - 1).0 {
                let hb = self.height_block((hx, hz));
                for (n, &d) in hb.down.iter().enumerate() {
                    let i = hx * BLOCK + (n as i64 % BLOCK);
                    let k = hz * BLOCK + (n as i64 / BLOCK);
                    if d == NONE && is.contains(&i) && ks.contains(&k) {
                        found.push((k, i));
                    }
                }
            }
        }
        found.sort_unstable();
        found.into_iter().map(|(k, i)| (i, k)).collect()
    }

    /// The pits within reach of block `b` that `outlet` routes (breaches, or in `lakes: 3`
    /// worlds spills), and their outlets: those of the block's pits, and the block's outlets'.
    fn compute_outlets(
        &mut self,
        (bx, bz): (i64, i64),
        outlet: fn(&mut Self, i64, i64) -> Option<(i64, i64)>,
    ) -> RouteBlock {
        let (i0, k0) = (bx * BLOCK, bz * BLOCK);
        let inside =
            |i: i64, k: i64| (i0..i0 + BLOCK).contains(&i) && (k0..k0 + BLOCK).contains(&k);
        let mut rb = RouteBlock::default();
        // An outlet lies within the flood radius (plus one) of its pit. Only nodes without a
        // lattice neighbour below them can be pits: each height block of the margin is scanned
        // for them, instead of asking every node of the margin.
        let r = self.plan.lake_radius + 1;
        for (i, k) in self.sinks(i0 - r..i0 + BLOCK + r, k0 - r..k0 + BLOCK + r) {
            let Some(o) = outlet(self, i, k) else {
                continue;
            };
            if inside(i, k) {
                rb.out.insert((i, k), o);
            }
            if inside(o.0, o.1) {
                rb.into.entry(o).or_default().push((i, k));
            }
        }
        rb
    }

    fn spill_block(&mut self, b: (i64, i64)) -> Arc<RouteBlock> {
        self.block(b, |n| &mut n.spills, &CACHES.spills, Self::compute_spills)
    }

    /// The outlet of breached pit `(i, k)`, if it is one.
    fn breached(&mut self, i: i64, k: i64) -> Option<(i64, i64)> {
        let ((bx, _), (bz, _)) = (block_of(i), block_of(k));
        self.route_block((bx, bz)).out.get(&(i, k)).copied()
    }

    /// Whether `(i, k)` holds a lake: a pit that is not breached.
    fn is_lake_pit(&mut self, i: i64, k: i64) -> bool {
        self.is_pit(i, k) && self.breached(i, k).is_none()
    }

    /// The downstream neighbour of `(i, k)` before lakes spill: its lattice neighbour of
    /// steepest descent, or for a breached pit its outlet.
    fn breach_down(&mut self, i: i64, k: i64) -> Option<(i64, i64)> {
        if let Some(d) = self.lattice_down(i, k) {
            return Some(d);
        }
        if !self.is_pit(i, k) {
            return None;
        }
        self.breached(i, k)
    }

    /// The outlet lake pit `(i, k)` spills to in `lakes: 3` worlds: the outlet of its flood, when
    /// the flow from there ([`Network::breach_down`], at most [`LAKE_WALK`] steps) reaches the
    /// sea, or first a lake pit whose `(level, index)` is below this one's. Levels never rise
    /// along a chain of spills and the order is strict, so the flow has no cycle, and the
    /// water levels that rest on the levels never rise downstream (module docs, steps 4–5).
    fn spill(&mut self, i: i64, k: i64) -> Option<(i64, i64)> {
        let lake = self.flood(i, k);
        let (level, outlet) = (lake.0, lake.2);
        let o = outlet?;
        let mut at = o;
        for _ in 0..=LAKE_WALK {
            if self.is_lake_pit(at.0, at.1) {
                if at == (i, k) {
                    return None;
                }
                let other = self.flood(at.0, at.1).0;
                let lower = other.total_cmp(&level).then(at.cmp(&(i, k))).is_lt();
                return lower.then_some(o);
            }
            match self.breach_down(at.0, at.1) {
                Some(next) => at = next,
                None => return (self.height(at.0, at.1) < self.plan.sea_level_m).then_some(o),
            }
        }
        None
    }

    fn compute_spills(&mut self, b: (i64, i64)) -> RouteBlock {
        self.compute_outlets(b, |net, i, k| {
            if net.is_lake_pit(i, k) {
                net.spill(i, k)
            } else {
                None
            }
        })
    }

    /// In the fine network of `lakes: 6` worlds and both networks of `lakes: 7` worlds
    /// ([`RiverPlan::saddles`]), where the water of a
    /// lake that spills over an outlet beyond its pit's neighbours leaves it: the lowest node of
    /// pit `(i, k)`'s flood linked to the outlet (the first by index on ties), the saddle the
    /// outlet was found beyond. The pit's edge is drawn and carved from there (`Network::edge`):
    /// from the pit, kilometres across the lake and the land its curve crossed beside it, the
    /// spill edge cut a trench down to a level falling from the lake's to the outlet's. `None`
    /// for every other node.
    pub(super) fn saddle(&mut self, i: i64, k: i64) -> Option<NodeId> {
        if !self.plan.saddles {
            return None;
        }
        let o = self.down(i, k)?;
        if (o.0 - i).abs() <= 1 && (o.1 - k).abs() <= 1 || !self.is_lake_pit(i, k) {
            return None;
        }
        let lake = self.flood(i, k);
        let mut best: Option<(f32, NodeId)> = None;
        for (d, (di, dk)) in OFFSETS.iter().enumerate() {
            let n = (o.0 - di, o.1 - dk);
            if !self.plan.linked(n.0, n.1, d) || !lake.1.contains(&n) {
                continue;
            }
            let h = self.height(n.0, n.1);
            if best.is_none_or(|(bh, bn)| h.total_cmp(&bh).then(n.cmp(&bn)).is_lt()) {
                best = Some((h, n));
            }
        }
        best.map(|(_, n)| n)
    }

    /// Where node `(i, k)`'s edge starts, metres: its position, or its [`Network::saddle`]'s.
    pub(super) fn edge_start(&mut self, i: i64, k: i64) -> (f32, f32) {
        let (a, b) = self.saddle(i, k).unwrap_or((i, k));
        self.plan.position(a, b)
    }

    /// The downstream neighbour of node `(i, k)`: its lattice neighbour of steepest descent, for
    /// a breached pit its outlet, and in `lakes: 3` worlds for a spilling lake its outlet.
    pub fn down(&mut self, i: i64, k: i64) -> Option<(i64, i64)> {
        if let Some(d) = self.breach_down(i, k) {
            return Some(d);
        }
        if self.plan.lakes < 3 || !self.is_pit(i, k) {
            return None;
        }
        let ((bx, _), (bz, _)) = (block_of(i), block_of(k));
        self.spill_block((bx, bz)).out.get(&(i, k)).copied()
    }

    /// The upstream neighbours of node `(i, k)`: lattice neighbours in [`OFFSETS`] order, then
    /// the breached pits that drain into it, then (`lakes: 3`) the lakes that spill into it.
    pub fn upstream(&mut self, i: i64, k: i64) -> Vec<(i64, i64)> {
        let mut out = Vec::new();
        let ((bx, li), (bz, lk)) = (block_of(i), block_of(k));
        let n = BLOCK as usize;
        // Inside its block a node's neighbours are in the same block: one lookup for all eight.
        let interior = (1..n - 1).contains(&li) && (1..n - 1).contains(&lk);
        let hb = interior.then(|| self.height_block((bx, bz)));
        for (d, (di, dk)) in OFFSETS.iter().enumerate() {
            if !self.plan.linked(i, k, d) {
                continue;
            }
            let (ni, nk) = (i + di, k + dk);
            let down = match &hb {
                Some(hb) => {
                    let v = (lk as i64 + dk) as usize * n + (li as i64 + di) as usize;
                    match hb.down[v] {
                        NONE => None,
                        e => {
                            let (ei, ek) = OFFSETS[e as usize];
                            Some((ni + ei, nk + ek))
                        }
                    }
                }
                None => self.lattice_down(ni, nk),
            };
            if down == Some((i, k)) {
                out.push((ni, nk));
            }
        }
        if let Some(pits) = self.route_block((bx, bz)).into.get(&(i, k)) {
            out.extend_from_slice(pits);
        }
        if self.plan.lakes >= 3 {
            if let Some(lakes) = self.spill_block((bx, bz)).into.get(&(i, k)) {
                out.extend_from_slice(lakes);
            }
        }
        out
    }

    /// The long edges' pieces that can reach piece block `b`, from the process cache or
    /// computed ([`Network::block_long_pieces`]).
    pub(super) fn long_pieces(&mut self, b: (i64, i64)) -> Arc<Vec<LongPiece>> {
        if let Some(p) = CACHES.long.get(&(self.plan.fingerprint, b)) {
            return p;
        }
        let p = Arc::new(self.block_long_pieces(b));
        CACHES.long.insert((self.plan.fingerprint, b), p.clone());
        p
    }

    /// The pieces of piece block `b` (`Network::block_pieces`), memoised.
    pub(super) fn pieces(&mut self, b: (i64, i64)) -> Arc<Vec<Piece>> {
        if let Some(p) = CACHES.pieces.get(&(self.plan.fingerprint, b)) {
            return p;
        }
        let p = Arc::new(self.block_pieces(b));
        CACHES.pieces.insert((self.plan.fingerprint, b), p.clone());
        p
    }

    /// The main upstream neighbour of `(i, k)`: the largest discharge, the first in
    /// [`Network::upstream`] order on ties.
    pub fn main_upstream(&mut self, i: i64, k: i64) -> Option<NodeId> {
        let mut main: Option<(u32, NodeId)> = None;
        for u in self.upstream(i, k) {
            let q = self.q(u.0, u.1);
            if main.is_none_or(|(mq, _)| q > mq) {
                main = Some((q, u));
            }
        }
        main.map(|(_, u)| u)
    }

    fn flow_block(&mut self, b: (i64, i64)) -> Arc<FlowBlock> {
        self.block(b, |n| &mut n.flows, &CACHES.flow, Self::compute_flow)
    }

    /// Discharge of node `(i, k)`, nodes.
    pub fn q(&mut self, i: i64, k: i64) -> u32 {
        let ((bx, li), (bz, lk)) = (block_of(i), block_of(k));
        self.flow_block((bx, bz)).q[lk * BLOCK as usize + li]
    }

    fn lake_block(&mut self, b: (i64, i64)) -> Arc<LakeBlock> {
        self.block(b, |n| &mut n.lakes, &CACHES.lakes, Self::compute_lakes)
    }

    /// Level of the highest lake covering node `(i, k)`.
    pub fn lake(&mut self, i: i64, k: i64) -> Option<f32> {
        let ((bx, li), (bz, lk)) = (block_of(i), block_of(k));
        let l = self.lake_block((bx, bz)).lake[lk * BLOCK as usize + li];
        (!l.is_nan()).then_some(l)
    }

    /// Water level of the river through node `(i, k)`, metres.
    pub fn water_level(&mut self, i: i64, k: i64) -> f32 {
        let ((bx, li), (bz, lk)) = (block_of(i), block_of(k));
        self.flow_block((bx, bz)).w[lk * BLOCK as usize + li]
    }

    fn incision(&self, q: u32) -> f32 {
        let q = (q * self.plan.q_scale).min(Q_MAX);
        self.plan.incision_m * libm::log2f(1.0 + q as f32) / libm::log2f(1.0 + Q_MAX as f32)
    }

    /// Everything about node `(i, k)`.
    pub fn node(&mut self, i: i64, k: i64) -> Node {
        let (x, z) = self.plan.position(i, k);
        let h = self.height(i, k);
        Node {
            i,
            k,
            x,
            z,
            h,
            q: self.q(i, k),
            w: self.water_level(i, k),
            down: self.down(i, k),
            sea: h < self.plan.sea_level_m,
            lake: self.lake(i, k),
        }
    }

    /// `min(upstream count, Q_MAX)` by a depth-first count that stops at the cap.
    fn count(&mut self, i: i64, k: i64, memo: &mut HashMap<(i64, i64), u32>) -> u32 {
        if let Some(&q) = memo.get(&(i, k)) {
            return q;
        }
        // Frames: node, its upstream neighbours, the next one to visit, the count so far.
        let mut stack: Vec<Frame> = vec![((i, k), self.upstream(i, k), 0, 1)];
        loop {
            let top = stack.len() - 1;
            let (node, next, acc) = (stack[top].0, stack[top].2, stack[top].3);
            if acc >= Q_MAX || next == stack[top].1.len() {
                let q = acc.min(Q_MAX);
                memo.insert(node, q);
                stack.pop();
                match stack.last_mut() {
                    Some(parent) => parent.3 += q,
                    None => return q,
                }
                continue;
            }
            let child = stack[top].1[next];
            stack[top].2 += 1;
            match memo.get(&child) {
                Some(&q) => stack[top].3 += q,
                None => {
                    let ups = self.upstream(child.0, child.1);
                    stack.push((child, ups, 0, 1));
                }
            }
        }
    }

    fn compute_flow(&mut self, (bx, bz): (i64, i64)) -> FlowBlock {
        let n = BLOCK as usize;
        let (i0, k0) = (bx * BLOCK, bz * BLOCK);
        let mut memo = HashMap::default();
        let mut q = vec![0u32; n * n];
        for lk in 0..n {
            for li in 0..n {
                q[lk * n + li] = self.count(i0 + li as i64, k0 + lk as i64, &mut memo);
            }
        }
        // Water levels: incised below the node height by the discharge, faded out with the
        // distance to the end of the flow, and never below the end's base level.
        let mut ends: Ends = HashMap::default();
        let mut w = vec![0.0f32; n * n];
        for lk in 0..n {
            for li in 0..n {
                let (i, k) = (i0 + li as i64, k0 + lk as i64);
                let h = self.height(i, k);
                let Some((end, steps)) = self.end_of_flow(i, k, &mut ends) else {
                    // No end within LAKE_WALK steps: not incised (module docs, step 4).
                    w[lk * n + li] = h;
                    continue;
                };
                // `lakes: 6`: the flow ends at lake water, whose level is the highest of the
                // lakes covering the node (a pit's own lake may lie submerged in a higher one).
                let lake = match self.plan.lake_ends {
                    true => self.lake(end.0, end.1),
                    false => None,
                };
                let base = if let Some(level) = lake {
                    level
                } else if self.is_pit(end.0, end.1) {
                    self.flood(end.0, end.1).0
                } else {
                    self.plan.sea_level_m
                };
                let fade = (2.0 - 2.0 * steps as f32 / LAKE_WALK as f32).clamp(0.0, 1.0);
                let cut = self.incision(q[lk * n + li]) * fade;
                w[lk * n + li] = (h - cut).max(base).min(h.max(base));
            }
        }
        FlowBlock { q, w }
    }

    /// The lake levels of block `b`: each node takes the highest level of the lakes whose
    /// floods cover it (module docs, step 5).
    fn compute_lakes(&mut self, (bx, bz): (i64, i64)) -> LakeBlock {
        let n = BLOCK as usize;
        let (i0, k0) = (bx * BLOCK, bz * BLOCK);
        let mut lake = vec![f32::NAN; n * n];
        let r = self.plan.lake_radius;
        for (i, k) in self.sinks(i0 - r..i0 + BLOCK + r, k0 - r..k0 + BLOCK + r) {
            if !self.is_lake_pit(i, k) {
                continue;
            }
            let flood = self.flood(i, k);
            for &(fi, fk) in &flood.1 {
                let (li, lk) = (fi - i0, fk - k0);
                if (0..BLOCK).contains(&li) && (0..BLOCK).contains(&lk) {
                    let v = &mut lake[lk as usize * n + li as usize];
                    if v.is_nan() || flood.0 > *v {
                        *v = flood.0;
                    }
                }
            }
        }
        LakeBlock { lake }
    }

    /// Where the flow from `(i, k)` ends (the sea or a pit) and in how many steps, if at most
    /// [`LAKE_WALK`]. `memo` keeps exact answers only, so the result never depends on what was
    /// asked before.
    fn end_of_flow(&mut self, i: i64, k: i64, memo: &mut Ends) -> Option<(NodeId, usize)> {
        // Walk down at most LAKE_WALK steps, stopping at a memoised node or the end.
        let mut path = Vec::new();
        let mut at = (i, k);
        let (end, mut steps) = loop {
            if let Some(&known) = memo.get(&at) {
                break known;
            }
            // A lake ends the flow, also one that spills (`lakes: 3`): the water levels rest
            // on its level. With `lakes: 6` the flow ends where it first reaches a lake's
            // water, also one it passes through without meeting the pit.
            let reached = if self.plan.lake_ends {
                self.lake(at.0, at.1).is_some()
            } else {
                self.plan.lakes >= 3 && self.is_lake_pit(at.0, at.1)
            };
            if reached {
                memo.insert(at, (at, 0));
                break (at, 0);
            }
            match self.down(at.0, at.1) {
                None => {
                    memo.insert(at, (at, 0));
                    break (at, 0);
                }
                Some(next) => {
                    path.push(at);
                    if path.len() > LAKE_WALK {
                        return None;
                    }
                    at = next;
                }
            }
        };
        for &node in path.iter().rev() {
            steps += 1;
            memo.insert(node, (end, steps));
        }
        memo.get(&(i, k)).copied().filter(|&(_, s)| s <= LAKE_WALK)
    }

    /// The lake of pit `(i, k)`: its level, the nodes it covers and the outlet (the first node
    /// below the level beyond the saddle; `None` when the search stopped first) (module docs,
    /// step 5), from the process cache or computed.
    pub fn flood(&mut self, i: i64, k: i64) -> Arc<Lake> {
        if let Some(lake) = self.floods.get(&(i, k)) {
            return lake.clone();
        }
        // Most pits' floods end within a few nodes, sooner than the process cache answers:
        // those are computed again where asked, the others kept.
        let lake = match self.compute_flood(i, k, SMALL_FLOOD_NODES) {
            (lake, true) => Arc::new(lake),
            (_, false) => {
                let key = (self.plan.fingerprint, (i, k));
                match CACHES.floods.get(&key) {
                    Some(lake) => lake,
                    None => {
                        let max = self.plan.lake_max_nodes;
                        let lake = Arc::new(self.compute_flood(i, k, max).0);
                        CACHES.floods.insert(key, lake.clone());
                        lake
                    }
                }
            }
        };
        self.floods.insert((i, k), lake.clone());
        lake
    }

    /// The lake of pit `(i, k)` ([`Network::flood`]) as far as a search of at most
    /// `max_nodes` flooded nodes finds it, and whether that is the lake: true when the search
    /// ended before it flooded `max_nodes`, or at the world's limit (`RiverPlan::lake_max_nodes`,
    /// where the world's search stops too).
    fn compute_flood(&mut self, i: i64, k: i64, max_nodes: usize) -> (Lake, bool) {
        #[derive(PartialEq)]
        struct Entry(f32, i64, i64);
        impl Eq for Entry {}
        impl PartialOrd for Entry {
            fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
                Some(self.cmp(o))
            }
        }
        impl Ord for Entry {
            // Lowest height first, then by index (a min-heap in a max-heap).
            fn cmp(&self, o: &Self) -> std::cmp::Ordering {
                o.0.total_cmp(&self.0)
                    .then(o.1.cmp(&self.1))
                    .then(o.2.cmp(&self.2))
            }
        }
        let floor = self.height(i, k);
        let mut level = floor;
        let mut flooded = vec![(i, k)];
        let mut seen: HashSet<(i64, i64)> = HashSet::default();
        seen.insert((i, k));
        let mut heap = BinaryHeap::new();
        let push = |net: &mut Self,
                    heap: &mut BinaryHeap<Entry>,
                    seen: &mut HashSet<_>,
                    a: i64,
                    b: i64| {
            for (d, (di, dk)) in OFFSETS.iter().enumerate() {
                let (ni, nk) = (a + di, b + dk);
                if net.plan.linked(a, b, d) && seen.insert((ni, nk)) {
                    heap.push(Entry(net.height(ni, nk), ni, nk));
                }
            }
        };
        push(self, &mut heap, &mut seen, i, k);
        let mut outlet = None;
        // `lakes: 7`: the flooded nodes before the level last rose, and that level.
        let mut rise = (1, level);
        // `lakes: 3`: the nodes flooded so far, to tell an outlet from a node below the level
        // whose flow runs back into the lake.
        let spills = self.plan.lakes >= 3;
        let mut lake: HashSet<(i64, i64)> = HashSet::default();
        if spills {
            lake.insert((i, k));
        }
        while let Some(Entry(h, ni, nk)) = heap.pop() {
            if h < level && !(spills && self.drains_into(ni, nk, &lake, floor)) {
                // The coarse network of `lakes: 7`: the nodes below the level that drain into
                // the lake are flooded too, also those popped after the outlet.
                outlet = outlet.or(Some((ni, nk)));
                if self.plan.whole_lakes {
                    continue;
                }
                break;
            }
            if outlet.is_some() && h >= level {
                break;
            }
            if flooded.len() >= self.plan.lake_max_nodes
                || (ni - i).abs().max((nk - k).abs()) > self.plan.lake_radius
            {
                if self.plan.full_floods && outlet.is_none() {
                    level = rise.1;
                    flooded.truncate(rise.0);
                }
                break;
            }
            if flooded.len() >= max_nodes {
                return ((level, flooded, outlet), false);
            }
            if h > level {
                rise = (flooded.len(), h);
            }
            level = level.max(h);
            flooded.push((ni, nk));
            if spills {
                lake.insert((ni, nk));
            }
            push(self, &mut heap, &mut seen, ni, nk);
        }
        ((level, flooded, outlet), true)
    }

    /// Whether a node below a lake's level belongs to its basin rather than being its outlet
    /// (`lakes: 3`): the steepest descent from `(i, k)` on the lattice ([`Network::lattice_down`],
    /// at most [`LAKE_WALK`] steps) reaches a node of `lake`, or ends in a pit no lower than the
    /// lake's `floor` (two pits on flat land, each the other's first node below its level: the
    /// flood goes on over both). So an outlet drains to the sea or to a pit lower than the
    /// lake's, and the pits along a chain of outlets fall strictly.
    fn drains_into(&mut self, i: i64, k: i64, lake: &HashSet<(i64, i64)>, floor: f32) -> bool {
        let mut at = (i, k);
        for _ in 0..LAKE_WALK {
            if lake.contains(&at) {
                return true;
            }
            match self.lattice_down(at.0, at.1) {
                Some(next) => at = next,
                None => return self.height(at.0, at.1) >= floor,
            }
        }
        false
    }
}

fn compute_heights(earth: &EarthPlan, plan: &RiverPlan, (bx, bz): (i64, i64)) -> HeightBlock {
    let m = BLOCK as usize + 2;
    let (i0, k0) = (bx * BLOCK - 1, bz * BLOCK - 1);
    let mut xs = Vec::with_capacity(m * m);
    let mut zs = Vec::with_capacity(m * m);
    for lk in 0..m {
        for li in 0..m {
            let (x, z) = plan.position(i0 + li as i64, k0 + lk as i64);
            xs.push(x);
            zs.push(z);
        }
    }
    let mut h = vec![0.0f32; m * m];
    let mut amp = vec![0.0f32; m * m];
    let (mut x, mut z) = ([0.0f32; LANES], [0.0f32; LANES]);
    let ero = [plan.erosion; LANES];
    let rough = [1.0f32; LANES];
    let mut out = [0.0f32; LANES];
    for start in (0..m * m).step_by(LANES) {
        let c = (m * m - start).min(LANES);
        x[..c].copy_from_slice(&xs[start..start + c]);
        z[..c].copy_from_slice(&zs[start..start + c]);
        // `kernel::heights`, keeping the relief amplitude its macro fields computed.
        let mut p = kernel::Partial::start(earth, &x, &z);
        amp[start..start + c].copy_from_slice(&p.amp[..c]);
        // `lakes: 6`: the lower of two LODs' heights, so the network sees the hollows the
        // finer one holds (module docs, step 1); the macro fields are shared.
        let hollow = plan.hollow_lod.map(|lod| {
            let mut q = p.clone();
            let mut below = [0.0f32; LANES];
            q.add_layers(earth, &earth.lods[lod].layers, &x, &z, &ero, &rough);
            q.finish(&mut below);
            below
        });
        let layers = &earth.lods[plan.node_lod].layers;
        p.add_layers(earth, layers, &x, &z, &ero, &rough);
        p.finish(&mut out);
        if let Some(below) = hollow {
            for (o, b) in out.iter_mut().zip(below) {
                *o = o.min(b);
            }
        }
        h[start..start + c].copy_from_slice(&out[..c]);
    }
    let n = BLOCK as usize;
    let mut down = vec![NONE; n * n];
    let mut relief = Vec::with_capacity(n * n);
    for lk in 0..n {
        for li in 0..n {
            let (ci, ck) = (li + 1, lk + 1);
            let (i, k) = (i0 + ci as i64, k0 + ck as i64);
            let c = ck * m + ci;
            relief.push(amp[c]);
            let hc = h[c];
            if hc < plan.sea_level_m {
                continue;
            }
            let mut best = 0.0f32;
            for (d, (di, dk)) in OFFSETS.iter().enumerate() {
                if !plan.linked(i, k, d) {
                    continue;
                }
                let o = (ck as i64 + dk) as usize * m + (ci as i64 + di) as usize;
                let drop = hc - h[o];
                if drop <= 0.0 {
                    continue;
                }
                let (dx, dz) = (xs[o] - xs[c], zs[o] - zs[c]);
                // Steepest descent with a hashed preference per link (Scheidegger's random
                // drainage on an inclined plane): on even slopes the rivers wander and merge
                // instead of running in parallel lattice rows.
                let bias = unit(hash2(
                    i as i32,
                    k as i32,
                    plan.seed ^ (0x2f6b_4c1d_u32.wrapping_mul(d as u32 + 1)),
                ));
                let slope =
                    drop / (dx * dx + dz * dz).sqrt() * (1.0 + ROUTE_NOISE * (2.0 * bias - 1.0));
                if slope > best {
                    best = slope;
                    down[lk * n + li] = d as u8;
                }
            }
        }
    }
    HeightBlock { h, down, relief }
}
