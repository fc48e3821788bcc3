//! Durable worlds: scenes, their versions, the edit log and access tokens.
//!
//! [`SceneStore`] is the interface the server uses. Two stores implement it with the same
//! tables: [`SqliteStore`], the embedded default (`<data>/strata.db`), and [`PostgresStore`]
//! (`strata serve --store postgres://…`), which several replicas can share. What they compute
//! alike (an edit's checks, the log's replay) lives in `shared.rs`. The trait's contract is what
//! any store must honour, and `tests/store_contract.rs` checks it on both:
//!
//! - **Versions.** A world is created at version 1; every accepted edit yields `version + 1`.
//!   Versions are never rewritten or removed.
//! - **Atomic, durable edits.** [`SceneStore::apply_edit`] reads the latest scene, checks the
//!   expected version, applies the JSON Patch, validates the result ([`Scene::from_value`]) and
//!   commits, all under one write transaction; it returns only after the commit is durable (for
//!   SQLite: WAL with `synchronous=FULL`, so the WAL is fsynced by the commit; for PostgreSQL:
//!   its default `synchronous_commit = on`). Edits of one world are serialised (SQLite: one
//!   writer; PostgreSQL: the world's row locked by `SELECT … FOR UPDATE`). A refused edit
//!   changes nothing.
//! - **History.** The patch of every version is kept, with a content hash of the scene it made,
//!   and full snapshots at version 1 and every [`SNAPSHOT_EVERY`] versions, so any past version
//!   is a snapshot plus fewer than [`SNAPSHOT_EVERY`] patches ([`SceneStore::scene_at`]). The
//!   latest scene is also kept whole.
//! - **Tokens** are stored as `blake3(token)` only ([`hash_token`]); tokens are 32 random bytes
//!   from the OS, so an unsalted fast hash is enough (no dictionary to attack).
//! - **Export jobs** ([`jobs`]): a job row is changed only by the replica holding its lease
//!   ([`SceneStore::update_job`]); a row whose lease has passed while queued or running is
//!   claimed by exactly one caller of [`SceneStore::claim_job`].

pub mod jobs;
mod postgres;
mod shared;
mod sqlite;

pub use jobs::{now_ms, Admission, JobQuota, JobRecord, JobUpdate};

pub use postgres::notify::{FeedEvent, RemoteEdit};
pub use postgres::{is_postgres_url, PostgresStore, POOL_SIZE};
pub use sqlite::SqliteStore;

use crate::scene::{Dirty, Scene, SceneError};
use async_trait::async_trait;
use serde::{Deserialize, Serialize};
use serde_json::Value;

/// A full snapshot of the scene is kept at every multiple of this version (and at version 1).
pub const SNAPSHOT_EVERY: u64 = 32;
/// Largest scene document, bytes of compact JSON.
pub const MAX_SCENE_BYTES: usize = 1 << 20;
/// Most entries [`SceneStore::edit_log`] returns at once.
pub const MAX_LOG_ENTRIES: usize = 1000;
/// Most images one world may hold ([`SceneStore::put_image`]).
pub const MAX_WORLD_IMAGES: usize = 32;

/// What a token lets its holder do with one world. Ordered: each role includes the ones below.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Role {
    /// Read scenes and products of a private world.
    Read,
    /// Read, and apply edits.
    Edit,
    /// Edit, mint tokens and change access.
    Admin,
}

impl Role {
    /// `"read"`, `"edit"` or `"admin"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Role::Read => "read",
            Role::Edit => "edit",
            Role::Admin => "admin",
        }
    }

    /// The role named by [`Role::as_str`].
    pub fn parse(s: &str) -> Option<Self> {
        match s {
            "read" => Some(Role::Read),
            "edit" => Some(Role::Edit),
            "admin" => Some(Role::Admin),
            _ => None,
        }
    }
}

/// `blake3(token)`, the only form in which tokens are stored.
pub type TokenHash = [u8; 32];

/// The stored form of a token.
pub fn hash_token(token: &str) -> TokenHash {
    *blake3::hash(token.as_bytes()).as_bytes()
}

/// `n` random bytes from the operating system, as lowercase hex.
pub fn random_hex(n: usize) -> Result<String, StoreError> {
    let mut bytes = vec![0u8; n];
    getrandom::fill(&mut bytes)
        .map_err(|e| StoreError::Backend(format!("the OS random source failed: {e}")))?;
    Ok(bytes.iter().map(|b| format!("{b:02x}")).collect())
}

/// A new bearer token: `st_` and 32 random bytes in hex.
pub fn new_token() -> Result<String, StoreError> {
    Ok(format!("st_{}", random_hex(32)?))
}

/// A new world id: 12 random bytes in hex (24 characters).
pub fn new_world_id() -> Result<String, StoreError> {
    random_hex(12)
}

/// Whether `id` has the shape of a world id (so it can be looked up without surprises).
pub fn valid_world_id(id: &str) -> bool {
    (1..=64).contains(&id.len())
        && id
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'-')
}

/// A world to create.
#[derive(Clone, Debug)]
pub struct NewWorld {
    /// Its id ([`new_world_id`]).
    pub id: String,
    /// World seed.
    pub seed: u64,
    /// Version 1 of its scene, already valid ([`Scene::to_value`]).
    pub scene: Value,
    /// Whether anyone may read it.
    pub public: bool,
    /// Hash of its first admin token.
    pub admin_token: TokenHash,
}

/// A world without its scene.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct WorldMeta {
    /// Id.
    pub id: String,
    /// Seed.
    pub seed: u64,
    /// Whether anyone may read it.
    pub public: bool,
    /// Latest version.
    pub version: u64,
    /// Creation time, seconds since the Unix epoch.
    pub created_at: i64,
    /// Time of the latest edit (or creation), seconds since the Unix epoch.
    pub updated_at: i64,
}

/// A world with its latest scene.
#[derive(Clone, Debug, PartialEq)]
pub struct WorldHead {
    /// The world.
    pub meta: WorldMeta,
    /// Scene at `meta.version`.
    pub scene: Value,
}

/// An accepted edit.
#[derive(Clone, Debug, PartialEq)]
pub struct EditApplied {
    /// The version the edit made.
    pub version: u64,
    /// What it changed.
    pub dirty: Dirty,
}

/// One entry of the edit log.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EditRecord {
    /// The version this patch made (≥ 2).
    pub version: u64,
    /// The JSON Patch.
    pub patch: Value,
    /// When it was accepted, seconds since the Unix epoch.
    pub at: i64,
}

/// What a stored token grants.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TokenGrant {
    /// The world it is for.
    pub world: String,
    /// Its role there.
    pub role: Role,
}

/// Why a store operation failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum StoreError {
    /// No world has this id.
    #[error("no world {0:?}")]
    WorldNotFound(String),
    /// The world has no such version.
    #[error("version {version} does not exist; the latest is {latest}")]
    VersionNotFound {
        /// Asked for.
        version: u64,
        /// Latest version of the world.
        latest: u64,
    },
    /// The expected version is not the latest.
    #[error("expected version {expected} but the latest is {latest}")]
    Conflict {
        /// What the client expected.
        expected: u64,
        /// What is there.
        latest: u64,
    },
    /// Operation `operation` (0-based) of the patch cannot be applied.
    #[error("patch operation {operation} failed: {message}")]
    Patch {
        /// Index in the patch.
        operation: usize,
        /// Why.
        message: String,
    },
    /// The scene the edit would make is invalid.
    #[error("the resulting scene is invalid: {0}")]
    Invalid(SceneError),
    /// The world holds [`MAX_WORLD_IMAGES`] images already.
    #[error("a world holds at most {limit} images")]
    TooManyImages {
        /// [`MAX_WORLD_IMAGES`].
        limit: usize,
    },
    /// The scene the edit would make is larger than [`MAX_SCENE_BYTES`].
    #[error("the scene would be {bytes} bytes, more than the limit of {limit}")]
    TooLarge {
        /// Its size.
        bytes: usize,
        /// [`MAX_SCENE_BYTES`].
        limit: usize,
    },
    /// The id is taken.
    #[error("world {0:?} exists")]
    Duplicate(String),
    /// The database failed or its content is inconsistent.
    #[error("store failure: {0}")]
    Backend(String),
}

/// The scene store. Every method is durable on success: when it returns `Ok`, the change is
/// committed to stable storage.
#[async_trait]
pub trait SceneStore: Send + Sync + std::fmt::Debug {
    /// Creates a world at version 1, with its first admin token.
    async fn create_world(&self, world: NewWorld) -> Result<WorldMeta, StoreError>;

    /// A world without its scene.
    async fn meta(&self, id: &str) -> Result<WorldMeta, StoreError>;

    /// A world and its latest scene.
    async fn head(&self, id: &str) -> Result<WorldHead, StoreError>;

    /// The scene of a world at `version`.
    async fn scene_at(&self, id: &str, version: u64) -> Result<Value, StoreError>;

    /// Applies a JSON Patch to the latest scene, atomically; with `expected`, only if the latest
    /// version is `expected`. Returns after the new version is committed.
    async fn apply_edit(
        &self,
        id: &str,
        patch: json_patch::Patch,
        expected: Option<u64>,
    ) -> Result<EditApplied, StoreError>;

    /// The patches that made versions `after + 1 ..`, at most `limit` (capped at
    /// [`MAX_LOG_ENTRIES`]), oldest first.
    async fn edit_log(
        &self,
        id: &str,
        after: u64,
        limit: usize,
    ) -> Result<Vec<EditRecord>, StoreError>;

    /// Makes a world public-read or private.
    async fn set_public(&self, id: &str, public: bool) -> Result<WorldMeta, StoreError>;

    /// Stores a token (by its hash) granting `role` on world `id`.
    async fn add_token(&self, id: &str, token: TokenHash, role: Role) -> Result<(), StoreError>;

    /// What a token grants, if it is known.
    async fn token(&self, token: TokenHash) -> Result<Option<TokenGrant>, StoreError>;

    /// All worlds, oldest first.
    async fn list_worlds(&self) -> Result<Vec<WorldMeta>, StoreError>;

    /// Stores an image of world `id` under its content hash `hash` (blake3 of `png`, checked by
    /// the caller); whether it was new (an image already stored is left as it is). Images are
    /// never changed or removed, so a scene version that names one pins its bytes.
    /// [`StoreError::TooManyImages`] beyond [`MAX_WORLD_IMAGES`] for the world.
    async fn put_image(&self, id: &str, hash: [u8; 32], png: Vec<u8>) -> Result<bool, StoreError>;

    /// The PNG bytes of world `id`'s image `hash`, if it is stored.
    async fn image(&self, id: &str, hash: [u8; 32]) -> Result<Option<Vec<u8>>, StoreError>;

    /// Stores a new export job; [`StoreError::Duplicate`] if its id is taken,
    /// [`StoreError::WorldNotFound`] without its world.
    async fn insert_job(&self, job: &JobRecord) -> Result<(), StoreError>;

    /// The export job `id`, if it is known.
    async fn job(&self, id: &str) -> Result<Option<JobRecord>, StoreError>;

    /// Writes `update` to job `id` if `owner` still owns it; whether it did (`false`: another
    /// replica claimed it, or there is no such job).
    async fn update_job(
        &self,
        id: &str,
        owner: &str,
        update: &JobUpdate,
    ) -> Result<bool, StoreError>;

    /// Stores the new export job `job` if it fits `quota` beside every job already stored
    /// ([`jobs`]: the world's and the store's bytes, the queued jobs), as one step no other
    /// admission interleaves with; what it found. [`StoreError::Duplicate`] if its id is taken,
    /// [`StoreError::WorldNotFound`] without its world.
    async fn admit_job(&self, job: &JobRecord, quota: &JobQuota) -> Result<Admission, StoreError>;

    /// Marks `expired` every `done` job finished at or before `before_s` (seconds since the
    /// Unix epoch); their ids, each returned to one caller only, whose archives it deletes.
    async fn expire_jobs(&self, before_s: i64) -> Result<Vec<String>, StoreError>;

    /// Takes over the oldest queued or running job whose lease ended before `now_ms`: it becomes
    /// `owner`'s until `lease_until_ms`, `queued` with no tile written, and is returned. At most
    /// one of any number of concurrent callers gets a given job.
    async fn claim_job(
        &self,
        owner: &str,
        now_ms: i64,
        lease_until_ms: i64,
    ) -> Result<Option<JobRecord>, StoreError>;
}

/// Validates a new world's scene document, cost limits included ([`Scene::check_costs`]), and
/// returns its stored form (every field present).
pub fn canonical_scene(doc: &Value) -> Result<Value, StoreError> {
    let scene = Scene::from_value(doc).map_err(StoreError::Invalid)?;
    scene.check_costs(None).map_err(StoreError::Invalid)?;
    check_images(&scene, &[])?;
    Ok(scene.to_value())
}

/// Checks that every image `scene` names is among `stored` (a new world has none: images are
/// uploaded to a world that exists).
///
/// # Errors
/// [`StoreError::Invalid`] naming the first reference to an image not stored.
pub fn check_images(scene: &Scene, stored: &[[u8; 32]]) -> Result<(), StoreError> {
    for (pointer, hash) in scene.image_refs() {
        if !stored.contains(&hash) {
            return Err(StoreError::Invalid(SceneError {
                pointer,
                message: format!(
                    "no image {} is stored for this world: upload it first \
                     (POST /v1/worlds/{{id}}/images)",
                    crate::ptex::image::hash_hex(&hash)
                ),
            }));
        }
    }
    Ok(())
}

/// Applies an edit's JSON Patch to the scene document `doc` whose parsed form is `old`, and
/// checks the result as an edit must be: a valid scene ([`Scene::from_value`]), within the cost
/// limits for what the edit added or changed ([`Scene::check_costs`]) and at most
/// [`MAX_SCENE_BYTES`]. Returns the new document as stored (compact JSON) and its parsed form.
/// Pure, so the store commits only what this accepted and the fuzz target `scene_patch` drives
/// the same code.
///
/// # Errors
/// [`StoreError::Patch`], [`StoreError::Invalid`] or [`StoreError::TooLarge`].
pub fn patch_scene(
    mut doc: Value,
    old: &Scene,
    patch: &json_patch::Patch,
) -> Result<(String, Scene), StoreError> {
    // Not `json_patch::patch`: on a failing operation it undoes the ones applied, and json-patch
    // 5.0.0 panics when an undo fails (a `copy` to `/regions/-`, then a failing operation: found
    // by the fuzz target `scene_patch`). The document is ours and dropped on error, so nothing
    // needs undoing.
    json_patch::patch_unsafe(&mut doc, &patch.0).map_err(|e| StoreError::Patch {
        operation: e.operation,
        message: format!("{} at {:?}", e.kind, e.path.as_str()),
    })?;
    let new = Scene::from_value(&doc).map_err(StoreError::Invalid)?;
    new.check_costs(Some(old)).map_err(StoreError::Invalid)?;
    Ok((scene_text(&doc)?, new))
}

/// A scene document as stored: compact JSON of at most [`MAX_SCENE_BYTES`].
///
/// # Errors
/// [`StoreError::TooLarge`] beyond the limit.
pub fn scene_text(doc: &Value) -> Result<String, StoreError> {
    let text = serde_json::to_string(doc).map_err(|e| StoreError::Backend(e.to_string()))?;
    if text.len() > MAX_SCENE_BYTES {
        return Err(StoreError::TooLarge {
            bytes: text.len(),
            limit: MAX_SCENE_BYTES,
        });
    }
    Ok(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_and_ids() {
        let a = new_token().expect("token");
        let b = new_token().expect("token");
        assert_ne!(a, b);
        assert_eq!(a.len(), 3 + 64);
        assert_eq!(hash_token(&a), hash_token(&a.clone()));
        assert_ne!(hash_token(&a), hash_token(&b));
        let id = new_world_id().expect("id");
        assert!(valid_world_id(&id) && id.len() == 24);
        assert!(!valid_world_id("../x") && !valid_world_id(""));
        for r in [Role::Read, Role::Edit, Role::Admin] {
            assert_eq!(Role::parse(r.as_str()), Some(r));
        }
        assert!(Role::Read < Role::Edit && Role::Edit < Role::Admin);
    }
}
