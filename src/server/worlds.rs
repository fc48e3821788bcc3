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
//! | `GET /v1/worlds/{id}/tiles/{lod}/{x}/{z}.{ext}[?v=N][&seams=…][&format=1\|2]` | read | height tile |
//! | `GET /v1/worlds/{id}/scatter/{lod}/{x}/{z}.json[?v=N]` | read | scatter points |
//! | `GET /v1/worlds/{id}/rivers/{lod}/{x}/{z}.json[?v=N]` | read | river lines ([`super::rivers`]) |
//!
//! A product URL with `v` is immutable (`Cache-Control: public, max-age=31536000, immutable`,
//! `private` for private worlds); without `v` it is the latest version, cached for
//! [`LATEST_MAX_AGE_S`] seconds and revalidated by its content-hash `ETag`. Every product
//! answer names its version in `X-Strata-Version`. A world created from a bare seed has the
//! default scene, so its products equal those of `/v1/seeds/{seed}/…`.
//!
//! Accepted edits are announced on an in-process broadcast ([`EditEvent`], see
//! [`AppState::subscribe_edits`]) after they are committed.

use super::access::{caller, Caller};
use super::error::{code, AppError};
use super::params::{
    check_bounds, parse_coord, parse_format, parse_lod, parse_seams, parse_tile_version,
    split_extension,
};
use super::routes::{
    check_scatter_cost, check_scatter_format, scatter_product, segments, Segments, IMMUTABLE,
};
use super::AppState;
use crate::cache::Memo;
use crate::encode::Format;
use crate::scene::{Scene, SceneInputs};
use crate::store::{
    self, hash_token, new_token, new_world_id, valid_world_id, NewWorld, Role, SceneStore,
    StoreError, TokenHash, WorldMeta,
};
use crate::terrain::{TileKey, WorldPlan};
use axum::body::Bytes;
use axum::extract::{Path, RawQuery, State};
use axum::http::{header, HeaderMap, HeaderName, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::{Json, Router};
use serde::Deserialize;
use serde_json::{json, Value};
use std::sync::atomic::Ordering;
use std::sync::Arc;
use tokio::sync::broadcast;

/// Seconds a product URL without `v` (the latest version) may be cached.
pub const LATEST_MAX_AGE_S: u32 = 5;
/// Edit events buffered per subscriber before the slowest one lags.
pub const EDIT_CHANNEL_CAPACITY: usize = 1024;
/// World plans kept, one per `(world, version)`; versions with equal world settings share one.
pub const WORLD_PLAN_BUDGET_BYTES: usize = 24 << 20;
/// Header naming the version a product or scene answer is of.
pub const VERSION_HEADER: &str = "x-strata-version";
/// The media type of edits.
pub const JSON_PATCH: &str = "application/json-patch+json";

/// An accepted edit, as broadcast to the streaming side.
pub use crate::stream::session::EditEvent;

/// The world-related state of an [`AppState`].
#[derive(Debug)]
pub struct Worlds {
    /// The scene store.
    pub store: Arc<dyn SceneStore>,
    admin: Option<TokenHash>,
    edits: broadcast::Sender<EditEvent>,
    plans: VersionPlans,
}

impl Worlds {
    /// Worlds kept in `store`; `admin` is the server admin token, if any.
    pub fn new(store: Arc<dyn SceneStore>, admin: Option<&str>) -> Self {
        Self::with_plan_budget(store, admin, WORLD_PLAN_BUDGET_BYTES)
    }

    /// Like [`Worlds::new`], keeping at most `plan_bytes` of plans and scene inputs.
    pub fn with_plan_budget(
        store: Arc<dyn SceneStore>,
        admin: Option<&str>,
        plan_bytes: usize,
    ) -> Self {
        let (edits, _) = broadcast::channel(EDIT_CHANNEL_CAPACITY);
        Self {
            store,
            admin: admin.map(hash_token),
            edits,
            plans: VersionPlans::new(plan_bytes),
        }
    }

    /// A new receiver of [`EditEvent`]s.
    pub fn subscribe(&self) -> broadcast::Receiver<EditEvent> {
        self.edits.subscribe()
    }

    /// Current receivers of the edit broadcast.
    pub fn subscribers(&self) -> usize {
        self.edits.receiver_count()
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
        Ok(self.plans.get(&*self.store, meta, version).await?.0)
    }

    /// The plan of world `meta` at `version` and what its tiles' input hashes are made of.
    pub async fn plan_and_inputs(
        &self,
        meta: &WorldMeta,
        version: u64,
    ) -> Result<(Arc<WorldPlan>, Arc<SceneInputs>), AppError> {
        self.plans.get(&*self.store, meta, version).await
    }

    /// What the input hashes of world `id`'s tiles at `version` are made of.
    pub async fn inputs(&self, id: &str, version: u64) -> Result<Arc<SceneInputs>, AppError> {
        if let Some((_, inputs)) = self.plans.lookup(id, version) {
            return Ok(inputs);
        }
        let meta = self.store.meta(id).await.map_err(store_error)?;
        Ok(self.plans.get(&*self.store, &meta, version).await?.1)
    }
}

/// A version's plan and inputs, and the bytes its inputs are counted for.
#[derive(Clone)]
struct VersionEntry {
    plan: Arc<WorldPlan>,
    inputs: Arc<SceneInputs>,
    bytes: usize,
}

/// Plans by `(world, version)` ([`Memo`]s, least recently used evicted first); versions with
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

    /// The cached plan and inputs of `(world, version)`, counted as a hit when found.
    fn lookup(&self, world: &str, version: u64) -> Option<(Arc<WorldPlan>, Arc<SceneInputs>)> {
        let e = self.versions.lookup(&(world.to_owned(), version))?;
        Some((e.plan, e.inputs))
    }

    async fn get(
        &self,
        store: &dyn SceneStore,
        meta: &WorldMeta,
        version: u64,
    ) -> Result<(Arc<WorldPlan>, Arc<SceneInputs>), AppError> {
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
                    plan,
                    inputs,
                    bytes,
                })
            })
            .await?;
        Ok((e.plan, e.inputs))
    }
}

/// The routes of this module (merged into the service's router).
pub(super) fn routes() -> Router<AppState> {
    Router::new()
        .route("/v1/worlds", post(create).get(list))
        .route("/v1/worlds/{id}", get(show))
        .route("/v1/worlds/{id}/versions/{v}", get(version))
        .route("/v1/worlds/{id}/edits", post(edit).get(edit_log))
        .route("/v1/worlds/{id}/tokens", post(mint_token))
        .route("/v1/worlds/{id}/access", post(set_access))
        .route("/v1/worlds/{id}/tiles/{lod}/{x}/{z_ext}", get(tile))
        .route("/v1/worlds/{id}/scatter/{lod}/{x}/{z_ext}", get(scatter))
        .route("/v1/worlds/{id}/regions/{rid}/stats", get(region_stats))
}

/// Maps a store failure to its HTTP answer.
pub(super) fn store_error(e: StoreError) -> AppError {
    match e {
        StoreError::WorldNotFound(id) => world_not_found(&id),
        StoreError::VersionNotFound { version, latest } => AppError::new(
            StatusCode::NOT_FOUND,
            code::VERSION_NOT_FOUND,
            format!("version {version} does not exist; the latest is {latest}"),
        )
        .with_field("v"),
        StoreError::Conflict { expected, latest } => AppError::new(
            StatusCode::CONFLICT,
            code::VERSION_CONFLICT,
            format!("If-Match names version {expected} but the latest is {latest}"),
        )
        .with_field("If-Match"),
        StoreError::Patch { operation, message } => AppError::new(
            StatusCode::UNPROCESSABLE_ENTITY,
            code::PATCH_FAILED,
            format!("patch operation {operation} cannot be applied: {message}"),
        )
        .with_field(format!("/{operation}")),
        StoreError::Invalid(e) => AppError::bad_request(
            code::INVALID_SCENE,
            e.pointer.clone(),
            format!("the scene would be invalid: {}", e.message),
        ),
        StoreError::TooLarge { bytes, limit } => AppError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            code::SCENE_TOO_LARGE,
            format!("the scene would be {bytes} bytes; the limit is {limit}"),
        ),
        StoreError::Duplicate(_) | StoreError::Backend(_) => {
            tracing::error!("scene store: {e}");
            AppError::internal("the scene store failed")
        }
    }
}

fn world_not_found(id: &str) -> AppError {
    AppError::new(
        StatusCode::NOT_FOUND,
        code::WORLD_NOT_FOUND,
        format!("no world {:?}", super::error::truncate(id, 64)),
    )
    .with_field("id")
}

/// The world `id` and the caller, after checking that the caller has `need` on it.
pub(crate) async fn authorize(
    st: &AppState,
    headers: &HeaderMap,
    id: &str,
    need: Role,
) -> Result<(WorldMeta, Caller), AppError> {
    if !valid_world_id(id) {
        return Err(world_not_found(id));
    }
    let w = &st.worlds;
    let who = caller(headers, w.admin.as_ref(), &*w.store).await?;
    let meta = w.store.meta(id).await.map_err(store_error)?;
    who.require(&meta, need)?;
    Ok((meta, who))
}

/// Checks that the caller has `need` on world `id` and that the body is JSON (a missing
/// `Content-Type` is accepted), then parses the body as [`parse_body`] does. Returns the world
/// and the parsed body; the checks run in that order, so the first failing one is answered.
pub(super) async fn authorized_body<T: serde::de::DeserializeOwned>(
    st: &AppState,
    headers: &HeaderMap,
    id: &str,
    need: Role,
    body: &[u8],
) -> Result<(WorldMeta, T), AppError> {
    let (meta, _) = authorize(st, headers, id, need).await?;
    check_content_type(headers, "application/json", false)?;
    Ok((meta, parse_body(body)?))
}

/// Refuses a body whose `Content-Type` is present and not `want` (parameters ignored); with
/// `required`, a missing `Content-Type` is refused too.
pub(super) fn check_content_type(
    headers: &HeaderMap,
    want: &str,
    required: bool,
) -> Result<(), AppError> {
    let got = headers
        .get(header::CONTENT_TYPE)
        .map(|v| v.to_str().unwrap_or("?"));
    let ok = match got {
        None => !required,
        Some(v) => v
            .split(';')
            .next()
            .is_some_and(|t| t.trim().eq_ignore_ascii_case(want)),
    };
    if ok {
        return Ok(());
    }
    Err(AppError::new(
        StatusCode::UNSUPPORTED_MEDIA_TYPE,
        code::UNSUPPORTED_MEDIA_TYPE,
        format!(
            "the body must be {want}, got {}",
            got.map(|g| super::error::truncate(g, 60))
                .unwrap_or_else(|| "no Content-Type".into())
        ),
    )
    .with_field("Content-Type"))
}

fn pointer_of(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    path.iter()
        .filter_map(|s| match s {
            Segment::Seq { index } => Some(format!("/{index}")),
            Segment::Map { key } => Some(format!("/{}", crate::scene::escape_token(key))),
            Segment::Enum { variant } => Some(format!("/{}", crate::scene::escape_token(variant))),
            Segment::Unknown => None,
        })
        .collect()
}

/// Parses a JSON body; a syntax error blames `body`, a shape error the JSON pointer of the
/// offending value.
pub(super) fn parse_body<T: serde::de::DeserializeOwned>(body: &[u8]) -> Result<T, AppError> {
    let value: Value = serde_json::from_slice(body).map_err(|e| {
        AppError::bad_request(code::BAD_BODY, "body", format!("the body is not JSON: {e}"))
    })?;
    serde_path_to_error::deserialize(value).map_err(|e| {
        let pointer = pointer_of(e.path());
        AppError::bad_request(
            code::BAD_BODY,
            if pointer.is_empty() {
                "body".to_string()
            } else {
                pointer
            },
            format!("{}", e.inner()),
        )
    })
}

pub(super) fn json_response(status: StatusCode, body: Value, cache: &'static str) -> Response {
    let mut res = (status, Json(body)).into_response();
    res.headers_mut()
        .insert(header::CACHE_CONTROL, HeaderValue::from_static(cache));
    res
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

fn version_etag(version: u64) -> String {
    format!("\"{version}\"")
}

pub(super) fn set_version_headers(res: &mut Response, version: u64, etag: bool) {
    let h = res.headers_mut();
    h.insert(
        HeaderName::from_static(VERSION_HEADER),
        HeaderValue::from(version),
    );
    if etag {
        if let Ok(v) = HeaderValue::from_str(&version_etag(version)) {
            h.insert(header::ETAG, v);
        }
    }
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

/// A version number: 1 to 19 ASCII digits, at least 1.
pub(crate) fn parse_version(s: &str, field: &'static str) -> Result<u64, AppError> {
    let bad = || {
        AppError::bad_request(
            code::BAD_VERSION,
            field,
            format!(
                "{field} must be a version number (a positive integer), got {:?}",
                super::error::truncate(s, 40)
            ),
        )
    };
    if s.is_empty() || s.len() > 19 || !s.bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad());
    }
    match s.parse::<u64>() {
        Ok(v) if v >= 1 => Ok(v),
        _ => Err(bad()),
    }
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

/// The value of a query parameter (first occurrence, no percent-decoding: the parameters read
/// here are plain integers).
pub(crate) fn query_param<'a>(query: Option<&'a str>, name: &str) -> Option<&'a str> {
    query?
        .split('&')
        .filter_map(|p| p.split_once('=').or(Some((p, ""))))
        .find(|(k, _)| *k == name)
        .map(|(_, v)| v)
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

/// `If-Match`: absent or `*` is no condition; else one version, plain or quoted (`5`, `"5"`,
/// `W/"5"`).
pub(super) fn parse_if_match(headers: &HeaderMap) -> Result<Option<u64>, AppError> {
    let Some(v) = headers.get(header::IF_MATCH) else {
        return Ok(None);
    };
    let bad = || {
        AppError::bad_request(
            code::BAD_VERSION,
            "If-Match",
            "If-Match must be one version number, plain or quoted",
        )
    };
    let s = v.to_str().map_err(|_| bad())?.trim();
    if s == "*" {
        return Ok(None);
    }
    let s = s.strip_prefix("W/").unwrap_or(s);
    let s = s
        .strip_prefix('"')
        .and_then(|t| t.strip_suffix('"'))
        .unwrap_or(s);
    parse_version(s, "If-Match").map(Some).map_err(|_| bad())
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

/// The answer to an edit of world `id` that was committed as `applied`: 200 with
/// `{id, version, dirty}`, `Cache-Control: no-store`, and the new version in the version header
/// and the `ETag`.
pub(super) fn edit_answer(id: &str, applied: &crate::store::EditApplied) -> Response {
    let mut res = json_response(
        StatusCode::OK,
        json!({ "id": id, "version": applied.version, "dirty": applied.dirty }),
        "no-store",
    );
    set_version_headers(&mut res, applied.version, true);
    res
}

/// Attempts of a read-modify-write edit made without `If-Match` ([`commit_on_head`]).
pub const EDIT_ATTEMPTS: u32 = 3;

/// Commits an edit that is built from the scene it applies to (an element's index, the length
/// of a list it appends to): `build` gets the head's scene and version and returns the patch
/// and what the answer reports. The patch is committed against exactly that version, so it can
/// never apply to a scene it was not built from. With `If-Match` (`expected`) a stale version is
/// 409 `version_conflict`; without it, a concurrent edit between the read and the commit makes
/// it read the new head and build again, up to [`EDIT_ATTEMPTS`] times.
pub(crate) async fn commit_on_head<T>(
    st: &AppState,
    id: &str,
    expected: Option<u64>,
    build: impl Fn(&Value, u64) -> Result<(json_patch::Patch, T), AppError>,
) -> Result<(crate::store::EditApplied, T), AppError> {
    let mut attempt = 0;
    loop {
        attempt += 1;
        let head = st.worlds.store.head(id).await.map_err(store_error)?;
        let version = head.meta.version;
        if let Some(expected) = expected {
            if expected != version {
                return Err(store_error(StoreError::Conflict {
                    expected,
                    latest: version,
                }));
            }
        }
        let (patch, answer) = build(&head.scene, version)?;
        match commit_edit(st, id, patch, Some(version)).await {
            Err(e)
                if e.code == code::VERSION_CONFLICT
                    && expected.is_none()
                    && attempt < EDIT_ATTEMPTS => {}
            r => return Ok((r?, answer)),
        }
    }
}

/// Applies an edit the caller may make (checked by the caller), durably, then broadcasts it; the
/// HTTP edit route and stream edits share it.
pub(crate) async fn commit_edit(
    st: &AppState,
    id: &str,
    patch: json_patch::Patch,
    expected: Option<u64>,
) -> Result<crate::store::EditApplied, AppError> {
    let applied = match st.worlds.store.apply_edit(id, patch, expected).await {
        Ok(a) => a,
        Err(e) => {
            let counter = if matches!(e, StoreError::Conflict { .. }) {
                &st.metrics.edits_conflict
            } else {
                &st.metrics.edits_refused
            };
            counter.fetch_add(1, Ordering::Relaxed);
            return Err(store_error(e));
        }
    };
    st.metrics.edits_applied.fetch_add(1, Ordering::Relaxed);
    tracing::info!(world = %id, version = applied.version, "edit committed");
    // No receivers is not an error: nobody is streaming this process's worlds.
    let _ = st.worlds.edits.send(EditEvent {
        world: id.to_string(),
        version: applied.version,
        dirty: applied.dirty.clone(),
    });
    Ok(applied)
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

/// A parsed world product URL, access checked.
struct WorldProduct {
    meta: WorldMeta,
    version: u64,
    pinned: bool,
    key: TileKey,
    format: Format,
    plan: Arc<WorldPlan>,
    inputs: Arc<SceneInputs>,
}

async fn world_product(
    st: &AppState,
    headers: &HeaderMap,
    (id, lod, x, z_ext): (String, String, String, String),
    query: Option<&str>,
) -> Result<WorldProduct, AppError> {
    let (meta, _) = authorize(st, headers, &id, Role::Read).await?;
    let lod = parse_lod(&lod)?;
    let x = parse_coord(&x, "x")?;
    let (z, ext) = split_extension(&z_ext);
    let z = parse_coord(z, "z")?;
    let format = parse_format(ext)?;
    let version = requested_version(&meta, query)?;
    let pinned = query_param(query, "v").is_some();
    let key = TileKey { lod, x, z };
    let (plan, inputs) = st.worlds.plan_and_inputs(&meta, version).await?;
    check_bounds(&plan, key)?;
    Ok(WorldProduct {
        meta,
        version,
        pinned,
        key,
        format,
        plan,
        inputs,
    })
}

/// Caching headers of a world product answer.
fn finish_product(p: &WorldProduct, mut res: Response) -> Response {
    product_headers(&mut res, &p.meta, p.version, p.pinned);
    res
}

/// Caching headers of any product of world `meta` at `version` (tiles, chunks, region meshes):
/// immutable when `pinned` by `?v=N`, short-lived otherwise; private and varying by
/// `Authorization` unless the world is public; the version header.
pub(super) fn product_headers(res: &mut Response, meta: &WorldMeta, version: u64, pinned: bool) {
    let cache = match (pinned, meta.public) {
        (true, true) => IMMUTABLE.to_string(),
        (true, false) => "private, max-age=31536000, immutable".to_string(),
        (false, true) => format!("public, max-age={LATEST_MAX_AGE_S}"),
        (false, false) => format!("private, max-age={LATEST_MAX_AGE_S}"),
    };
    if let Ok(v) = HeaderValue::from_str(&cache) {
        res.headers_mut().insert(header::CACHE_CONTROL, v);
    }
    if !meta.public {
        res.headers_mut()
            .insert(header::VARY, HeaderValue::from_static("Authorization"));
    }
    set_version_headers(res, version, false);
}

/// `GET /v1/worlds/{id}/tiles/{lod}/{x}/{z}.{ext}[?v=N][&seams=n,e,s,w][&format=1|2]`.
async fn tile(
    State(st): State<AppState>,
    path: Segments,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let p = world_product(&st, &headers, segments(path)?, query.as_deref()).await?;
    let seams = parse_seams(query.as_deref())?;
    let version = parse_tile_version(query.as_deref(), p.format)?;
    let product = st
        .tile_product(&p.inputs, p.plan.clone(), p.key, seams, p.format, version)
        .await?;
    Ok(finish_product(&p, product.respond(&headers)))
}

/// `GET /v1/worlds/{id}/scatter/{lod}/{x}/{z}.json[?v=N]`.
async fn scatter(
    State(st): State<AppState>,
    path: Segments,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let p = world_product(&st, &headers, segments(path)?, query.as_deref()).await?;
    check_scatter_format(p.format)?;
    check_scatter_cost(&p.plan, p.key.lod)?;
    let (state, plan, inputs, key) = (st.clone(), p.plan.clone(), p.inputs.clone(), p.key);
    let product = st
        .limited(async move {
            let tile = state
                .tile_with_inputs(&inputs, plan.clone(), key, [false; 4])
                .await;
            scatter_product(plan, tile).await
        })
        .await?;
    Ok(finish_product(&p, product.respond(&headers)))
}

/// Parses `x,z;x,z;…` (metres) for the stats readout.
fn parse_points(text: &str, field: &'static str) -> Result<Vec<[f64; 2]>, AppError> {
    let bad = || {
        AppError::bad_request(
            code::BAD_COORDINATE,
            field,
            format!("{field} must be x,z pairs in metres separated by ';'"),
        )
    };
    let points = text
        .split(';')
        .map(|pair| {
            let mut it = pair.split(',').map(|v| v.trim().parse::<f64>());
            match (it.next(), it.next(), it.next()) {
                (Some(Ok(x)), Some(Ok(z)), None) if x.is_finite() && z.is_finite() => Ok([x, z]),
                _ => Err(bad()),
            }
        })
        .collect::<Result<Vec<_>, _>>()?;
    if points.is_empty() || points.len() > crate::authoring::MAX_POINTS {
        return Err(bad());
    }
    Ok(points)
}

/// The version a product request names with `?v=N` (the latest without), checked against the
/// world's latest.
pub(crate) fn requested_version(meta: &WorldMeta, query: Option<&str>) -> Result<u64, AppError> {
    let version = match query_param(query, "v") {
        None => meta.version,
        Some(v) => parse_version(v, "v")?,
    };
    if version > meta.version {
        return Err(store_error(StoreError::VersionNotFound {
            version,
            latest: meta.version,
        })
        .with_field("v"));
    }
    Ok(version)
}

/// Checks that the caller may read world `id`, then returns the world and the version the
/// request names with `?v=N` (the latest without), checked as [`requested_version`] does.
pub(super) async fn readable_version(
    st: &AppState,
    headers: &HeaderMap,
    id: &str,
    query: Option<&str>,
) -> Result<(WorldMeta, u64), AppError> {
    let (meta, _) = authorize(st, headers, id, Role::Read).await?;
    let version = requested_version(&meta, query)?;
    Ok((meta, version))
}

/// `GET /v1/worlds/{id}/regions/{rid}/stats?point=x,z | polyline=x,z;x,z;… |
/// rect=x0,z0;x1,z1 [&v=N]`: elevation (min, mean, max, metres) and mean and steepest slope
/// (degrees) of the authored region's heights over a point, a curve or a rectangle (Guérin et al.
/// §6.3).
async fn region_stats(
    State(st): State<AppState>,
    Path((id, rid)): Path<(String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    use crate::authoring::stats::{stats, StatsShape};
    let query = query.as_deref();
    let (meta, version) = readable_version(&st, &headers, &id, query).await?;
    let shape = match (
        query_param(query, "point"),
        query_param(query, "polyline"),
        query_param(query, "rect"),
    ) {
        (Some(p), None, None) => StatsShape::Point(parse_points(p, "point")?[0]),
        (None, Some(p), None) => StatsShape::Polyline(parse_points(p, "polyline")?),
        (None, None, Some(p)) => match parse_points(p, "rect")?.as_slice() {
            [a, b] => StatsShape::Rect {
                min: [a[0].min(b[0]), a[1].min(b[1])],
                max: [a[0].max(b[0]), a[1].max(b[1])],
            },
            _ => {
                return Err(AppError::bad_request(
                    code::BAD_COORDINATE,
                    "rect",
                    "rect must be two corners: x0,z0;x1,z1",
                ))
            }
        },
        _ => {
            return Err(AppError::bad_request(
                code::BAD_COORDINATE,
                "point",
                "give exactly one of point, polyline and rect",
            ))
        }
    };
    let (plan, inputs) = st.worlds.plan_and_inputs(&meta, version).await?;
    let region = inputs
        .region(&rid)
        .ok_or_else(|| super::region_io::no_region(&id, &rid, version))?;
    let solved = st
        .regions
        .get(&plan, region)
        .await
        .ok_or_else(|| AppError::internal("the region could not be solved"))?;
    let s = stats(&solved, &shape)
        .map_err(|e| AppError::bad_request(code::BAD_COORDINATE, e.field, e.message))?;
    let mut res = json_response(
        StatusCode::OK,
        json!({ "region": rid, "version": version, "stats": s }),
        "private, no-cache",
    );
    set_version_headers(&mut res, version, false);
    Ok(res)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn if_match_forms() {
        let h = |v: &str| {
            let mut m = HeaderMap::new();
            m.insert(header::IF_MATCH, HeaderValue::from_str(v).expect("value"));
            m
        };
        assert_eq!(parse_if_match(&HeaderMap::new()).expect("none"), None);
        assert_eq!(parse_if_match(&h("*")).expect("any"), None);
        assert_eq!(parse_if_match(&h("7")).expect("plain"), Some(7));
        assert_eq!(parse_if_match(&h("\"7\"")).expect("quoted"), Some(7));
        assert_eq!(parse_if_match(&h("W/\"7\"")).expect("weak"), Some(7));
        for bad in ["0", "-1", "x", "\"7", "7, 8", "99999999999999999999"] {
            let e = parse_if_match(&h(bad)).expect_err(bad);
            assert_eq!(e.field.as_deref(), Some("If-Match"), "{bad}");
        }
    }

    /// A concurrent edit between reading the head and committing makes [`commit_on_head`] build
    /// again on the new head (without `If-Match`), so both edits land; with `If-Match` it is 409.
    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn commit_on_head_rebuilds_after_a_concurrent_edit() {
        let st = AppState::new(crate::compute::Compute::cpu());
        let scene = Scene::default().to_value();
        let id = new_world_id().expect("id");
        let token = new_token().expect("token");
        st.worlds
            .store
            .create_world(NewWorld {
                id: id.clone(),
                seed: 1,
                scene,
                public: true,
                admin_token: hash_token(&token),
            })
            .await
            .expect("world");
        let decal = |name: &str| -> json_patch::Patch {
            serde_json::from_value(json!([{ "op": "add", "path": "/decals/-", "value":
                { "id": name, "bbox": { "min": [0.0, 0.0], "max": [10.0, 10.0] } } }]))
            .expect("patch")
        };
        let calls = std::sync::atomic::AtomicU32::new(0);
        let build = |scene: &Value, version: u64| {
            // On the first call another writer commits first: the patch built here is stale.
            if calls.fetch_add(1, Ordering::SeqCst) == 0 {
                tokio::task::block_in_place(|| {
                    tokio::runtime::Handle::current().block_on(commit_edit(
                        &st,
                        &id,
                        decal("other"),
                        None,
                    ))
                })
                .expect("the concurrent edit");
            }
            let seen = scene["decals"].as_array().map_or(0, Vec::len);
            Ok((decal("mine"), (version, seen)))
        };
        let (applied, (built_on, seen)) = commit_on_head(&st, &id, None, &build)
            .await
            .expect("committed on the second attempt");
        assert_eq!(
            calls.load(Ordering::SeqCst),
            2,
            "built again after the conflict"
        );
        assert_eq!((built_on, applied.version), (2, 3));
        assert_eq!(seen, 1, "the second build saw the concurrent edit");
        // With If-Match on a stale version the edit is refused and nothing is built.
        calls.store(1, Ordering::SeqCst);
        let e = commit_on_head(&st, &id, Some(2), &build)
            .await
            .expect_err("stale If-Match");
        assert_eq!(e.code, code::VERSION_CONFLICT);
        assert_eq!(calls.load(Ordering::SeqCst), 1);
    }

    #[test]
    fn query_params() {
        assert_eq!(query_param(Some("v=3&seams=1,0,0,0"), "v"), Some("3"));
        assert_eq!(query_param(Some("seams=1,0,0,0&v=4"), "v"), Some("4"));
        assert_eq!(query_param(Some("vv=3"), "v"), None);
        assert_eq!(query_param(Some("v"), "v"), Some(""));
        assert_eq!(query_param(None, "v"), None);
    }
}
