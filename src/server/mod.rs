//! The HTTP service: product URLs keyed by seed and tile address, the viewer, and the API
//! contract of `api/openapi.yaml`.
//!
//! [`serve`] is a thin wrapper that opens the compute backend, binds the socket and runs
//! [`app`]; [`app`] builds the whole router from an [`AppState`] so tests drive it with
//! `tower::ServiceExt::oneshot` and no socket.
//!
//! Routes (see [`routes`]):
//!
//! | route | product |
//! |---|---|
//! | `GET /healthz` | `{"status":"ok"}` |
//! | `GET /v1/info` | version, backend, limits, formats, world |
//! | `GET /v1/seeds/{seed}/tiles/{lod}/{x}/{z}.{json,bin,png,glb}[?seams=n,e,s,w][&format=1\|2]` | height tile |
//! | `GET /v1/seeds/{seed}/scatter/{lod}/{x}/{z}.json` | scatter points |
//! | `GET /v1/seeds/{seed}/rivers/{lod}/{x}/{z}.json` | river lines of a tile, LOD `0..=MAX_CARVE_LOD` (see [`rivers`]; worlds: `/v1/worlds/{id}/rivers/…`) |
//! | `/v1/worlds…` | worlds, scenes, edits, tokens and their products (see [`worlds`]) |
//! | `/v1/worlds/{id}/volumes/{vid}/{mesh.glb,curves.json,meshes}` | volume-region mesh export, curves in and out, glb uploads (see [`volume_routes`]) |
//! | `POST /v1/worlds/{id}/exports`, `/v1/jobs/{job}[/events\|/archive]` | export jobs (see [`exports`]) |
//! | `GET /metrics` | Prometheus text format (see [`metrics`]) |
//! | `GET /*` | the viewer directory (`--web`) |
//!
//! Product responses are pure functions of the URL: they carry a content-hash `ETag`, answer
//! `If-None-Match` with 304 and are `Cache-Control: public, max-age=31536000, immutable`. Errors
//! have one JSON shape ([`AppError`]). Limits: [`Limits`].
//!
//! Every product route starts from a [`view::WorldView`] (the world at one version), which its
//! first extractor [`view::WorldAt`] resolves. Tiles go through the stage cache ([`crate::cache`],
//! [`AppState::tile`]) keyed by their input hash ([`crate::scene::SceneInputs`]), so repeated
//! requests and edits elsewhere in a world run no stage.

pub mod access;
pub mod args;
pub mod bodies;
pub mod budget;
pub mod chunk_meshes;
pub mod chunks;
pub mod connections;
pub mod cors;
pub mod edit_service;
pub mod error;
pub mod exports;
pub mod geology;
pub mod http;
pub mod images;
pub mod jobs;
pub mod metrics;
pub mod overrun;
pub mod params;
mod plans;
pub mod ptex_routes;
pub mod rate_limit;
pub mod region_io;
pub mod regions;
mod replicas;
pub mod rivers;
pub mod route_table;
pub mod routes;
pub mod solved;
mod stream_ptex;
pub mod stream_routes;
mod takeover;
pub mod view;
pub mod volume_routes;
pub mod volumes;
pub mod worlds;

pub use args::ServeArgs;
pub use error::AppError;

use crate::cache::StageCache;
use crate::compute::Compute;
use crate::scene::SceneInputs;
use crate::terrain::{Tile, TileKey, WorldParams, WorldPlan};
use plans::PlanCache;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;
use tokio::sync::Semaphore;

/// Tile syntheses (plus their encoding) that may run at once; the rest queue.
pub const MAX_CONCURRENT_SYNTHESES: usize = 16;
/// A request whose synthesis has not finished (queueing included) within this time gets 503
/// `synthesis_timeout`; a synthesis that had started is cancelled ([`overrun`]): it stops at
/// its next await, releasing its slot, and the solves it waited for stop too unless another
/// request waits for them ([`solved`]); one still queued never starts.
pub const SYNTHESIS_TIMEOUT: Duration = Duration::from_secs(30);
/// Largest request body accepted (a world's scene is at most [`crate::store::MAX_SCENE_BYTES`]).
pub const MAX_BODY_BYTES: usize = 2 << 20;
/// World plans kept, one per seed, least recently used evicted first.
pub const PLAN_CACHE_SEEDS: usize = 32;
/// A connection that has not sent a request's whole header this long after it opened (or
/// after its previous request) is closed.
pub const HEADER_READ_TIMEOUT: Duration = Duration::from_secs(10);
/// A request body that sends no data for this long fails (400 `bad_request`) and its
/// connection is closed.
pub const BODY_READ_TIMEOUT: Duration = Duration::from_secs(10);
/// Connections held at once, stream connections included; further ones are answered 503
/// `too_many_connections` and closed.
pub const MAX_CONNECTIONS: usize = 4096;

/// Request limits of an [`AppState`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Syntheses running at once ([`MAX_CONCURRENT_SYNTHESES`]).
    pub max_concurrent_syntheses: usize,
    /// Time limit of one synthesis, queueing included ([`SYNTHESIS_TIMEOUT`]).
    pub synthesis_timeout: Duration,
    /// World plans cached ([`PLAN_CACHE_SEEDS`]).
    pub plan_cache_seeds: usize,
    /// Time to send a request's header ([`HEADER_READ_TIMEOUT`]; enforced by [`serve`]).
    pub header_read_timeout: Duration,
    /// Longest pause of a request body ([`BODY_READ_TIMEOUT`]).
    pub body_read_timeout: Duration,
    /// Connections held at once ([`MAX_CONNECTIONS`]; enforced by [`serve`]).
    pub max_connections: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            max_concurrent_syntheses: MAX_CONCURRENT_SYNTHESES,
            synthesis_timeout: SYNTHESIS_TIMEOUT,
            plan_cache_seeds: PLAN_CACHE_SEEDS,
            header_read_timeout: HEADER_READ_TIMEOUT,
            body_read_timeout: BODY_READ_TIMEOUT,
            max_connections: MAX_CONNECTIONS,
        }
    }
}

/// Shared state of the handlers; cheap to clone.
#[derive(Clone, Debug)]
pub struct AppState {
    /// The compute backends.
    pub compute: Compute,
    /// Directory served at `/`, if any.
    pub web: Option<PathBuf>,
    /// Worlds: the scene store, access, the edit broadcast.
    pub worlds: Arc<worlds::Worlds>,
    /// Counters of `GET /metrics`.
    pub metrics: Arc<metrics::Metrics>,
    /// Finished tiles by input hash (see [`AppState::with_cache`]).
    pub cache: Arc<StageCache>,
    /// Encoded products by input hash and format (see [`bodies`]).
    pub bodies: Arc<bodies::BodyCache>,
    /// Export jobs (see [`AppState::with_jobs_dir`]).
    pub jobs: Arc<jobs::Jobs>,
    /// Solved authored regions.
    pub regions: Arc<regions::RegionCache>,
    /// Solved volume regions.
    pub volumes: Arc<volumes::VolumeCache>,
    /// Decoded images of the worlds' materials and decals.
    pub images: Arc<images::ImageCache>,
    /// Meshed volume chunks by input hash.
    pub chunk_meshes: Arc<chunk_meshes::ChunkMeshCache>,
    /// Open stream sessions and the signal that closes them at shutdown.
    pub sessions: Sessions,
    /// Origins besides the server's own that may call every route from a browser.
    pub cors: cors::CorsOrigins,
    /// Rate limits of the expensive routes (see [`rate_limit`]).
    pub rate: Arc<rate_limit::RateLimits>,
    /// The Ptex page budget of stream sessions, per session and for the server
    /// ([`crate::stream::ptex`]).
    pub ptex: Arc<crate::stream::ptex::PtexPool>,
    limits: Limits,
    budget: budget::MemoryBudget,
    plans: Arc<PlanCache>,
    slots: Arc<Semaphore>,
}

impl AppState {
    /// State with default [`Limits`] and no viewer directory.
    pub fn new(compute: Compute) -> Self {
        Self::with_limits(compute, Limits::default())
    }

    /// State with the given limits and no viewer directory. Worlds live in an in-memory store
    /// (nothing survives the process; see [`AppState::with_worlds`]) and anyone may create them.
    pub fn with_limits(compute: Compute, limits: Limits) -> Self {
        let store = crate::store::SqliteStore::open_in_memory()
            .map(|s| Arc::new(s) as Arc<dyn crate::store::SceneStore>)
            .unwrap_or_else(|e| panic!("cannot open an in-memory SQLite database: {e}"));
        Self {
            compute,
            web: None,
            worlds: Arc::new(worlds::Worlds::new(store, None)),
            metrics: Arc::default(),
            cache: Arc::new(StageCache::new(budget::MemoryBudget::default().stage)),
            bodies: Arc::default(),
            jobs: Arc::new(jobs::Jobs::new(
                default_jobs_dir(),
                jobs::JobLimits::default(),
            )),
            regions: Arc::default(),
            volumes: Arc::default(),
            images: Arc::default(),
            chunk_meshes: Arc::default(),
            sessions: Sessions::default(),
            cors: cors::CorsOrigins::default(),
            rate: Arc::default(),
            ptex: Arc::new(crate::stream::ptex::PtexPool::new(
                crate::stream::ptex::PtexSettings::default(),
            )),
            limits,
            budget: budget::MemoryBudget::default(),
            plans: Arc::new(PlanCache::new(
                limits.plan_cache_seeds,
                budget::MemoryBudget::default().seed_plans,
            )),
            slots: Arc::new(Semaphore::new(limits.max_concurrent_syntheses)),
        }
    }

    /// Writes export archives to `dir` (created on first use) instead of a directory under
    /// [`std::env::temp_dir`]. Replaces the job queue, so call it before serving.
    pub fn with_jobs_dir(mut self, dir: impl Into<PathBuf>) -> Self {
        self.jobs = Arc::new(jobs::Jobs::new(dir, self.jobs.limits()));
        self
    }

    /// Runs export jobs under `limits` (default [`jobs::JobLimits::default`]). Replaces the job
    /// queue, so call it before serving.
    pub fn with_job_limits(mut self, limits: jobs::JobLimits) -> Self {
        self.jobs = Arc::new(jobs::Jobs::new(self.jobs.dir().to_path_buf(), limits));
        self
    }

    /// Keeps the export jobs' state in `ledger`'s store ([`jobs::ledger`]), so that replicas
    /// sharing the store and the archive directory answer for each other's jobs and take over
    /// those of a replica that died. Replaces the job queue, so call it after
    /// [`AppState::with_jobs_dir`] and [`AppState::with_job_limits`], before serving.
    pub fn with_job_ledger(mut self, ledger: jobs::Ledger) -> Self {
        self.jobs = Arc::new(
            jobs::Jobs::new(self.jobs.dir().to_path_buf(), self.jobs.limits()).with_ledger(ledger),
        );
        self
    }

    /// Splits `budget` between the caches (see [`budget`]): replaces the stage cache (memory
    /// only: add the disk tier with [`AppState::with_cache`] after this), the body, solution
    /// and seed-plan caches, and sizes the world-plan cache of later [`AppState::with_worlds`]
    /// calls. Call it before serving.
    pub fn with_memory_budget(mut self, budget: budget::MemoryBudget) -> Self {
        self.budget = budget;
        self.cache = Arc::new(StageCache::new(budget.stage));
        self.bodies = Arc::new(bodies::BodyCache::new(budget.bodies));
        self.regions = Arc::new(regions::RegionCache::new(budget.regions));
        self.volumes = Arc::new(volumes::VolumeCache::new(budget.volumes));
        self.images = Arc::new(images::ImageCache::new(budget.images));
        self.chunk_meshes = Arc::new(chunk_meshes::ChunkMeshCache::new(budget.chunk_meshes));
        self.plans = Arc::new(PlanCache::new(
            self.limits.plan_cache_seeds,
            budget.seed_plans,
        ));
        self
    }

    /// Grants stream sessions Ptex pages under `settings` (per session and for the server).
    /// Call it before serving.
    pub fn with_ptex(mut self, settings: crate::stream::ptex::PtexSettings) -> Self {
        self.ptex = Arc::new(crate::stream::ptex::PtexPool::new(settings));
        self
    }

    /// The memory budget of the caches and its split.
    pub fn memory_budget(&self) -> budget::MemoryBudget {
        self.budget
    }

    /// Keeps finished tiles in `cache` instead of a memory-only cache of the budget's stage
    /// share ([`budget::MemoryBudget::stage`]).
    pub fn with_cache(mut self, cache: StageCache) -> Self {
        self.cache = Arc::new(cache);
        self
    }

    /// Lets browsers on `origins` call every route (see [`cors`]); without it only the
    /// server's own origin may, besides the public routes.
    pub fn with_cors_origins(mut self, origins: cors::CorsOrigins) -> Self {
        self.cors = origins;
        self
    }

    /// Allows `per_minute` expensive requests per minute per client address and per token (see
    /// [`rate_limit`]; default [`rate_limit::DEFAULT_RATE_LIMIT_PER_MINUTE`]).
    pub fn with_rate_limit(mut self, per_minute: u32) -> Self {
        self.rate = Arc::new(rate_limit::RateLimits::new(per_minute));
        self
    }

    /// Serves `dir` at `/`.
    pub fn with_web(mut self, dir: impl Into<PathBuf>) -> Self {
        self.web = Some(dir.into());
        self
    }

    /// Keeps worlds in `store`; `admin_token` is the server admin token (world creation is open
    /// to anyone without one).
    pub fn with_worlds(
        mut self,
        store: Arc<dyn crate::store::SceneStore>,
        admin_token: Option<&str>,
    ) -> Self {
        self.worlds = Arc::new(worlds::Worlds::with_plan_budget(
            store,
            admin_token,
            self.budget.world_plans,
        ));
        self
    }

    /// A receiver of every accepted edit, after its commit.
    pub fn subscribe_edits(&self) -> tokio::sync::broadcast::Receiver<edit_service::EditEvent> {
        self.worlds.subscribe()
    }

    /// The default world of `seed`, its plan from the cache or built on the blocking pool.
    pub async fn bare_view(&self, seed: u64) -> Result<Arc<view::WorldView>, AppError> {
        Ok(Arc::new(view::WorldView::bare(self.plan(seed).await?)))
    }

    /// Tile `key` with `seams` of the world `view` through the stage cache.
    pub async fn tile(&self, view: &view::WorldView, key: TileKey, seams: [bool; 4]) -> Arc<Tile> {
        self.tile_hashed(view, view.tile_hash(key, seams), key, seams)
            .await
    }

    /// [`AppState::tile`] given the tile's input hash `hash` ([`view::WorldView::tile_hash`]),
    /// so a request hashes its inputs once.
    async fn tile_hashed(
        &self,
        view: &view::WorldView,
        hash: [u8; 32],
        key: TileKey,
        seams: [bool; 4],
    ) -> Arc<Tile> {
        let edits = view.tile_edits(self, key);
        self.compute
            .tile_cached(&self.cache, hash, view.plan.clone(), key, seams, edits)
            .await
    }

    /// Whether the tile whose input hash is `hash` ([`view::WorldView::tile_hash`]) encoded in
    /// `format` of `version` is in the body cache (so that answering it costs a memory read).
    pub fn tile_is_cached(
        &self,
        hash: [u8; 32],
        format: crate::encode::Format,
        version: crate::encode::TileVersion,
    ) -> bool {
        self.bodies.contains(&(hash, version.tag(format)))
    }

    /// Tile `key` with `seams` of the world `view` encoded in `format` of `version`, from the
    /// body cache or through the stage cache and the encoder ([`crate::encode::tile`]) in one
    /// synthesis slot (once for concurrent requests of one body).
    pub async fn tile_product(
        &self,
        view: &Arc<view::WorldView>,
        key: TileKey,
        seams: [bool; 4],
        format: crate::encode::Format,
        version: crate::encode::TileVersion,
    ) -> Result<Arc<routes::CachedProduct>, AppError> {
        let hash = view.tile_hash(key, seams);
        self.tile_product_hashed(view, hash, key, seams, format, version)
            .await
    }

    /// [`AppState::tile_product`] of a tile whose input hash the caller has computed
    /// ([`view::WorldView::tile_hash`] of the same key and seams), so a handler that first asks
    /// [`AppState::tile_is_cached`] hashes the tile once.
    pub async fn tile_product_hashed(
        &self,
        view: &Arc<view::WorldView>,
        hash: [u8; 32],
        key: TileKey,
        seams: [bool; 4],
        format: crate::encode::Format,
        version: crate::encode::TileVersion,
    ) -> Result<Arc<routes::CachedProduct>, AppError> {
        let body_key = (hash, version.tag(format));
        let (state, view) = (self.clone(), view.clone());
        self.bodies
            .get_or_encode(body_key, || {
                self.limited(async move {
                    let tile = state.tile_hashed(&view, hash, key, seams).await;
                    let plan = view.plan.clone();
                    let encoded = routes::blocking(move || {
                        crate::encode::tile(&plan, &tile, format, version)
                    })
                    .await?
                    .map_err(|e| AppError::internal(e.to_string()))?;
                    Ok(Arc::new(routes::CachedProduct::from(encoded)))
                })
            })
            .await
    }

    /// The limits in force.
    pub fn limits(&self) -> Limits {
        self.limits
    }

    /// The plan of a seed's default world, from the cache or built on the blocking pool.
    pub async fn plan(&self, seed: u64) -> Result<Arc<WorldPlan>, AppError> {
        self.plans.get_or_build(seed).await
    }

    /// Runs `job` in one synthesis slot under the time limit. The job runs as its own task, so
    /// on timeout the client is answered at once; the task is then cancelled (it drops `job` at
    /// its next await, frees its slot and is counted in `strata_synthesis_cancelled_total`),
    /// and nothing it had not finished is cached.
    pub async fn limited<T, F>(&self, job: F) -> Result<T, AppError>
    where
        T: Send + 'static,
        F: std::future::Future<Output = Result<T, AppError>> + Send + 'static,
    {
        let slots = self.slots.clone();
        let tracker = overrun::Tracker::new(self.metrics.overruns.clone());
        let started = tracker.clone();
        let cancel = tokio_util::sync::CancellationToken::new();
        let cancelled = cancel.clone();
        // Cancels the task when the request's wait ends early (its timeout, or the request
        // dropped because its client left); disarmed once the task has answered.
        let on_drop = cancel.clone().drop_guard();
        let run = async move {
            let permit = slots
                .acquire_owned()
                .await
                .map_err(|_| AppError::internal("synthesis slots closed"))?;
            let task = tokio::spawn(async move {
                let _permit = permit;
                let running = started.start();
                tokio::select! {
                    r = job => r,
                    () = cancelled.cancelled() => {
                        running.cancelled();
                        Err(AppError::new(
                            axum::http::StatusCode::SERVICE_UNAVAILABLE,
                            error::code::SYNTHESIS_TIMEOUT,
                            "the synthesis was cancelled: no request waits for it",
                        ))
                    }
                }
            });
            match task.await {
                Ok(r) => r,
                Err(e) if e.is_panic() => {
                    tracing::error!("synthesis task failed: {e}");
                    Err(AppError::internal("tile synthesis failed"))
                }
                Err(_) => Err(AppError::new(
                    axum::http::StatusCode::SERVICE_UNAVAILABLE,
                    error::code::SHUTTING_DOWN,
                    "the server is shutting down; retry later",
                )),
            }
        };
        let answer = tokio::time::timeout(self.limits.synthesis_timeout, run).await;
        if answer.is_ok() {
            on_drop.disarm();
        }
        match answer {
            Ok(r) => r,
            Err(_) => Err({
                tracker.timed_out();
                AppError::new(
                    axum::http::StatusCode::SERVICE_UNAVAILABLE,
                    error::code::SYNTHESIS_TIMEOUT,
                    format!(
                        "tile synthesis did not finish within {} ms; retry later",
                        self.limits.synthesis_timeout.as_millis()
                    ),
                )
            }),
        }
    }
}

/// How long shutdown waits for stream sessions to send their close frames and end.
pub const SESSION_DRAIN_TIMEOUT: Duration = Duration::from_secs(5);

/// The stream sessions of a server: each runs with a token that [`Sessions::close`] cancels,
/// and [`Sessions::drained`] waits for them to end. Cheap to clone; clones share the sessions.
#[derive(Clone, Debug, Default)]
pub struct Sessions {
    closing: tokio_util::sync::CancellationToken,
    tracker: tokio_util::task::TaskTracker,
}

impl Sessions {
    /// The session `session(closing)`, counted until it ends; `closing` is cancelled by
    /// [`Sessions::close`].
    pub fn track<F, Fut>(&self, session: F) -> impl std::future::Future<Output = ()>
    where
        F: FnOnce(tokio_util::sync::CancellationToken) -> Fut,
        Fut: std::future::Future<Output = ()>,
    {
        self.tracker.track_future(session(self.closing.clone()))
    }

    /// Tells every session, running or still to start, to close with code 1001.
    pub fn close(&self) {
        self.closing.cancel();
    }

    /// Waits until every session has ended, at most `within`; whether they all did.
    pub async fn drained(&self, within: Duration) -> bool {
        self.tracker.close();
        tokio::time::timeout(within, self.tracker.wait())
            .await
            .is_ok()
    }
}

/// Where export archives go without [`AppState::with_jobs_dir`]: a directory of this process
/// under the system temporary directory.
fn default_jobs_dir() -> PathBuf {
    std::env::temp_dir().join(format!("strata-exports-{}", std::process::id()))
}

/// The [`SceneInputs`] of a world with settings `params` and no elements; those of the default
/// settings (every bare seed's) are built once.
pub(crate) fn bare_inputs(params: &WorldParams) -> Arc<SceneInputs> {
    static DEFAULT: std::sync::OnceLock<Arc<SceneInputs>> = std::sync::OnceLock::new();
    let default = DEFAULT.get_or_init(|| Arc::new(SceneInputs::bare(&WorldParams::default())));
    if default.world() == params {
        default.clone()
    } else {
        Arc::new(SceneInputs::bare(params))
    }
}

/// The router of the whole service.
pub fn app(state: AppState) -> axum::Router {
    routes::router(state)
}

/// Opens the compute backend the command line asks for: a GPU device task when
/// [`crate::gpu::open`] yields one (`auto` with a hardware adapter, `gpu` with any adapter), else
/// the CPU path. With `--backend gpu` and no usable adapter this fails, so the server does not start.
async fn open_compute(choice: crate::gpu::BackendChoice) -> anyhow::Result<Compute> {
    Ok(match crate::gpu::open(choice).await? {
        Some(gpu) => Compute::with_gpu(gpu),
        None => Compute::cpu(),
    })
}

/// The scene store and, for PostgreSQL, the feed of the edits other replicas commit.
type OpenedStore = (
    Arc<dyn crate::store::SceneStore>,
    Option<tokio::sync::mpsc::Receiver<crate::store::FeedEvent>>,
);

/// Opens the scene store the command line asks for: PostgreSQL at `--store` or
/// `STRATA_DATABASE_URL` ([`ServeArgs::database_url`]), listening for other replicas' edits,
/// else SQLite in `<data>/strata.db`.
async fn open_store(args: &ServeArgs) -> anyhow::Result<OpenedStore> {
    if let Some(url) = args.database_url()? {
        let store = crate::store::PostgresStore::connect(url.expose())
            .await
            .map_err(|e| anyhow::anyhow!("cannot open the PostgreSQL scene store: {e}"))?;
        tracing::info!(database = %store.target(), "scene store: PostgreSQL");
        let feed = store.follow_edits();
        return Ok((Arc::new(store), Some(feed)));
    }
    let store = crate::store::SqliteStore::open_in_dir(&args.data).map_err(|e| {
        anyhow::anyhow!(
            "cannot open the scene store in {}: {e}",
            args.data.display()
        )
    })?;
    tracing::info!(path = %args.data.join("strata.db").display(), "scene store");
    Ok((Arc::new(store), None))
}

/// Runs the server until Ctrl-C or SIGTERM.
pub async fn serve(args: ServeArgs) -> anyhow::Result<()> {
    std::fs::create_dir_all(&args.data).map_err(|e| {
        anyhow::anyhow!(
            "cannot create the data directory {}: {e}",
            args.data.display()
        )
    })?;
    let compute = open_compute(args.backend).await?;
    tracing::info!(backend = ?compute.info(), "compute backend");
    let (store, feed) = open_store(&args).await?;
    let admin = args.admin_token.clone().or_else(|| {
        std::env::var("STRATA_ADMIN_TOKEN")
            .ok()
            .and_then(|t| t.parse().ok())
    });
    if admin.is_none() {
        tracing::warn!(
            "no admin token (--admin-token or STRATA_ADMIN_TOKEN): anyone may create worlds"
        );
    }
    let limits = Limits {
        header_read_timeout: args.read_timeout(),
        body_read_timeout: args.read_timeout(),
        max_connections: usize::try_from(args.max_connections).unwrap_or(MAX_CONNECTIONS),
        ..Limits::default()
    };
    let budget = budget::MemoryBudget::from_mb(args.memory_budget_mb()?);
    tracing::info!(
        total_mb = budget.total >> 20,
        stage_mb = budget.stage >> 20,
        bodies_mb = budget.bodies >> 20,
        images_mb = budget.images >> 20,
        chunk_meshes_mb = budget.chunk_meshes >> 20,
        regions_mb = budget.regions >> 20,
        volumes_mb = budget.volumes >> 20,
        "cache memory budget"
    );
    let ledger = jobs::Ledger::new(store.clone(), Duration::from_secs(args.export_lease))
        .map_err(|e| anyhow::anyhow!("export jobs: {e}"))?;
    let mut state = AppState::with_limits(compute, limits)
        .with_memory_budget(budget)
        .with_worlds(store, admin.as_ref().map(access::Secret::expose))
        .with_job_limits(args.job_limits())
        .with_jobs_dir(args.shared_dir())
        .with_job_ledger(ledger);
    state = state
        .with_rate_limit(args.rate_limit)
        .with_ptex(args.ptex_settings());
    tracing::info!(dir = %state.jobs.dir().display(), "export archives");
    match state.jobs.sweep().await {
        Ok(0) => {}
        Ok(n) => tracing::info!("deleted {n} export archives no job needs"),
        Err(e) => tracing::warn!("cannot sweep {}: {e}", state.jobs.dir().display()),
    }
    if let Some(dir) = &args.cache_dir {
        let cache = StageCache::new(budget.stage).with_disk(dir).map_err(|e| {
            anyhow::anyhow!("cannot open the cache directory {}: {e}", dir.display())
        })?;
        tracing::info!(dir = %dir.display(), "stage cache on disk");
        state = state.with_cache(cache);
    }
    if args.web.is_dir() {
        state = state.with_web(args.web.clone());
    } else {
        tracing::warn!(
            "viewer directory {} does not exist; / serves nothing",
            args.web.display()
        );
    }
    let origins = if args.cors_origin.is_empty() {
        std::env::var("STRATA_CORS_ORIGINS")
            .ok()
            .map(|v| {
                v.split(',')
                    .map(str::trim)
                    .filter(|o| !o.is_empty())
                    .map(str::to_owned)
                    .collect::<Vec<_>>()
            })
            .unwrap_or_default()
    } else {
        args.cors_origin.clone()
    };
    let origins = cors::CorsOrigins::new(&origins)
        .map_err(|e| anyhow::anyhow!("STRATA_CORS_ORIGINS: {e}"))?;
    if !origins.origins().is_empty() {
        tracing::info!(origins = ?origins.origins(), "cross-origin requests allowed");
    }
    state = state.with_cors_origins(origins);
    if let Some(feed) = feed {
        tokio::spawn(replicas::follow(feed, state.worlds.clone()));
    }
    tokio::spawn(expire_archives(state.jobs.clone()));
    state.jobs.start_renewing();
    tokio::spawn(takeover::run(state.clone()));
    let listener = tokio::net::TcpListener::bind(args.addr).await?;
    tracing::info!("listening on http://{}", listener.local_addr()?);
    let sessions = state.sessions.clone();
    let stopping = tokio_util::sync::CancellationToken::new();
    let stop = (sessions.clone(), stopping.clone());
    tokio::spawn(async move {
        shutdown_signal().await;
        stop.0.close();
        stop.1.cancel();
    });
    connections::serve(listener, app(state), limits, stopping).await;
    // Upgraded connections are not the HTTP server's: wait for the streams' close frames here.
    if !sessions.drained(SESSION_DRAIN_TIMEOUT).await {
        tracing::warn!(
            "stream sessions still open after {} s; closing their connections",
            SESSION_DRAIN_TIMEOUT.as_secs()
        );
    }
    Ok(())
}

/// Deletes expired export archives every [`EXPIRY_SWEEP_INTERVAL`] (or `max_age`, if shorter),
/// so they go even when no request looks at the jobs: with a ledger, every job the store holds
/// ([`jobs::Jobs::expire_shared`]), those of replicas that died included.
async fn expire_archives(jobs: Arc<jobs::Jobs>) {
    let every = jobs.limits().max_age.min(EXPIRY_SWEEP_INTERVAL);
    let mut tick = tokio::time::interval(every);
    loop {
        tick.tick().await;
        jobs.expire_shared().await;
    }
}

/// Longest time between two sweeps of expired export archives.
pub const EXPIRY_SWEEP_INTERVAL: Duration = Duration::from_secs(60);

async fn shutdown_signal() {
    let ctrl_c = async {
        if let Err(e) = tokio::signal::ctrl_c().await {
            tracing::warn!("cannot listen for Ctrl-C: {e}");
            std::future::pending::<()>().await;
        }
    };
    #[cfg(unix)]
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    #[cfg(not(unix))]
    let term = std::future::pending::<()>();
    tokio::select! {
        _ = ctrl_c => {},
        _ = term => {},
    }
    tracing::info!("shutting down");
}
