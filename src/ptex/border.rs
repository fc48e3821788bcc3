//! The one-texel borders of baked faces, taken from the neighbours (§4.6–4.7; McDonald's
//! real-time Ptex keeps such borders so hardware bilinear filtering reads across face edges).
//!
//! # Border rule
//!
//! Border texel `j` of edge `k` (`t = (j + ½)/res` along the edge's direction) is the texel of
//! the neighbour that holds the point one half texel beyond the edge:
//!
//! - a neighbour of the same size ([`Span::Whole`]): the border texel's centre mapped by the uv
//!   transform `4k + k'` of [`UV_TRANSFORMS`], which lands on a texel centre of the neighbour's
//!   row along its edge `k'` (the transforms are quarter turns and unit translations);
//! - a neighbour twice as large ([`Span::FirstHalf`], [`Span::SecondHalf`], a coarser height
//!   tile's face): the texel of the neighbour's row along edge `k'` at edge parameter
//!   `t' = s₀ + (1 − t)/2` (`s₀` = 0 or ½; the edges run in opposite directions), the nearest
//!   coarser texel;
//! - no neighbour: the face's own edge texel (clamp).
//!
//! The four corner texels repeat the face's own corner texel (a quad's diagonal neighbour is not
//! part of the adjacency). Borders copy whole texels of every plane, so they are the neighbour's
//! bytes exactly.

use super::face::{FaceSet, Span, NO_FACE};
use super::pages::Pages;
use crate::volume::mesh::ptex::edge_point;
use crate::volume::mesh::UV_TRANSFORMS;

/// The outward unit normal of edge `k` (to the right of its direction).
fn outward(k: usize) -> [f32; 2] {
    [[0.0, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]][k % 4]
}

/// The texel holding `uv`.
fn texel_of(uv: [f32; 2], res: u32) -> (i32, i32) {
    let r = res as f32;
    ((uv[0] * r).floor() as i32, (uv[1] * r).floor() as i32)
}

/// Where border texel `j` of edge `k` of face `f` reads from: `(face, i, j)`.
pub fn border_source(set: &FaceSet, res: u32, f: usize, k: usize, j: u32) -> (usize, i32, i32) {
    let half = 0.5 / res as f32;
    let t = (j as f32 + 0.5) / res as f32;
    let e = edge_point(k, t);
    let out = outward(k);
    let link = set.links[f][k];
    if link.face == NO_FACE {
        let (i, jj) = texel_of([e[0] - out[0] * half, e[1] - out[1] * half], res);
        return (f, i, jj);
    }
    let n = link.face as usize;
    let k2 = link.edge as usize;
    let uv = match link.span {
        Span::Whole => UV_TRANSFORMS[link.transform as usize]
            .apply([e[0] + out[0] * half, e[1] + out[1] * half]),
        Span::FirstHalf | Span::SecondHalf => {
            let s0 = if link.span == Span::FirstHalf {
                0.0
            } else {
                0.5
            };
            let e2 = edge_point(k2, s0 + (1.0 - t) * 0.5);
            let out2 = outward(k2);
            [e2[0] - out2[0] * half, e2[1] - out2[1] * half]
        }
    };
    let (i, jj) = texel_of(uv, res);
    let last = res as i32 - 1;
    (n, i.clamp(0, last), jj.clamp(0, last))
}

/// The border texel `(i, j)` (one of them −1 or `res`) that border texel `j` of edge `k` is.
pub fn border_texel(res: u32, k: usize, j: u32) -> (i32, i32) {
    let t = (j as f32 + 0.5) / res as f32;
    let e = edge_point(k, t);
    let out = outward(k);
    let half = 0.5 / res as f32;
    texel_of([e[0] + out[0] * half, e[1] + out[1] * half], res)
}

/// Fills the borders of every face of `pages` (baked from `set`, interiors complete).
pub fn fill_borders(set: &FaceSet, pages: &mut Pages) {
    let res = pages.res;
    let r = res as i32;
    for f in 0..pages.faces {
        for k in 0..4 {
            for j in 0..res {
                let (bi, bj) = border_texel(res, k, j);
                let (sf, si, sj) = border_source(set, res, f, k, j);
                let (dst, src) = (pages.at(f, bi, bj), pages.at(sf, si, sj));
                pages.copy(dst, src);
            }
        }
        for (ci, cj, si, sj) in [
            (-1, -1, 0, 0),
            (r, -1, r - 1, 0),
            (r, r, r - 1, r - 1),
            (-1, r, 0, r - 1),
        ] {
            let (dst, src) = (pages.at(f, ci, cj), pages.at(f, si, sj));
            pages.copy(dst, src);
        }
    }
}
