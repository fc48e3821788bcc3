//! Ptex pages (`strata::ptex`, Becher §4.6–4.7): the one-texel borders equal the neighbour's
//! texels after the uv transform — for the quads of a surface-nets mesh (whose adjacency uses 8
//! of the 16 transforms), for pairs of quads built to use each of the 16, and for height tiles at the same LOD and across LODs, each tile baked in its own request — and
//! re-baking gives the same bytes.
//!
//! The expected neighbour texel is computed here by integer edge arithmetic (a border texel `j`
//! of edge `k` faces the neighbour's edge `k'` at along-index `res − 1 − j`, edges running in
//! opposite directions), not through the uv-transform table the baker uses.

use std::collections::BTreeSet;
use strata::ptex::face::{quad_faces, QuadSource, TileFaceKey, TileFacePlan, NO_FACE};
use strata::ptex::{bake, FaceSet, MaterialSet, Pages, Span};
use strata::terrain::tile::{snap_edges, synthesize, Tile, TileKey};
use strata::terrain::world::WorldParams;
use strata::terrain::WorldPlan;
use strata::volume::mesh::{surface_nets, MeshOptions, QuadMesh, SampleAttributes};

/// Border texel `j` of edge `k` of a face of `res`.
fn border_texel(k: usize, j: i32, r: i32) -> (i32, i32) {
    match k {
        0 => (j, -1),
        1 => (r, j),
        2 => (r - 1 - j, r),
        _ => (-1, r - 1 - j),
    }
}

/// The texel at along-index `m` (in the edge's direction) of the row just inside edge `k`.
fn edge_texel(k: usize, m: i32, r: i32) -> (i32, i32) {
    match k {
        0 => (m, 0),
        1 => (r - 1, m),
        2 => (r - 1 - m, r - 1),
        _ => (0, r - 1 - m),
    }
}

fn texel(p: &Pages, f: usize, (i, j): (i32, i32)) -> ([u8; 4], [u8; 4], u32) {
    let k = p.at(f, i, j);
    (p.albedo[k], p.normal[k], p.displacement[k].to_bits())
}

/// A blobby field with overhangs and many small features: every quad class pairing and so all
/// 16 transforms occur.
fn blobby_mesh() -> (QuadMesh, [usize; 3]) {
    let dims = [22usize, 20, 21];
    let mut sdf = Vec::with_capacity(dims.iter().product());
    for z in 0..dims[2] {
        for y in 0..dims[1] {
            for x in 0..dims[0] {
                let (x, y, z) = (x as f32, y as f32, z as f32);
                sdf.push(
                    (x * 0.71).sin()
                        + (y * 0.93 + z * 0.2).cos()
                        + (z * 0.57 + x * 0.3).sin() * 0.9
                        - 0.35,
                );
            }
        }
    }
    let mut mesh = QuadMesh::default();
    surface_nets(
        &sdf,
        SampleAttributes::default(),
        &MeshOptions::new(dims, 1.0),
        &mut mesh,
    )
    .expect("valid grid");
    // Give the vertices several materials so borders also cross material changes.
    mesh.materials = (0..mesh.vertex_count()).map(|v| (v % 5) as u8).collect();
    (mesh, dims)
}

fn mesh_set(mesh: &QuadMesh, mats: &MaterialSet) -> FaceSet {
    let origin = [1000.0f64, -37.0, 513.0];
    let world = |v: u32| -> [f64; 3] {
        let p = mesh.positions[v as usize];
        std::array::from_fn(|c| origin[c] + f64::from(p[c]))
    };
    quad_faces(
        &QuadSource {
            quads: &mesh.quads,
            adjacency: &mesh.adjacency,
            world: &world,
            normals: &mesh.normals,
            materials: &mesh.materials,
            spacing_m: 1.0,
        },
        mats,
    )
}

#[test]
fn quad_borders_equal_the_neighbours_texels_on_a_surface_nets_mesh() {
    let (mesh, _) = blobby_mesh();
    let mats = MaterialSet::default_ground(11);
    let set = mesh_set(&mesh, &mats);
    let mut seen = BTreeSet::new();
    for row in &set.links {
        for l in row.iter().filter(|l| l.face != NO_FACE) {
            seen.insert(l.transform);
        }
    }
    // Surface nets pair quad edges of 8 of the 16 kinds (the others are exercised by
    // `synthetic_quad_pairs_exercise_all_16_transforms`).
    assert!(seen.len() >= 8, "transforms exercised: {seen:?}");
    // Borders of every face at two resolutions (8 and 16 keep the test fast; the rule does not
    // depend on the resolution).
    for res in [8u32, 16] {
        let mut pages = Pages::default();
        bake(&set, &mats, res, &mut pages);
        assert_eq!(pages.faces, set.faces.len());
        let r = res as i32;
        let mut checked = [0usize; 16];
        for (f, row) in set.links.iter().enumerate() {
            for (k, l) in row.iter().enumerate() {
                for j in 0..r {
                    let got = texel(&pages, f, border_texel(k, j, r));
                    let want = if l.face == NO_FACE {
                        texel(&pages, f, edge_texel(k, j, r))
                    } else {
                        checked[l.transform as usize] += 1;
                        texel(
                            &pages,
                            l.face as usize,
                            edge_texel(l.edge as usize, r - 1 - j, r),
                        )
                    };
                    assert_eq!(got, want, "res {res} face {f} edge {k} texel {j}");
                }
            }
        }
        assert_eq!(
            checked.iter().filter(|&&c| c > 0).count(),
            seen.len(),
            "{checked:?}"
        );
    }
}

/// Two unit quads on the ground sharing edge `k` of the first and `k'` of the second: the
/// second's vertex order is rotated so that its edge `k'` runs back along the first's edge `k`.
fn quad_pair(k: usize, k2: usize, mats: &MaterialSet) -> FaceSet {
    let corner = [[0.0f64, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let out = [[0.0f64, -1.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0]][k];
    // The translated square's corner m = k + 2 is the first quad's corner k + 1.
    let shift = (k + 2 + 4 - k2) % 4;
    let a: Vec<[f64; 3]> = corner
        .iter()
        .map(|c| [c[0] + 40.0, 3.0, c[1] + 70.0])
        .collect();
    let b: Vec<[f64; 3]> = (0..4)
        .map(|i| {
            let c = corner[(i + shift) % 4];
            [c[0] + out[0] + 40.0, 3.0, c[1] + out[1] + 70.0]
        })
        .collect();
    let positions: Vec<[f64; 3]> = a.into_iter().chain(b).collect();
    let quads = [[0u32, 1, 2, 3], [4, 5, 6, 7]];
    let adjacency = {
        let mut adj = [[strata::volume::mesh::Neighbor::NONE; 4]; 2];
        adj[0][k] = strata::volume::mesh::Neighbor {
            quad: 1,
            edge: k2 as u8,
            transform: (4 * k + k2) as u8,
        };
        adj[1][k2] = strata::volume::mesh::Neighbor {
            quad: 0,
            edge: k as u8,
            transform: (4 * k2 + k) as u8,
        };
        adj
    };
    let world = |v: u32| positions[v as usize];
    let normals = [[0.0f32, 1.0, 0.0]; 8];
    let materials = [2u8, 4, 2, 1, 4, 4, 2, 1];
    quad_faces(
        &QuadSource {
            quads: &quads,
            adjacency: &adjacency,
            world: &world,
            normals: &normals,
            materials: &materials,
            spacing_m: 1.0,
        },
        mats,
    )
}

#[test]
fn synthetic_quad_pairs_exercise_all_16_transforms() {
    let mats = MaterialSet::default_ground(11);
    let res = 8u32;
    let r = res as i32;
    for k in 0..4 {
        for k2 in 0..4 {
            let set = quad_pair(k, k2, &mats);
            // The shared edge is the same segment seen from both quads.
            let p = |f: usize, corner: usize| {
                let face = set.faces[f];
                let idx = [0usize, 1, 3, 2][corner];
                set.samples[face.first as usize + idx].position
            };
            assert_eq!(p(0, k), p(1, (k2 + 1) % 4), "pair {k} {k2}");
            assert_eq!(p(0, (k + 1) % 4), p(1, k2), "pair {k} {k2}");
            let mut pages = Pages::default();
            bake(&set, &mats, res, &mut pages);
            for (f, fk, nk) in [(0usize, k, k2), (1, k2, k)] {
                for j in 0..r {
                    let got = texel(&pages, f, border_texel(fk, j, r));
                    let want = texel(&pages, 1 - f, edge_texel(nk, r - 1 - j, r));
                    assert_eq!(got, want, "transform {} texel {j}", 4 * fk + nk);
                }
            }
            // Across the shared edge the two faces' texels continue the same world pattern:
            // the border texel and the neighbour texel it copies are half a texel from the
            // edge on either side, so their displacements differ by a small step only.
            let edge_a = texel(&pages, 0, edge_texel(k, 3, r));
            let border_a = texel(&pages, 0, border_texel(k, 3, r));
            let da = f32::from_bits(edge_a.2);
            let db = f32::from_bits(border_a.2);
            assert!((da - db).abs() < 0.2, "pair {k} {k2}: {da} vs {db}");
        }
    }
}

#[test]
fn rebaking_gives_the_same_bytes_and_a_face_bakes_alike_in_any_set() {
    let (mesh, _) = blobby_mesh();
    let mats = MaterialSet::default_ground(11);
    let set = mesh_set(&mesh, &mats);
    let (mut a, mut b) = (Pages::default(), Pages::default());
    bake(&set, &mats, 16, &mut a);
    bake(&set, &mats, 16, &mut b);
    assert_eq!(a, b);
    // The interior differs between faces (the bake is not constant) ...
    let distinct: BTreeSet<u32> = a.displacement.iter().map(|d| d.to_bits()).collect();
    assert!(
        distinct.len() > 1000,
        "{} distinct displacements",
        distinct.len()
    );
    // ... and a face's interior is a function of the face alone: bake face 7 on its own.
    let mut alone = set.clone();
    let f = alone.faces[7];
    alone.samples = set.samples[f.first as usize..f.first as usize + 4].to_vec();
    alone.faces = vec![strata::ptex::Face { first: 0, ..f }];
    alone.links = vec![[strata::ptex::Link::NONE; 4]];
    alone.output = 1;
    let mut c = Pages::default();
    bake(&alone, &mats, 16, &mut c);
    let interior: Vec<_> = a.interior(7).collect();
    assert_eq!(c.interior(0).collect::<Vec<_>>(), interior);
    // Another seed gives other texels.
    let other = MaterialSet::default_ground(12);
    let mut d = Pages::default();
    bake(&set, &other, 16, &mut d);
    assert_ne!(a.albedo, d.albedo);
}

fn plan() -> WorldPlan {
    WorldPlan::new(5, WorldParams::default()).expect("default world is valid")
}

/// The pages of tile `key` drawn with `seams`, its neighbours synthesised unsnapped.
fn tile_pages(
    plan: &WorldPlan,
    key: TileKey,
    seams: [bool; 4],
    res: u32,
) -> (TileFacePlan, FaceSet, Pages) {
    let faces = TileFacePlan::new(key, seams, plan.lods.len() as u32 - 1);
    let tiles: Vec<Tile> = faces
        .tiles()
        .into_iter()
        .map(|t| {
            let mut tile = synthesize(plan, t);
            if t == key {
                snap_edges(plan, &mut tile, seams);
            }
            tile
        })
        .collect();
    let mats = MaterialSet::default_ground(plan.seed);
    let set = faces.build(|t| tiles.iter().find(|x| x.key == t), &mats, plan);
    let mut pages = Pages::default();
    bake(&set, &mats, res, &mut pages);
    (faces, set, pages)
}

#[test]
fn tile_borders_equal_the_neighbouring_tiles_pages_at_the_same_lod() {
    let plan = plan();
    let res = 16;
    let r = res as i32;
    let a = TileKey {
        lod: 0,
        x: 3,
        z: -2,
    };
    let (fa, set, pa) = tile_pages(&plan, a, [false; 4], res);
    assert_eq!(pa.faces, 16);
    // Inside the tile, borders come from the tile's own faces.
    let mut crossing = 0;
    for (f, row) in set.links.iter().take(16).enumerate() {
        for (k, l) in row.iter().enumerate() {
            assert_eq!(l.span, Span::Whole);
            let n = fa.faces[l.face as usize];
            // The neighbour's own page: its tile baked alone.
            let (_, _, pn) = tile_pages(&plan, n.tile(), [false; 4], res);
            let nf = n.id() as usize;
            if n.tile() != a {
                crossing += 1;
            }
            for j in 0..r {
                let got = texel(&pa, f, border_texel(k, j, r));
                let want = texel(&pn, nf, edge_texel(l.edge as usize, r - 1 - j, r));
                assert_eq!(got, want, "face {f} edge {k} texel {j} (neighbour {n:?})");
            }
        }
    }
    assert_eq!(crossing, 16, "4 faces along each of 4 sides");
}

#[test]
fn tile_borders_across_lods_take_the_nearest_coarser_texel() {
    let plan = plan();
    let res = 16;
    let r = res as i32;
    // Fine tile (0, 1, 1) covers [64, 128)² m; snapped on its east and south sides, it meets
    // LOD 1 tiles (1, 1, 0) (east) and (1, 0, 1) (south).
    let fine = TileKey { lod: 0, x: 1, z: 1 };
    let seams = [false, true, true, false];
    let (ff, set, pf) = tile_pages(&plan, fine, seams, res);
    let mut coarse: std::collections::BTreeMap<TileKey, Pages> = Default::default();
    let mut halves = [0usize; 2];
    for (f, row) in set.links.iter().take(16).enumerate() {
        for (k, l) in row.iter().enumerate() {
            let n: TileFaceKey = ff.faces[l.face as usize];
            if n.lod == 0 {
                assert_eq!(l.span, Span::Whole);
                continue;
            }
            let pc = coarse
                .entry(n.tile())
                .or_insert_with(|| tile_pages(&plan, n.tile(), [false; 4], res).2);
            let s0 = match l.span {
                Span::FirstHalf => 0,
                Span::SecondHalf => 1,
                Span::Whole => panic!("a coarser neighbour covers twice the edge"),
            };
            halves[s0] += 1;
            for j in 0..r {
                // t' = s0/2 + (1 − t)/2 with t = (j + ½)/r: along index ⌊t'·r⌋.
                let m = (s0 as i32 * r + (r - j - 1)) / 2;
                let got = texel(&pf, f, border_texel(k, j, r));
                let want = texel(pc, n.id() as usize, edge_texel(l.edge as usize, m, r));
                assert_eq!(got, want, "face {f} edge {k} texel {j}");
            }
        }
    }
    assert_eq!(
        halves,
        [4, 4],
        "8 faces meet the coarser tiles, half on each half"
    );
    let keys: Vec<TileKey> = coarse.keys().copied().collect();
    assert_eq!(
        keys,
        [
            TileKey { lod: 1, x: 0, z: 1 },
            TileKey { lod: 1, x: 1, z: 0 }
        ]
    );
}
