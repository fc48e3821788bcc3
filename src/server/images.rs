//! Uploaded images of a world (issue 20): the PNGs that image materials and decals name by
//! content hash ([`crate::ptex::spec`]), and the [`MaterialSet`] a world version's pages bake
//! with ([`world_materials`]).
//!
//! | route | what |
//! |---|---|
//! | `POST /v1/worlds/{id}/images` | stores an `image/png` body (edit role): 201, or 200 if held |
//! | `GET /v1/worlds/{id}/images/{hash}` | the PNG (read role) |
//!
//! Every limit is checked before work: the body is at most
//! [`crate::ptex::image::MAX_IMAGE_BYTES`] (the request body limit), its header states
//! power-of-two sides of at most [`crate::ptex::image::MAX_IMAGE_SIDE`] pixels (400
//! `invalid_image`, field `body`), and a world holds at most [`crate::store::MAX_WORLD_IMAGES`]
//! (409 `too_many_images`). Images are stored under the blake3 of their bytes and never changed or
//! removed, so a scene version that names one pins its bytes; an edit may name only images the
//! world holds (checked by the store in the edit's transaction).

use super::error::{code, AppError};
use super::http::{authorize, check_content_type, json_response, store_error};
use super::route_table::RouteTable;
use super::view::WorldView;
use super::AppState;
use crate::ptex::image::{check_png, decode_png, hash_hex, image_hash, parse_hash, Image};
use crate::ptex::MaterialSet;
use crate::store::Role;
use axum::body::Bytes;
use axum::extract::{Path, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde_json::json;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock, Weak};

/// The routes of this module.
pub(super) fn routes() -> RouteTable {
    RouteTable::new()
        .post("/v1/worlds/{id}/images", upload)
        .get("/v1/worlds/{id}/images/{hash}", download)
}

fn invalid(message: String) -> AppError {
    AppError::bad_request(code::INVALID_IMAGE, "body", message)
}

/// `POST /v1/worlds/{id}/images`.
async fn upload(
    State(st): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, AppError> {
    authorize(&st, &headers, &id, Role::Edit).await?;
    check_content_type(&headers, "image/png", true)?;
    let (width, height) = check_png(&body).map_err(|e| invalid(e.0))?;
    let png = body.to_vec();
    // At most MAX_IMAGE_SIDE² pixels: a bounded decode, off the runtime's threads.
    let decoded = tokio::task::spawn_blocking(move || decode_png(&png).map(|_| png))
        .await
        .map_err(|e| AppError::internal(format!("decoding the image failed: {e}")))?;
    let png = decoded.map_err(|e| invalid(e.0))?;
    let hash = image_hash(&png);
    let bytes = png.len();
    let created = st
        .worlds
        .store
        .put_image(&id, hash, png)
        .await
        .map_err(store_error)?;
    let hex = hash_hex(&hash);
    let status = if created {
        StatusCode::CREATED
    } else {
        StatusCode::OK
    };
    let mut res = json_response(
        status,
        json!({"image": hex, "width": width, "height": height, "bytes": bytes}),
        "no-store",
    );
    if let Ok(v) = HeaderValue::from_str(&format!("/v1/worlds/{id}/images/{hex}")) {
        res.headers_mut().insert(header::LOCATION, v);
    }
    Ok(res)
}

/// `GET /v1/worlds/{id}/images/{hash}`.
async fn download(
    State(st): State<AppState>,
    Path((id, hash)): Path<(String, String)>,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    authorize(&st, &headers, &id, Role::Read).await?;
    let not_found = || {
        AppError::new(
            StatusCode::NOT_FOUND,
            code::IMAGE_NOT_FOUND,
            format!(
                "no image {:?} in this world",
                super::error::truncate(&hash, 64)
            ),
        )
        .with_field("hash")
    };
    let h = parse_hash(&hash).ok_or_else(not_found)?;
    let png = st
        .worlds
        .store
        .image(&id, h)
        .await
        .map_err(store_error)?
        .ok_or_else(not_found)?;
    let mut res = (StatusCode::OK, png).into_response();
    let hdrs = res.headers_mut();
    hdrs.insert(header::CONTENT_TYPE, HeaderValue::from_static("image/png"));
    hdrs.insert(
        header::CACHE_CONTROL,
        HeaderValue::from_static("private, max-age=31536000, immutable"),
    );
    if let Ok(v) = HeaderValue::from_str(&format!("\"{hash}\"")) {
        hdrs.insert(header::ETAG, v);
    }
    Ok(res)
}

/// Decoded images by hash, held weakly: whoever holds an image (a bake under way, a stream
/// session's batch) shares one decode with every other user, also after [`ImageCache`] let it
/// go. Hashes name bytes, so worlds holding the same image share it too.
fn live() -> &'static Mutex<HashMap<[u8; 32], Weak<Image>>> {
    static LIVE: OnceLock<Mutex<HashMap<[u8; 32], Weak<Image>>>> = OnceLock::new();
    LIVE.get_or_init(Mutex::default)
}

/// The decoded image `hash` if anyone holds it.
fn held(hash: &[u8; 32]) -> Option<Arc<Image>> {
    let map = live().lock().unwrap_or_else(|p| p.into_inner());
    map.get(hash).and_then(Weak::upgrade)
}

/// Decodes `png` (whose hash is `hash`) and shares the result.
fn decoded(hash: [u8; 32], png: &[u8]) -> Result<Arc<Image>, AppError> {
    let img = Arc::new(
        decode_png(png)
            .map_err(|e| AppError::internal(format!("a stored image does not decode: {e}")))?,
    );
    let mut map = live().lock().unwrap_or_else(|p| p.into_inner());
    map.retain(|_, w| w.strong_count() > 0);
    map.insert(hash, Arc::downgrade(&img));
    Ok(img)
}

/// The decoded images of the worlds' materials and decals, by hash, within their share of
/// `--memory-budget` ([`super::budget`]), each weighed by its texels (every mip level). A world
/// version's [`MaterialSet`] is built from it on every use and held only while a bake runs, so
/// the images held besides the cache are those of the bakes under way; one that was let go is
/// read from the store and decoded again (the same bytes, so the same texels).
pub struct ImageCache {
    memo: crate::cache::Memo<[u8; 32], Arc<Image>>,
}

impl std::fmt::Debug for ImageCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ImageCache")
            .field("budget", &self.memo.budget_bytes())
            .finish()
    }
}

impl Default for ImageCache {
    fn default() -> Self {
        Self::new(super::budget::MemoryBudget::default().images)
    }
}

impl ImageCache {
    /// An empty cache of at most `budget_bytes`.
    pub fn new(budget_bytes: usize) -> Self {
        Self {
            memo: crate::cache::Memo::new(budget_bytes, |_, img: &Arc<Image>| img.bytes()),
        }
    }

    /// Hits, misses, evictions and bytes.
    pub fn stats(&self) -> crate::cache::MemoStats {
        self.memo.stats()
    }

    /// Image `h` of world `id`: from the cache, from a holder, or read from the store and
    /// decoded on the blocking pool; `None` if the store lacks it.
    async fn get(
        &self,
        st: &AppState,
        id: &str,
        h: [u8; 32],
    ) -> Result<Option<Arc<Image>>, AppError> {
        let got = self
            .memo
            .try_get_or_compute_async(h, || async {
                if let Some(img) = held(&h) {
                    return Ok(img);
                }
                let png = st
                    .worlds
                    .store
                    .image(id, h)
                    .await
                    .map_err(store_error)?
                    .ok_or(None)?;
                tokio::task::spawn_blocking(move || decoded(h, &png))
                    .await
                    .map_err(|e| AppError::internal(format!("decoding an image failed: {e}")))?
                    .map_err(Some)
            })
            .await;
        match got {
            Ok((img, _)) => Ok(Some(img)),
            Err(None) => Ok(None),
            Err(Some(e)) => Err(e),
        }
    }
}

/// The materials (and decals) world `view`'s pages bake with: the default set when its scene
/// has no `materials` or `decals` (a bare seed, or a world without them: the bytes of before
/// these elements), else the set its elements make with their images from [`ImageCache`].
/// Built on every call (the images are the only heavy part); hold it only while baking.
///
/// # Errors
/// A store failure, or a stored image that no longer decodes (500).
pub async fn world_materials(
    st: &AppState,
    view: &WorldView,
) -> Result<Arc<MaterialSet>, AppError> {
    let specs = view.inputs.ptex();
    let seed = view.seed();
    let Some((id, _)) = &view.world else {
        return Ok(Arc::new(MaterialSet::default_ground(seed)));
    };
    if specs.is_empty() {
        return Ok(Arc::new(MaterialSet::default_ground(seed)));
    }
    let mut images: HashMap<[u8; 32], Arc<Image>> = HashMap::new();
    for h in specs.images() {
        if images.contains_key(&h) {
            continue;
        }
        match st.images.get(st, id, h).await? {
            Some(img) => {
                images.insert(h, img);
            }
            None => {
                let image = hash_hex(&h);
                tracing::error!(world = %id, %image, "a scene names an image the store lacks");
            }
        }
    }
    Ok(Arc::new(specs.set(seed, &images)))
}
