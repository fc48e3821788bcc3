//! Batch exports: a rectangle of tiles at one LOD, as chosen products and formats, in one
//! deterministic tar archive, optionally one shard of N.
//!
//! Members are written in canonical order — rows `z` ascending, then columns `x`, then products
//! (`tiles` before `scatter`), then formats in the order asked — as `tiles/{lod}/{x}/{z}.{ext}`,
//! `scatter/{lod}/{x}/{z}.json` and `ptex/{lod}/{x}/{z}.ptx`, followed by `manifest.json` (the spec, the shard, and a blake3 hash
//! per member). Shard `i` of `N` takes the contiguous tiles `[i·T/N, (i+1)·T/N)` of the `T` tiles
//! in canonical order, so the members of shards `0..N` in order are exactly the members of the
//! unsharded export, byte for byte, and [`join`] writes the whole archive from the shards'.
//! Every member is the same bytes the HTTP API serves for the same key.

pub mod cli;
pub mod join;
pub mod size;
pub mod tar;

use crate::encode::{self, Format};
use crate::terrain::{Tile, TileKey, WorldPlan, MAX_LOD};
use serde::{Deserialize, Serialize};
use std::io::Write;

/// Most tiles one export may cover.
pub const MAX_EXPORT_TILES: u64 = 65_536;

/// A product of an export.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Product {
    /// Height tiles in the chosen formats.
    Tiles,
    /// Scatter points (JSON).
    Scatter,
    /// The tile's 4 × 4 Ptex faces as a `.ptx` file (Disney's Ptex format, [`encode::ptx`]) at
    /// [`ExportSpec::ptex_res`].
    Ptex,
}

/// What to export.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ExportSpec {
    /// Level of detail of every tile.
    pub lod: u32,
    /// First tile column (inclusive).
    pub x0: i64,
    /// First tile row (inclusive).
    pub z0: i64,
    /// Last tile column (exclusive).
    pub x1: i64,
    /// Last tile row (exclusive).
    pub z1: i64,
    /// Products, in member order.
    pub products: Vec<Product>,
    /// Tile formats by extension (`json`, `bin`, `png`, `glb`), in member order.
    pub formats: Vec<String>,
    /// Texels per Ptex face side of the `ptex` product (a power of two in 8..=256).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ptex_res: Option<u32>,
}

/// One shard of an export: `index` in `0..count`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    /// Zero-based shard index.
    pub index: u32,
    /// Number of shards.
    pub count: u32,
}

impl Shard {
    /// The whole export.
    pub const WHOLE: Shard = Shard { index: 0, count: 1 };

    /// Parses `i/N` with `i` counted from 1 (as the CLI takes it).
    pub fn parse(s: &str) -> Result<Self, String> {
        let (i, n) = s.split_once('/').ok_or("shard must look like i/N")?;
        let i: u32 = i
            .trim()
            .parse()
            .map_err(|_| "shard index must be a number")?;
        let n: u32 = n
            .trim()
            .parse()
            .map_err(|_| "shard count must be a number")?;
        if n == 0 || i == 0 || i > n {
            return Err(format!("shard {i}/{n}: need 1 ≤ i ≤ N"));
        }
        Ok(Shard {
            index: i - 1,
            count: n,
        })
    }
}

/// A spec that cannot be exported; `field` names the offending field.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct SpecError {
    /// Offending field.
    pub field: &'static str,
    /// What is wrong.
    pub message: String,
}

impl ExportSpec {
    /// Checks the spec against the world's limits.
    pub fn validate(&self, plan: &WorldPlan) -> Result<(), SpecError> {
        let err = |field, message: String| Err(SpecError { field, message });
        if self.lod > MAX_LOD {
            return err("lod", format!("must be in 0..={MAX_LOD}"));
        }
        let lim = plan.max_tile_coord(self.lod);
        for (field, v) in [
            ("x0", self.x0),
            ("z0", self.z0),
            ("x1", self.x1.saturating_sub(1)),
            ("z1", self.z1.saturating_sub(1)),
        ] {
            if v.unsigned_abs() > lim.unsigned_abs() {
                return err(
                    field,
                    format!("tile coordinates at LOD {} must be within ±{lim}", self.lod),
                );
            }
        }
        if self.x1 <= self.x0 {
            return err("x1", "must be greater than x0".into());
        }
        if self.z1 <= self.z0 {
            return err("z1", "must be greater than z0".into());
        }
        if self.tile_count() > MAX_EXPORT_TILES {
            return err(
                "x1",
                format!("an export covers at most {MAX_EXPORT_TILES} tiles"),
            );
        }
        if self.products.is_empty() {
            return err(
                "products",
                "name at least one of tiles, scatter, ptex".into(),
            );
        }
        if self.products.contains(&Product::Scatter) {
            if let Some(message) = crate::terrain::scatter::cost_error(plan, self.lod) {
                return err("lod", message);
            }
        }
        if self.products.contains(&Product::Tiles) && self.formats.is_empty() {
            return err(
                "formats",
                "tiles need at least one of json, bin, png, glb".into(),
            );
        }
        if self.products.contains(&Product::Ptex)
            && !self.ptex_res.is_some_and(crate::ptex::valid_res)
        {
            return err(
                "ptex_res",
                "ptex needs ptex_res, a power of two in 8..=256".into(),
            );
        }
        for f in &self.formats {
            if Format::from_extension(f).is_none() {
                return err(
                    "formats",
                    format!("unknown format {f:?}; known: json, bin, png, glb"),
                );
            }
        }
        Ok(())
    }

    /// Number of tiles.
    pub fn tile_count(&self) -> u64 {
        ((self.x1 - self.x0).max(0) as u64) * ((self.z1 - self.z0).max(0) as u64)
    }

    /// The tiles of a shard, in canonical order.
    pub fn keys(&self, shard: Shard) -> Vec<TileKey> {
        let total = self.tile_count();
        let a = total * shard.index as u64 / shard.count as u64;
        let b = total * (shard.index as u64 + 1) / shard.count as u64;
        let w = (self.x1 - self.x0) as u64;
        (a..b)
            .map(|i| TileKey {
                lod: self.lod,
                x: self.x0 + (i % w) as i64,
                z: self.z0 + (i / w) as i64,
            })
            .collect()
    }
}

/// Archive members: names and bytes.
pub type Members = Vec<(String, Vec<u8>)>;

/// The archive members of one tile, in canonical order, encoded as the tile routes encode them
/// ([`encode::tile`], version 1).
///
/// # Errors
/// An encoder failed (PNG).
pub fn members(
    plan: &WorldPlan,
    spec: &ExportSpec,
    tile: &Tile,
) -> Result<Members, encode::EncodeError> {
    members_with(
        plan,
        spec,
        &crate::ptex::MaterialSet::default_ground(plan.seed),
        tile,
    )
}

/// [`members`] with the world's Ptex materials and decals `mats`.
///
/// # Errors
/// An encoder failed (PNG).
pub fn members_with(
    plan: &WorldPlan,
    spec: &ExportSpec,
    mats: &crate::ptex::MaterialSet,
    tile: &Tile,
) -> Result<Members, encode::EncodeError> {
    let k = tile.key;
    let mut out = Vec::new();
    for product in &spec.products {
        match product {
            Product::Tiles => {
                for f in spec
                    .formats
                    .iter()
                    .filter_map(|f| Format::from_extension(f))
                {
                    let bytes = encode::tile(plan, tile, f, encode::TileVersion::V1)?.body;
                    out.push((
                        format!("tiles/{}/{}/{}.{}", k.lod, k.x, k.z, f.extension()),
                        bytes,
                    ));
                }
            }
            Product::Scatter => out.push((
                format!("scatter/{}/{}/{}.json", k.lod, k.x, k.z),
                encode::scatter::encode(plan, tile),
            )),
            Product::Ptex => out.push((
                format!("ptex/{}/{}/{}.ptx", k.lod, k.x, k.z),
                ptx_member(
                    plan,
                    mats,
                    tile,
                    spec.ptex_res.unwrap_or(crate::ptex::MIN_RES),
                ),
            )),
        }
    }
    Ok(out)
}

/// The `.ptx` of a tile's 4 × 4 Ptex faces at `res`: their interiors, a function of the tile
/// alone, are the HTTP pages' interior texels (with the same materials `mats`); adjacency within
/// the tile.
pub fn ptx_member(
    plan: &WorldPlan,
    mats: &crate::ptex::MaterialSet,
    tile: &Tile,
    res: u32,
) -> Vec<u8> {
    use crate::ptex::face::TileFacePlan;
    let faces = TileFacePlan::new(tile.key, [false; 4], plan.lods.len() as u32 - 1);
    let mut set = faces.build(|t| (t == tile.key).then_some(tile), mats, plan);
    set.output = set.faces.len();
    let mut pages = crate::ptex::Pages::default();
    crate::ptex::bake_interior(&set, mats, res, &mut pages);
    encode::ptx::write(&pages, &encode::ptx::adjacency(&set))
}

/// Manifest entry of one member.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ManifestEntry {
    /// Member name.
    pub name: String,
    /// Size, bytes.
    pub bytes: u64,
    /// blake3 of the member, hex.
    pub blake3: String,
}

/// `manifest.json`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Manifest {
    /// Always `"strata.export.v1"`.
    pub format: String,
    /// World seed (decimal string: it may not fit a JavaScript number).
    pub seed: String,
    /// What was exported.
    pub spec: ExportSpec,
    /// Which shard this archive is.
    pub shard: Shard,
    /// Members before the manifest, in order.
    pub members: Vec<ManifestEntry>,
}

/// Writes the archive of one shard, synthesising tiles on `threads` CPU threads; `progress` is
/// called with `(tiles done, tiles in the shard)` after each tile is written.
///
/// # Errors
/// An invalid spec or a failing writer.
pub fn write_archive(
    plan: &WorldPlan,
    edits: &crate::edits::TileEdits,
    spec: &ExportSpec,
    shard: Shard,
    threads: usize,
    out: &mut impl Write,
    mut progress: impl FnMut(usize, usize),
) -> anyhow::Result<Manifest> {
    spec.validate(plan)?;
    let keys = spec.keys(shard);
    let threads = threads.max(1);
    let default_mats;
    let mats = match &edits.materials {
        Some(m) => m.as_ref(),
        None => {
            default_mats = crate::ptex::MaterialSet::default_ground(plan.seed);
            &default_mats
        }
    };
    let mut manifest = Manifest {
        format: "strata.export.v1".into(),
        seed: plan.seed.to_string(),
        spec: spec.clone(),
        shard,
        members: Vec::new(),
    };
    let mut done = 0;
    for batch in keys.chunks(threads * 4) {
        let tiles: Vec<Result<Members, encode::EncodeError>> = std::thread::scope(|s| {
            let handles: Vec<_> = (0..threads)
                .map(|t| {
                    s.spawn(move || {
                        batch
                            .iter()
                            .skip(t)
                            .step_by(threads)
                            .map(|k| {
                                let tile = crate::edits::synthesize(plan, *k, edits);
                                members_with(plan, spec, mats, &tile)
                            })
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            // Thread `t` made keys `t, t + threads, …`: taking from the threads in turn restores
            // the keys' order without copying any bytes.
            let mut per_thread: Vec<_> = handles
                .into_iter()
                .map(|h| h.join().expect("export worker panicked").into_iter())
                .collect();
            (0..batch.len())
                .filter_map(|i| per_thread[i % threads].next())
                .collect()
        });
        for tile_members in tiles {
            for (name, bytes) in tile_members? {
                tar::write_member(out, &name, &bytes)?;
                manifest.members.push(ManifestEntry {
                    bytes: bytes.len() as u64,
                    blake3: blake3::hash(&bytes).to_hex().to_string(),
                    name,
                });
            }
            done += 1;
            progress(done, keys.len());
        }
    }
    let json = serde_json::to_vec_pretty(&manifest)?;
    tar::write_member(out, "manifest.json", &json)?;
    tar::finish(out)?;
    Ok(manifest)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::terrain::WorldParams;

    fn spec() -> ExportSpec {
        ExportSpec {
            lod: 1,
            x0: -2,
            z0: -1,
            x1: 2,
            z1: 2,
            products: vec![Product::Tiles, Product::Scatter],
            formats: vec!["bin".into(), "png".into()],
            ptex_res: None,
        }
    }

    #[test]
    fn scatter_exports_are_refused_where_a_scan_tile_costs_too_much() {
        let levels = WorldPlan::new(5, WorldParams::default()).expect("plan");
        let scan = WorldPlan::new(5, WorldParams::classic()).expect("plan");
        let at = |lod| ExportSpec { lod, ..spec() };
        assert_eq!(at(12).validate(&levels), Ok(()));
        assert_eq!(at(6).validate(&scan), Ok(()));
        let e = at(7)
            .validate(&scan)
            .expect_err("LOD 7 scatter of a scan world");
        assert_eq!(e.field, "lod");
        assert!(e.message.contains("up to LOD 6"), "{}", e.message);
        let tiles_only = ExportSpec {
            products: vec![Product::Tiles],
            ..at(7)
        };
        assert_eq!(tiles_only.validate(&scan), Ok(()));
    }

    #[test]
    fn shards_concatenate_to_the_whole_export() {
        let plan = WorldPlan::new(5, WorldParams::default()).expect("plan");
        let mut whole = Vec::new();
        write_archive(
            &plan,
            &Default::default(),
            &spec(),
            Shard::WHOLE,
            2,
            &mut whole,
            |_, _| {},
        )
        .expect("export");
        let whole = tar::read_members(&whole).expect("read");
        assert_eq!(whole.len(), 12 * 3 + 1);
        let mut joined = Vec::new();
        for i in 0..3 {
            let mut part = Vec::new();
            write_archive(
                &plan,
                &Default::default(),
                &spec(),
                Shard { index: i, count: 3 },
                1 + i as usize,
                &mut part,
                |_, _| {},
            )
            .expect("export");
            let mut members = tar::read_members(&part).expect("read");
            assert_eq!(members.pop().map(|m| m.0), Some("manifest.json".into()));
            joined.extend(members);
        }
        assert_eq!(joined, whole[..whole.len() - 1].to_vec());
    }

    #[test]
    fn bad_specs_name_the_field() {
        let plan = WorldPlan::new(5, WorldParams::default()).expect("plan");
        let field = |f: &dyn Fn(&mut ExportSpec)| {
            let mut s = spec();
            f(&mut s);
            s.validate(&plan).err().map(|e| e.field)
        };
        assert_eq!(field(&|_| {}), None);
        assert_eq!(field(&|s| s.lod = 13), Some("lod"));
        assert_eq!(field(&|s| s.x1 = s.x0), Some("x1"));
        assert_eq!(field(&|s| s.formats = vec!["tiff".into()]), Some("formats"));
        assert_eq!(field(&|s| s.products.clear()), Some("products"));
        assert_eq!(field(&|s| s.x1 = 100_000), Some("x1"));
        assert_eq!(Shard::parse("2/3"), Ok(Shard { index: 1, count: 3 }));
        assert!(
            Shard::parse("0/3").is_err()
                && Shard::parse("4/3").is_err()
                && Shard::parse("x").is_err()
        );
    }
}
