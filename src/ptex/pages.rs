//! The baked texels of a set of faces, laid out as `api/ptex_pages_v1.md` describes: each face a
//! square of `(res + 2)²` texels (its `res²` interior and the one-texel border), three planes.
//!
//! Texel `(i, j)` of a face, `i` along `u` and `j` along `v`, both in `−1..=res` (−1 and `res`
//! are the border), sits at index `(j + 1)·(res + 2) + (i + 1)` of the face's square; its centre
//! is at `uv = ((i + ½)/res, (j + ½)/res)`.

/// Baked pages: `faces` squares of `(res + 2)²` texels in each plane.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Pages {
    /// Interior texels per side.
    pub res: u32,
    /// Number of faces.
    pub faces: usize,
    /// Albedo (sRGB-encoded R, G, B) and roughness (linear), 8 bits each.
    pub albedo: Vec<[u8; 4]>,
    /// Displaced normal, world space, each of x, y, z as a signed 8-bit `round(127·n)` (two's
    /// complement), then the id of the texel's dominant material.
    pub normal: Vec<[u8; 4]>,
    /// Displacement along the face's interpolated normal, metres.
    pub displacement: Vec<f32>,
}

impl Pages {
    /// Texels per side including the border.
    pub fn side(&self) -> usize {
        self.res as usize + 2
    }

    /// Texels per face including the border.
    pub fn texels_per_face(&self) -> usize {
        self.side() * self.side()
    }

    /// Resets to `faces` zeroed faces of `res` (keeping the allocations).
    pub fn reset(&mut self, res: u32, faces: usize) {
        self.res = res;
        self.faces = faces;
        let n = faces * self.texels_per_face();
        for v in [&mut self.albedo, &mut self.normal] {
            v.clear();
            v.resize(n, [0; 4]);
        }
        self.displacement.clear();
        self.displacement.resize(n, 0.0);
    }

    /// Index of texel `(i, j)` (`−1..=res` each) of face `f`.
    pub fn at(&self, f: usize, i: i32, j: i32) -> usize {
        let side = self.side();
        f * side * side + (j + 1) as usize * side + (i + 1) as usize
    }

    /// Copies texel `src` over texel `dst` in every plane.
    pub fn copy(&mut self, dst: usize, src: usize) {
        self.albedo[dst] = self.albedo[src];
        self.normal[dst] = self.normal[src];
        self.displacement[dst] = self.displacement[src];
    }

    /// Keeps the first `faces` faces.
    pub fn truncate(&mut self, faces: usize) {
        let faces = faces.min(self.faces);
        let n = faces * self.texels_per_face();
        self.albedo.truncate(n);
        self.normal.truncate(n);
        self.displacement.truncate(n);
        self.faces = faces;
    }

    /// The interior texels of face `f` in `u`-fastest order, as `(albedo, normal,
    /// displacement)`.
    pub fn interior(&self, f: usize) -> impl Iterator<Item = ([u8; 4], [u8; 4], f32)> + '_ {
        let r = self.res as i32;
        (0..r).flat_map(move |j| {
            (0..r).map(move |i| {
                let k = self.at(f, i, j);
                (self.albedo[k], self.normal[k], self.displacement[k])
            })
        })
    }
}
