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

/// Applies `decals` at local position `p` of a face anchored at `anchor` whose finest octave is
/// `kmax`, over `albedo` and `rough`.
pub fn apply(
    decals: &[Decal],
    images: &[Arc<Image>],
    anchor: [i32; 3],
    p: [f32; 3],
    kmax: i32,
    albedo: &mut [f32; 3],
    rough: &mut f32,
) {
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
        let a = d.opacity * mask;
        for (k, x) in albedo.iter_mut().enumerate() {
            *x += (c[k] - *x) * a;
        }
        if let Some(r) = d.roughness {
            *rough += (r - *rough) * a;
        }
    }
}
