//! The closest point of a polyline to many query points, within a reach: a bucket grid over the
//! polyline's segments, so a tool that edits the samples or edges near a stroke costs the grid's
//! area plus the stroke's length, not their product.
//!
//! [`Nearest::get`] answers exactly what [`super::raster::polyline_distance`] answers whenever
//! the closest point lies within the reach: both measure each segment with
//! [`segment_distance`] and keep the first segment of the least distance in index order, and
//! every segment closer than the reach to a point is listed in that point's bucket.

use super::raster::dist;

/// Most buckets along one side of the grid; the bucket size grows for long polylines with a
/// short reach.
const MAX_BUCKETS_PER_SIDE: f64 = 256.0;

/// Distance from `p` to the segment `a → b` and the fraction `t ∈ [0, 1]` of its closest point
/// (`t = 0` for a degenerate segment).
pub fn segment_distance(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> (f64, f64) {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let q = [a[0] + t * d[0], a[1] + t * d[1]];
    (dist(q, p), t)
}

/// Segments of a polyline bucketed by the squares their reach covers.
#[derive(Debug)]
pub struct Nearest<'a> {
    pts: &'a [[f64; 2]],
    reach: f64,
    /// Lower corner of the bucket grid, metres.
    origin: [f64; 2],
    /// Bucket side, metres.
    cell: f64,
    /// Buckets along x and z.
    dims: [usize; 2],
    /// Bucket `b`'s segments are `items[starts[b]..starts[b + 1]]`, in increasing order.
    starts: Vec<usize>,
    items: Vec<u32>,
}

impl<'a> Nearest<'a> {
    /// Indexes the segments of `pts` (one point is a degenerate segment) for queries within
    /// `reach` metres (positive and finite; otherwise every query is answered by a full scan).
    pub fn new(pts: &'a [[f64; 2]], reach: f64) -> Self {
        let segments = pts
            .len()
            .saturating_sub(1)
            .max(usize::from(!pts.is_empty()));
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in pts {
            for a in 0..2 {
                lo[a] = lo[a].min(p[a]);
                hi[a] = hi[a].max(p[a]);
            }
        }
        let bounded = reach.is_finite() && reach > 0.0 && !pts.is_empty();
        let r = if bounded { reach } else { 0.0 };
        let origin = [lo[0] - r, lo[1] - r];
        let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]) + 2.0 * r;
        let cell = if bounded {
            reach.max(extent / MAX_BUCKETS_PER_SIDE)
        } else {
            f64::INFINITY
        };
        let side = |a: usize| {
            if bounded {
                ((hi[a] + r - origin[a]) / cell).floor() as usize + 1
            } else {
                1
            }
        };
        let dims = [side(0), side(1)];
        let mut me = Self {
            pts,
            reach,
            origin,
            cell,
            dims,
            starts: vec![0; dims[0] * dims[1] + 1],
            items: Vec::new(),
        };
        // Two passes (count, then fill) keep each bucket's segments in increasing order.
        let mut lists: Vec<Vec<u32>> = vec![Vec::new(); dims[0] * dims[1]];
        for s in 0..segments {
            let (a, b) = me.segment(s);
            let (i0, k0) = me.bucket_clamped([a[0].min(b[0]) - r, a[1].min(b[1]) - r]);
            let (i1, k1) = me.bucket_clamped([a[0].max(b[0]) + r, a[1].max(b[1]) + r]);
            for k in k0..=k1 {
                for i in i0..=i1 {
                    lists[k * dims[0] + i].push(s as u32);
                }
            }
        }
        for (b, list) in lists.iter().enumerate() {
            me.starts[b + 1] = me.starts[b] + list.len();
        }
        me.items = lists.concat();
        me
    }

    fn segment(&self, s: usize) -> ([f64; 2], [f64; 2]) {
        if self.pts.len() == 1 {
            (self.pts[0], self.pts[0])
        } else {
            (self.pts[s], self.pts[s + 1])
        }
    }

    fn bucket_clamped(&self, p: [f64; 2]) -> (usize, usize) {
        let at = |a: usize| {
            if self.cell.is_infinite() {
                return 0;
            }
            let f = ((p[a] - self.origin[a]) / self.cell).floor();
            (f.max(0.0) as usize).min(self.dims[a] - 1)
        };
        (at(0), at(1))
    }

    /// `(distance, segment, fraction)` of the closest point of the polyline to `p`, as
    /// [`super::raster::polyline_distance`] gives it, when that distance is below the reach;
    /// `None` otherwise.
    pub fn get(&self, p: [f64; 2]) -> Option<(f64, usize, f64)> {
        if self.pts.is_empty() {
            return None;
        }
        let b = if self.cell.is_infinite() {
            0
        } else {
            let f = [
                ((p[0] - self.origin[0]) / self.cell).floor(),
                ((p[1] - self.origin[1]) / self.cell).floor(),
            ];
            if f[0] < 0.0 || f[1] < 0.0 {
                return None;
            }
            let (i, k) = (f[0] as usize, f[1] as usize);
            if i >= self.dims[0] || k >= self.dims[1] {
                return None;
            }
            k * self.dims[0] + i
        };
        let mut best = (f64::INFINITY, 0, 0.0);
        for &s in &self.items[self.starts[b]..self.starts[b + 1]] {
            let (a, e) = self.segment(s as usize);
            let (d, t) = segment_distance(a, e, p);
            if d < best.0 {
                best = (d, s as usize, t);
            }
        }
        (best.0 < self.reach).then_some(best)
    }
}

#[cfg(test)]
mod tests {
    use super::super::raster::polyline_distance;
    use super::*;

    #[test]
    fn answers_as_the_full_scan_within_the_reach_and_nothing_beyond() {
        // A zig-zag with a repeated point (a degenerate segment) and a point alone.
        let zigzag: Vec<[f64; 2]> = (0..40)
            .map(|k| [k as f64 * 3.0, if k % 2 == 0 { 0.0 } else { 5.0 }])
            .chain([[117.0, 5.0], [117.0, 5.0], [90.0, 30.0]])
            .collect();
        let single = vec![[10.0, -4.0]];
        for (pts, reach) in [(&zigzag, 4.0), (&zigzag, 0.7), (&single, 6.0)] {
            let index = Nearest::new(pts, reach);
            let (mut inside, mut outside) = (0, 0);
            for j in 0..120 {
                for i in 0..300 {
                    let p = [-15.0 + i as f64 * 0.5, -20.0 + j as f64 * 0.5];
                    let full = polyline_distance(pts, p);
                    match index.get(p) {
                        Some(got) => {
                            assert_eq!(got, full, "at {p:?}");
                            inside += 1;
                        }
                        None => {
                            assert!(full.0 >= reach, "missed {full:?} at {p:?}");
                            outside += 1;
                        }
                    }
                }
            }
            assert!(inside > 100 && outside > 100, "{inside} {outside}");
        }
    }
}
