//! The disk tier of the stage cache: one file per tile under a directory (see the
//! [module docs](super) for the layout), in the [`super::codec`] form.

use super::codec::{decode_tile, encode_tile};
use super::InputHash;
use crate::terrain::Tile;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// The disk tier: one file per tile under a directory (see the module docs for the layout).
#[derive(Debug)]
pub struct DiskCache {
    dir: PathBuf,
    pub(super) writes: AtomicU64,
    pub(super) errors: AtomicU64,
    temp: AtomicU64,
}

fn hex(hash: &InputHash) -> String {
    hash.iter().map(|b| format!("{b:02x}")).collect()
}

impl DiskCache {
    /// The disk tier in `dir`, created if missing.
    pub fn open(dir: impl Into<PathBuf>) -> std::io::Result<Self> {
        let dir = dir.into();
        std::fs::create_dir_all(&dir)?;
        Ok(Self {
            dir,
            writes: AtomicU64::new(0),
            errors: AtomicU64::new(0),
            temp: AtomicU64::new(0),
        })
    }

    /// The directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The file of a hash: `DIR/<hh>/<64 hex digits>.tile`.
    pub fn path(&self, hash: &InputHash) -> PathBuf {
        let h = hex(hash);
        self.dir.join(&h[..2]).join(format!("{h}.tile"))
    }

    /// The tile under `hash`, if its file exists and is intact. A damaged file is deleted.
    pub fn read(&self, hash: &InputHash) -> Option<Tile> {
        let path = self.path(hash);
        let bytes = match std::fs::read(&path) {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return None,
            Err(e) => {
                self.errors.fetch_add(1, Ordering::Relaxed);
                tracing::warn!(path = %path.display(), "stage cache: cannot read: {e}");
                return None;
            }
        };
        match decode_tile(&bytes, hash) {
            Ok(t) => Some(t),
            Err(why) => {
                self.errors.fetch_add(1, Ordering::Relaxed);
                tracing::warn!(path = %path.display(), "stage cache: dropping a bad file: {why}");
                let _ = std::fs::remove_file(&path);
                None
            }
        }
    }

    /// Writes the tile under `hash` (to a temporary file, then renamed into place).
    pub fn write(&self, hash: &InputHash, tile: &Tile) {
        let path = self.path(hash);
        let result = (|| -> std::io::Result<()> {
            let parent = path.parent().unwrap_or(&self.dir);
            std::fs::create_dir_all(parent)?;
            let n = self.temp.fetch_add(1, Ordering::Relaxed);
            let tmp = parent.join(format!(".{}.{}.{n}.tmp", hex(hash), std::process::id()));
            let written = std::fs::File::create(&tmp)
                .and_then(|mut f| f.write_all(&encode_tile(hash, tile)))
                .and_then(|()| std::fs::rename(&tmp, &path));
            if written.is_err() {
                let _ = std::fs::remove_file(&tmp);
            }
            written
        })();
        match result {
            Ok(()) => {
                self.writes.fetch_add(1, Ordering::Relaxed);
            }
            Err(e) => {
                self.errors.fetch_add(1, Ordering::Relaxed);
                tracing::warn!(path = %path.display(), "stage cache: cannot write: {e}");
            }
        }
    }
}
