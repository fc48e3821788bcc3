//! The water of a whole grid of samples ([`water_at`] for each), with the bins and the lake
//! nodes of each row and column found once instead of once per sample.
//!
//! A sample's bin is its row's bin row and its column's bin column, and the four lake nodes
//! around it are its column's and its row's, so both are computed per axis with the formulas
//! of [`RiverJob::bin_index`] and [`RiverJob::lake_level`]; the river levels and the lake levels
//! are then read in the scalar code's order, so every sample gets [`water_at`]'s bits (tested
//! against it in `tests/rivers.rs`). With shaped shores, each row's lake fields are computed side
//! by side ([`RiverJob::lake_field_row`], the same bits as one at a time).
//!
//! [`water_at`]: super::carve::water_at

use super::carve::{water_at_lake, RiverJob};
use super::kind;
use super::shores::LakeField;

impl RiverJob {
    /// The water surface (metres) and kind ([`kind`]) of each sample of the grid at
    /// `(xs[i], zs[j])` (metres) whose carved heights are `carved[j · xs.len() + i]`, appended
    /// to `surface` and `kinds`: [`water_at`] of each, bit for bit.
    pub fn water_grid(
        &self,
        sea_level_m: f32,
        xs: &[f32],
        zs: &[f32],
        carved: &[f32],
        surface: &mut Vec<f32>,
        kinds: &mut Vec<u8>,
    ) {
        self.water_grid_fields(sea_level_m, (xs, zs), carved, &[], surface, kinds);
    }

    /// [`RiverJob::water_grid`] given the lake field of each sample, row-major, as
    /// [`RiverJob::carve_grid_fields`] returns them (empty: computed here).
    pub fn water_grid_fields(
        &self,
        sea_level_m: f32,
        (xs, zs): (&[f32], &[f32]),
        carved: &[f32],
        given: &[Option<LakeField>],
        surface: &mut Vec<f32>,
        kinds: &mut Vec<u8>,
    ) {
        assert_eq!(carved.len(), xs.len() * zs.len(), "a grid of heights");
        let bins = |v: &[f32], origin: f32, n: usize| -> Vec<Option<usize>> {
            v.iter()
                .map(|&c| {
                    let b = ((c - origin) / self.bin_m).floor();
                    (!self.bin_start.is_empty() && b >= 0.0 && b < n as f32).then_some(b as usize)
                })
                .collect()
        };
        let (cols, rows) = (
            bins(xs, self.x0, self.bins_w),
            bins(zs, self.z0, self.bins_h),
        );
        let lake_rows = self.lakes.len() / self.lakes_w.max(1);
        let nodes = |v: &[f32], origin: i64, n: usize| -> Vec<[Option<usize>; 2]> {
            v.iter()
                .map(|&c| {
                    let i = ((c / self.spacing_m) - 0.5).floor() as i64 - origin;
                    [i, i + 1].map(|a| (a >= 0 && (a as usize) < n).then_some(a as usize))
                })
                .collect()
        };
        // No lake around (an empty window), or shaped shores (read through `shore_level`): no
        // node is read here.
        let (lake_cols, lake_rows) = if self.lakes.is_empty() || self.shores {
            (Vec::new(), Vec::new())
        } else {
            (
                nodes(xs, self.li0, self.lakes_w),
                nodes(zs, self.lk0, lake_rows),
            )
        };
        // No lake level reaches above this (a weighted mean of the window's levels, with a
        // margin for its rounding): higher samples skip the lake field.
        let lake_top = self
            .lakes
            .iter()
            .filter(|l| !l.is_nan())
            .fold(f32::NEG_INFINITY, |a, &l| a.max(l));
        let lake_top = lake_top + lake_top.abs() * 1e-5 + 1e-3;
        surface.reserve(carved.len());
        kinds.reserve(carved.len());
        assert!(
            given.is_empty() || given.len() == carved.len(),
            "a lake field per sample, or none"
        );
        // Shaped shores: each row's lake fields, side by side ([`RiverJob::lake_field_row`]),
        // for the rows where a sample reads them (one under a river piece's bin, or below the
        // highest lake); the other rows' are never read.
        let mut computed = vec![None; xs.len()];
        let shaped = self.shores && !self.lakes.is_empty();
        let has_pieces = |j: usize, i: usize| {
            rows[j].zip(cols[i]).is_some_and(|(r, c)| {
                let b = r * self.bins_w + c;
                self.bin_start[b] < self.bin_start[b + 1]
            })
        };
        for (j, row) in carved.chunks(xs.len()).enumerate() {
            let fields = if !given.is_empty() {
                &given[j * xs.len()..(j + 1) * xs.len()]
            } else {
                let read = || (0..xs.len()).any(|i| row[i] < lake_top || has_pieces(j, i));
                if shaped && read() {
                    self.lake_field_row(xs, zs[j], &mut computed);
                }
                &computed[..]
            };
            // `shore_level` of sample `i`.
            let shore_level = |i: usize| fields[i].filter(|f| f.e < 0.0).map(|f| f.level);
            for (i, &h) in row.iter().enumerate() {
                let (x, z) = (xs[i], zs[j]);
                let bin = rows[j].zip(cols[i]).map(|(r, c)| r * self.bins_w + c);
                let pieces = match bin {
                    Some(b) => {
                        &self.bin_pieces[self.bin_start[b] as usize..self.bin_start[b + 1] as usize]
                    }
                    None => &[],
                };
                if !pieces.is_empty() {
                    let lake = if self.shores {
                        shore_level(i)
                    } else {
                        self.lake_level(x, z)
                    };
                    let (s, k) = water_at_lake(self, sea_level_m, x, z, h, lake);
                    surface.push(s);
                    kinds.push(k);
                    continue;
                }
                // No piece: `water_at` with no river, the lake read as `lake_surface` reads it.
                let (mut s, mut k) = (h, kind::NONE);
                if h < sea_level_m {
                    (s, k) = (sea_level_m, kind::SEA);
                }
                if self.shores {
                    let level = (h < lake_top).then(|| shore_level(i)).flatten();
                    if let Some(l) = level.filter(|&l| l > h && l > s) {
                        (s, k) = (l, kind::LAKE);
                    }
                } else if !self.lakes.is_empty() {
                    let mut best: Option<f32> = None;
                    for (dk, di) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                        let (Some(a), Some(b)) = (lake_cols[i][di], lake_rows[j][dk]) else {
                            continue;
                        };
                        let l = self.lakes[b * self.lakes_w + a];
                        if !l.is_nan() {
                            best = Some(best.map_or(l, |o| o.max(l)));
                        }
                    }
                    if let Some(l) = best.filter(|&l| l > h && l > s) {
                        (s, k) = (l, kind::LAKE);
                    }
                }
                surface.push(s);
                kinds.push(k);
            }
        }
    }
}
