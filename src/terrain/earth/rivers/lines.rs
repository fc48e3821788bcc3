//! River polylines of a tile: the wet edges of the network that reach into the tile's rectangle,
//! chained from upstream to downstream (the JSON product `…/rivers/{lod}/{x}/{z}.json`).
//!
//! At a confluence the chain follows the main upstream edge (largest discharge, first in
//! lattice order on ties, as the carve's curves do); the other incoming chains end there, in a
//! river at least as large. A chain also ends in the sea, in a lake, or at the edge of what the
//! tile touches, where the neighbouring tile's product continues it from the same node.
//!
//! Points: each piece's ends; a bent piece (`valleys: 3` and later) adds its middle, or with
//! `lines: 2` ([`RiverPlan::dense_lines`]) as many points of the curve the carve follows as keep
//! the chords within [`LINE_TOLERANCE_M`] of it, so a client drawing the river along the line
//! covers the carved channel's water (with the middle alone the chords strayed up to about
//! 30 m from it). `lines: 2` also reads the long edges of breached pits and spilling lakes
//! whose pits lie beyond the nodes around the rectangle, which the carve reads since
//! `coarse: 1` ([`RiverPlan::long_edges`]).
//!
//! An edge reaches into the rectangle when the box around one of its pieces' chords, widened by
//! the channel and a quarter of the piece's largest bend (a bound on the curve's offset), meets
//! it; in `lakes: 6` worlds a bent piece must also have one of the chords within
//! [`LINE_TOLERANCE_M`] of its curve there ([`RiverPlan::exact_lines`]): the long edge of a
//! spilling lake bends kilometres from its chord, and its box took in tiles its curve never
//! reaches.
//!
//! [`RiverPlan::dense_lines`]: super::RiverPlan::dense_lines
//! [`RiverPlan::long_edges`]: super::RiverPlan::long_edges
//! [`RiverPlan::exact_lines`]: super::RiverPlan::exact_lines

use super::carve::{curve_at, Edge};
use super::network::{Network, NodeId};
use super::{channel, discharge_m3s, LINE_MAX_STEPS, LINE_TOLERANCE_M};
use std::collections::{HashMap, HashSet};

/// How a river line ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LineEnd {
    /// It reaches the sea.
    Sea,
    /// It ends in a lake (a pit filled to its outlet).
    Lake,
    /// It joins a river at least as large (a confluence where another chain continues).
    River,
    /// It leaves the part of the network the tile touches; the chain from `to` continues it.
    Continues,
}

/// One river line of a tile.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct RiverLine {
    /// Centre-line points `[x, z, water level]`, metres, from upstream to downstream.
    pub points: Vec<[f32; 3]>,
    /// Channel width at each point, metres.
    pub width_m: Vec<f32>,
    /// Discharge at each point, m³/s.
    pub discharge_m3s: Vec<f32>,
    /// Node the line starts at (lattice index `[i, k]` of the river network).
    pub from: [i64; 2],
    /// Node the line ends at.
    pub to: [i64; 2],
    /// How it ends.
    pub ends: LineEnd,
}

impl Network<'_> {
    /// The river lines that reach into `[x0, x1] × [z0, z1]` (metres).
    pub fn lines(&mut self, x0: f32, z0: f32, x1: f32, z1: f32) -> Vec<RiverLine> {
        let s_m = self.plan.spacing_m;
        let wet = self.plan.wet_q;
        let margin = 2.0 * s_m;
        let ni0 = ((x0 - margin) / s_m).floor() as i64;
        let ni1 = ((x1 + margin) / s_m).floor() as i64;
        let nk0 = ((z0 - margin) / s_m).floor() as i64;
        let nk1 = ((z1 + margin) / s_m).floor() as i64;
        // The wet edges whose curve (with its channel) touches the rectangle: those of the nodes
        // around it, and with `lines: 2` in worlds that carve them the long edges of the pits
        // within a flood's radius (a breached pit or a spilling lake drains to an outlet up to
        // that far away), each once.
        let mut nodes: Vec<NodeId> = Vec::new();
        for k in nk0..=nk1 {
            for i in ni0..=ni1 {
                nodes.push((i, k));
            }
        }
        if self.plan.dense_lines && self.plan.long_edges {
            let far = self.plan.lake_radius + 1;
            let sinks = self.sinks(ni0 - far..ni1 + far + 1, nk0 - far..nk1 + far + 1);
            for (i, k) in sinks {
                let near = (ni0..=ni1).contains(&i) && (nk0..=nk1).contains(&k);
                let long = self
                    .down(i, k)
                    .is_some_and(|(di, dk)| (di - i).abs() > 1 || (dk - k).abs() > 1);
                if long && !near {
                    nodes.push((i, k));
                }
            }
        }
        let mut edges: Vec<Edge> = Vec::new();
        for (i, k) in nodes {
            let q = self.q(i, k);
            if q < wet || !self.carves(i, k, q) {
                continue;
            }
            let Some(e) = self.edge(i, k) else { continue };
            if e.from.sea {
                continue;
            }
            // `valleys: 3`: a piece touches when the box around its chord, widened by the
            // channel and the piece's bulge, meets the rectangle (a piece may cross a small
            // tile between its points). Before, a point within the channel's half-width of
            // it did, and stored worlds keep that test and their bytes.
            let hw = channel(e.from.q).0;
            let near_point = |p: &[f32; 3]| {
                p[0] >= x0 - hw && p[0] <= x1 + hw && p[1] >= z0 - hw && p[1] <= z1 + hw
            };
            // The box around the segment from `a` to `b`, widened by `m`, meets the rectangle.
            let boxed = |a: [f32; 3], b: [f32; 3], m: f32| {
                a[0].min(b[0]) - m <= x1
                    && a[0].max(b[0]) + m >= x0
                    && a[1].min(b[1]) - m <= z1
                    && a[1].max(b[1]) + m >= z0
            };
            // `lakes: 6`: a bent piece whose box meets the rectangle touches it only if one of
            // the chords within `LINE_TOLERANCE_M` of its curve does, widened by the channel
            // and that tolerance (the long edge of a spilling lake, tens of kilometres, bends
            // kilometres from its chord, and its box took in tiles its curve never reaches).
            let exact = self.plan.exact_lines;
            let touches = if self.plan.valleys < 3 {
                e.points.iter().any(near_point)
            } else {
                e.points.windows(2).zip(&e.bends).any(|(p, b)| {
                    let m = hw + 0.25 * b[0].hypot(b[1]).max(b[2].hypot(b[3]));
                    boxed(p[0], p[1], m)
                        && (!exact || *b == [0.0; 4] || {
                            let steps = piece_steps(*b);
                            let at =
                                |c: usize| piece_point(p[0], p[1], *b, c as f32 / steps as f32);
                            (0..steps).any(|c| boxed(at(c), at(c + 1), hw + LINE_TOLERANCE_M))
                        })
                })
            };
            if touches {
                edges.push(e);
            }
        }
        let by_from: HashMap<NodeId, usize> = edges
            .iter()
            .enumerate()
            .map(|(n, e)| ((e.from.i, e.from.k), n))
            .collect();
        // The successor of each edge: the collected edge out of its end, if it is the main one in.
        let mut next: Vec<Option<usize>> = vec![None; edges.len()];
        let mut is_next = HashSet::new();
        for (n, e) in edges.iter().enumerate() {
            let to = (e.to.i, e.to.k);
            // A spilling lake's edge starts at its saddle, across the lake from its pit
            // (`RiverPlan::saddles`): the lines into the pit end there, in the lake.
            if self.main_upstream(to.0, to.1) != Some((e.from.i, e.from.k))
                || self.saddle(to.0, to.1).is_some()
            {
                continue;
            }
            if let Some(&m) = by_from.get(&to) {
                next[n] = Some(m);
                is_next.insert(m);
            }
        }
        let dense = self.plan.dense_lines;
        let mut lines = Vec::new();
        for start in 0..edges.len() {
            if is_next.contains(&start) {
                continue;
            }
            let mut line = RiverLine {
                points: Vec::new(),
                width_m: Vec::new(),
                discharge_m3s: Vec::new(),
                from: [edges[start].from.i, edges[start].from.k],
                to: [0, 0],
                ends: LineEnd::Continues,
            };
            let mut at = Some(start);
            let mut last = start;
            while let Some(n) = at {
                let e = &edges[n];
                let skip = usize::from(!line.points.is_empty());
                for (j, p) in e.points.iter().enumerate().skip(skip) {
                    // A bent piece (`valleys: 3`) adds points on the curve the carve follows
                    // before its downstream end: its middle, or with `lines: 2` as many as keep
                    // the chords within `LINE_TOLERANCE_M` of the curve.
                    if j > 0 && e.bends[j - 1] != [0.0; 4] {
                        let (a, s) = (e.points[j - 1], e.bends[j - 1]);
                        let steps = if dense { piece_steps(s) } else { 2 };
                        for m in 1..steps {
                            line.points.push(if dense {
                                piece_point(a, *p, s, m as f32 / steps as f32)
                            } else {
                                // The piece's offset at its middle is `(sa + sb) / 8`.
                                [
                                    0.5 * (a[0] + p[0]) + 0.125 * (s[0] + s[2]),
                                    0.5 * (a[1] + p[1]) + 0.125 * (s[1] + s[3]),
                                    0.5 * (a[2] + p[2]),
                                ]
                            });
                            line.width_m.push(2.0 * channel(e.from.q).0);
                            line.discharge_m3s.push(discharge_m3s(e.from.q, s_m));
                        }
                    }
                    // Width and discharge change at the downstream node of the edge.
                    let q = if j + 1 == e.points.len() {
                        e.to.q
                    } else {
                        e.from.q
                    };
                    line.points.push(*p);
                    line.width_m.push(2.0 * channel(q).0);
                    line.discharge_m3s.push(discharge_m3s(q, s_m));
                }
                last = n;
                at = next[n];
            }
            let e = &edges[last];
            line.to = [e.to.i, e.to.k];
            line.ends = if e.to.sea {
                LineEnd::Sea
            } else if e.to.down.is_none() || self.saddle(e.to.i, e.to.k).is_some() {
                LineEnd::Lake
            } else if self.main_upstream(e.to.i, e.to.k) != Some((e.from.i, e.from.k)) {
                LineEnd::River
            } else {
                LineEnd::Continues
            };
            lines.push(line);
        }
        lines
    }
}

/// Chords per piece that keep a line within [`LINE_TOLERANCE_M`] of the piece's curve: the
/// curve's offset from its chord is `t(1 − t)²·sa + t²(1 − t)·sb`, whose second derivative is at
/// most `4(|sa| + |sb|)`, so chords of `1/n` in `t` stray at most `(|sa| + |sb|) / (2n²)`.
fn piece_steps(bend: [f32; 4]) -> usize {
    let s = bend[0].hypot(bend[1]) + bend[2].hypot(bend[3]);
    ((s / (2.0 * LINE_TOLERANCE_M)).sqrt().ceil() as usize).clamp(2, LINE_MAX_STEPS)
}

/// The point of the piece from `a` to `b` with offset slopes `bend` ([`Edge::bends`]) at `t`:
/// the chord's point plus the carve's offset across it ([`curve_at`], as the carve's feet), and
/// the water level interpolated along the chord.
fn piece_point(a: [f32; 3], b: [f32; 3], bend: [f32; 4], t: f32) -> [f32; 3] {
    [
        curve_at(a[0], b[0] - a[0], bend[0], bend[2], t),
        curve_at(a[1], b[1] - a[1], bend[1], bend[3], t),
        a[2] + t * (b[2] - a[2]),
    ]
}
