//! The embedded scene store: one SQLite file, `<data>/strata.db`.
//!
//! - **Durability.** WAL journal with `synchronous=FULL`: a commit fsyncs the WAL before it
//!   returns, so an acknowledged edit survives a crash of the process or the machine.
//! - **One writer.** All writes go through one connection behind a mutex, each in a
//!   `BEGIN IMMEDIATE` transaction, on tokio's blocking pool; edits to a world are therefore
//!   serialised and the expected-version check and the write are atomic. Reads use a small pool
//!   of other connections (WAL lets them run beside the writer); an in-memory store (tests) uses
//!   the writer for everything.
//!
//! Schema (`PRAGMA user_version = 1`); the PostgreSQL store ([`super::PostgresStore`]) has the
//! same tables with `BIGINT`, `BOOLEAN` and `BYTEA` (`migrations/postgres/`):
//!
//! ```sql
//! worlds    (id TEXT PK, seed INTEGER  -- the u64 seed's bits as i64
//!            , public INTEGER, version INTEGER  -- latest
//!            , scene TEXT  -- latest scene
//!            , created_at INTEGER, updated_at INTEGER)
//! edits     (world_id, version  -- the version the patch made, >= 2
//!            , patch TEXT, scene_hash BLOB  -- blake3 of the resulting scene's JSON text
//!            , created_at; PK (world_id, version))
//! snapshots (world_id, version, scene TEXT; PK (world_id, version))  -- v1 and every 32nd
//! tokens    (hash BLOB PK  -- blake3(token)
//!            , world_id, role TEXT, created_at)
//! export_jobs (id TEXT PK, world_id, version, spec TEXT, status TEXT, done, total, error,
//!            reserved, bytes, owner TEXT, lease_until_ms, created_at, finished_at)  -- v2
//! images    (world_id, hash BLOB  -- blake3 of png
//!            , png BLOB, created_at; PK (world_id, hash))  -- v3
//! ```
//!
//! Version 2 added `export_jobs` ([`super::jobs`]), version 3 `images` (uploaded PNGs for
//! materials and decals); an older file is migrated when opened.

use super::jobs::{refusal, Held, CHARGE_SQL};
use super::shared::{admit_image, backend, image_hash_of, now, parse_json, prepare_edit, replay};
use super::{
    canonical_scene, scene_text, Admission, EditApplied, EditRecord, JobQuota, JobRecord,
    JobUpdate, NewWorld, Role, SceneStore, StoreError, TokenGrant, TokenHash, WorldHead, WorldMeta,
    MAX_LOG_ENTRIES,
};
use async_trait::async_trait;
use rusqlite::{params, Connection, OptionalExtension, TransactionBehavior};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// Connections kept for reads.
const READERS: usize = 4;

const SCHEMA: &str = "
CREATE TABLE IF NOT EXISTS worlds (
    id TEXT PRIMARY KEY,
    seed INTEGER NOT NULL,
    public INTEGER NOT NULL,
    version INTEGER NOT NULL,
    scene TEXT NOT NULL,
    created_at INTEGER NOT NULL,
    updated_at INTEGER NOT NULL
) STRICT;
CREATE TABLE IF NOT EXISTS edits (
    world_id TEXT NOT NULL REFERENCES worlds(id),
    version INTEGER NOT NULL,
    patch TEXT NOT NULL,
    scene_hash BLOB NOT NULL,
    created_at INTEGER NOT NULL,
    PRIMARY KEY (world_id, version)
) STRICT, WITHOUT ROWID;
CREATE TABLE IF NOT EXISTS snapshots (
    world_id TEXT NOT NULL REFERENCES worlds(id),
    version INTEGER NOT NULL,
    scene TEXT NOT NULL,
    PRIMARY KEY (world_id, version)
) STRICT, WITHOUT ROWID;
CREATE TABLE IF NOT EXISTS tokens (
    hash BLOB PRIMARY KEY,
    world_id TEXT NOT NULL REFERENCES worlds(id),
    role TEXT NOT NULL CHECK (role IN ('read', 'edit', 'admin')),
    created_at INTEGER NOT NULL
) STRICT, WITHOUT ROWID;
";

/// Migration to schema version 2: export jobs (the PostgreSQL store's
/// `migrations/postgres/0002_export_jobs.sql`).
const MIGRATION_2: &str = "
CREATE TABLE IF NOT EXISTS export_jobs (
    id TEXT PRIMARY KEY,
    world_id TEXT NOT NULL REFERENCES worlds(id),
    version INTEGER NOT NULL,
    spec TEXT NOT NULL,
    status TEXT NOT NULL CHECK (status IN ('queued', 'running', 'done', 'failed', 'expired')),
    done INTEGER NOT NULL,
    total INTEGER NOT NULL,
    error TEXT,
    reserved INTEGER NOT NULL,
    bytes INTEGER NOT NULL,
    owner TEXT NOT NULL,
    lease_until_ms INTEGER NOT NULL,
    created_at INTEGER NOT NULL,
    finished_at INTEGER
) STRICT, WITHOUT ROWID;
CREATE INDEX IF NOT EXISTS export_jobs_unfinished ON export_jobs (lease_until_ms, created_at, id)
    WHERE status IN ('queued', 'running');
PRAGMA user_version = 2;
";

/// Migration to schema version 3: uploaded images (the PostgreSQL store's
/// `migrations/postgres/0003_images.sql`).
const MIGRATION_3: &str = "
CREATE TABLE IF NOT EXISTS images (
    world_id TEXT NOT NULL REFERENCES worlds(id),
    hash BLOB NOT NULL,
    png BLOB NOT NULL,
    created_at INTEGER NOT NULL,
    PRIMARY KEY (world_id, hash)
) STRICT, WITHOUT ROWID;
PRAGMA user_version = 3;
";

/// The schema version this build writes.
const SCHEMA_VERSION: i64 = 3;

/// The SQLite [`SceneStore`]; cheap to clone.
#[derive(Clone)]
pub struct SqliteStore {
    inner: Arc<Inner>,
}

struct Inner {
    path: Option<PathBuf>,
    writer: Mutex<Connection>,
    readers: Mutex<Vec<Connection>>,
}

impl std::fmt::Debug for SqliteStore {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SqliteStore")
            .field("path", &self.inner.path)
            .finish_non_exhaustive()
    }
}

fn configure(conn: &Connection) -> rusqlite::Result<()> {
    conn.busy_timeout(std::time::Duration::from_secs(10))?;
    conn.pragma_update(None, "foreign_keys", "ON")?;
    Ok(())
}

fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|p| p.into_inner())
}

impl SqliteStore {
    /// Opens (creating if needed) the database file at `path`.
    pub fn open(path: impl AsRef<Path>) -> Result<Self, StoreError> {
        let path = path.as_ref().to_path_buf();
        let conn = Connection::open(&path).map_err(backend)?;
        configure(&conn).map_err(backend)?;
        let mode: String = conn
            .query_row("PRAGMA journal_mode = WAL", [], |r| r.get(0))
            .map_err(backend)?;
        if !mode.eq_ignore_ascii_case("wal") {
            return Err(StoreError::Backend(format!(
                "cannot put {} in WAL mode (got {mode})",
                path.display()
            )));
        }
        Self::init(conn, Some(path))
    }

    /// A store in memory, for tests: nothing survives the process.
    pub fn open_in_memory() -> Result<Self, StoreError> {
        let conn = Connection::open_in_memory().map_err(backend)?;
        configure(&conn).map_err(backend)?;
        Self::init(conn, None)
    }

    /// `<data>/strata.db`.
    pub fn open_in_dir(data: impl AsRef<Path>) -> Result<Self, StoreError> {
        Self::open(data.as_ref().join("strata.db"))
    }

    fn init(conn: Connection, path: Option<PathBuf>) -> Result<Self, StoreError> {
        conn.pragma_update(None, "synchronous", "FULL")
            .map_err(backend)?;
        let version: i64 = conn
            .query_row("PRAGMA user_version", [], |r| r.get(0))
            .map_err(backend)?;
        if version > SCHEMA_VERSION {
            return Err(StoreError::Backend(format!(
                "the database has schema version {version}; this build knows {SCHEMA_VERSION}"
            )));
        }
        conn.execute_batch(&format!(
            "BEGIN IMMEDIATE; {SCHEMA} {MIGRATION_2} {MIGRATION_3} COMMIT;"
        ))
        .map_err(backend)?;
        Ok(Self {
            inner: Arc::new(Inner {
                path,
                writer: Mutex::new(conn),
                readers: Mutex::new(Vec::new()),
            }),
        })
    }

    /// The database file, if not in memory.
    pub fn path(&self) -> Option<&Path> {
        self.inner.path.as_deref()
    }

    /// Runs `f` in a write transaction on the blocking pool; commits if it returns `Ok`.
    async fn write<T, F>(&self, f: F) -> Result<T, StoreError>
    where
        T: Send + 'static,
        F: FnOnce(&rusqlite::Transaction<'_>) -> Result<T, StoreError> + Send + 'static,
    {
        let inner = self.inner.clone();
        tokio::task::spawn_blocking(move || {
            let mut conn = lock(&inner.writer);
            let tx = conn
                .transaction_with_behavior(TransactionBehavior::Immediate)
                .map_err(backend)?;
            let out = f(&tx)?;
            tx.commit().map_err(backend)?;
            Ok(out)
        })
        .await
        .map_err(backend)?
    }

    /// Runs `f` with a read connection on the blocking pool.
    async fn read<T, F>(&self, f: F) -> Result<T, StoreError>
    where
        T: Send + 'static,
        F: FnOnce(&Connection) -> Result<T, StoreError> + Send + 'static,
    {
        let inner = self.inner.clone();
        tokio::task::spawn_blocking(move || {
            let Some(path) = &inner.path else {
                return f(&lock(&inner.writer));
            };
            let pooled = lock(&inner.readers).pop();
            let conn = match pooled {
                Some(c) => c,
                None => {
                    let c = Connection::open(path).map_err(backend)?;
                    configure(&c).map_err(backend)?;
                    c.pragma_update(None, "query_only", "ON").map_err(backend)?;
                    c
                }
            };
            // A read-only transaction so multi-statement reads see one snapshot.
            conn.execute_batch("BEGIN").map_err(backend)?;
            let out = f(&conn);
            let end = conn.execute_batch("COMMIT");
            if end.is_ok() {
                let mut pool = lock(&inner.readers);
                if pool.len() < READERS {
                    pool.push(conn);
                }
            }
            out
        })
        .await
        .map_err(backend)?
    }
}

fn meta_row(r: &rusqlite::Row<'_>) -> rusqlite::Result<WorldMeta> {
    Ok(WorldMeta {
        id: r.get(0)?,
        seed: r.get::<_, i64>(1)? as u64,
        public: r.get::<_, i64>(2)? != 0,
        version: r.get::<_, i64>(3)? as u64,
        created_at: r.get(4)?,
        updated_at: r.get(5)?,
    })
}

const META_COLUMNS: &str = "id, seed, public, version, created_at, updated_at";

fn load_meta(conn: &Connection, id: &str) -> Result<WorldMeta, StoreError> {
    conn.query_row(
        &format!("SELECT {META_COLUMNS} FROM worlds WHERE id = ?1"),
        params![id],
        meta_row,
    )
    .optional()
    .map_err(backend)?
    .ok_or_else(|| StoreError::WorldNotFound(id.to_string()))
}

fn load_scene_at(conn: &Connection, id: &str, version: u64) -> Result<Value, StoreError> {
    let meta = load_meta(conn, id)?;
    if version == 0 || version > meta.version {
        return Err(StoreError::VersionNotFound {
            version,
            latest: meta.version,
        });
    }
    if version == meta.version {
        let text: String = conn
            .query_row("SELECT scene FROM worlds WHERE id = ?1", params![id], |r| {
                r.get(0)
            })
            .map_err(backend)?;
        return parse_json(&text, "scene");
    }
    let (base, text): (i64, String) = conn
        .query_row(
            "SELECT version, scene FROM snapshots WHERE world_id = ?1 AND version <= ?2
             ORDER BY version DESC LIMIT 1",
            params![id, version as i64],
            |r| Ok((r.get(0)?, r.get(1)?)),
        )
        .optional()
        .map_err(backend)?
        .ok_or_else(|| StoreError::Backend(format!("world {id} has no snapshot")))?;
    let mut stmt = conn
        .prepare(
            "SELECT version, patch, scene_hash FROM edits
             WHERE world_id = ?1 AND version > ?2 AND version <= ?3 ORDER BY version",
        )
        .map_err(backend)?;
    let rows = stmt
        .query_map(params![id, base, version as i64], |r| {
            Ok((
                r.get::<_, i64>(0)? as u64,
                r.get::<_, String>(1)?,
                r.get::<_, Vec<u8>>(2)?,
            ))
        })
        .map_err(backend)?;
    replay(
        id,
        base as u64,
        &text,
        rows.map(|r| r.map_err(backend)),
        version,
    )
}

#[async_trait]
impl SceneStore for SqliteStore {
    async fn create_world(&self, world: NewWorld) -> Result<WorldMeta, StoreError> {
        let scene = canonical_scene(&world.scene)?;
        let text = scene_text(&scene)?;
        self.write(move |tx| {
            let t = now();
            let inserted = tx
                .execute(
                    "INSERT INTO worlds (id, seed, public, version, scene, created_at, updated_at)
                     VALUES (?1, ?2, ?3, 1, ?4, ?5, ?5) ON CONFLICT (id) DO NOTHING",
                    params![world.id, world.seed as i64, world.public as i64, text, t],
                )
                .map_err(backend)?;
            if inserted == 0 {
                return Err(StoreError::Duplicate(world.id));
            }
            tx.execute(
                "INSERT INTO snapshots (world_id, version, scene) VALUES (?1, 1, ?2)",
                params![world.id, text],
            )
            .map_err(backend)?;
            tx.execute(
                "INSERT INTO tokens (hash, world_id, role, created_at) VALUES (?1, ?2, 'admin', ?3)",
                params![world.admin_token.as_slice(), world.id, t],
            )
            .map_err(backend)?;
            load_meta(tx, &world.id)
        })
        .await
    }

    async fn meta(&self, id: &str) -> Result<WorldMeta, StoreError> {
        let id = id.to_string();
        self.read(move |c| load_meta(c, &id)).await
    }

    async fn head(&self, id: &str) -> Result<WorldHead, StoreError> {
        let id = id.to_string();
        self.read(move |c| {
            let meta = load_meta(c, &id)?;
            let text: String = c
                .query_row("SELECT scene FROM worlds WHERE id = ?1", params![id], |r| {
                    r.get(0)
                })
                .map_err(backend)?;
            Ok(WorldHead {
                meta,
                scene: parse_json(&text, "scene")?,
            })
        })
        .await
    }

    async fn scene_at(&self, id: &str, version: u64) -> Result<Value, StoreError> {
        let id = id.to_string();
        self.read(move |c| load_scene_at(c, &id, version)).await
    }

    async fn apply_edit(
        &self,
        id: &str,
        patch: json_patch::Patch,
        expected: Option<u64>,
    ) -> Result<EditApplied, StoreError> {
        let id = id.to_string();
        self.write(move |tx| {
            let (version, text): (i64, String) = tx
                .query_row(
                    "SELECT version, scene FROM worlds WHERE id = ?1",
                    params![id],
                    |r| Ok((r.get(0)?, r.get(1)?)),
                )
                .optional()
                .map_err(backend)?
                .ok_or_else(|| StoreError::WorldNotFound(id.clone()))?;
            let images = image_hashes(tx, &id)?;
            let edit = prepare_edit(&id, version as u64, &text, expected, &patch, &images)?;
            let t = now();
            tx.execute(
                "INSERT INTO edits (world_id, version, patch, scene_hash, created_at)
                 VALUES (?1, ?2, ?3, ?4, ?5)",
                params![id, edit.version as i64, edit.patch, edit.scene_hash, t],
            )
            .map_err(backend)?;
            if edit.snapshot {
                tx.execute(
                    "INSERT INTO snapshots (world_id, version, scene) VALUES (?1, ?2, ?3)",
                    params![id, edit.version as i64, edit.scene],
                )
                .map_err(backend)?;
            }
            tx.execute(
                "UPDATE worlds SET version = ?2, scene = ?3, updated_at = ?4 WHERE id = ?1",
                params![id, edit.version as i64, edit.scene, t],
            )
            .map_err(backend)?;
            Ok(edit.applied)
        })
        .await
    }

    async fn edit_log(
        &self,
        id: &str,
        after: u64,
        limit: usize,
    ) -> Result<Vec<EditRecord>, StoreError> {
        let id = id.to_string();
        let limit = limit.min(MAX_LOG_ENTRIES) as i64;
        self.read(move |c| {
            load_meta(c, &id)?;
            let mut stmt = c
                .prepare(
                    "SELECT version, patch, created_at FROM edits
                     WHERE world_id = ?1 AND version > ?2 ORDER BY version LIMIT ?3",
                )
                .map_err(backend)?;
            let rows = stmt
                .query_map(params![id, after.min(i64::MAX as u64) as i64, limit], |r| {
                    Ok((
                        r.get::<_, i64>(0)?,
                        r.get::<_, String>(1)?,
                        r.get::<_, i64>(2)?,
                    ))
                })
                .map_err(backend)?;
            let mut out = Vec::new();
            for row in rows {
                let (version, patch, at) = row.map_err(backend)?;
                out.push(EditRecord {
                    version: version as u64,
                    patch: parse_json(&patch, "patch")?,
                    at,
                });
            }
            Ok(out)
        })
        .await
    }

    async fn set_public(&self, id: &str, public: bool) -> Result<WorldMeta, StoreError> {
        let id = id.to_string();
        self.write(move |tx| {
            let n = tx
                .execute(
                    "UPDATE worlds SET public = ?2 WHERE id = ?1",
                    params![id, public as i64],
                )
                .map_err(backend)?;
            if n == 0 {
                return Err(StoreError::WorldNotFound(id));
            }
            load_meta(tx, &id)
        })
        .await
    }

    async fn add_token(&self, id: &str, token: TokenHash, role: Role) -> Result<(), StoreError> {
        let id = id.to_string();
        self.write(move |tx| {
            load_meta(tx, &id)?;
            tx.execute(
                "INSERT INTO tokens (hash, world_id, role, created_at) VALUES (?1, ?2, ?3, ?4)",
                params![token.as_slice(), id, role.as_str(), now()],
            )
            .map_err(backend)?;
            Ok(())
        })
        .await
    }

    async fn token(&self, token: TokenHash) -> Result<Option<TokenGrant>, StoreError> {
        self.read(move |c| {
            let row: Option<(String, String)> = c
                .query_row(
                    "SELECT world_id, role FROM tokens WHERE hash = ?1",
                    params![token.as_slice()],
                    |r| Ok((r.get(0)?, r.get(1)?)),
                )
                .optional()
                .map_err(backend)?;
            row.map(|(world, role)| {
                let role = Role::parse(&role)
                    .ok_or_else(|| StoreError::Backend(format!("stored role {role:?}")))?;
                Ok(TokenGrant { world, role })
            })
            .transpose()
        })
        .await
    }

    async fn list_worlds(&self) -> Result<Vec<WorldMeta>, StoreError> {
        self.read(|c| {
            let mut stmt = c
                .prepare(&format!(
                    "SELECT {META_COLUMNS} FROM worlds ORDER BY created_at, id"
                ))
                .map_err(backend)?;
            let rows = stmt.query_map([], meta_row).map_err(backend)?;
            rows.map(|r| r.map_err(backend)).collect()
        })
        .await
    }

    async fn put_image(&self, id: &str, hash: [u8; 32], png: Vec<u8>) -> Result<bool, StoreError> {
        let id = id.to_string();
        self.write(move |tx| {
            load_meta(tx, &id)?;
            if !admit_image(&image_hashes(tx, &id)?, &hash)? {
                return Ok(false);
            }
            tx.execute(
                "INSERT INTO images (world_id, hash, png, created_at) VALUES (?1, ?2, ?3, ?4)",
                params![id, hash.as_slice(), png, now()],
            )
            .map_err(backend)?;
            Ok(true)
        })
        .await
    }

    async fn image(&self, id: &str, hash: [u8; 32]) -> Result<Option<Vec<u8>>, StoreError> {
        let id = id.to_string();
        self.read(move |c| {
            c.query_row(
                "SELECT png FROM images WHERE world_id = ?1 AND hash = ?2",
                params![id, hash.as_slice()],
                |r| r.get(0),
            )
            .optional()
            .map_err(backend)
        })
        .await
    }

    async fn insert_job(&self, job: &JobRecord) -> Result<(), StoreError> {
        let job = job.clone();
        self.write(move |tx| {
            load_meta(tx, &job.world)?;
            insert_job_row(tx, &job)
        })
        .await
    }

    async fn job(&self, id: &str) -> Result<Option<JobRecord>, StoreError> {
        let id = id.to_string();
        self.read(move |c| {
            c.query_row(
                &format!("SELECT {JOB_COLUMNS} FROM export_jobs WHERE id = ?1"),
                params![id],
                job_row,
            )
            .optional()
            .map_err(backend)
        })
        .await
    }

    async fn update_job(
        &self,
        id: &str,
        owner: &str,
        update: &JobUpdate,
    ) -> Result<bool, StoreError> {
        let (id, owner, u) = (id.to_string(), owner.to_string(), update.clone());
        self.write(move |tx| {
            let n = tx
                .execute(
                    "UPDATE export_jobs SET status = ?3, done = ?4, total = ?5, error = ?6,
                     bytes = ?7, lease_until_ms = ?8, finished_at = ?9
                     WHERE id = ?1 AND owner = ?2",
                    params![
                        id,
                        owner,
                        u.status,
                        u.done as i64,
                        u.total as i64,
                        u.error,
                        u.bytes as i64,
                        u.lease_until_ms,
                        u.finished_at,
                    ],
                )
                .map_err(backend)?;
            Ok(n == 1)
        })
        .await
    }

    async fn admit_job(&self, job: &JobRecord, quota: &JobQuota) -> Result<Admission, StoreError> {
        let (job, quota) = (job.clone(), *quota);
        // One writer: the sums and the insert are one transaction no other admission
        // interleaves with.
        self.write(move |tx| {
            load_meta(tx, &job.world)?;
            let sums = |filter: &str| -> Result<(u64, Option<i64>), StoreError> {
                tx.query_row(
                    &format!(
                        "SELECT COALESCE(SUM({CHARGE_SQL}), 0),
                         MIN(CASE WHEN status = 'done' THEN finished_at END)
                         FROM export_jobs {filter}"
                    ),
                    params![job.world],
                    |r| Ok((r.get::<_, i64>(0)? as u64, r.get(1)?)),
                )
                .map_err(backend)
            };
            let held = Held {
                world: sums("WHERE world_id = ?1")?,
                all: sums("WHERE ?1 IS NOT NULL")?,
                queued: tx
                    .query_row(
                        "SELECT COUNT(*) FROM export_jobs WHERE status = 'queued'",
                        [],
                        |r| r.get::<_, i64>(0),
                    )
                    .map_err(backend)? as u64,
            };
            if let Some(refused) = refusal(job.reserved, &quota, &held) {
                return Ok(refused);
            }
            insert_job_row(tx, &job)?;
            Ok(Admission::Admitted)
        })
        .await
    }

    async fn expire_jobs(&self, before_s: i64) -> Result<Vec<String>, StoreError> {
        self.write(move |tx| {
            let mut stmt = tx
                .prepare(
                    "UPDATE export_jobs SET status = 'expired'
                     WHERE status = 'done' AND finished_at <= ?1 RETURNING id",
                )
                .map_err(backend)?;
            let ids = stmt
                .query_map(params![before_s], |r| r.get::<_, String>(0))
                .map_err(backend)?
                .collect::<Result<Vec<_>, _>>()
                .map_err(backend)?;
            Ok(ids)
        })
        .await
    }

    async fn claim_job(
        &self,
        owner: &str,
        now_ms: i64,
        lease_until_ms: i64,
    ) -> Result<Option<JobRecord>, StoreError> {
        let owner = owner.to_string();
        // One writer: the select and the update below are one transaction no other writer
        // interleaves with.
        self.write(move |tx| {
            let id: Option<String> = tx
                .query_row(
                    "SELECT id FROM export_jobs
                     WHERE status IN ('queued', 'running') AND lease_until_ms < ?1
                     ORDER BY created_at, id LIMIT 1",
                    params![now_ms],
                    |r| r.get(0),
                )
                .optional()
                .map_err(backend)?;
            let Some(id) = id else { return Ok(None) };
            tx.execute(
                "UPDATE export_jobs SET owner = ?2, lease_until_ms = ?3, status = 'queued',
                 done = 0 WHERE id = ?1",
                params![id, owner, lease_until_ms],
            )
            .map_err(backend)?;
            tx.query_row(
                &format!("SELECT {JOB_COLUMNS} FROM export_jobs WHERE id = ?1"),
                params![id],
                job_row,
            )
            .map(Some)
            .map_err(backend)
        })
        .await
    }
}

/// Inserts the row of `job`; [`StoreError::Duplicate`] if its id is taken.
/// The hashes of world `id`'s stored images.
fn image_hashes(conn: &Connection, id: &str) -> Result<Vec<[u8; 32]>, StoreError> {
    let mut stmt = conn
        .prepare_cached("SELECT hash FROM images WHERE world_id = ?1")
        .map_err(backend)?;
    let rows = stmt
        .query_map(params![id], |r| r.get::<_, Vec<u8>>(0))
        .map_err(backend)?;
    rows.map(|row| image_hash_of(row.map_err(backend)?))
        .collect()
}

fn insert_job_row(tx: &rusqlite::Transaction<'_>, job: &JobRecord) -> Result<(), StoreError> {
    let inserted = tx
        .execute(
            &format!(
                "INSERT INTO export_jobs ({JOB_COLUMNS}) VALUES
                 (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14)
                 ON CONFLICT (id) DO NOTHING"
            ),
            params![
                job.id,
                job.world,
                job.version as i64,
                job.spec,
                job.status,
                job.done as i64,
                job.total as i64,
                job.error,
                job.reserved as i64,
                job.bytes as i64,
                job.owner,
                job.lease_until_ms,
                job.created_at,
                job.finished_at,
            ],
        )
        .map_err(backend)?;
    if inserted == 0 {
        return Err(StoreError::Duplicate(job.id.clone()));
    }
    Ok(())
}

const JOB_COLUMNS: &str = "id, world_id, version, spec, status, done, total, error, reserved, \
                           bytes, owner, lease_until_ms, created_at, finished_at";

fn job_row(r: &rusqlite::Row<'_>) -> rusqlite::Result<JobRecord> {
    Ok(JobRecord {
        id: r.get(0)?,
        world: r.get(1)?,
        version: r.get::<_, i64>(2)? as u64,
        spec: r.get(3)?,
        status: r.get(4)?,
        done: r.get::<_, i64>(5)? as u64,
        total: r.get::<_, i64>(6)? as u64,
        error: r.get(7)?,
        reserved: r.get::<_, i64>(8)? as u64,
        bytes: r.get::<_, i64>(9)? as u64,
        owner: r.get(10)?,
        lease_until_ms: r.get(11)?,
        created_at: r.get(12)?,
        finished_at: r.get(13)?,
    })
}
