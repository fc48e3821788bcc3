//! Bilinear reading of values stored on a regular lattice of samples (heights of a tile, of an
//! authored region, of a chunk's ground), shared so every reader interpolates the same way.

/// Bilinear blend of the four corners of a cell: `c00` at `(0, 0)`, `c10` at `(1, 0)`, `c01` at
/// `(0, 1)`, `c11` at `(1, 1)`, at the fractions `tx`, `tz` in `[0, 1]` of the cell. The blend
/// runs along x first, then z, so equal inputs give equal bits wherever it is used.
pub fn lerp2(c00: f64, c10: f64, c01: f64, c11: f64, tx: f64, tz: f64) -> f64 {
    let near = c00 * (1.0 - tx) + c10 * tx;
    let far = c01 * (1.0 - tx) + c11 * tx;
    near * (1.0 - tz) + far * tz
}

/// The value at lattice coordinates `(u, v)` (in samples, `u` along the row) of `values`, a
/// row-major lattice of `nx × nz` samples (both at least 2), clamped to the lattice: positions
/// outside it take the value at the nearest border point.
pub fn bilinear_clamped(values: &[f32], nx: usize, nz: usize, u: f64, v: f64) -> f64 {
    debug_assert!(nx >= 2 && nz >= 2 && values.len() >= nx * nz);
    let u = u.clamp(0.0, (nx - 1) as f64);
    let v = v.clamp(0.0, (nz - 1) as f64);
    let (i, k) = ((u as usize).min(nx - 2), (v as usize).min(nz - 2));
    let at = |i: usize, k: usize| f64::from(values[k * nx + i]);
    lerp2(
        at(i, k),
        at(i + 1, k),
        at(i, k + 1),
        at(i + 1, k + 1),
        u - i as f64,
        v - k as f64,
    )
}

/// A rectangle of a world lattice: vertices `(gx0 + i, gz0 + j)` for `i < w`, `j < h`,
/// `spacing_m` metres apart (the layout of a [`crate::terrain::tile::Field`] or a snap strip),
/// stored row-major.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// Vertex spacing, metres.
    pub spacing_m: f32,
    /// Lattice index of the first column.
    pub gx0: i64,
    /// Lattice index of the first row.
    pub gz0: i64,
    /// Vertices per row.
    pub w: usize,
    /// Rows.
    pub h: usize,
}

impl Window {
    /// Calls `f(x, z, value)` for every vertex of `values` (row-major `w × h`), row by row, with
    /// the vertex's world position in metres: `x = (gx0 + i) · spacing_m`, and `z` likewise.
    /// The position is a function of the lattice index alone, so the same world vertex seen
    /// through two windows (two tiles, two LODs) gets the same position bits.
    pub fn visit_mut(&self, values: &mut [f32], mut f: impl FnMut(f64, f64, &mut f32)) {
        debug_assert_eq!(values.len(), self.w * self.h);
        let s = f64::from(self.spacing_m);
        for (j, row) in values.chunks_exact_mut(self.w).take(self.h).enumerate() {
            let z = (self.gz0 + j as i64) as f64 * s;
            for (i, v) in row.iter_mut().enumerate() {
                f((self.gx0 + i as i64) as f64 * s, z, v);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_a_bilinear_function_and_clamps_outside() {
        // f(u, v) = 1 + 2u + 3v + 0.5uv on a 4 × 3 lattice is reproduced exactly inside.
        let (nx, nz) = (4, 3);
        let f = |u: f64, v: f64| 1.0 + 2.0 * u + 3.0 * v + 0.5 * u * v;
        let values: Vec<f32> = (0..nx * nz)
            .map(|s| f((s % nx) as f64, (s / nx) as f64) as f32)
            .collect();
        for (u, v) in [(0.0, 0.0), (0.25, 1.5), (2.9, 1.99), (3.0, 2.0), (1.0, 0.5)] {
            let got = bilinear_clamped(&values, nx, nz, u, v);
            assert!(
                (got - f(u, v)).abs() < 1e-9,
                "({u}, {v}): {got} vs {}",
                f(u, v)
            );
        }
        assert_eq!(
            bilinear_clamped(&values, nx, nz, -5.0, 9.0),
            bilinear_clamped(&values, nx, nz, 0.0, 2.0)
        );
    }

    #[test]
    fn a_window_visits_each_vertex_once_at_its_world_position() {
        let win = Window {
            spacing_m: 2.0,
            gx0: -3,
            gz0: 5,
            w: 3,
            h: 2,
        };
        let mut values = vec![0.0f32; 6];
        let mut seen = Vec::new();
        win.visit_mut(&mut values, |x, z, v| {
            *v += 1.0;
            seen.push((x, z));
        });
        assert!(values.iter().all(|v| *v == 1.0));
        assert_eq!(
            seen,
            [
                (-6.0, 10.0),
                (-4.0, 10.0),
                (-2.0, 10.0),
                (-6.0, 12.0),
                (-4.0, 12.0),
                (-2.0, 12.0)
            ]
        );
    }
}
