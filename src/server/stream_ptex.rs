//! The Ptex pages of stream sessions (protocol v2, [`crate::stream::ptex`]): a batch's faces
//! baked from the tiles of the session's world version, on the blocking pool, into a frame of
//! kind 3.
//!
//! The faces of one tile are baked together: the tile's face plan ([`TileFacePlan`], with the
//! seams the session drew it with) reads the tile and the neighbouring tiles its borders need,
//! through [`AppState::tile`] (the stage cache), and [`bake_faces`] bakes only the batch's faces,
//! so a page is byte for byte the one the HTTP route serves for that tile and `res` (with the
//! same materials and decals, [`super::images::world_materials`]). So are the faces of one
//! volume chunk: the chunk is meshed as its routes mesh it ([`super::chunks::mesh`], the same
//! tiles and solved regions) and its quads' faces ([`chunk_faces`]) baked as
//! `GET …/ptex/{lod}/{x}/{y}/{z}?res=` bakes them.

use super::edit_service::StreamView;
use super::params::check_bounds;
use super::AppState;
use crate::ptex::budget::FaceBounds;
use crate::ptex::face::{chunk_faces, FaceSet, TileFacePlan};
use crate::ptex::noise::ANCHOR_M;
use crate::ptex::select::bake_faces;
use crate::ptex::Pages;
use crate::stream::ptex::{PageFace, PtexBaked, PtexBatch};
use crate::stream::ptex_frame::{encode, PageRecord};
use crate::stream::session::StreamError;
use crate::terrain::TileKey;
use std::collections::BTreeMap;
use std::sync::Arc;

/// The bounding sphere of face `f` of `set`: the centre of its samples' box and the largest
/// distance from it to a sample.
fn bounds(set: &FaceSet, f: usize) -> FaceBounds {
    let face = &set.faces[f];
    let n = (face.n * face.n) as usize;
    let samples = &set.samples[face.first as usize..face.first as usize + n];
    let origin = face.anchor.map(|a| f64::from(a) * ANCHOR_M);
    let mut lo = [f32::INFINITY; 3];
    let mut hi = [f32::NEG_INFINITY; 3];
    for s in samples {
        for c in 0..3 {
            lo[c] = lo[c].min(s.position[c]);
            hi[c] = hi[c].max(s.position[c]);
        }
    }
    let mid: [f32; 3] = std::array::from_fn(|c| (lo[c] + hi[c]) * 0.5);
    let radius = samples
        .iter()
        .map(|s| {
            let d: [f32; 3] = std::array::from_fn(|c| s.position[c] - mid[c]);
            (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
        })
        .fold(0.0f32, f32::max);
    FaceBounds {
        centre: std::array::from_fn(|c| (origin[c] + f64::from(mid[c])) as f32),
        radius,
    }
}

/// The faces a batch's pages are baked from: a tile's face plan and the tiles it reads, or a
/// chunk's faces.
enum Job {
    Tile(TileFacePlan, Vec<Arc<crate::terrain::Tile>>),
    Chunk(FaceSet),
}

/// Bakes `batch` from the world `view` into a frame of kind 3.
pub(super) async fn frame(
    state: &AppState,
    view: &StreamView,
    batch: &PtexBatch,
) -> Result<PtexBaked, StreamError> {
    let plan = view.view.plan.clone();
    let max_lod = plan.lods.len() as u32 - 1;
    let mats = super::images::world_materials(state, &view.view)
        .await
        .map_err(|e| StreamError {
            code: "internal",
            message: format!("ptex materials failed: {}", e.message),
            field: None,
        })?;
    // The batch's pages by tile (and the seams it was drawn with) or by chunk, in batch order
    // within each.
    let mut by_tile: BTreeMap<(TileKey, [bool; 4]), Vec<usize>> = BTreeMap::new();
    let mut by_chunk: BTreeMap<(u32, i64, i64, i64), Vec<usize>> = BTreeMap::new();
    for (k, p) in batch.pages.iter().enumerate() {
        match p.face {
            PageFace::Tile(f) => by_tile.entry((f.tile(), p.seams)).or_default().push(k),
            PageFace::Chunk(f) => {
                let c = f.chunk;
                by_chunk.entry((c.lod, c.x, c.y, c.z)).or_default().push(k);
            }
        }
    }
    // Each job: a set of faces (built on the blocking pool) and the batch's pages in it, by
    // their face's index in the set.
    let mut jobs: Vec<(Job, Vec<(usize, usize)>)> = Vec::new();
    for ((key, seams), pages) in by_tile {
        let faces = TileFacePlan::new(key, seams, max_lod);
        let mut tiles = Vec::new();
        for t in faces.tiles() {
            if check_bounds(&plan, t).is_err() {
                continue;
            }
            let s = if t == key { seams } else { [false; 4] };
            tiles.push(state.tile(&view.view, t, s).await);
        }
        let chosen = pages
            .iter()
            .filter_map(|&k| match batch.pages[k].face {
                PageFace::Tile(f) => Some((k, f.id() as usize)),
                PageFace::Chunk(_) => None,
            })
            .collect();
        jobs.push((Job::Tile(faces, tiles), chosen));
    }
    for ((lod, x, y, z), pages) in by_chunk {
        let key = crate::volume::chunk::ChunkKey { lod, x, y, z };
        let mesh = super::chunks::mesh(state, &view.view, key)
            .await
            .map_err(|e| StreamError {
                code: "internal",
                message: format!("meshing chunk {lod}/{x}/{y}/{z} for its Ptex pages failed: {e}"),
                field: None,
            })?;
        let spacing_m = plan.lods[lod as usize].spacing_m;
        let set = tokio::task::spawn_blocking({
            let mats = mats.clone();
            move || chunk_faces(&mesh, spacing_m, &mats)
        })
        .await
        .map_err(|e| StreamError {
            code: "internal",
            message: format!("ptex chunk faces failed: {e}"),
            field: None,
        })?;
        // A quad past the chunk's (meshed again since the session held its faces) has no page
        // here: its chunk's fresh frame holds the new faces.
        let chosen = pages
            .iter()
            .filter_map(|&k| match batch.pages[k].face {
                PageFace::Chunk(f) if (f.quad as usize) < set.faces.len() => {
                    Some((k, f.quad as usize))
                }
                _ => None,
            })
            .collect();
        jobs.push((Job::Chunk(set), chosen));
    }
    let batch = batch.clone();
    let version = view.version;
    tokio::task::spawn_blocking(move || {
        let res = batch.res();
        let mut all = Pages::default();
        all.reset(res, batch.pages.len());
        let mut bounds = vec![
            FaceBounds {
                centre: [0.0; 3],
                radius: 0.0
            };
            batch.pages.len()
        ];
        let per = all.texels_per_face();
        let mut some = Pages::default();
        for (job, pages) in jobs {
            let set = match job {
                Job::Tile(faces, tiles) => faces.build(
                    |t| tiles.iter().find(|x| x.key == t).map(Arc::as_ref),
                    &mats,
                    &plan,
                ),
                Job::Chunk(set) => set,
            };
            let chosen: Vec<usize> = pages.iter().map(|&(_, f)| f).collect();
            bake_faces(&set, &mats, res, &chosen, &mut some);
            for (j, &(k, _)) in pages.iter().enumerate() {
                let (src, dst) = (j * per..(j + 1) * per, k * per);
                all.albedo[dst..dst + per].copy_from_slice(&some.albedo[src.clone()]);
                all.normal[dst..dst + per].copy_from_slice(&some.normal[src.clone()]);
                all.displacement[dst..dst + per].copy_from_slice(&some.displacement[src]);
                bounds[k] = self::bounds(&set, chosen[j]);
            }
        }
        let records: Vec<PageRecord> = batch
            .pages
            .iter()
            .zip(&bounds)
            .map(|(p, b)| PageRecord {
                face: p.face,
                seams: p
                    .seams
                    .iter()
                    .enumerate()
                    .fold(0u8, |b, (i, s)| b | ((*s as u8) << i)),
                slot: p.slot,
                bounds: *b,
            })
            .collect();
        PtexBaked {
            bytes: encode(batch.level, version, &records, &all).into(),
            bounds,
        }
    })
    .await
    .map_err(|e| StreamError {
        code: "internal",
        message: format!("ptex bake failed: {e}"),
        field: None,
    })
}
