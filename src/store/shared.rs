//! What both stores compute the same way, outside their databases: the time stamp, the scene
//! hash of the edit log, an edit's checks and new rows ([`prepare_edit`]) and the replay of the
//! log from a snapshot ([`replay`]).

use super::{check_images, patch_scene, EditApplied, StoreError, SNAPSHOT_EVERY};
use crate::scene::{dirty_region, Scene};
use serde_json::Value;

/// `StoreError::Backend` with `e`'s message.
pub(super) fn backend(e: impl std::fmt::Display) -> StoreError {
    StoreError::Backend(e.to_string())
}

/// Seconds since the Unix epoch (0 if the clock is before it).
/// Whether an upload of image `hash` to a world already holding `known` stores a row: `false`
/// when the world holds it (uploads are idempotent), `true` when there is room.
///
/// # Errors
/// [`StoreError::TooManyImages`] when the world holds [`super::MAX_WORLD_IMAGES`] others.
pub(super) fn admit_image(known: &[[u8; 32]], hash: &[u8; 32]) -> Result<bool, StoreError> {
    if known.contains(hash) {
        return Ok(false);
    }
    if known.len() >= super::MAX_WORLD_IMAGES {
        return Err(StoreError::TooManyImages {
            limit: super::MAX_WORLD_IMAGES,
        });
    }
    Ok(true)
}

/// An image hash as a row stores it (32 bytes).
///
/// # Errors
/// [`StoreError::Backend`] for a value of another length.
pub(super) fn image_hash_of(bytes: Vec<u8>) -> Result<[u8; 32], StoreError> {
    bytes
        .try_into()
        .map_err(|_| StoreError::Backend("an image hash is not 32 bytes".into()))
}

pub(super) fn now() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_secs() as i64)
        .unwrap_or(0)
}

/// `blake3` of a scene's stored JSON text, as the edit log keeps it.
pub(super) fn scene_hash(text: &str) -> Vec<u8> {
    blake3::hash(text.as_bytes()).as_bytes().to_vec()
}

/// Parses stored JSON; a failure is a [`StoreError::Backend`] naming `what`.
pub(super) fn parse_json(text: &str, what: &str) -> Result<Value, StoreError> {
    serde_json::from_str(text).map_err(|e| StoreError::Backend(format!("stored {what}: {e}")))
}

/// The rows an accepted edit writes, computed before anything is written.
#[derive(Debug)]
pub(super) struct PreparedEdit {
    /// The version it makes.
    pub version: u64,
    /// The new scene's stored text.
    pub scene: String,
    /// [`scene_hash`] of `scene`.
    pub scene_hash: Vec<u8>,
    /// The patch's stored text.
    pub patch: String,
    /// Whether `version` gets a snapshot (a multiple of [`SNAPSHOT_EVERY`]).
    pub snapshot: bool,
    /// What the store returns once the rows are committed.
    pub applied: EditApplied,
}

/// Checks an edit of world `id`, whose latest version is `version` with stored scene `text`,
/// against `expected` and applies `patch` ([`patch_scene`]); every image the new scene names is
/// among `images`, the world's stored images ([`check_images`]). Pure: the caller writes the rows
/// in the transaction that read `version` and `text`, or writes nothing on error.
///
/// # Errors
/// [`StoreError::Conflict`] when `expected` is not `version`, or what [`patch_scene`] refuses.
pub(super) fn prepare_edit(
    id: &str,
    version: u64,
    text: &str,
    expected: Option<u64>,
    patch: &json_patch::Patch,
    images: &[[u8; 32]],
) -> Result<PreparedEdit, StoreError> {
    if let Some(expected) = expected {
        if expected != version {
            return Err(StoreError::Conflict {
                expected,
                latest: version,
            });
        }
    }
    let doc = parse_json(text, "scene")?;
    let old = Scene::from_value(&doc).map_err(|e| {
        StoreError::Backend(format!("stored scene of {id} v{version} is invalid: {e}"))
    })?;
    let (scene, new) = patch_scene(doc, &old, patch)?;
    check_images(&new, images)?;
    let next = version + 1;
    Ok(PreparedEdit {
        version: next,
        scene_hash: scene_hash(&scene),
        scene,
        patch: serde_json::to_string(patch).map_err(backend)?,
        snapshot: next.is_multiple_of(SNAPSHOT_EVERY),
        applied: EditApplied {
            version: next,
            dirty: dirty_region(&old, &new),
        },
    })
}

/// The scene of world `id` at `version`, from the snapshot `snapshot` taken at version `base`
/// and the log entries `(version, patch text, scene hash)` of versions `base + 1 ..= version`
/// in order. Checks that none is missing and that the result hashes to what the last one
/// recorded.
///
/// # Errors
/// [`StoreError::Backend`] when the log is incomplete, does not apply or does not give the
/// recorded scene.
pub(super) fn replay(
    id: &str,
    base: u64,
    snapshot: &str,
    log: impl IntoIterator<Item = Result<(u64, String, Vec<u8>), StoreError>>,
    version: u64,
) -> Result<Value, StoreError> {
    let mut doc = parse_json(snapshot, "snapshot")?;
    let mut expect = base + 1;
    let mut last_hash = None;
    for entry in log {
        let (v, patch, hash) = entry?;
        if v != expect {
            return Err(StoreError::Backend(format!(
                "world {id}: edit {expect} is missing from the log"
            )));
        }
        let patch: json_patch::Patch = serde_json::from_str(&patch)
            .map_err(|e| StoreError::Backend(format!("stored patch {v}: {e}")))?;
        // The document is dropped on error, so no undo is needed (see `patch_scene`).
        json_patch::patch_unsafe(&mut doc, &patch.0)
            .map_err(|e| StoreError::Backend(format!("replaying edit {v}: {e}")))?;
        expect += 1;
        last_hash = Some(hash);
    }
    if expect != version + 1 {
        return Err(StoreError::Backend(format!(
            "world {id}: edit {expect} is missing from the log"
        )));
    }
    if let Some(hash) = last_hash {
        let text = serde_json::to_string(&doc).map_err(backend)?;
        if scene_hash(&text) != hash {
            return Err(StoreError::Backend(format!(
                "world {id}: replaying the log to version {version} does not give the scene it \
                 recorded"
            )));
        }
    }
    Ok(doc)
}
