//! Worlds: `(seed, scene@version)` created, edited and read over HTTP, and their products.
//!
//! | route | who | answer |
//! |---|---|---|
//! | `POST /v1/worlds` `{seed, scene?, public?}` | server admin (anyone without one) | 201 `{id, version, seed, public, tokens: {admin}}` |
//! | `GET /v1/worlds` | anyone (server admin: all, others: public ones) | `{worlds: [...]}` |
//! | `GET /v1/worlds/{id}` | read | `{id, seed, version, public, scene}`, `ETag: "<version>"` |
//! | `GET /v1/worlds/{id}/versions/{v}` | read | `{id, version, scene}` (immutable) |
//! | `GET /v1/worlds/{id}/edits?after=N&limit=M` | read | `{edits: [{version, patch, at}]}` |
//! | `POST /v1/worlds/{id}/edits` (`application/json-patch+json`, `If-Match: <v>`) | edit | `{version, dirty}` after the commit |
//! | `POST /v1/worlds/{id}/tokens` `{role}` | admin | 201 `{token, role}` |
//! | `POST /v1/worlds/{id}/access` `{public}` | admin | `{id, public}` |
//! | `GET /v1/worlds/{id}/tiles/{lod}/{x}/{z}.{ext}[?v=N][&seams=…][&format=1\|2]` | read | height tile ([`super::routes::tile`]) |
//! | `GET /v1/worlds/{id}/scatter/{lod}/{x}/{z}.json[?v=N]` | read | scatter points ([`super::routes::scatter`]) |
//! | `GET /v1/worlds/{id}/regions/{rid}/stats` | read | a region's statistics ([`super::region_io::region_stats`]) |
//!
//! The world products' caching rules are in [`super::http`]. A world created from a bare seed
//! has the default scene, so its products equal those of `/v1/seeds/{seed}/…`. Edits are
//! committed and announced by [`super::edit_service`]. [`Worlds`] also keeps the views of
//! recent versions ([`WorldView`], one per `(world, version)`).

use super::access::caller;
use super::edit_service::{commit_edit, edit_answer, EditChannels, EditEvent, WorldEdit};
use super::error::{code, AppError};
use super::http::{
    authorize, authorized_body, check_content_type, json_response, parse_body, parse_if_match,
    parse_version, query_param, set_version_headers, store_error, JSON_PATCH,
};
use super::route_table::RouteTable;
use super::routes::IMMUTABLE;
use super::view::WorldView;
use super::AppState;
use crate::cache::Memo;
use crate::scene::{Scene, SceneInputs};
use crate::store::{
    self, hash_token, new_token, new_world_id, NewWorld, Role, SceneStore, TokenHash, WorldMeta,
};
use crate::terrain::WorldPlan;
use axum::body::Bytes;
use axum::extract::{Path, RawQuery, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::Response;
use serde::Deserialize;
use serde_json::{json, Value};
use std::sync::atomic::Ordering;
use std::sync::Arc;

/// World plans kept, one per `(world, version)`; versions with equal world settings share one.
pub const WORLD_PLAN_BUDGET_BYTES: usize = 24 << 20;

/// The world-related state of an [`AppState`].
#[derive(Debug)]
pub struct Worlds {
    /// The scene store.
    pub store: Arc<dyn SceneStore>,
    admin: Option<TokenHash>,
    /// Where accepted edits are announced.
    pub edits: EditChannels,
    plans: VersionPlans,
}

impl Worlds {
    /// Worlds kept in `store`; `admin` is the server admin token, if any.
    pub fn new(store: Arc<dyn SceneStore>, admin: Option<&str>) -> Self {
        Self::with_plan_budget(store, admin, WORLD_PLAN_BUDGET_BYTES)
    }

    /// Like [`Worlds::new`], keeping at most `plan_bytes` of views and their plans.
    pub fn with_plan_budget(
        store: Arc<dyn SceneStore>,
        admin: Option<&str>,
        plan_bytes: usize,
    ) -> Self {
        Self {
            store,
            admin: admin.map(hash_token),
            edits: EditChannels::default(),
            plans: VersionPlans::new(plan_bytes),
        }
    }

    /// A new receiver of every world's edits ([`EditChannels::subscribe`]).
    pub fn subscribe(&self) -> tokio::sync::broadcast::Receiver<EditEvent> {
        self.edits.subscribe()
    }

    /// A new receiver of world `id`'s edits ([`EditChannels::subscribe_world`]).
    pub fn subscribe_world(&self, id: &str) -> tokio::sync::broadcast::Receiver<WorldEdit> {
        self.edits.subscribe_world(id)
    }

    /// The server admin token's hash, if one is configured.
    pub(super) fn admin(&self) -> Option<&TokenHash> {
        self.admin.as_ref()
    }

    /// `(hits, misses)` of the world plan cache.
    pub fn plan_stats(&self) -> (u64, u64) {
        let s = self.plans.versions.stats();
        (s.hits + s.joined, s.misses)
    }

    /// `(entries, bytes, budget bytes)` of the world plan cache (its versions and their shared
    /// plans together).
    pub fn plan_size(&self) -> (u64, u64, u64) {
        let (v, p) = (self.plans.versions.stats(), self.plans.shared.stats());
        (
            v.entries,
            v.bytes + p.bytes,
            v.budget_bytes + p.budget_bytes,
        )
    }

    /// Whether a server admin token is configured.
    pub fn admin_configured(&self) -> bool {
        self.admin.is_some()
    }

    /// The plan of world `meta` at `version` (which must exist).
    pub async fn plan(&self, meta: &WorldMeta, version: u64) -> Result<Arc<WorldPlan>, AppError> {
        Ok(self.view(meta, version).await?.plan.clone())
    }

    /// The view of world `meta` at `version` (which must exist), built once per version.
    pub async fn view(&self, meta: &WorldMeta, version: u64) -> Result<Arc<WorldView>, AppError> {
        self.plans.get(&*self.store, meta, version).await
    }

    /// The view of world `id` at `version`.
    pub async fn view_of(&self, id: &str, version: u64) -> Result<Arc<WorldView>, AppError> {
        if let Some(view) = self.plans.lookup(id, version) {
            return Ok(view);
        }
        let meta = self.store.meta(id).await.map_err(store_error)?;
        self.view(&meta, version).await
    }
}

/// A version's view, and the bytes its scene inputs are counted for.
#[derive(Clone)]
struct VersionEntry {
    view: Arc<WorldView>,
    bytes: usize,
}

/// Views by `(world, version)` ([`Memo`]s, least recently used evicted first); versions with
/// the same seed and world settings share one plan, kept by `(seed, settings hash)`. A quarter
/// of the budget is the versions' scene inputs (each counted as its scene document's JSON
/// length: approximate), three quarters the plans
/// ([`super::plans::PLAN_BYTES_ESTIMATE`] each). Concurrent misses of one version, or of one
/// plan, build it once.
struct VersionPlans {
    versions: Memo<(String, u64), VersionEntry>,
    shared: Memo<(u64, [u8; 32]), Arc<WorldPlan>>,
}

impl std::fmt::Debug for VersionPlans {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("VersionPlans")
            .field("versions", &self.versions)
            .field("shared", &self.shared)
            .finish()
    }
}

impl VersionPlans {
    fn new(budget_bytes: usize) -> Self {
        Self {
            versions: Memo::new(budget_bytes / 4, |k: &(String, u64), e: &VersionEntry| {
                k.0.capacity() + e.bytes
            }),
            shared: Memo::new(budget_bytes - budget_bytes / 4, |_, _| {
                super::plans::PLAN_BYTES_ESTIMATE
            }),
        }
    }

    /// The cached view of `(world, version)`, counted as a hit when found.
    fn lookup(&self, world: &str, version: u64) -> Option<Arc<WorldView>> {
        Some(self.versions.lookup(&(world.to_owned(), version))?.view)
    }

    async fn get(
        &self,
        store: &dyn SceneStore,
        meta: &WorldMeta,
        version: u64,
    ) -> Result<Arc<WorldView>, AppError> {
        let key = (meta.id.clone(), version);
        let (e, _) = self
            .versions
            .try_get_or_compute_async(key, || async {
                let doc = store
                    .scene_at(&meta.id, version)
                    .await
                    .map_err(store_error)?;
                let scene = Scene::from_value(&doc).map_err(|e| {
                    tracing::error!(world = %meta.id, version, "stored scene is invalid: {e}");
                    AppError::internal("the stored scene is invalid")
                })?;
                let inputs = Arc::new(SceneInputs::new(&scene));
                let bytes = std::mem::size_of::<SceneInputs>()
                    + serde_json::to_vec(&doc).map_or(0, |v| v.len());
                let params_hash =
                    *blake3::hash(&serde_json::to_vec(&scene.world).unwrap_or_default()).as_bytes();
                let seed = meta.seed;
                let (plan, _) =
                    self.shared
                        .try_get_or_compute_async((seed, params_hash), || async move {
                            let built = tokio::task::spawn_blocking(move || {
                                WorldPlan::new(seed, scene.world)
                            })
                            .await
                            .map_err(|e| {
                                AppError::internal(format!("building the world plan failed: {e}"))
                            })?
                            .map_err(|e| {
                                AppError::internal(format!("invalid world settings: {e}"))
                            })?;
                            Ok::<_, AppError>(Arc::new(built))
                        })
                        .await?;
                Ok::<_, AppError>(VersionEntry {
                    view: Arc::new(WorldView::stored(&meta.id, version, plan, inputs)),
                    bytes,
                })
            })
            .await?;
        Ok(e.view)
    }
}

/// The routes of this module (merged into the service's router).
pub(super) fn routes() -> RouteTable {
    RouteTable::new()
        .post("/v1/worlds", create)
        .get("/v1/worlds", list)
        .get("/v1/worlds/{id}", show)
        .get("/v1/worlds/{id}/versions/{v}", version)
        .post("/v1/worlds/{id}/edits", edit)
        .get("/v1/worlds/{id}/edits", edit_log)
        .post("/v1/worlds/{id}/tokens", mint_token)
        .post("/v1/worlds/{id}/access", set_access)
        .get(
            "/v1/worlds/{id}/tiles/{lod}/{x}/{z_ext}",
            super::routes::tile,
        )
        .get(
            "/v1/worlds/{id}/scatter/{lod}/{x}/{z_ext}",
            super::routes::scatter,
        )
        .get(
            "/v1/worlds/{id}/regions/{rid}/stats",
            super::region_io::region_stats,
        )
}

/// A seed as a JSON number or a decimal string (for clients without 64-bit integers).
#[derive(Deserialize)]
#[serde(untagged)]
enum SeedIn {
    Number(u64),
    Text(String),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CreateBody {
    seed: SeedIn,
    #[serde(default)]
    scene: Option<Value>,
    #[serde(default)]
    public: bool,
}

/// `POST /v1/worlds`.
async fn create(
    State(st): State<AppState>,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, AppError> {
    let w = &st.worlds;
    let who = caller(&headers, w.admin.as_ref(), &*w.store).await?;
    who.require_creator(w.admin_configured())?;
    check_content_type(&headers, "application/json", false)?;
    let req: CreateBody = parse_body(&body)?;
    let seed = match req.seed {
        SeedIn::Number(n) => n,
        SeedIn::Text(s) => super::params::parse_seed(&s).map_err(|e| e.with_field("/seed"))?,
    };
    let scene = match &req.scene {
        None => Scene::default().to_value(),
        Some(doc) => Scene::from_value(doc)
            .map_err(|e| {
                AppError::bad_request(
                    code::INVALID_SCENE,
                    format!("/scene{}", e.pointer),
                    format!("invalid scene: {}", e.message),
                )
            })?
            .to_value(),
    };
    let token = new_token().map_err(store_error)?;
    let id = new_world_id().map_err(store_error)?;
    let meta = w
        .store
        .create_world(NewWorld {
            id,
            seed,
            scene,
            public: req.public,
            admin_token: hash_token(&token),
        })
        .await
        .map_err(store_error)?;
    st.metrics.worlds_created.fetch_add(1, Ordering::Relaxed);
    tracing::info!(world = %meta.id, seed, public = meta.public, "world created");
    let mut res = json_response(
        StatusCode::CREATED,
        json!({
            "id": meta.id,
            "version": meta.version,
            "seed": meta.seed,
            "public": meta.public,
            "tokens": { "admin": token },
        }),
        "no-store",
    );
    if let Ok(v) = HeaderValue::from_str(&format!("/v1/worlds/{}", meta.id)) {
        res.headers_mut().insert(header::LOCATION, v);
    }
    Ok(res)
}

fn summary(m: &WorldMeta) -> Value {
    json!({ "id": m.id, "seed": m.seed, "version": m.version, "public": m.public })
}

/// `GET /v1/worlds`.
async fn list(State(st): State<AppState>, headers: HeaderMap) -> Result<Response, AppError> {
    let w = &st.worlds;
    let who = caller(&headers, w.admin.as_ref(), &*w.store).await?;
    let all = w.store.list_worlds().await.map_err(store_error)?;
    let worlds: Vec<Value> = all
        .iter()
        .filter(|m| m.public || who.role_on(&m.id).is_some())
        .map(summary)
        .collect();
    Ok(json_response(
        StatusCode::OK,
        json!({ "worlds": worlds }),
        "private, no-cache",
    ))
}

/// `GET /v1/worlds/{id}`.
async fn show(
    State(st): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    authorize(&st, &headers, &id, Role::Read).await?;
    let head = st.worlds.store.head(&id).await.map_err(store_error)?;
    let m = &head.meta;
    let cache = if m.public {
        "no-cache"
    } else {
        "private, no-cache"
    };
    let mut res = json_response(
        StatusCode::OK,
        json!({ "id": m.id, "seed": m.seed, "version": m.version, "public": m.public,
                "scene": head.scene }),
        cache,
    );
    set_version_headers(&mut res, m.version, true);
    Ok(res)
}

/// `GET /v1/worlds/{id}/versions/{v}`.
async fn version(
    State(st): State<AppState>,
    Path((id, v)): Path<(String, String)>,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (meta, _) = authorize(&st, &headers, &id, Role::Read).await?;
    let v = parse_version(&v, "v")?;
    let scene = st
        .worlds
        .store
        .scene_at(&id, v)
        .await
        .map_err(store_error)?;
    let cache = if meta.public {
        IMMUTABLE
    } else {
        "private, max-age=31536000, immutable"
    };
    let mut res = json_response(
        StatusCode::OK,
        json!({ "id": meta.id, "version": v, "scene": scene }),
        cache,
    );
    set_version_headers(&mut res, v, true);
    Ok(res)
}

/// `GET /v1/worlds/{id}/edits?after=N&limit=M`.
async fn edit_log(
    State(st): State<AppState>,
    Path(id): Path<String>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    authorize(&st, &headers, &id, Role::Read).await?;
    let after = match query_param(query.as_deref(), "after") {
        None | Some("0") => 0,
        Some(s) => parse_version(s, "after")?,
    };
    let limit = match query_param(query.as_deref(), "limit") {
        None => store::MAX_LOG_ENTRIES,
        Some(s) => s
            .parse::<usize>()
            .ok()
            .filter(|n| {
                (1..=store::MAX_LOG_ENTRIES).contains(n) && s.bytes().all(|b| b.is_ascii_digit())
            })
            .ok_or_else(|| {
                AppError::bad_request(
                    code::BAD_PARAMETER,
                    "limit",
                    format!(
                        "limit must be an integer in 1..={}, got {:?}",
                        store::MAX_LOG_ENTRIES,
                        super::error::truncate(s, 40)
                    ),
                )
            })?,
    };
    let edits = st
        .worlds
        .store
        .edit_log(&id, after, limit)
        .await
        .map_err(store_error)?;
    Ok(json_response(
        StatusCode::OK,
        json!({ "id": id, "edits": edits }),
        "private, no-cache",
    ))
}

/// `POST /v1/worlds/{id}/edits`: answers after the new version is committed.
async fn edit(
    State(st): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, AppError> {
    authorize(&st, &headers, &id, Role::Edit).await?;
    let refused = |e: AppError| {
        st.metrics.edits_refused.fetch_add(1, Ordering::Relaxed);
        e
    };
    check_content_type(&headers, JSON_PATCH, true).map_err(refused)?;
    let expected = parse_if_match(&headers).map_err(refused)?;
    let patch: json_patch::Patch = parse_body(&body).map_err(refused)?;
    let applied = commit_edit(&st, &id, patch, expected).await?;
    Ok(edit_answer(&id, &applied))
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct TokenBody {
    role: Role,
}

/// `POST /v1/worlds/{id}/tokens`.
async fn mint_token(
    State(st): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, AppError> {
    let (_, req): (_, TokenBody) = authorized_body(&st, &headers, &id, Role::Admin, &body).await?;
    let token = new_token().map_err(store_error)?;
    st.worlds
        .store
        .add_token(&id, hash_token(&token), req.role)
        .await
        .map_err(store_error)?;
    tracing::info!(world = %id, role = req.role.as_str(), "token minted");
    Ok(json_response(
        StatusCode::CREATED,
        json!({ "token": token, "role": req.role }),
        "no-store",
    ))
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct AccessBody {
    public: bool,
}

/// `POST /v1/worlds/{id}/access`.
async fn set_access(
    State(st): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, AppError> {
    let (_, req): (_, AccessBody) = authorized_body(&st, &headers, &id, Role::Admin, &body).await?;
    let meta = st
        .worlds
        .store
        .set_public(&id, req.public)
        .await
        .map_err(store_error)?;
    tracing::info!(world = %id, public = meta.public, "access changed");
    Ok(json_response(
        StatusCode::OK,
        json!({ "id": meta.id, "public": meta.public }),
        "no-store",
    ))
}
