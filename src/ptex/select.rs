//! Baking chosen faces of a set: what a stream session's budget asks for, a few faces of a
//! height tile at one level, without baking the rest of the tile or its neighbours.
//!
//! A chosen face's interior is [`super::bake::texel`] at each texel, and each border texel is
//! the texel [`super::border::border_source`] names, computed alone: a neighbour's texel is a
//! function of the neighbour face only, so the page is byte for byte the one [`super::bake`]
//! writes for the whole set (tested below), at a cost of `res² + 4·res` texels a face instead of
//! the neighbours' `res²` each.

use super::bake::{bake_rows, face_constants, texels_lanes, NoiseCache};
use super::border::{border_source, border_texel};
use super::face::FaceSet;
use super::material::MaterialSet;
use super::noise::LANES;
use super::pages::Pages;
use rayon::prelude::*;

/// Bakes faces `chosen` of `set` (indices into `set.faces`) at `res` into `out`, face `k` of
/// `out` being `chosen[k]`, borders included. The interiors' rows are shared among the cores
/// (a batch of one 256² page uses them all), then each face's border in parallel (the texels
/// a border reads from a neighbour baked [`LANES`] at a time, as the interiors' are).
pub fn bake_faces(set: &FaceSet, mats: &MaterialSet, res: u32, chosen: &[usize], out: &mut Pages) {
    out.reset(res, chosen.len());
    bake_rows(set, mats, res, chosen, out);
    let per = out.texels_per_face();
    let side = out.side();
    let r = res as i32;
    let at = |i: i32, j: i32| (j + 1) as usize * side + (i + 1) as usize;
    out.albedo
        .par_chunks_mut(per)
        .zip(out.normal.par_chunks_mut(per))
        .zip(out.displacement.par_chunks_mut(per))
        .zip(chosen.par_iter())
        .for_each_init(
            || (NoiseCache::new(mats), Vec::new()),
            |(cache, todo), (((alb, nrm), disp), &f)| {
                // Border texels read from the face itself are copies; those of neighbours are
                // baked in runs of one source face, up to [`LANES`] texels side by side.
                todo.clear();
                for k in 0..4 {
                    for j in 0..res {
                        let (bi, bj) = border_texel(res, k, j);
                        let (sf, si, sj) = border_source(set, res, f, k, j);
                        let d = at(bi, bj);
                        if sf == f {
                            let s = at(si, sj);
                            alb[d] = alb[s];
                            nrm[d] = nrm[s];
                            disp[d] = disp[s];
                        } else {
                            todo.push((d, sf, si as u32, sj as u32));
                        }
                    }
                }
                for run in todo.chunk_by(|a, b| a.1 == b.1) {
                    let sf = run[0].1;
                    let constants = face_constants(&set.faces[sf], res);
                    for part in run.chunks(LANES) {
                        // A short run repeats its last texel in the spare lanes.
                        let ij = std::array::from_fn(|l| {
                            let (_, _, si, sj) = part[l.min(part.len() - 1)];
                            (si, sj)
                        });
                        let texels = texels_lanes(set, mats, sf, res, constants, ij, cache);
                        for (&(d, ..), t) in part.iter().zip(&texels) {
                            alb[d] = t.albedo;
                            nrm[d] = t.normal;
                            disp[d] = t.displacement;
                        }
                    }
                }
                for (ci, cj, si, sj) in [
                    (-1, -1, 0, 0),
                    (r, -1, r - 1, 0),
                    (r, r, r - 1, r - 1),
                    (-1, r, 0, r - 1),
                ] {
                    let (d, s) = (at(ci, cj), at(si, sj));
                    alb[d] = alb[s];
                    nrm[d] = nrm[s];
                    disp[d] = disp[s];
                }
            },
        );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::{TileKey, WorldParams, WorldPlan};

    #[test]
    fn chosen_faces_are_the_whole_bakes_bytes() {
        let plan = WorldPlan::new(5, WorldParams::default()).expect("plan");
        let mats = MaterialSet::default_ground(plan.seed);
        let key = TileKey {
            lod: 2,
            x: 3,
            z: -2,
        };
        let set = crate::ptex::face::test_face_set(&plan, key, &mats);
        let mut whole = Pages::default();
        crate::ptex::bake(&set, &mats, 16, &mut whole);
        let chosen = [0usize, 5, 3, 15, 12];
        let mut some = Pages::default();
        bake_faces(&set, &mats, 16, &chosen, &mut some);
        let per = whole.texels_per_face();
        for (k, &f) in chosen.iter().enumerate() {
            let (a, b) = (f * per..(f + 1) * per, k * per..(k + 1) * per);
            assert_eq!(whole.albedo[a.clone()], some.albedo[b.clone()], "face {f}");
            assert_eq!(whole.normal[a.clone()], some.normal[b.clone()], "face {f}");
            assert_eq!(whole.displacement[a], some.displacement[b], "face {f}");
        }
    }
}
