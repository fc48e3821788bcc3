//! Volume bricking (Becher §5.2): a region is split into bricks, each with its own fields and a
//! one-sample halo; after every iteration the bricks exchange the values on their shared
//! boundaries, so the iterative stages compute the global solution.
//!
//! [`Bricked`] holds the bricks (interior up to `brick` samples per axis, plus the halo). A halo
//! sample on the region's border holds a copy of the brick's own border sample, which is exactly
//! the homogeneous Neumann condition of the single-grid sweep (the difference to it is zero), so
//! [`Bricked::sweeps`] reproduces [`super::diffuse::sweeps`] bit for bit and
//! [`Bricked::propagate_surface`] reproduces [`super::propagate::propagate_surface`] bit for bit
//! (tested). Exchange copies halo samples from the neighbouring brick that owns them.
//!
//! Deviations and limits: all bricks share one resolution (the paper allows bricks of different
//! resolution, which needs resampling at the exchange); the bricked propagation runs one pass per
//! wavefront layer over every brick (O(n·L), the GPU formulation) rather than the single-grid
//! breadth-first search; the coarse-to-fine initialisation of the diffusion is left to the caller
//! (it can run on a downsampled copy of the whole region, which is small).

use super::diffuse::sweep;
use super::grid::Grid;
use super::propagate::UNREACHED;

/// One brick: its interior box in the region and its padded fields.
#[derive(Clone, Debug)]
pub struct Brick {
    /// First interior sample, region coordinates.
    pub lo: [usize; 3],
    /// Interior samples per axis.
    pub size: [usize; 3],
    /// Padded dimensions (`size + 2`).
    pub padded: [usize; 3],
    /// Channels, padded layout.
    pub chans: Vec<Vec<f32>>,
    /// Constraint flags, padded layout (halo samples are always fixed: they are inputs).
    pub fixed: Vec<u8>,
}

impl Brick {
    fn pidx(&self, x: usize, y: usize, z: usize) -> usize {
        x + self.padded[0] * (y + self.padded[1] * z)
    }
}

/// A region split into bricks.
#[derive(Clone, Debug)]
pub struct Bricked {
    /// Region dimensions.
    pub dims: [usize; 3],
    /// Interior samples per brick and axis (the last brick of an axis may be smaller).
    pub brick: [usize; 3],
    /// Bricks per axis.
    pub counts: [usize; 3],
    /// The bricks, x fastest.
    pub bricks: Vec<Brick>,
}

impl Bricked {
    /// Splits `chans` (region layout) with constraint flags `fixed` into bricks of at most
    /// `brick` interior samples per axis (each at least 1), halos filled.
    pub fn split(dims: [usize; 3], brick: [usize; 3], chans: &[Vec<f32>], fixed: &[u8]) -> Self {
        let brick = brick.map(|b| b.max(1));
        let counts = [0, 1, 2].map(|k| dims[k].div_ceil(brick[k]));
        let mut bricks = Vec::new();
        for bz in 0..counts[2] {
            for by in 0..counts[1] {
                for bx in 0..counts[0] {
                    let lo = [bx * brick[0], by * brick[1], bz * brick[2]];
                    let size = [0, 1, 2].map(|k| brick[k].min(dims[k] - lo[k]));
                    let padded = size.map(|s| s + 2);
                    let n = padded.iter().product::<usize>();
                    let mut b = Brick {
                        lo,
                        size,
                        padded,
                        chans: chans.iter().map(|_| vec![0.0; n]).collect(),
                        fixed: vec![1; n],
                    };
                    for z in 0..size[2] {
                        for y in 0..size[1] {
                            for x in 0..size[0] {
                                let g =
                                    (lo[0] + x) + dims[0] * ((lo[1] + y) + dims[1] * (lo[2] + z));
                                let p = b.pidx(x + 1, y + 1, z + 1);
                                b.fixed[p] = fixed[g];
                                for (bc, c) in b.chans.iter_mut().zip(chans) {
                                    bc[p] = c[g];
                                }
                            }
                        }
                    }
                    bricks.push(b);
                }
            }
        }
        let mut s = Self {
            dims,
            brick,
            counts,
            bricks,
        };
        s.exchange(|b| &mut b.chans);
        s
    }

    /// The brick owning region sample `g` and that sample's padded index in it.
    fn owner(&self, g: [usize; 3]) -> (usize, usize) {
        let b = [0, 1, 2].map(|k| g[k] / self.brick[k]);
        let bi = b[0] + self.counts[0] * (b[1] + self.counts[1] * b[2]);
        let br = &self.bricks[bi];
        (
            bi,
            br.pidx(
                g[0] - br.lo[0] + 1,
                g[1] - br.lo[1] + 1,
                g[2] - br.lo[2] + 1,
            ),
        )
    }

    /// Calls `copy(self, bi, p, oi, op)` for every halo sample of every brick, bricks in order and
    /// samples x fastest: halo sample `p` (padded index) of brick `bi` takes its value from
    /// sample `op` of brick `oi`, the owner of the region sample it mirrors — the neighbour
    /// brick's, or (on the region's border, where the coordinate is clamped onto the region) the
    /// brick's own border sample.
    fn for_each_halo(&mut self, mut copy: impl FnMut(&mut Self, usize, usize, usize, usize)) {
        let dims = self.dims;
        for bi in 0..self.bricks.len() {
            let (lo, padded) = (self.bricks[bi].lo, self.bricks[bi].padded);
            for z in 0..padded[2] {
                for y in 0..padded[1] {
                    for x in 0..padded[0] {
                        let c = [x, y, z];
                        if (0..3).all(|k| c[k] >= 1 && c[k] + 1 < padded[k]) {
                            continue;
                        }
                        // Region coordinate of the halo sample, clamped onto the region.
                        let g = [0, 1, 2].map(|k| {
                            (lo[k] as i64 + c[k] as i64 - 1).clamp(0, dims[k] as i64 - 1) as usize
                        });
                        let (oi, op) = self.owner(g);
                        let p = self.bricks[bi].pidx(x, y, z);
                        copy(self, bi, p, oi, op);
                    }
                }
            }
        }
    }

    /// Fills every halo sample of the channels selected by `pick`: from the owning neighbour
    /// brick, or (on the region's border) from the brick's own border sample.
    pub fn exchange<T: Copy>(&mut self, pick: impl Fn(&mut Brick) -> &mut Vec<Vec<T>>) {
        self.for_each_halo(|s, bi, p, oi, op| {
            let m = pick(&mut s.bricks[oi]).len();
            for ch in 0..m {
                let v = pick(&mut s.bricks[oi])[ch][op];
                pick(&mut s.bricks[bi])[ch][p] = v;
            }
        });
    }

    /// `n` Jacobi sweeps (Laplace or Perona–Malik, as [`super::diffuse::sweep`]) brick by brick,
    /// exchanging halos after each sweep.
    pub fn sweeps(&mut self, pm: Option<f32>, n: u32) {
        for _ in 0..n {
            for b in &mut self.bricks {
                let mut out: Vec<Vec<f32>> = b.chans.clone();
                {
                    let src: Vec<&[f32]> = b.chans.iter().map(|c| c.as_slice()).collect();
                    let mut dst: Vec<&mut [f32]> =
                        out.iter_mut().map(|c| c.as_mut_slice()).collect();
                    sweep(b.padded, &src, &b.fixed, pm, &mut dst);
                }
                b.chans = out;
            }
            self.exchange(|b| &mut b.chans);
        }
    }

    /// Gathers channel `ch` back into the region layout.
    pub fn gather(&self, ch: usize) -> Vec<f32> {
        let mut out = vec![0.0f32; self.dims.iter().product()];
        for b in &self.bricks {
            for z in 0..b.size[2] {
                for y in 0..b.size[1] {
                    for x in 0..b.size[0] {
                        let g = (b.lo[0] + x)
                            + self.dims[0] * ((b.lo[1] + y) + self.dims[1] * (b.lo[2] + z));
                        out[g] = b.chans[ch][b.pidx(x + 1, y + 1, z + 1)];
                    }
                }
            }
        }
        out
    }

    /// Surface propagation (§4.5) brick by brick: the bricks hold `[N_x, N_y, N_z, S]` as their
    /// channels (split from the normal field and `S`); one pass per wavefront layer sets the
    /// unset interior samples with a neighbour of a lower layer, then the bricks exchange `S` and
    /// the layers. Returns `S` and the layers in region layout.
    pub fn propagate_surface(
        grid: &Grid,
        normal: &[Vec<f32>],
        omega_s: &[u8],
        s: &[f32],
        brick: [usize; 3],
    ) -> (Vec<f32>, Vec<u32>) {
        let dims = grid.dims;
        let chans = vec![
            normal[0].clone(),
            normal[1].clone(),
            normal[2].clone(),
            s.to_vec(),
        ];
        let mut br = Self::split(dims, brick, &chans, omega_s);
        // Layers as a second set of per-brick arrays.
        let mut layers: Vec<Vec<Vec<u32>>> = br
            .bricks
            .iter()
            .map(|b| {
                vec![b
                    .fixed
                    .iter()
                    .map(|&f| if f != 0 { 0 } else { UNREACHED })
                    .collect()]
            })
            .collect();
        // Halo layers come from the owners (the split marked halos fixed, not seeds).
        let mut lb = LayerBricks {
            inner: &mut br,
            layers: &mut layers,
        };
        lb.exchange_layers();
        let h = grid.spacing;
        let passes = (dims[0] + dims[1] + dims[2]) as u32;
        for l in 1..=passes {
            let mut changed = false;
            for (b, lay) in lb.inner.bricks.iter_mut().zip(lb.layers.iter_mut()) {
                let [px, py, _] = b.padded;
                let lay = &mut lay[0];
                let mut set = Vec::new();
                for z in 1..=b.size[2] {
                    for y in 1..=b.size[1] {
                        for x in 1..=b.size[0] {
                            let i = x + px * (y + py * z);
                            if lay[i] != UNREACHED {
                                continue;
                            }
                            let g = [b.lo[0] + x - 1, b.lo[1] + y - 1, b.lo[2] + z - 1];
                            let nbs = [
                                (g[0] + 1 < dims[0], i + 1, 0usize, -1.0f32),
                                (g[0] > 0, i - 1, 0, 1.0),
                                (g[1] + 1 < dims[1], i + px, 1, -1.0),
                                (g[1] > 0, i - px, 1, 1.0),
                                (g[2] + 1 < dims[2], i + px * py, 2, -1.0),
                                (g[2] > 0, i - px * py, 2, 1.0),
                            ];
                            let mut best = f32::INFINITY;
                            let mut found = false;
                            for (ok, j, a, sign) in nbs {
                                if ok && lay[j] < l {
                                    let v = b.chans[3][j]
                                        + (sign * h) * ((b.chans[a][i] + b.chans[a][j]) * 0.5);
                                    best = best.min(v);
                                    found = true;
                                }
                            }
                            if found {
                                set.push((i, best));
                            }
                        }
                    }
                }
                for (i, v) in set {
                    b.chans[3][i] = v;
                    lay[i] = l;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
            lb.inner.exchange(|b| &mut b.chans);
            lb.exchange_layers();
        }
        let s = lb.inner.gather(3);
        let mut out = vec![UNREACHED; dims.iter().product()];
        for (b, lay) in lb.inner.bricks.iter().zip(lb.layers.iter()) {
            for z in 0..b.size[2] {
                for y in 0..b.size[1] {
                    for x in 0..b.size[0] {
                        let g = (b.lo[0] + x) + dims[0] * ((b.lo[1] + y) + dims[1] * (b.lo[2] + z));
                        out[g] = lay[0][b.pidx(x + 1, y + 1, z + 1)];
                    }
                }
            }
        }
        (s, out)
    }
}

/// Bricks plus per-brick layer arrays, for the halo exchange of the layers.
struct LayerBricks<'a> {
    inner: &'a mut Bricked,
    layers: &'a mut Vec<Vec<Vec<u32>>>,
}

impl LayerBricks<'_> {
    fn exchange_layers(&mut self) {
        let layers = &mut *self.layers;
        self.inner.for_each_halo(|_, bi, p, oi, op| {
            layers[bi][0][p] = layers[oi][0][op];
        });
    }
}
