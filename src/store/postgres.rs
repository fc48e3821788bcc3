//! The PostgreSQL scene store, for several replicas sharing one database: `strata serve --store
//! postgres://…` (or `STRATA_DATABASE_URL`).
//!
//! - **Schema.** The tables of the SQLite store (`sqlite.rs`) with `BIGINT`, `BOOLEAN` and
//!   `BYTEA`; scenes and patches stay `TEXT` because the edit log hashes their exact text. The
//!   files of `migrations/postgres/` are applied at connect ([`migrate`]).
//! - **Durability.** Each write is one transaction, and PostgreSQL's default
//!   `synchronous_commit = on` flushes its WAL before the commit returns, so an acknowledged
//!   edit survives a crash of the database server.
//! - **Edits.** [`SceneStore::apply_edit`] locks the world's row (`SELECT … FOR UPDATE`), so edits
//!   of one world from any number of replicas are serialised and the expected-version check and
//!   the write are atomic; edits of different worlds do not wait on each other.
//! - **Reads** that take several statements run in one `REPEATABLE READ` read-only transaction,
//!   so they see one snapshot.
//! - **Connections** come from a pool of [`POOL_SIZE`]; the connection is plain TCP or a Unix
//!   socket (no TLS: a URL with `sslmode=require` is refused at connect).
//! - **Replicas.** Each edit's transaction also sends a `NOTIFY` ([`notify`]), delivered at its
//!   commit; [`PostgresStore::follow_edits`] listens for the other replicas' edits. Export jobs
//!   live in `export_jobs` ([`jobs`]), claimed with `SELECT … FOR UPDATE SKIP LOCKED`.

mod jobs;
mod migrate;
pub mod notify;

use super::shared::{admit_image, backend, image_hash_of, now, parse_json, prepare_edit, replay};
use super::{
    canonical_scene, scene_text, Admission, EditApplied, EditRecord, JobQuota, JobRecord,
    JobUpdate, NewWorld, Role, SceneStore, StoreError, TokenGrant, TokenHash, WorldHead, WorldMeta,
    MAX_LOG_ENTRIES,
};
use async_trait::async_trait;
use deadpool_postgres::{GenericClient, Manager, ManagerConfig, Pool, RecyclingMethod, Runtime};
use migrate::pg_message;
use serde_json::Value;
use std::time::Duration;
use tokio_postgres::{IsolationLevel, NoTls, Row};

/// Connections the pool holds at most.
pub const POOL_SIZE: usize = 16;
/// How long a request waits for a pooled connection, or for a new one to connect.
const POOL_TIMEOUT: Duration = Duration::from_secs(10);

/// The PostgreSQL [`SceneStore`]; cheap to clone.
#[derive(Clone)]
pub struct PostgresStore {
    pool: Pool,
    /// Where it connects, without the password.
    target: String,
    /// The connection settings, for the listening connection of [`Self::follow_edits`].
    config: tokio_postgres::Config,
    /// This store's id in its edits' notifications (random per connect).
    origin: String,
}

impl std::fmt::Debug for PostgresStore {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PostgresStore")
            .field("target", &self.target)
            .finish_non_exhaustive()
    }
}

fn db(e: tokio_postgres::Error) -> StoreError {
    StoreError::Backend(pg_message(&e))
}

/// Whether `s` is a PostgreSQL connection URL (`postgres://` or `postgresql://`).
pub fn is_postgres_url(s: &str) -> bool {
    s.starts_with("postgres://") || s.starts_with("postgresql://")
}

impl PostgresStore {
    /// Connects to the database at `url` (`postgres://user:password@host:port/db`, or
    /// `postgres://user@/db?host=/run/postgresql` for a Unix socket), checks that it answers
    /// and applies the migrations it lacks.
    ///
    /// # Errors
    /// [`StoreError::Backend`] when the URL is malformed, asks for TLS, the database cannot be
    /// reached or was migrated by a newer build.
    pub async fn connect(url: &str) -> Result<Self, StoreError> {
        let config: tokio_postgres::Config = url
            .parse()
            .map_err(|e| StoreError::Backend(format!("the database URL is invalid: {e}")))?;
        let target = describe(&config);
        let manager = Manager::from_config(
            config.clone(),
            NoTls,
            ManagerConfig {
                recycling_method: RecyclingMethod::Fast,
            },
        );
        let pool = Pool::builder(manager)
            .max_size(POOL_SIZE)
            .runtime(Runtime::Tokio1)
            .wait_timeout(Some(POOL_TIMEOUT))
            .create_timeout(Some(POOL_TIMEOUT))
            .build()
            .map_err(backend)?;
        let store = Self {
            pool,
            target,
            config,
            origin: super::random_hex(8)?,
        };
        let mut client = store.client().await?;
        migrate::migrate(&mut client).await?;
        Ok(store)
    }

    /// Starts listening for the edits other replicas commit (a connection of its own, made again
    /// when lost) and returns what it hears ([`notify::FeedEvent`]); it stops when the receiver is
    /// dropped. This store's own edits are not reported.
    pub fn follow_edits(&self) -> tokio::sync::mpsc::Receiver<notify::FeedEvent> {
        let (tx, rx) = tokio::sync::mpsc::channel(1024);
        tokio::spawn(notify::follow(self.config.clone(), self.origin.clone(), tx));
        rx
    }

    /// The user, host, port and database it connects to (never the password).
    pub fn target(&self) -> &str {
        &self.target
    }

    async fn client(&self) -> Result<deadpool_postgres::Object, StoreError> {
        self.pool.get().await.map_err(|e| {
            StoreError::Backend(format!("no database connection ({}): {e}", self.target))
        })
    }
}

fn describe(config: &tokio_postgres::Config) -> String {
    let hosts: Vec<String> = config
        .get_hosts()
        .iter()
        .map(|h| match h {
            tokio_postgres::config::Host::Tcp(name) => name.clone(),
            tokio_postgres::config::Host::Unix(path) => path.display().to_string(),
        })
        .collect();
    format!(
        "{}@{}:{}/{}",
        config.get_user().unwrap_or(""),
        hosts.join(","),
        config.get_ports().first().copied().unwrap_or(5432),
        config.get_dbname().unwrap_or("")
    )
}

const META_COLUMNS: &str = "id, seed, public, version, created_at, updated_at";

fn meta_row(r: &Row) -> WorldMeta {
    WorldMeta {
        id: r.get(0),
        seed: r.get::<_, i64>(1) as u64,
        public: r.get(2),
        version: r.get::<_, i64>(3) as u64,
        created_at: r.get(4),
        updated_at: r.get(5),
    }
}

/// The hashes of world `id`'s stored images.
async fn image_hashes(c: &impl GenericClient, id: &str) -> Result<Vec<[u8; 32]>, StoreError> {
    let rows = c
        .query("SELECT hash FROM images WHERE world_id = $1", &[&id])
        .await
        .map_err(db)?;
    rows.iter()
        .map(|r| image_hash_of(r.get::<_, Vec<u8>>(0)))
        .collect()
}

async fn load_meta(c: &impl GenericClient, id: &str) -> Result<WorldMeta, StoreError> {
    c.query_opt(
        &format!("SELECT {META_COLUMNS} FROM worlds WHERE id = $1"),
        &[&id],
    )
    .await
    .map_err(db)?
    .map(|r| meta_row(&r))
    .ok_or_else(|| StoreError::WorldNotFound(id.to_string()))
}

async fn load_scene_at(
    c: &impl GenericClient,
    id: &str,
    version: u64,
) -> Result<Value, StoreError> {
    let meta = load_meta(c, id).await?;
    if version == 0 || version > meta.version {
        return Err(StoreError::VersionNotFound {
            version,
            latest: meta.version,
        });
    }
    if version == meta.version {
        let row = c
            .query_one("SELECT scene FROM worlds WHERE id = $1", &[&id])
            .await
            .map_err(db)?;
        return parse_json(row.get(0), "scene");
    }
    let v = version as i64;
    let snapshot = c
        .query_opt(
            "SELECT version, scene FROM snapshots WHERE world_id = $1 AND version <= $2
             ORDER BY version DESC LIMIT 1",
            &[&id, &v],
        )
        .await
        .map_err(db)?
        .ok_or_else(|| StoreError::Backend(format!("world {id} has no snapshot")))?;
    let base: i64 = snapshot.get(0);
    let log = c
        .query(
            "SELECT version, patch, scene_hash FROM edits
             WHERE world_id = $1 AND version > $2 AND version <= $3 ORDER BY version",
            &[&id, &base, &v],
        )
        .await
        .map_err(db)?;
    replay(
        id,
        base as u64,
        snapshot.get(1),
        log.iter()
            .map(|r| Ok((r.get::<_, i64>(0) as u64, r.get(1), r.get(2)))),
        version,
    )
}

impl PostgresStore {
    /// Runs a read-only `REPEATABLE READ` transaction around `f`'s statements.
    async fn snapshot_read<T>(
        &self,
        f: impl for<'t> FnOnce(
            &'t deadpool_postgres::Transaction<'t>,
        ) -> futures::future::BoxFuture<'t, Result<T, StoreError>>,
    ) -> Result<T, StoreError> {
        let mut client = self.client().await?;
        let tx = client
            .build_transaction()
            .isolation_level(IsolationLevel::RepeatableRead)
            .read_only(true)
            .start()
            .await
            .map_err(db)?;
        let out = f(&tx).await?;
        tx.commit().await.map_err(db)?;
        Ok(out)
    }
}

#[async_trait]
impl SceneStore for PostgresStore {
    async fn create_world(&self, world: NewWorld) -> Result<WorldMeta, StoreError> {
        let scene = canonical_scene(&world.scene)?;
        let text = scene_text(&scene)?;
        let mut client = self.client().await?;
        let tx = client.transaction().await.map_err(db)?;
        let t = now();
        let inserted = tx
            .execute(
                "INSERT INTO worlds (id, seed, public, version, scene, created_at, updated_at)
                 VALUES ($1, $2, $3, 1, $4, $5, $5) ON CONFLICT (id) DO NOTHING",
                &[&world.id, &(world.seed as i64), &world.public, &text, &t],
            )
            .await
            .map_err(db)?;
        if inserted == 0 {
            return Err(StoreError::Duplicate(world.id));
        }
        tx.execute(
            "INSERT INTO snapshots (world_id, version, scene) VALUES ($1, 1, $2)",
            &[&world.id, &text],
        )
        .await
        .map_err(db)?;
        tx.execute(
            "INSERT INTO tokens (hash, world_id, role, created_at) VALUES ($1, $2, 'admin', $3)",
            &[&world.admin_token.as_slice(), &world.id, &t],
        )
        .await
        .map_err(db)?;
        let meta = load_meta(&tx, &world.id).await?;
        tx.commit().await.map_err(db)?;
        Ok(meta)
    }

    async fn meta(&self, id: &str) -> Result<WorldMeta, StoreError> {
        load_meta(&self.client().await?, id).await
    }

    async fn head(&self, id: &str) -> Result<WorldHead, StoreError> {
        let client = self.client().await?;
        let row = client
            .query_opt(
                &format!("SELECT {META_COLUMNS}, scene FROM worlds WHERE id = $1"),
                &[&id],
            )
            .await
            .map_err(db)?
            .ok_or_else(|| StoreError::WorldNotFound(id.to_string()))?;
        Ok(WorldHead {
            meta: meta_row(&row),
            scene: parse_json(row.get(6), "scene")?,
        })
    }

    async fn scene_at(&self, id: &str, version: u64) -> Result<Value, StoreError> {
        let id = id.to_string();
        self.snapshot_read(move |tx| Box::pin(async move { load_scene_at(tx, &id, version).await }))
            .await
    }

    async fn apply_edit(
        &self,
        id: &str,
        patch: json_patch::Patch,
        expected: Option<u64>,
    ) -> Result<EditApplied, StoreError> {
        let mut client = self.client().await?;
        let tx = client.transaction().await.map_err(db)?;
        let row = tx
            .query_opt(
                "SELECT version, scene FROM worlds WHERE id = $1 FOR UPDATE",
                &[&id],
            )
            .await
            .map_err(db)?
            .ok_or_else(|| StoreError::WorldNotFound(id.to_string()))?;
        let version: i64 = row.get(0);
        let text: String = row.get(1);
        // Patching and validating a scene of up to a megabyte is CPU work: off the runtime's
        // threads, with the row still locked.
        let images = image_hashes(&tx, id).await?;
        let owned = id.to_string();
        let edit = tokio::task::spawn_blocking(move || {
            prepare_edit(&owned, version as u64, &text, expected, &patch, &images)
        })
        .await
        .map_err(backend)??;
        let t = now();
        let next = edit.version as i64;
        tx.execute(
            "INSERT INTO edits (world_id, version, patch, scene_hash, created_at)
             VALUES ($1, $2, $3, $4, $5)",
            &[&id, &next, &edit.patch, &edit.scene_hash, &t],
        )
        .await
        .map_err(db)?;
        if edit.snapshot {
            tx.execute(
                "INSERT INTO snapshots (world_id, version, scene) VALUES ($1, $2, $3)",
                &[&id, &next, &edit.scene],
            )
            .await
            .map_err(db)?;
        }
        tx.execute(
            "UPDATE worlds SET version = $2, scene = $3, updated_at = $4 WHERE id = $1",
            &[&id, &next, &edit.scene, &t],
        )
        .await
        .map_err(db)?;
        let payload = notify::Payload {
            origin: self.origin.clone(),
            world: id.to_string(),
            version: edit.version,
            dirty: Some(edit.applied.dirty.clone()),
        }
        .text()?;
        tx.execute("SELECT pg_notify($1, $2)", &[&notify::CHANNEL, &payload])
            .await
            .map_err(db)?;
        tx.commit().await.map_err(db)?;
        Ok(edit.applied)
    }

    async fn edit_log(
        &self,
        id: &str,
        after: u64,
        limit: usize,
    ) -> Result<Vec<EditRecord>, StoreError> {
        let id = id.to_string();
        let limit = limit.min(MAX_LOG_ENTRIES) as i64;
        let after = after.min(i64::MAX as u64) as i64;
        self.snapshot_read(move |tx| {
            Box::pin(async move {
                load_meta(tx, &id).await?;
                let rows = tx
                    .query(
                        "SELECT version, patch, created_at FROM edits
                         WHERE world_id = $1 AND version > $2 ORDER BY version LIMIT $3",
                        &[&id, &after, &limit],
                    )
                    .await
                    .map_err(db)?;
                rows.iter()
                    .map(|r| {
                        Ok(EditRecord {
                            version: r.get::<_, i64>(0) as u64,
                            patch: parse_json(r.get(1), "patch")?,
                            at: r.get(2),
                        })
                    })
                    .collect()
            })
        })
        .await
    }

    async fn set_public(&self, id: &str, public: bool) -> Result<WorldMeta, StoreError> {
        let client = self.client().await?;
        client
            .query_opt(
                &format!("UPDATE worlds SET public = $2 WHERE id = $1 RETURNING {META_COLUMNS}"),
                &[&id, &public],
            )
            .await
            .map_err(db)?
            .map(|r| meta_row(&r))
            .ok_or_else(|| StoreError::WorldNotFound(id.to_string()))
    }

    async fn add_token(&self, id: &str, token: TokenHash, role: Role) -> Result<(), StoreError> {
        let client = self.client().await?;
        let inserted = client
            .execute(
                "INSERT INTO tokens (hash, world_id, role, created_at)
                 SELECT $1, id, $3, $4 FROM worlds WHERE id = $2",
                &[&token.as_slice(), &id, &role.as_str(), &now()],
            )
            .await
            .map_err(db)?;
        if inserted == 0 {
            return Err(StoreError::WorldNotFound(id.to_string()));
        }
        Ok(())
    }

    async fn token(&self, token: TokenHash) -> Result<Option<TokenGrant>, StoreError> {
        let client = self.client().await?;
        let row = client
            .query_opt(
                "SELECT world_id, role FROM tokens WHERE hash = $1",
                &[&token.as_slice()],
            )
            .await
            .map_err(db)?;
        row.map(|r| {
            let role: String = r.get(1);
            let role = Role::parse(&role)
                .ok_or_else(|| StoreError::Backend(format!("stored role {role:?}")))?;
            Ok(TokenGrant {
                world: r.get(0),
                role,
            })
        })
        .transpose()
    }

    async fn list_worlds(&self) -> Result<Vec<WorldMeta>, StoreError> {
        let client = self.client().await?;
        let rows = client
            .query(
                &format!("SELECT {META_COLUMNS} FROM worlds ORDER BY created_at, id"),
                &[],
            )
            .await
            .map_err(db)?;
        Ok(rows.iter().map(meta_row).collect())
    }

    async fn put_image(&self, id: &str, hash: [u8; 32], png: Vec<u8>) -> Result<bool, StoreError> {
        let mut client = self.client().await?;
        let tx = client.transaction().await.map_err(db)?;
        // The world's row locked, so concurrent uploads count the images one at a time.
        tx.query_opt("SELECT 1 FROM worlds WHERE id = $1 FOR UPDATE", &[&id])
            .await
            .map_err(db)?
            .ok_or_else(|| StoreError::WorldNotFound(id.to_string()))?;
        if !admit_image(&image_hashes(&tx, id).await?, &hash)? {
            return Ok(false);
        }
        tx.execute(
            "INSERT INTO images (world_id, hash, png, created_at) VALUES ($1, $2, $3, $4)",
            &[&id, &hash.as_slice(), &png, &now()],
        )
        .await
        .map_err(db)?;
        tx.commit().await.map_err(db)?;
        Ok(true)
    }

    async fn image(&self, id: &str, hash: [u8; 32]) -> Result<Option<Vec<u8>>, StoreError> {
        let row = self
            .client()
            .await?
            .query_opt(
                "SELECT png FROM images WHERE world_id = $1 AND hash = $2",
                &[&id, &hash.as_slice()],
            )
            .await
            .map_err(db)?;
        Ok(row.map(|r| r.get(0)))
    }

    async fn insert_job(&self, job: &JobRecord) -> Result<(), StoreError> {
        jobs::insert(&self.client().await?, job).await
    }

    async fn job(&self, id: &str) -> Result<Option<JobRecord>, StoreError> {
        jobs::get(&self.client().await?, id).await
    }

    async fn update_job(
        &self,
        id: &str,
        owner: &str,
        update: &JobUpdate,
    ) -> Result<bool, StoreError> {
        jobs::update(&self.client().await?, id, owner, update).await
    }

    async fn admit_job(&self, job: &JobRecord, quota: &JobQuota) -> Result<Admission, StoreError> {
        let mut client = self.client().await?;
        let tx = client.transaction().await.map_err(db)?;
        let admitted = jobs::admit(&tx, job, quota).await?;
        tx.commit().await.map_err(db)?;
        Ok(admitted)
    }

    async fn expire_jobs(&self, before_s: i64) -> Result<Vec<String>, StoreError> {
        jobs::expire(&self.client().await?, before_s).await
    }

    async fn claim_job(
        &self,
        owner: &str,
        now_ms: i64,
        lease_until_ms: i64,
    ) -> Result<Option<JobRecord>, StoreError> {
        jobs::claim(&self.client().await?, owner, now_ms, lease_until_ms).await
    }
}
