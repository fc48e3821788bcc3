//! Rivers and lakes of an `earth-1` world: a drainage network on a world-anchored node lattice,
//! evaluated on demand with a bounded dependency radius.
//!
//! Génevaux et al. (2013) build terrain from a hydrology-first river graph over a bounded map;
//! strata's world is unbounded and every tile must be produced alone, in any order, on any node.
//! So the network here is a pure function of the node lattice:
//!
//! 1. **Nodes.** Node `(i, k)` sits at `((i + ½ + j_x)·s, (k + ½ + j_z)·s)` with a hashed jitter
//!    `|j| ≤` [`JITTER`] (no lattice alignment), `s` = `spacing_m`. Its height `H` is the world's
//!    height function at the LOD whose spacing is [`NODE_LOD_FACTOR`] `· s` (relief finer than
//!    that is left to the carve), with the world's mean erosion; with `lakes: 6` (the default
//!    of new worlds) at most the height function at the LOD [`HOLLOW_LODS`] finer (spacing `s`;
//!    the coarse network's node LOD is clamped to the coarsest, so its finer one has a quarter
//!    of its spacing), so the network sees the hollows of a plain that the coarser LOD smooths
//!    over (there its heights stood up to 90 m above the ground, and a bowl kilometres wide held
//!    neither river nor lake) while the coarser LOD's valleys keep their depth.
//! 2. **Flow.** Neighbours are the four axis nodes and, per lattice cell, one hashed diagonal, so
//!    the graph is planar and no two rivers cross. A land node drains to the neighbour of steepest
//!    descent; a node below sea level is the sea; a land node with no lower neighbour is a pit,
//!    where a lake begins. Depends on a node's 3×3 neighbourhood only.
//! 3. **Discharge.** `Q(n) = min(upstream nodes including n, Q_MAX)`, computed by a depth-first
//!    count that stops once `Q_MAX` is reached, so it reads at most `Q_MAX` nodes upstream and is
//!    exact below the cap. It never falls downstream (`Q(down(n)) ≥ Q(n)`, also at the cap).
//! 4. **Water level.** `W(n) = max(H(n) − incision(Q(n)), B)`, `B` the level of the lake the
//!    flow reaches first (its pit's level; with `lakes: 6` the flow ends at the first node a
//!    lake covers, pit or not, and `B` is the highest level of the lakes covering it: a flow
//!    may cross a lake's water without meeting its pit, and a pit's lake may lie submerged in a
//!    higher lake whose flood took in its basin, step 5), or sea level: `H` falls strictly
//!    along the flow (out of a lake that
//!    spills, step 5, it climbs to the outlet, below the lake's level, which is the pit's `W`),
//!    the incision grows with `Q` and `B` never rises, so `W` never rises downstream.
//! 5. **Lakes.** From each pit a priority flood raises the level node by node until it reaches a
//!    node lower than the level (the outlet: the lake is full) or [`LAKE_MAX_NODES`] nodes /
//!    [`LAKE_RADIUS`] spacings (a lake in a basin too large to search is filled to that level;
//!    with `lakes: 7` it keeps the nodes it flooded before its level last rose, full to the
//!    height of the rim node that raised it, and drops those it reached beyond that rim, which
//!    lie below the level beside unvisited neighbours as low;
//!    in the coarse network of `lakes: 7` a flood that found its outlet goes on over the nodes
//!    below its level that drain into the lake, so none lies beside it below its level;
//!    [`LAKE_MAX_NODES_5`] and [`LAKE_RADIUS_5`] from `lakes: 5`, where the basins
//!    that a mountain belt's ridges close fill to their outlets and spill instead of holding a
//!    lake in their bottoms below a dry closed floor). Each pit's flood is computed once per
//!    world and kept in a bounded process cache.
//!    In worlds with `lakes` 1 and 2 rivers end in the lake and lakes do not spill. In worlds
//!    with `lakes` 3 to 5 (4: the default of new worlds) a node below the level whose steepest
//!    descent runs back into the lake, or into a pit no lower than the lake's, is flooded too (on
//!    flat land two neighbouring pits are each other's first node below the level), and a lake
//!    whose flood found an outlet spills there when the flow from the outlet reaches the sea,
//!    or first a lake whose `(level, index)` is lower (so levels never rise along a chain of
//!    spills and the flow has no cycle): its pit drains to the outlet, the discharge goes on,
//!    the water level through the lake is its level, and the carve cuts the rim down to it
//!    along the spill's edge (with `lakes: 6`, in the fine network, an edge from the saddle
//!    the outlet was found beyond, the lowest flooded node linked to it: from the pit the edge
//!    ran up to 29 km across the lake and the land beside it, a trench falling from the lake's
//!    level to the outlet's). In worlds with `lakes` 2 to 4 the ground is shaped to meet each
//!    lake's level along a curved shore ([`shores`]) before the carve, and with `lakes: 4` the
//!    carve keeps a sill there: it cuts no floodplain or valley wall below the lake's level on
//!    the land beside the water (the river that leaves a spilling lake, and those that join it
//!    near the outlet, run lower than the lake); with `lakes: 1` a sample
//!    is lake water where one of the four nodes around it holds a lake above its height, so the
//!    water can end along straight lines between dry nodes.
//! 6. **Carve.** Each edge `n → down(n)` with `Q(n) ≥ 2` is a uniform Catmull–Rom curve through
//!    the main upstream neighbour, `n`, `down(n)` and its successor, cut into [`PIECES`]
//!    ([`PIECES_2`] with `valleys: 2`) straight pieces with `W` linear along it; with
//!    `valleys: 3` and later (`6` is the default of new worlds) into [`PIECES_3`] pieces, each a
//!    cubic offset from its chord that leaves and reaches its ends along the curve's tangents
//!    ([`Piece::sax`]; the edge's hashed bend is flat at the nodes), so the centre line has no
//!    corner and the valley's walls follow the curve instead of showing a facet per piece.
//!    Each piece
//!    lowers the samples within its reach (at most [`REACH`] spacings) to its valley profile: the
//!    parabola `W − c·(1 − (d/b)²)` inside the channel (`b` half-width, `c` depth, from the
//!    discharge, `d` the distance to the piece) and the walls below outside it; a sample takes
//!    the lowest of the pieces' profiles, at most [`CARVE_MAX_M`] below its height. Where a
//!    channel holds water, the vertex is `river` water.
//!    Valley walls ([`profile`]): above the water a sample keeps its height above `W`
//!    scaled by a smoothstep of its distance from the floor's edge `F` to the valley's
//!    half-width `V' = clamp(F + (h − W) / WALL_SLOPE, V, R)`, so walls average [`WALL_SLOPE`]
//!    however high they climb. In worlds with `valleys: 1` the floor ends at the channel
//!    (`F = b`) and the narrowest valley `V` is [`VALLEY_MIN`], growing by discharge to the
//!    reach (a kilometre and more): every sample between rivers lies in a valley, pulled down
//!    towards the planes of their water levels, which draws straight facets across the plains.
//!    With `valleys: 2` and `3` the floor is a flat floodplain at `W`
//!    ([`FLOODPLAIN`] channel half-widths plus [`FLOODPLAIN_MIN_M`]), `V` twice that, so a
//!    valley is as wide as its walls need and the land beyond keeps its own shape; and the flat
//!    floor keeps a valley sampled at 64 m from reading as a chain of pits. With `valleys: 3`
//!    `V'` grows by 0 to 90 m of value noise ([`WALL_NOISE`]), so the walls of valleys in the
//!    plains reach out in embayments between spurs instead of running as even banks. With
//!    `valleys: 4` (and `5`) each piece's floodplain half-width and wall slope
//!    are linear between values at its ends ([`RiverPlan::valley_shape`]: the `valleys: 3`
//!    floodplain times [`FLOOR_SCALE`], [`WALL_SLOPE`] times [`SLOPE_SCALE`], by value noise of
//!    the end's position, shared by the pieces that meet there), so a valley narrows to a gorge
//!    and opens to a wide floor, and its walls steepen to bluffs and ease to long banks, along
//!    its river; at 8 m spacing the `valleys: 3` floors of one width between walls of one slope
//!    read as canals. With `valleys: 5` (the valleys of `4`) each
//!    wall's smoothstep runs over a place bent by a spur value ([`SPUR`]), linear along each
//!    piece between the spur noise at its ends ([`Piece::spur_a`]) and taken at the sample's
//!    foot on the piece: spurs and hollows run straight down each wall to its river, and where the walls of two
//!    valleys meet (in mountains, everywhere: their walls are as wide as the reach) the crease
//!    wanders with both rivers' spurs instead of running straight, equidistant from them.
//!    With `valleys: 6` (new worlds until `7`: the valleys of `5`) an edge's walls are
//!    gentler where the relief is lower ([`RELIEF_WALLS_MIN`]): in plains a river runs in a
//!    broad swale between low rises rather than a trench between flat banks. With `valleys: 7`
//!    (new worlds until `8`: the valleys of `6`) only the larger rivers carve where the
//!    relief is high ([`RELIEF_SOURCE_Q`]): an edge whose discharge is below
//!    `1 + RELIEF_SOURCE_Q · a²` (`a` the relief above [`RELIEF_SOURCE_FROM`]), and neither out
//!    of nor into a lake, carves no valley and holds no water, so a range's surface between its
//!    larger valleys is its own relief and gullies rather than the walls of a
//!    stream every kilometre. With `valleys: 8` (the default of new worlds: the valleys of `7`)
//!    a valley is sized by its river ([`RiverPlan::size_of`], full from [`SIZED_Q`]): the
//!    floodplain beyond the channel's share and the edge's bend shrink with the discharge, to a
//!    sixth of the floodplain and [`SMALL_BEND`] of the bend at a source, so a plain's brooks
//!    run nearly straight in V-shaped valleys that join into trees instead of winding as
//!    flat-floored trenches; and each tile's job widens every floodplain to [`LOD_FLOOR`] of
//!    its vertex spacing (an 8 m floor is stepped over at 64 m spacing, a chain of pits).
//!
//! Seams: pieces and lakes are functions of nodes only, and a piece farther than its reach from
//! a sample returns its height unchanged, bit for bit ([`profile`]), so every tile
//! that contains a vertex computes its height and water bit for bit alike. Node data are
//! memoised in process-wide caches (`moka`, bounded in bytes, keyed by the world's fingerprint):
//! the cache changes the time, never the bytes.
//!
//! LODs: the carve (and the lake shores before it) runs at LODs `0..=MAX_CARVE_LOD` (spacing up
//! to a quarter of a node spacing by default); coarser tiles skip it (in worlds with `lakes: 5`
//! their water still shows the lakes, the lake field of the shores over their uncarved heights:
//! [`lake_job_for`]; before, a lake vanished beyond `MAX_CARVE_LOD`, and the basin it fills
//! stood open beside the water of the finer tiles), and their LOD bound grows by
//! [`CARVE_MAX_M`], the most the carve may remove, and in worlds with shores by
//! [`SHORE_MAX_M`], the most the shores change. (Finer LODs carve with the same pieces, and a
//! sample's carved height moves by no more than its uncarved height does — each profile's slope
//! in `h` lies in [−¼, 1] (in (−1, 1] with the spurs of `valleys: 5`), the shores' in [0, 1],
//! and the minimum over pieces keeps that — so
//! their bound stands; in `valleys: 8` worlds a tile widens the floodplains to its spacing,
//! and the bound of those LODs grows by [`widened_floor_bound_m`].)
//!
//! The coarse network (worlds with `coarse: 1`, the default of new worlds): the tiles of LODs
//! `MAX_CARVE_LOD + 1 ..=` [`MAX_COARSE_LOD`] (512 m and 1 km with the default 1 m cell) are
//! carved by a second network, the same function of a node lattice [`COARSE_FACTOR`] times as
//! coarse ([`RiverPlan::new`] with `coarse`: its own fingerprint and lattice seeds), whose node
//! heights come from the coarsest LOD; a node stands for `COARSE_FACTOR²` fine nodes
//! ([`RiverPlan::q_scale`]) wherever a discharge sets a size, and its floodplains are at least
//! [`COARSE_FLOOR_M`] wide each side, so a 512 m sample grid finds the valley floors without
//! pits; its floods search as far and over as much land as the fine network's (a radius and
//! a node count scaled by the spacings), so its lakes fill the basins the fine network's fill;
//! with `lakes: 7` they search 30 of its own spacings (123 km) over at most
//! [`COARSE_LAKE_MAX_NODES_7`] nodes ([`COARSE_LAKE_MAX_NODES_8`] with `lakes: 8`), so the
//! basins a hundred kilometres across that stopped
//! both networks' floods fill to their outlets in the tiles seen from afar (the fine network's
//! lakes there stay as they were: a tile of LOD 8 can show such a basin's lake lower than
//! LOD 9 does), and its spilling lakes leave from their saddles too.
//! In `lakes: 5` worlds tiles coarser still show its lakes. Without it the 512 m surface was
//! the uncarved relief: no valleys, and 15 to 24 % of its land in closed basins (`bench
//! realism`). The two networks are computed apart, so their rivers and lakes agree only where
//! both follow the same slopes (its lakes lie where the fine network's do, in other outlines):
//! a tile of LOD 9 shows the coarse network's valleys and lakes, its finer neighbours the fine
//! network's, and the two differ by at most twice the carve and the shores (the LOD bound of
//! those LODs grows by that).

mod carve;
mod lanes;
mod lines;
mod network;
mod shores;
mod water;

pub use carve::{
    job_for, lake_job_for, profile, spur_step, water_at, water_job_for, Edge, Piece, PrunedBins,
    RiverJob, PIECE_LEN2_EPS,
};
pub use lines::{LineEnd, RiverLine};
pub use network::{clear_caches, Lake, Network, Node, NodeId};
pub use shores::{
    LakeField, Sill, SHORE_FULL, SHORE_GENTLE_M, SHORE_MAX_M, SHORE_N1, SHORE_N2, SHORE_NOISE,
    SHORE_NOISE2_INV_M, SHORE_NOISE_CLAMP, SHORE_NOISE_INV_M, SHORE_NOISE_M, SHORE_STEEP_M,
    SHORE_WARP, SHORE_WARP_WAVE, SILL_E, SILL_FULL, SINK_FROM, SINK_MAX_M, SINK_SCALE,
};

use super::super::hash::{hash2, mix32, purpose, stream, unit};
use super::super::noise::lattice;
use super::params::RiverParams;

/// The node heights come from the LOD whose spacing is this many node spacings: relief finer
/// than a few node spacings is left out, so the drainage follows the larger slopes and cuts
/// through smaller hills rather than ending in a pit behind each.
pub const NODE_LOD_FACTOR: f32 = 4.0;
/// With `lakes: 6` the node heights are at most the heights of the LOD this many finer than
/// the node LOD ([`RiverPlan::hollow_lod`]).
pub const HOLLOW_LODS: usize = 2;
/// Nodes per side of a block of the piece cache.
pub const PIECE_BLOCK: i64 = 8;
/// Nodes per block side of the caches.
pub const BLOCK: i64 = 32;
/// Largest discharge counted, in nodes: rivers wider than this basin look alike.
pub const Q_MAX: u32 = 4096;
/// Largest jitter of a node from its cell centre, in spacings.
pub const JITTER: f32 = 0.3;
/// Largest bend of an edge's middle across it, in units of its length.
pub const MEANDER: f32 = 0.35;
/// [`MEANDER`] of `valleys: 2` worlds: their narrow valleys show the lattice's directions more
/// than the wide ones did, so the edges bend further.
pub const MEANDER_2: f32 = 0.5;
/// Straight pieces per river edge in `valleys: 1` worlds.
pub const PIECES: usize = 4;
/// Straight pieces per river edge in `valleys: 2` worlds: a valley as narrow as its walls shows
/// the corners of four pieces, so the centre line follows its curve closer (eight, not more:
/// the carve's cost grows with the pieces a sample is tested against).
pub const PIECES_2: usize = 8;
/// Bent pieces per river edge in `valleys: 3` worlds: each is a parabola through the curve's
/// point halfway along it, whose ends' tangents nearly agree with its neighbours', so four
/// follow the curve without the facets of eight straight ones, at half their cost.
pub const PIECES_3: usize = 4;
/// A lake's flood visits at most this many nodes (worlds with `lakes` 1 to 4).
pub const LAKE_MAX_NODES: usize = 256;
/// A lake's flood stays within this many spacings of its pit (Chebyshev distance; worlds with
/// `lakes` 1 to 4).
pub const LAKE_RADIUS: i64 = 12;
/// [`LAKE_MAX_NODES`] of worlds with `lakes: 5`: the basins the mountain belts' ridges close,
/// tens of kilometres across, fill to their outlets.
pub const LAKE_MAX_NODES_5: usize = 2048;
/// [`LAKE_RADIUS`] of worlds with `lakes: 5`: one less than a block, so the pits whose lakes
/// can reach a block lie in the eight blocks around it (a larger radius reads a ring of blocks
/// more for every block: a quarter more time for cold coarse tiles).
pub const LAKE_RADIUS_5: i64 = 30;
/// Most nodes a flood of the coarse network visits in worlds with `lakes: 7`, whose coarse
/// floods search [`LAKE_RADIUS_5`] of its own spacings (123 km at the default 4 km): a
/// basin of a hundred kilometres fills to its outlet, where the fine network's radius in
/// coarse spacings (8) stopped the floods of the far area's largest basins 20 to 40 km short of
/// it (512 nodes of 16.8 km²; 2 048 closed 0.05 % of that area's land more).
pub const COARSE_LAKE_MAX_NODES_7: usize = 512;
/// Most nodes a flood of the coarse network visits in worlds with `lakes: 8`: the largest
/// basins of the default world, about 150 km across, held a lake in the bottom of a dry closed
/// bowl after 512 nodes (8,600 km²; `bench realism`'s worst 512 m area, 24.8 % of its land in
/// closed depressions) and fill to their outlets with 2,048.
pub const COARSE_LAKE_MAX_NODES_8: usize = 2048;
/// A pit whose lake would be shallower than this, metres, drains over its saddle instead.
pub const BREACH_DEPTH_M: f32 = 20.0;
/// Rivers are incised in full within half this many steps of where their flow ends (the sea or
/// a lake), less farther up, and not at all beyond it.
pub const LAKE_WALK: usize = 384;
/// Reach of a river's valley, in node spacings.
pub const REACH: f32 = 1.5;
/// Farthest a river line's chord strays from the curve of the piece it follows, metres
/// (`lines: 2`): less than the finest tile's vertex spacing, so a client that draws the river
/// along the line covers the carved channel's water.
pub const LINE_TOLERANCE_M: f32 = 1.0;
/// Most points a river line adds per piece (`lines: 2`).
pub const LINE_MAX_STEPS: usize = 32;
/// Mean slope of the valley walls the carve makes where the valley is deep (rise over run,
/// about 25°; the smoothstep's steepest point is 1.5 times that).
pub const WALL_SLOPE: f32 = 0.47;
/// Amplitude of the `valleys: 3` walls' width noise, metres: a wall is as wide as the height it
/// climbs over [`WALL_SLOPE`] plus `WALL_NOISE·(n + WALL_NOISE_CLAMP)`, with `n` value noise of
/// wavelength [`WALL_NOISE_M`] clamped to ±[`WALL_NOISE_CLAMP`] (0 to 90 m more), so the walls
/// of valleys in plains reach out in embayments and keep the design slope at the spurs between
/// them, instead of running as a canal's even banks; no wall is steeper than without the
/// noise, and the deep valleys of mountains, whose walls are hundreds of metres wide, barely
/// change.
pub const WALL_NOISE: f32 = 30.0;
/// Wavelength of the walls' width noise, metres.
pub const WALL_NOISE_M: f32 = 192.0;
/// `1 / WALL_NOISE_M`, 1/m: the noise is read at `(x, z) · WALL_NOISE_INV_M` (CPU and WGSL).
pub const WALL_NOISE_INV_M: f32 = 1.0 / WALL_NOISE_M;
/// Largest magnitude of the walls' noise value `n`.
pub const WALL_NOISE_CLAMP: f32 = 1.5;
/// Largest spur value of the `valleys: 5` walls: a sample's place `u` in `[0, 1]` between the
/// floor's edge and the valley's edge is bent to `u + s·u·(1 − u)`, `s` linear along each piece
/// between `SPUR ·` value noise of wavelength [`SPUR_M`] read at its ends and clamped as the
/// walls' noise is ([`WALL_NOISE_CLAMP`]). A wall rises sooner where `s > 0` (a spur reaching
/// towards the river) and later where `s < 0` (a hollow between spurs); since `s` depends on
/// the sample's foot on the river only, spurs and hollows run straight down the wall to the
/// river, as they do on eroded valley sides, and where the walls of two valleys meet, the
/// crease between them wanders with both rivers' spurs instead of running as the straight line
/// equidistant from them. `|s| < 1`, so the bent place still rises monotonically across the
/// wall: the spurs add no pit. (Reading the noise at the ends, not at each foot, keeps the
/// carve's cost: a sample pays one interpolation per piece.)
pub const SPUR: f32 = 0.9;
/// Wavelength of the spur noise along the river, metres.
pub const SPUR_M: f32 = 560.0;
/// `1 / SPUR_M`, 1/m: the spur noise is read at the foot's `(x, z) · SPUR_INV_M` (CPU and WGSL).
pub const SPUR_INV_M: f32 = 1.0 / SPUR_M;
/// Wavelength of the `valleys: 4` noise that scales a floodplain's width along its river,
/// metres: about four pieces of a default edge, so the width's piecewise-linear course between
/// piece ends shows no corners.
pub const FLOOR_NOISE_M: f32 = 960.0;
/// Smallest and largest factor of a `valleys: 4` floodplain's width: from a narrow floor between
/// close walls to a floodplain 1.75 times the `valleys: 3` one (but see [`FLOOR_NARROWEST_M`]).
pub const FLOOR_SCALE: (f32, f32) = (0.3, 1.75);
/// Narrowest half-width a `valleys: 4` floodplain narrows to, metres (a floodplain narrower
/// than this to begin with keeps its width): a floor narrower than about a 64 m sample spacing
/// is sampled as a chain of pits, and the closed-depression figure of `bench realism` at 64 m
/// rose above 5 % with floors down to 8 m.
pub const FLOOR_NARROWEST_M: f32 = 40.0;
/// Wavelength of the `valleys: 4` noise that scales the walls' slope along a river, metres.
pub const SLOPE_NOISE_M: f32 = 700.0;
/// Smallest and largest factor of the `valleys: 4` walls' mean slope ([`WALL_SLOPE`]): from
/// eased banks (about 18°) to steep bluffs (about 35°). Gentler walls are wider, and the carve
/// of a LOD-6 tile cost a quarter more with factors down to 0.55.
pub const SLOPE_SCALE: (f32, f32) = (0.7, 1.5);
/// Smallest factor of the `valleys: 6` walls' slope, where the relief is lowest: a wall's slope
/// (from [`RiverPlan::valley_shape`]) is scaled by `RELIEF_WALLS_MIN + (1 − RELIEF_WALLS_MIN)·√r`
/// (at most 1), `r` the relief amplitude of the macro fields at the edge's upper node over the
/// world's largest (`EarthPlan::inv_relief_max`): about 0.52 in the default world's plains
/// (walls of 10° to 20° instead of 18° to 35°), 0.7 in its hill country, 1 in the highest
/// mountains. Valleys cut into low land have gentle sides: with walls as steep as the
/// mountains' the rivers of a plain, a valley every kilometre, read at 64 m as a maze of
/// trenches between flat ground. Gentler walls are wider, and the carve's cost grows with the
/// samples they cover: with this factor a LOD-0 tile of `bench tiles`' plains strip costs
/// about 6.6 % more than with `valleys: 5` (0.3: 8 %).
pub const RELIEF_WALLS_MIN: f32 = 0.4;
/// Where the relief is high, `valleys: 7` carves only the larger rivers: an edge carves a valley
/// (and holds water) when its discharge is at least `1 + RELIEF_SOURCE_Q · a²` nodes, where
/// `a = max(0, (r − RELIEF_SOURCE_FROM) / (1 − RELIEF_SOURCE_FROM))` and `r` is the relief
/// amplitude of the macro fields at its upper node over the world's largest (as for
/// [`RELIEF_WALLS_MIN`]): every edge in plains and low hills (`r` up to 0.3; the origin's plain
/// reads 0.17–0.23), from 9 nodes at `r` 0.65, from 33 in the highest mountains. With an edge
/// carving every kilometre, a range's walls (as wide as the reach) covered all of it, and its
/// surface was the walls' bowls meeting in creases (a median cut of 250 m in the range at
/// (114.7 km, 114.7 km) at 8 m, 2 % of its samples cut by more than a metre after), with the
/// relief's own ridges, spurs and gullies scaled away. The edges out of and into a lake carve
/// whatever their discharge: the shores lower the land beside a lake towards its level by at
/// most [`SHORE_MAX_M`], faded in over the lake weight, and against uncarved mountains that fade
/// stood as a wall a node spacing from the water (at (112.1 km, 126.5 km), 0.6 % of the 8 m
/// steps steeper than 63°).
pub const RELIEF_SOURCE_Q: f32 = 32.0;
/// The relief (over the world's largest) up to which `valleys: 7` carves every edge
/// ([`RELIEF_SOURCE_Q`]): the plains keep the valleys that drain their hollows.
pub const RELIEF_SOURCE_FROM: f32 = 0.3;
/// The discharge, in nodes of the fine network, from which a `valleys: 8` valley has its full
/// size ([`RiverPlan::size_of`]): `valleys: 7`'s floodplain and bend. A smaller river's valley
/// grows with `log2(1 + Q)`, from a sixth of that size for a source (`Q = 1`).
pub const SIZED_Q: f32 = 63.0;
/// The share of [`MEANDER_2`] that the edge of a source keeps in `valleys: 8` worlds; larger
/// rivers bend further, in full from [`SIZED_Q`]. A brook runs nearly straight between its
/// confluences a kilometre apart, and its valley with it: the full bend on every edge drew the
/// plains' small valleys as a maze of worm-like trenches.
pub const SMALL_BEND: f32 = 0.3;
/// A `valleys: 8` job widens every floodplain to at least this many vertex spacings each side
/// ([`job_for`]): a coarse tile then samples each valley floor on every row and column that
/// crosses it instead of stepping over a narrow floor into a chain of pits (the smallest
/// valleys' floors are 8 m wide each side, a LOD-6 tile's vertices 64 m apart).
pub const LOD_FLOOR: f32 = 0.5;
/// The most a `valleys: 8` tile of vertex spacing `spacing_m` lowers a sample by widening its
/// floodplains to [`LOD_FLOOR`] spacings, in a network of nodes `node_spacing_m` apart (metres;
/// 0 where no floodplain is narrower: spacings up to 16 m): the added width, beyond the
/// narrowest floodplain (a source's, `FLOODPLAIN_MIN_M / log2(1 + SIZED_Q)`), times the
/// steepest a carved wall climbs. A wall's smoothstep climbs at most `1.5 · (1 + SPUR)` times
/// its mean slope, which is at most the steepest [`WALL_SLOPE`] (times [`SLOPE_SCALE`]'s largest
/// factor), or, where the wall is clamped to the valley's reach, [`CARVE_MAX_M`] over what the
/// floor leaves of the narrowest reach (`3 · VALLEY_MIN`, at most `REACH` node spacings; a
/// floodplain is at most half its reach before the widening); and never more than the carve's
/// own limit.
pub fn widened_floor_bound_m(spacing_m: f32, node_spacing_m: f32) -> f32 {
    let narrowest = FLOODPLAIN_MIN_M / libm::log2f(1.0 + SIZED_Q);
    let added = (LOD_FLOOR * spacing_m - narrowest).max(0.0);
    if added == 0.0 {
        return 0.0;
    }
    let reach = (3.0 * VALLEY_MIN).min(REACH * node_spacing_m);
    let wall = reach - (0.5 * reach).max(LOD_FLOOR * spacing_m);
    if wall <= 0.0 {
        return CARVE_MAX_M;
    }
    let mean = (WALL_SLOPE * SLOPE_SCALE.1).max(CARVE_MAX_M / wall);
    (1.5 * (1.0 + SPUR) * mean * added).min(CARVE_MAX_M)
}

/// Half-width of a `valleys: 2` floodplain in channel half-widths, plus [`FLOODPLAIN_MIN_M`].
pub const FLOODPLAIN: f32 = 4.0;
/// Half-width of the smallest `valleys: 2` floodplain, metres.
pub const FLOODPLAIN_MIN_M: f32 = 50.0;
/// Edges out of nodes with less discharge than this carve no valley.
pub const MIN_VALLEY_Q: u32 = 1;
/// Half-width of the smallest valleys, metres.
pub const VALLEY_MIN: f32 = 250.0;
/// Strength of the hashed preference between descending links, in [0, 1).
pub const ROUTE_NOISE: f32 = 0.6;
/// Runoff: discharge per square kilometre of basin, m³/s (about 630 mm a year).
pub const RUNOFF_M3S_PER_KM2: f32 = 0.02;
/// Coarsest LOD that the network of `spacing_m` carves.
pub const MAX_CARVE_LOD: usize = 8;
/// Coarsest LOD that the coarse network carves (in worlds with `coarse: 1`): LODs
/// `MAX_CARVE_LOD + 1 ..= MAX_COARSE_LOD`, spacings up to a quarter of its node spacing by
/// default, as the fine network's.
pub const MAX_COARSE_LOD: usize = 10;
/// The coarse network's node spacing in node spacings of the fine one.
pub const COARSE_FACTOR: f32 = 4.0;
/// Narrowest half-width of the coarse network's floodplains, metres: a floor narrower than the
/// spacing of the LODs it carves (512 m and more) is sampled as a chain of pits, which the
/// closed-depression figure at 512 m counted (a floor wider than `512·√2 / 2` m holds a chain of
/// samples joined diagonally all along it).
pub const COARSE_FLOOR_M: f32 = 400.0;
/// Deepest cut of the carve below the uncarved height, metres: the LOD bound of the coarser
/// LODs that skip it.
pub const CARVE_MAX_M: f32 = 600.0;

/// Water kinds of a vertex (tile format v2).
pub mod kind {
    /// Dry ground.
    pub const NONE: u8 = 0;
    /// Below sea level.
    pub const SEA: u8 = 1;
    /// Inside a lake filled to its level.
    pub const LAKE: u8 = 2;
    /// Inside a river's channel.
    pub const RIVER: u8 = 3;
}

/// `down` of a node that drains nowhere (the sea or a pit).
const NONE: u8 = 255;
/// Neighbour offsets in a fixed order (the tie-break of equal descents).
const OFFSETS: [(i64, i64); 8] = [
    (1, 0),
    (0, 1),
    (-1, 0),
    (0, -1),
    (1, 1),
    (-1, 1),
    (-1, -1),
    (1, -1),
];

/// The river settings of a world, resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct RiverPlan {
    /// Node spacing, metres.
    pub spacing_m: f32,
    /// Stream seed of the node jitter and diagonals.
    pub seed: u32,
    /// LOD whose height function gives the node heights.
    pub node_lod: usize,
    /// With `lakes: 6`, the finer LOD (two LODs finer than `node_lod`: one node spacing in the
    /// fine network) whose heights bound the node heights from above, so the network sees the
    /// hollows that the coarser LOD smooths over; `None` before.
    pub hollow_lod: Option<usize>,
    /// Whether a flow ends where it first reaches a lake's water (a node a lake covers), its
    /// water levels resting on the highest level of the lakes covering that node (`lakes: 6`);
    /// before, a flow ended at a lake's pit only and rested on that pit's own level, so a river
    /// that crossed a lake's water without meeting its pit, or ended in a lake submerged by a
    /// higher one, was cut below the water the tiles show.
    pub lake_ends: bool,
    /// Whether a bent piece's line touches a rectangle only where one of the chords within
    /// [`LINE_TOLERANCE_M`] of its curve does (`lakes: 6`, whose lakes spill over more long
    /// edges); before, where the box around its chord widened by the largest bend did, so a
    /// long edge's line was listed for tiles kilometres from its curve.
    pub exact_lines: bool,
    /// Whether a spilling lake's edge starts at its saddle instead of its pit
    /// (`Network::saddle`): the fine network of `lakes: 6` worlds, both networks of `lakes: 7`.
    /// The coarse network of `lakes: 6` keeps the edge from the pit: its floods stop within 8
    /// of its spacings, its lakes' levels often lie below the ground between its nodes, and the
    /// edge from the pit is the valley that opens such a basin (with saddles the origin's 512 m
    /// square read 5.1 % of its land in closed depressions, against 4.5 %). With the wider
    /// floods of `lakes: 7` those basins fill to their outlets, and the edges from their pits,
    /// as long as the floods, cut arcs of trench 40 km and more across the land (origin 2.9 %
    /// with saddles).
    pub saddles: bool,
    /// Discharge (nodes) from which a channel holds water.
    pub wet_q: u32,
    /// Incision of the largest rivers below the node heights, metres.
    pub incision_m: f32,
    /// World sea level, metres.
    pub sea_level_m: f32,
    /// Erosion strength of the node heights (the biomes' mean).
    pub erosion: f32,
    /// Identifies the world function the network is computed from (the seed and every setting
    /// the node heights read), so worlds and versions that share it share cached blocks.
    pub fingerprint: u64,
    /// `RiverParams::valleys` (step 6): 1 for the first valleys, 2 for floodplain valleys.
    pub valleys: u32,
    /// Pieces per edge: [`PIECES`], [`PIECES_2`] with `valleys: 2`, [`PIECES_3`] with
    /// `valleys: 3`.
    pub pieces: usize,
    /// Largest bend of an edge: [`MEANDER`], or [`MEANDER_2`] with `valleys: 2`.
    pub meander: f32,
    /// Amplitude of the walls' width noise, metres: [`WALL_NOISE`] with `valleys: 3`, else 0.
    pub wall_noise: f32,
    /// Stream seed of the walls' width noise.
    pub wall_seed: u32,
    /// Whether each piece's floodplain width and wall slope vary along the river
    /// (`valleys: 4` and later, [`FLOOR_SCALE`], [`SLOPE_SCALE`]).
    pub varied_valleys: bool,
    /// Whether the walls' slope falls with the relief (`valleys: 6`, [`RELIEF_WALLS_MIN`]).
    pub relief_walls: bool,
    /// Whether only the larger rivers carve where the relief is high (`valleys: 7`,
    /// [`RELIEF_SOURCE_Q`]).
    pub relief_sources: bool,
    /// Whether a valley's floodplain and bend grow with its river's discharge and every
    /// floodplain is at least [`LOD_FLOOR`] vertex spacings wide (`valleys: 8`, [`SIZED_Q`]).
    pub sized_valleys: bool,
    /// `SPUR / WALL_NOISE_CLAMP` with `valleys: 5` and later (the spurs of the walls, [`SPUR`]),
    /// else 0 ([`RiverPlan::spur_at`]).
    pub spur_scale: f32,
    /// Stream seed of the spur noise.
    pub spur_seed: u32,
    /// Stream seeds of the `valleys: 4` floodplain and slope noises.
    pub valley_seeds: [u32; 2],
    /// `RiverParams::lakes`: 1 for the first lakes, 2 for lakes with shaped shores
    /// ([`shores`]).
    pub lakes: u32,
    /// Most nodes a lake's flood visits: [`LAKE_MAX_NODES`], or [`LAKE_MAX_NODES_5`] from
    /// `lakes: 5` (divided by [`RiverPlan::q_scale`] in the coarse network, whose floods cover
    /// the fine network's land; [`COARSE_LAKE_MAX_NODES_7`] there with `lakes: 7`,
    /// [`COARSE_LAKE_MAX_NODES_8`] from `lakes: 8`).
    pub lake_max_nodes: usize,
    /// Chebyshev radius of a lake's flood, node spacings: [`LAKE_RADIUS`], or
    /// [`LAKE_RADIUS_5`] from `lakes: 5` (in the coarse network scaled to the same metres,
    /// rounded up, but [`LAKE_RADIUS_5`] of its own spacings with `lakes: 7`).
    pub lake_radius: i64,
    /// Whether a flood stopped by its limits keeps only the nodes it flooded before its level
    /// last rose, full to the height of the rim node that raised it (`lakes: 7`; module docs,
    /// step 5): before, it kept every node it had flooded, also those it had reached beyond the
    /// rim that set the level, lower than the level and dry beside their unvisited neighbours
    /// as low, so the shores flattened a closed dry floor below the level there.
    pub full_floods: bool,
    /// Whether a flood that found its outlet goes on over the nodes below its level that drain
    /// into the lake, popped after the outlet (module docs, step 5): the coarse network of
    /// `lakes: 7`. Its wider floods took in, by the rule for flat pits, a node of a lower lake's
    /// basin beside the outlet and stopped at the outlet before its neighbour, lower than their
    /// level and draining into the lake through it: the lower lake covered that neighbour, and
    /// the water level rose 3.3 m along the flow from it (`tests/rivers.rs`). In the fine
    /// network the same rule grew the origin's long lake over its 8 m square and the
    /// temperate–taiga border that `bench realism` measures, and is left for a later version.
    pub whole_lakes: bool,
    /// Whether the shoreline's noise octaves fade with the tile's vertex spacing
    /// ([`RiverPlan::shore_noise`], `lakes: 7`).
    pub lod_shores: bool,
    /// Whether the shores sink the ground inside a lake towards its nodes' heights
    /// ([`shores`]' step 3, `lakes: 8`): the relief between the nodes, which they do not see,
    /// raised ridges hundreds of metres above the level inside a lake, and every pool they cut
    /// off from the outlet was a closed depression.
    pub sink: bool,
    /// Stream seeds of the shores' two noise octaves and of their warp's x and z.
    pub shore_seeds: [u32; 4],
    /// Nodes of the fine network a node of this one stands for: 1, or `COARSE_FACTOR²` for the
    /// coarse network. Discharges are counted in this network's nodes and scaled by it where
    /// they set a size (channels, incision, the water threshold), so a river of a given basin
    /// is as wide and as deep in both networks; the relief threshold of `valleys: 7`
    /// ([`RELIEF_SOURCE_Q`]) reads the unscaled count, so in high relief only the coarse
    /// network's larger rivers carve, as in the fine one.
    pub q_scale: u32,
    /// Narrowest half-width of a floodplain, metres: 0 (no bound beyond
    /// [`FLOOR_NARROWEST_M`]'s), or [`COARSE_FLOOR_M`] for the coarse network.
    pub floor_min_m: f32,
    /// Whether a job also reads the long edges of pits beyond its blocks (worlds with
    /// `coarse: 1`): a breached pit or a spilling lake drains to an outlet up to the flood's
    /// radius away, and a job that read only the piece blocks within a few spacings of its
    /// rectangle missed such an edge's pieces where its pit lay farther, so two jobs over the
    /// same sample (two tiles, or a tile and the coarser edge a finer tile snaps to) could
    /// carve it differently. Worlds stored before keep their bytes.
    pub long_edges: bool,
    /// Whether the river lines follow each piece's curve within [`LINE_TOLERANCE_M`] and
    /// include the long edges of pits beyond the nodes around their rectangle (`lines: 2`);
    /// else a bent piece's ends and middle, and the edges of nodes near the rectangle only.
    pub dense_lines: bool,
}

impl RiverPlan {
    /// The plan of `params` in a world of LOD-0 spacing `cell_m` (the node heights come from the
    /// LOD of spacing `NODE_LOD_FACTOR` node spacings, clamped to the world's LODs); `world` is
    /// the serialised world settings the node heights depend on (hashed with the seed into the
    /// fingerprint).
    ///
    /// With `coarse` the plan is the coarse network's ([`MAX_COARSE_LOD`]): nodes
    /// [`COARSE_FACTOR`] times as far apart, its own fingerprint and lattice seeds.
    pub fn new(
        seed: u64,
        params: &RiverParams,
        cell_m: f32,
        sea_level_m: f32,
        erosion: f32,
        world: &[u8],
        coarse: bool,
    ) -> Self {
        let (domain, spacing_m, q_scale): (&[u8], f32, u32) = if coarse {
            let f = COARSE_FACTOR;
            (
                b"strata rivers coarse v1",
                params.spacing_m * f,
                (f * f) as u32,
            )
        } else {
            (b"strata rivers v1", params.spacing_m, 1)
        };
        let fingerprint = super::fingerprint(domain, seed, world);
        let lod = libm::log2((spacing_m * NODE_LOD_FACTOR / cell_m) as f64).floor();
        let node_lod = lod.clamp(0.0, super::super::plan::MAX_LOD as f64) as usize;
        // A radius of the fine network's, in this network's spacings.
        let scaled = |r: i64| (r as f32 * (params.spacing_m / spacing_m)).ceil() as i64;
        Self {
            spacing_m,
            q_scale,
            floor_min_m: if coarse { COARSE_FLOOR_M } else { 0.0 },
            long_edges: params.coarse >= 1,
            dense_lines: params.lines >= 2,
            seed: stream(seed, purpose::EARTH, if coarse { 420 } else { 400 }),
            node_lod,
            hollow_lod: (params.lakes >= 6).then(|| node_lod.saturating_sub(HOLLOW_LODS)),
            lake_ends: params.lakes >= 6,
            exact_lines: params.lakes >= 6,
            saddles: params.lakes >= 7 || (params.lakes == 6 && !coarse),
            full_floods: params.lakes >= 7,
            whole_lakes: params.lakes >= 7 && coarse,
            lod_shores: params.lakes >= 7,
            sink: params.lakes >= 8,
            wet_q: if coarse {
                ((8.0 / params.density) / q_scale as f32).ceil().max(1.0) as u32
            } else {
                ((8.0 / params.density).round() as u32).max(2)
            },
            incision_m: params.incision_m,
            sea_level_m,
            erosion,
            fingerprint,
            wall_noise: if params.valleys >= 3 { WALL_NOISE } else { 0.0 },
            wall_seed: stream(seed, purpose::EARTH, 401),
            varied_valleys: params.valleys >= 4,
            relief_walls: params.valleys >= 6,
            relief_sources: params.valleys >= 7,
            sized_valleys: params.valleys >= 8,
            spur_scale: if params.valleys >= 5 {
                SPUR / WALL_NOISE_CLAMP
            } else {
                0.0
            },
            spur_seed: stream(seed, purpose::EARTH, 408),
            valley_seeds: [406, 407].map(|k| stream(seed, purpose::EARTH, k)),
            lakes: params.lakes,
            // The coarse network searches as far and over as much land as the fine one, so
            // its lakes fill the basins the fine network's fill; with `lakes: 7` as far in its
            // own spacings, over a quarter of the fine network's nodes.
            lake_max_nodes: match (params.lakes, coarse) {
                (1..=4, _) => LAKE_MAX_NODES / q_scale as usize,
                (5 | 6, _) | (_, false) => LAKE_MAX_NODES_5 / q_scale as usize,
                (7, true) => COARSE_LAKE_MAX_NODES_7,
                (_, true) => COARSE_LAKE_MAX_NODES_8,
            },
            lake_radius: match (params.lakes, coarse) {
                (1..=4, _) => scaled(LAKE_RADIUS),
                (5 | 6, _) | (_, false) => scaled(LAKE_RADIUS_5),
                (_, true) => LAKE_RADIUS_5,
            },
            shore_seeds: [402, 403, 404, 405].map(|k| stream(seed, purpose::EARTH, k)),
            valleys: params.valleys,
            meander: if params.valleys >= 2 {
                MEANDER_2
            } else {
                MEANDER
            },
            pieces: match params.valleys {
                1 => PIECES,
                2 => PIECES_2,
                _ => PIECES_3,
            },
        }
    }

    /// The scales of the shoreline's two noise octaves in a tile of vertex spacing `spacing_m`
    /// (shores' step 2): [`SHORE_N1`] and [`SHORE_N2`], and with `lakes: 7` each times
    /// `clamp(log₂(λ / 2·spacing), 0, 1)` for its wavelength `λ` ([`SHORE_NOISE_M`] and a third
    /// of it), the rule of the relief layers (`earth` module docs, LOD rule): no wave shorter
    /// than two spacings. Unfaded, the 384 m octave read at 512 m spacing is a random value per
    /// vertex, and the band of the lake weight it moves across the shore (about a third of a
    /// node spacing each side) held isolated lake vertices on the land around the coarse
    /// network's lakes. Full up to 64 m (the second octave's 128 m: up to 32 m); exactly the
    /// constants there, so those tiles keep their bits.
    pub fn shore_noise(&self, spacing_m: f32) -> [f32; 2] {
        if !self.lod_shores {
            return [SHORE_N1, SHORE_N2];
        }
        let w = |len: f32| libm::log2f(len / (2.0 * spacing_m)).clamp(0.0, 1.0);
        [
            SHORE_N1 * w(SHORE_NOISE_M),
            SHORE_N2 * w(SHORE_NOISE_M / 3.0),
        ]
    }

    /// The floodplain's half-width (metres) and the walls' mean slope at the point `(x, z)` of
    /// a centre line whose floodplain is `floodplain` metres wide each side: in `valleys: 4`
    /// worlds both scaled by value noise of the point (wavelengths [`FLOOR_NOISE_M`] and
    /// [`SLOPE_NOISE_M`], factors in [`FLOOR_SCALE`] and [`SLOPE_SCALE`], the noise's N(0, 1)
    /// corner values mapped by `clamp(½ + 0.35·n, 0, 1)`; the floodplain no narrower than
    /// [`FLOOR_NARROWEST_M`] or its own width); before, `floodplain` and
    /// [`WALL_SLOPE`] as they are.
    pub fn valley_shape(&self, x: f32, z: f32, floodplain: f32) -> (f32, f32) {
        if !self.varied_valleys {
            return (floodplain, WALL_SLOPE);
        }
        let u = |n: f32| (0.5 + 0.35 * n).clamp(0.0, 1.0);
        let (inv_f, inv_s) = (1.0 / FLOOR_NOISE_M, 1.0 / SLOPE_NOISE_M);
        let nf = lattice(x * inv_f, z * inv_f, self.valley_seeds[0]);
        let ns = lattice(x * inv_s, z * inv_s, self.valley_seeds[1]);
        let f = FLOOR_SCALE.0 + (FLOOR_SCALE.1 - FLOOR_SCALE.0) * u(nf);
        let s = SLOPE_SCALE.0 + (SLOPE_SCALE.1 - SLOPE_SCALE.0) * u(ns);
        (
            (floodplain * f)
                .max(floodplain.min(FLOOR_NARROWEST_M))
                .max(self.floor_min_m),
            WALL_SLOPE * s,
        )
    }

    /// The size of the valley of a river of discharge `q` (in this network's nodes), in (0, 1]:
    /// `log2(1 + Q) / log2(1 + SIZED_Q)`, at most 1, with `Q` the discharge in nodes of the
    /// fine network (`valleys: 8`, [`SIZED_Q`]); 1 in worlds before, whose valleys have one
    /// size. A valley's floodplain, beyond its channel's share, and its bend scale with it.
    pub fn size_of(&self, q: u32) -> f32 {
        if !self.sized_valleys {
            return 1.0;
        }
        let q = q as f32 * self.q_scale as f32;
        (libm::log2f(1.0 + q) / libm::log2f(1.0 + SIZED_Q)).min(1.0)
    }

    /// The walls' spur value at the point `(x, z)` of a centre line ([`SPUR`]): `spur_scale ·`
    /// the spur noise there clamped to ±[`WALL_NOISE_CLAMP`], so `|s| ≤ SPUR`; exactly 0 in
    /// worlds without spurs. A piece keeps the values at its ends ([`Piece::spur_a`],
    /// [`Piece::spur_b`]; pieces that meet share the point, so they agree) and its walls take
    /// the value linear between them at each sample's foot.
    pub fn spur_at(&self, x: f32, z: f32) -> f32 {
        if self.spur_scale == 0.0 {
            return 0.0;
        }
        let n = lattice(x * SPUR_INV_M, z * SPUR_INV_M, self.spur_seed);
        n.clamp(-WALL_NOISE_CLAMP, WALL_NOISE_CLAMP) * self.spur_scale
    }

    fn jitter(&self, i: i64, k: i64) -> (f32, f32) {
        let h = hash2(i as i32, k as i32, self.seed);
        let jx = (unit(h) * 2.0 - 1.0) * JITTER;
        let jz = (unit(mix32(h ^ 0x68e3_1da4)) * 2.0 - 1.0) * JITTER;
        (jx, jz)
    }

    /// World position of node `(i, k)`, metres.
    pub fn position(&self, i: i64, k: i64) -> (f32, f32) {
        let (jx, jz) = self.jitter(i, k);
        let s = self.spacing_m as f64;
        (
            ((i as f64 + 0.5 + jx as f64) * s) as f32,
            ((k as f64 + 0.5 + jz as f64) * s) as f32,
        )
    }

    /// Whether lattice cell `(i, k)` (nodes `i..=i+1`, `k..=k+1`) links its main diagonal
    /// `(i, k)–(i+1, k+1)` rather than `(i+1, k)–(i, k+1)`.
    fn main_diagonal(&self, i: i64, k: i64) -> bool {
        mix32(hash2(i as i32, k as i32, self.seed ^ 0x5bd1_e995)) & 1 == 0
    }

    /// Whether node `(i, k)` links to its neighbour at `OFFSETS[d]`.
    pub(super) fn linked(&self, i: i64, k: i64, d: usize) -> bool {
        match d {
            4 => self.main_diagonal(i, k),
            6 => self.main_diagonal(i - 1, k - 1),
            5 => !self.main_diagonal(i - 1, k),
            7 => !self.main_diagonal(i, k - 1),
            _ => true,
        }
    }
}

/// Channel half-width and depth (metres) of a river of discharge `q` nodes per km² of node cell
/// (hydraulic geometry: width ∝ Q^0.5, depth ∝ Q^0.4).
pub(crate) fn channel(q: u32) -> (f32, f32) {
    let m3s = q as f32 * RUNOFF_M3S_PER_KM2;
    (1.0 + 2.0 * m3s.sqrt(), 0.3 + 0.4 * m3s.powf(0.4))
}

/// Discharge of `q` nodes, m³/s (per node of `spacing_m`).
pub fn discharge_m3s(q: u32, spacing_m: f32) -> f32 {
    q as f32 * spacing_m * spacing_m * 1e-6 * RUNOFF_M3S_PER_KM2
}
