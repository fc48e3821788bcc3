//! `strata export-join`: the archives of an export's shards, joined into the archive of the
//! whole export. The members of shards `0..N` in order are the whole export's members (see the
//! module doc of [`super`]), so the joined archive is byte for byte the one an unsharded
//! `strata export` writes. Each shard is checked first: its manifest lists exactly its members
//! (names, sizes, blake3), every shard is of the same export, and each index `0..N` is there
//! once. The shards may be given in any order.

use super::{tar, Manifest, Shard};
use anyhow::{bail, ensure, Context};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// `strata export-join` options.
#[derive(Debug, clap::Args)]
pub struct JoinArgs {
    /// The shards' archives (`strata export --shard i/N`), in any order.
    #[arg(required = true, value_name = "SHARD")]
    pub shards: Vec<PathBuf>,
    /// Output archive (tar): the whole export.
    #[arg(long, short, value_name = "FILE")]
    pub out: PathBuf,
}

/// Archive members, `(name, data)` in order.
type Members = Vec<(String, Vec<u8>)>;

/// A shard archive's members before its manifest, and the manifest, checked against each other.
fn read_shard(path: &Path) -> anyhow::Result<(Members, Manifest)> {
    let bytes = std::fs::read(path).with_context(|| format!("reading {}", path.display()))?;
    let mut members = tar::read_members(&bytes)
        .with_context(|| format!("{} is not an export archive", path.display()))?;
    let Some((name, json)) = members.pop() else {
        bail!("{} is empty", path.display());
    };
    ensure!(
        name == "manifest.json",
        "{}: the last member is {name:?}, not manifest.json",
        path.display()
    );
    let manifest: Manifest = serde_json::from_slice(&json)
        .with_context(|| format!("{}: manifest.json", path.display()))?;
    ensure!(
        manifest.members.len() == members.len(),
        "{}: the manifest lists {} members, the archive has {}",
        path.display(),
        manifest.members.len(),
        members.len()
    );
    for ((name, data), entry) in members.iter().zip(&manifest.members) {
        ensure!(
            *name == entry.name
                && data.len() as u64 == entry.bytes
                && blake3::hash(data).to_hex().as_str() == entry.blake3,
            "{}: member {name:?} is not what the manifest records",
            path.display()
        );
    }
    Ok((members, manifest))
}

/// Writes the whole export joined from the shard archives at `paths` to `out`; returns its
/// manifest. Holds one shard in memory at a time.
///
/// # Errors
/// A shard that cannot be read or checked, shards of different exports, or a missing or
/// repeated shard index.
pub fn join(paths: &[PathBuf], out: &mut impl Write) -> anyhow::Result<Manifest> {
    let mut order: Vec<(u32, &PathBuf)> = Vec::new();
    let mut first: Option<Manifest> = None;
    for path in paths {
        let (_, m) = read_shard(path)?;
        match &first {
            None => first = Some(m.clone()),
            Some(f) => ensure!(
                m.format == f.format
                    && m.seed == f.seed
                    && m.spec == f.spec
                    && m.shard.count == f.shard.count,
                "{} is a shard of another export than {}",
                path.display(),
                paths[0].display()
            ),
        }
        order.push((m.shard.index, path));
    }
    let Some(first) = first else {
        bail!("no shards to join");
    };
    order.sort();
    let count = first.shard.count;
    ensure!(
        order.len() == count as usize && order.iter().enumerate().all(|(i, s)| s.0 == i as u32),
        "the shards are {:?} of {count}: each of 1..={count} must be given once",
        order.iter().map(|s| s.0 + 1).collect::<Vec<_>>()
    );
    let mut manifest = Manifest {
        shard: Shard::WHOLE,
        members: Vec::new(),
        ..first
    };
    for (_, path) in order {
        let (members, m) = read_shard(path)?;
        for (name, data) in &members {
            tar::write_member(out, name, data)?;
        }
        manifest.members.extend(m.members);
    }
    tar::write_member(out, "manifest.json", &serde_json::to_vec_pretty(&manifest)?)?;
    tar::finish(out)?;
    Ok(manifest)
}

/// Runs `strata export-join`. The archive is written beside `--out` and renamed onto it once
/// complete, so a refused join leaves no partial file there.
pub fn run(args: &JoinArgs) -> anyhow::Result<()> {
    let mut partial = args.out.clone().into_os_string();
    partial.push(".partial");
    let partial = PathBuf::from(partial);
    let file = std::fs::File::create(&partial)
        .with_context(|| format!("creating {}", partial.display()))?;
    let mut out = BufWriter::new(file);
    let written = join(&args.shards, &mut out).and_then(|m| {
        out.flush()?;
        Ok(m)
    });
    let manifest = match written {
        Ok(m) => m,
        Err(e) => {
            let _ = std::fs::remove_file(&partial);
            return Err(e);
        }
    };
    std::fs::rename(&partial, &args.out)
        .with_context(|| format!("renaming {} onto {}", partial.display(), args.out.display()))?;
    eprintln!(
        "wrote {} ({} members from {} shards)",
        args.out.display(),
        manifest.members.len(),
        args.shards.len()
    );
    Ok(())
}
