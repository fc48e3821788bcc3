//! Decals baked into the Ptex albedo (Becher §4.7 and Fig. 14: images that decorate the
//! surface and mask the transitions between materials), projected top-down.
//!
//! A decal is an image on a rectangle of the ground plane: centre `c`, half sizes `(hw, hl)`,
//! turned by `θ` clockwise seen from above (its `u` axis `(cos θ, sin θ)` in `(x, z)`, from east
//! toward south; `v` axis `(−sin θ, cos θ)`). A texel at `p` reads the decal at
//! `u = ((p − c)·u_axis)/(2hw) + ½`, `v = ((p − c)·v_axis)/(2hl) + ½` when both are in `[0, 1]`
//! (at any height: the projection is top-down), with the clamped bilinear sample of the mip
//! level [`super::image::mip_level`] picks. Its weight is `a = opacity · mask`, `mask` the
//! image's alpha or the R channel of a separate mask image; then albedo `+= (rgb − albedo)·a`
//! (sRGB-encoded, like the material blend) and, when the decal sets one, roughness `+=
//! (roughness − r)·a`. Decals apply in document order, each over the result of the previous.
//!
//! A decal projected `top_down` paints every face in its footprint, walls and the undersides of
//! overhangs included (where a top-down projection stretches or mirrors the image). One projected
//! `top_down_facing` fades with the texel's displaced normal: its weight is multiplied by
//! `smoothstep(FACING_FROM, FACING_FULL, n_y)`, whole on ground up to 60° steep, nothing on faces
//! steeper than about 76° or facing down.
//!
//! The centre is held as an anchor (units of [`super::noise::ANCHOR_M`]) and an `f32` offset,
//! so a face reads it relative to its own anchor with exact integer arithmetic, as the noise
//! does.

use super::image::{mip_level, Image};
use std::sync::Arc;

/// One decal, ready to bake.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Decal {
    /// Centre's anchor `[x, z]`, units of 256 m.
    pub anchor: [i32; 2],
    /// Centre relative to the anchor, metres.
    pub offset: [f32; 2],
    /// `1/(2hw)` and `1/(2hl)`: reciprocal width and length, per metre.
    pub inv_size: [f32; 2],
    /// `cos θ`.
    pub cos: f32,
    /// `sin θ`.
    pub sin: f32,
    /// Opacity in `[0, 1]`.
    pub opacity: f32,
    /// Roughness the decal blends in, in `[0, 1]`; `None` leaves roughness alone.
    pub roughness: Option<f32>,
    /// The image, an index into the set's images.
    pub image: u32,
    /// The mask image (R channel), an index; `None`: the image's alpha.
    pub mask: Option<u32>,
    /// `⌈log2⌉` of the image's pixels per metre along its denser axis, for the mip level.
    pub density_log2: i32,
    /// Likewise for the mask image.
    pub mask_density_log2: i32,
    /// Whether the decal fades with the surface's facing (`top_down_facing`).
    pub facing: bool,
}

/// `n_y` below which a `top_down_facing` decal leaves a texel alone (about 76° of slope).
pub const FACING_FROM: f32 = 0.25;
/// `n_y` from which it applies whole (60° of slope).
pub const FACING_FULL: f32 = 0.5;

/// The weight a decal projected `facing` gives a texel whose displaced normal's y component is
/// `normal_y`: 1 for a `top_down` decal.
#[inline]
pub fn facing_weight(facing: bool, normal_y: f32) -> f32 {
    if !facing {
        return 1.0;
    }
    let t = ((normal_y - FACING_FROM) / (FACING_FULL - FACING_FROM)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

impl Decal {
    /// The decal's `(u, v)` at local position `p` (`[x, y, z]` metres from `anchor·256 m`) of a
    /// face anchored at `anchor`, when inside its rectangle.
    pub fn uv(&self, anchor: [i32; 3], p: [f32; 3]) -> Option<(f32, f32)> {
        let cx = (self.anchor[0].wrapping_sub(anchor[0])) as f32 * 256.0 + self.offset[0];
        let cz = (self.anchor[1].wrapping_sub(anchor[2])) as f32 * 256.0 + self.offset[1];
        let (dx, dz) = (p[0] - cx, p[2] - cz);
        let s = dx * self.cos + dz * self.sin;
        let t = dz * self.cos - dx * self.sin;
        let u = s * self.inv_size[0] + 0.5;
        let v = t * self.inv_size[1] + 0.5;
        ((0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v)).then_some((u, v))
    }
}

/// Where a texel reads the decals: its face's anchor, its local position `p` (`[x, y, z]`
/// metres from `anchor·256 m`), its displaced normal's y component and the face's finest octave.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spot {
    /// The face's anchor, units of 256 m.
    pub anchor: [i32; 3],
    /// Local position, metres.
    pub p: [f32; 3],
    /// `n_y` of the texel's displaced normal.
    pub normal_y: f32,
    /// The face's finest octave (the mip level's input).
    pub kmax: i32,
}

/// Applies `decals` at `spot` over `albedo` and `rough`.
pub fn apply(
    decals: &[Decal],
    images: &[Arc<Image>],
    spot: Spot,
    albedo: &mut [f32; 3],
    rough: &mut f32,
) {
    let Spot {
        anchor,
        p,
        normal_y,
        kmax,
    } = spot;
    for d in decals {
        let Some((u, v)) = d.uv(anchor, p) else {
            continue;
        };
        let img = &images[d.image as usize];
        let c = img.sample(
            mip_level(d.density_log2, kmax, img.levels.len()),
            u,
            v,
            false,
        );
        let mask = match d.mask {
            Some(m) => {
                let m = &images[m as usize];
                m.sample(
                    mip_level(d.mask_density_log2, kmax, m.levels.len()),
                    u,
                    v,
                    false,
                )[0]
            }
            None => c[3],
        };
        // Times 1 for a `top_down` decal: the bits it had before facing existed.
        let a = d.opacity * mask * facing_weight(d.facing, normal_y);
        for (k, x) in albedo.iter_mut().enumerate() {
            *x += (c[k] - *x) * a;
        }
        if let Some(r) = d.roughness {
            *rough += (r - *rough) * a;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_facing_decal_fades_on_steep_and_downward_faces_only() {
        assert_eq!(
            facing_weight(false, -1.0),
            1.0,
            "top_down paints every face"
        );
        assert_eq!(facing_weight(true, 1.0), 1.0);
        assert_eq!(
            facing_weight(true, FACING_FULL),
            1.0,
            "whole up to 60 degrees"
        );
        assert_eq!(facing_weight(true, FACING_FROM), 0.0);
        assert_eq!(facing_weight(true, -1.0), 0.0, "nothing under an overhang");
        let half = facing_weight(true, 0.5 * (FACING_FROM + FACING_FULL));
        assert!((half - 0.5).abs() < 1e-6, "{half}");
        // Through `apply`: a 2 × 2 red image over a 10 m square at the anchor's origin.
        let image = Arc::new(Image::new(2, 2, vec![[255, 0, 0, 255]; 4]));
        let decal = |facing| Decal {
            anchor: [0, 0],
            offset: [0.0, 0.0],
            inv_size: [0.1, 0.1],
            cos: 1.0,
            sin: 0.0,
            opacity: 1.0,
            roughness: None,
            image: 0,
            mask: None,
            density_log2: -2,
            mask_density_log2: 0,
            facing,
        };
        let paint = |facing, normal_y| {
            let (mut albedo, mut rough) = ([0.2f32, 0.4, 0.6], 0.5f32);
            let images = [image.clone()];
            let spot = Spot {
                anchor: [0, 0, 0],
                p: [1.0, 3.0, -2.0],
                normal_y,
                kmax: 0,
            };
            apply(&[decal(facing)], &images, spot, &mut albedo, &mut rough);
            albedo
        };
        assert_eq!(paint(false, -1.0), [1.0, 0.0, 0.0]);
        assert_eq!(paint(true, 0.9), paint(false, 0.9));
        assert_eq!(
            paint(true, -0.3),
            [0.2, 0.4, 0.6],
            "the underside keeps its albedo"
        );
    }
}
