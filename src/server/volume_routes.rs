//! Volume-region routes (issue 5, "Exports" and "input meshes uploaded as glTF/glb"): a region's
//! whole mesh as glb, its feature curves as JSON in and out, and glb mesh uploads.
//!
//! | route | who | answer |
//! |---|---|---|
//! | `GET /v1/worlds/{id}/volumes/{vid}/mesh.glb[?v=N]` | read | the region's surface-nets mesh ([`crate::encode::region_glb`]) |
//! | `GET /v1/worlds/{id}/volumes/{vid}/curves.json[?v=N]` | read | `{"curves": [...]}`, `ETag: "<version>"` |
//! | `PUT /v1/worlds/{id}/volumes/{vid}/curves.json` (`application/json`, `If-Match`) | edit | `{id, version, dirty}` |
//! | `POST /v1/worlds/{id}/volumes/{vid}/meshes[?alpha=&beta=&material=]` (`model/gltf-binary`, `If-Match`) | edit | 201 `{id, version, volume, mesh, triangles, dirty}` |
//!
//! **Edits go through the scene.** `PUT curves.json` and `POST meshes` are JSON Patches on the
//! world's scene committed by the same path as `POST /v1/worlds/{id}/edits`
//! ([`super::worlds::commit_on_head`]): each makes one new version, honours `If-Match` (409 on a
//! stale version), is announced to streams, and is validated like any edit. The patch is built
//! from the version it commits on (the element's index, the uploaded mesh's index), so it never
//! applies to a scene it was not built from: without `If-Match`, a concurrent edit makes it
//! rebuild on the new head (up to [`super::worlds::EDIT_ATTEMPTS`] times). The patch also starts
//! with a `test` of `/volumes/{i}/id`, a second guard. An uploaded glb is
//! stored in the element as a `{"glb_base64": …}` mesh entry (element docs,
//! [`crate::volume::element`]): the scene stays the one source of truth, versions and exports
//! carry it, and inline and uploaded meshes are solved by the same code. The cost is size: a glb
//! is at most [`MAX_GLB_BYTES`] and the whole scene at most
//! [`crate::store::MAX_SCENE_BYTES`] (413 `scene_too_large` beyond).
//!
//! Errors name the field: an unknown volume is 404 naming `vid`; a bad glb is 400 naming
//! `body`; an invalid curve in `PUT curves.json` is 400 naming its pointer in the body (e.g.
//! `/curves/2/control_points`). `mesh.glb` is a product: content-hash `ETag`, immutable when
//! pinned with `?v=N`, short-lived otherwise, like world chunks.

use super::edit_service::{commit_on_head, edit_answer};
use super::error::{code, truncate, AppError};
use super::http::{
    authorize, check_content_type, json_response, parse_if_match, query_param, readable_version,
    set_version_headers, store_error,
};
use super::route_table::RouteTable;
use super::routes::CachedProduct;
use super::view::WorldAt;
use super::AppState;
use crate::encode::region_glb::{self, RegionInfo};
use crate::scene::{Element, VolumeInput};
use crate::store::Role;
use crate::volume::element::{VolumeSpec, MAX_VOLUME_TRIANGLES};
use crate::volume::mesh_import::{glb_triangles, MAX_GLB_BYTES};
use axum::body::Bytes;
use axum::extract::{Path, RawQuery, State};
use axum::http::{HeaderMap, StatusCode};
use axum::response::Response;
use serde_json::{json, Value};

/// Media type of glb uploads and exports.
pub const GLB_CONTENT_TYPE: &str = "model/gltf-binary";

/// The volume routes.
pub fn routes() -> RouteTable {
    RouteTable::new()
        .get("/v1/worlds/{id}/volumes/{vid}/mesh.glb", mesh_glb)
        .get("/v1/worlds/{id}/volumes/{vid}/curves.json", get_curves)
        .put("/v1/worlds/{id}/volumes/{vid}/curves.json", put_curves)
        .post("/v1/worlds/{id}/volumes/{vid}/meshes", upload_mesh)
}

fn no_volume(id: &str, vid: &str, version: u64) -> AppError {
    AppError::new(
        StatusCode::NOT_FOUND,
        code::NOT_FOUND,
        format!(
            "world {id} has no volume {:?} at version {version}",
            truncate(vid, 128)
        ),
    )
    .with_field("vid")
}

/// Index and value of the `volumes` element `vid` in a scene document.
fn element_in(scene: &Value, vid: &str) -> Option<(usize, Value)> {
    scene
        .get("volumes")?
        .as_array()?
        .iter()
        .enumerate()
        .find(|(_, e)| e.get("id").and_then(Value::as_str) == Some(vid))
        .map(|(i, e)| (i, e.clone()))
}

/// The parsed volume `vid` of a scene version's inputs.
fn volume_input(inputs: &crate::scene::SceneInputs, vid: &str) -> Option<VolumeInput> {
    inputs
        .volumes_meeting([f64::MIN; 3], [f64::MAX; 3])
        .into_iter()
        .find(|v| v.spec.id == vid)
}

/// `GET /v1/worlds/{id}/volumes/{vid}/mesh.glb[?v=N]`.
async fn mesh_glb(
    _charge: super::rate_limit::Charge,
    world: WorldAt,
    State(st): State<AppState>,
    Path((id, vid)): Path<(String, String)>,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let view = world.view.clone();
    let (seed, version) = (view.seed(), view.version());
    let volume = volume_input(&view.inputs, &vid).ok_or_else(|| no_volume(&id, &vid, version))?;
    let state = st.clone();
    let product = st
        .limited(async move {
            let solved = state
                .volumes
                .get(&state, &view, &volume)
                .await
                .ok_or_else(|| {
                AppError::new(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    code::INVALID_SCENE,
                    format!(
                        "volume {:?} could not be solved (no seed curve, mesh or ground meets its box)",
                        volume.spec.id
                    ),
                )
                .with_field("vid")
            })?;
            let offload = state.compute.offload();
            tokio::task::spawn_blocking(move || {
                region_glb::encode(&solved, RegionInfo { seed, version }, &offload)
                    .map(|body| CachedProduct::new(body, GLB_CONTENT_TYPE, Vec::new()))
                    .map_err(|e| {
                        AppError::new(
                            StatusCode::UNPROCESSABLE_ENTITY,
                            code::BAD_PARAMETER,
                            e.to_string(),
                        )
                        .with_field("vid")
                    })
            })
            .await
            .map_err(|e| AppError::internal(format!("region export failed: {e}")))?
        })
        .await?;
    Ok(world.finish(product.respond(&headers)))
}

/// `GET /v1/worlds/{id}/volumes/{vid}/curves.json[?v=N]`.
async fn get_curves(
    State(st): State<AppState>,
    Path((id, vid)): Path<(String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
) -> Result<Response, AppError> {
    let (meta, version) = readable_version(&st, &headers, &id, query.as_deref()).await?;
    let scene = st
        .worlds
        .store
        .scene_at(&id, version)
        .await
        .map_err(store_error)?;
    let (_, element) = element_in(&scene, &vid).ok_or_else(|| no_volume(&id, &vid, version))?;
    let curves = element.get("curves").cloned().unwrap_or_else(|| json!([]));
    let cache = if meta.public {
        "no-cache"
    } else {
        "private, no-cache"
    };
    let mut res = json_response(StatusCode::OK, json!({ "curves": curves }), cache);
    set_version_headers(&mut res, version, true);
    Ok(res)
}

/// The element `e` with `field` set to `value`, checked as a `volumes` element.
fn check_element(mut e: Value, field: &str, value: Value) -> Result<(), (String, String)> {
    if let Some(o) = e.as_object_mut() {
        o.insert(field.to_string(), value);
    }
    let element: Element = serde_json::from_value(e).map_err(|x| (String::new(), x.to_string()))?;
    VolumeSpec::from_element(&element)
        .map(|_| ())
        .map_err(|x| (x.pointer, x.message))
}

/// `PUT /v1/worlds/{id}/volumes/{vid}/curves.json` with `{"curves": [...]}`.
async fn put_curves(
    State(st): State<AppState>,
    Path((id, vid)): Path<(String, String)>,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, AppError> {
    authorize(&st, &headers, &id, Role::Edit).await?;
    check_content_type(&headers, "application/json", false)?;
    let expected = parse_if_match(&headers)?;
    let doc: Value = serde_json::from_slice(&body).map_err(|e| {
        AppError::bad_request(code::BAD_BODY, "body", format!("the body is not JSON: {e}"))
    })?;
    let curves = match doc.as_object() {
        Some(o) if o.len() == 1 && o.get("curves").is_some_and(Value::is_array) => {
            o["curves"].clone()
        }
        _ => {
            return Err(AppError::bad_request(
                code::BAD_BODY,
                "body",
                "the body must be {\"curves\": [ … ]} and nothing else",
            ))
        }
    };
    let (applied, ()) = commit_on_head(&st, &id, expected, |scene, version| {
        let (i, element) = element_in(scene, &vid).ok_or_else(|| no_volume(&id, &vid, version))?;
        if let Err((pointer, message)) = check_element(element, "curves", curves.clone()) {
            let field = if pointer.starts_with("/curves") {
                pointer
            } else {
                format!("/volumes/{i}{pointer}")
            };
            return Err(AppError::bad_request(
                code::INVALID_SCENE,
                field,
                format!("the curves would be invalid: {message}"),
            ));
        }
        let patch = patch(json!([
            { "op": "test", "path": format!("/volumes/{i}/id"), "value": vid },
            { "op": "add", "path": format!("/volumes/{i}/curves"), "value": curves },
        ]))?;
        Ok((patch, ()))
    })
    .await?;
    Ok(edit_answer(&id, &applied))
}

fn patch(v: Value) -> Result<json_patch::Patch, AppError> {
    serde_json::from_value(v).map_err(|e| AppError::internal(format!("building the edit: {e}")))
}

/// A finite number query parameter, or `default`.
fn number_param(query: Option<&str>, name: &'static str, default: f64) -> Result<f64, AppError> {
    match query_param(query, name) {
        None => Ok(default),
        Some(s) => s
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| {
                AppError::bad_request(
                    code::BAD_PARAMETER,
                    name,
                    format!("{name} must be a finite number, got {:?}", truncate(s, 40)),
                )
            }),
    }
}

/// `POST /v1/worlds/{id}/volumes/{vid}/meshes[?alpha=&beta=&material=]` with a glb body.
async fn upload_mesh(
    State(st): State<AppState>,
    Path((id, vid)): Path<(String, String)>,
    RawQuery(query): RawQuery,
    headers: HeaderMap,
    body: Bytes,
) -> Result<Response, AppError> {
    use base64::Engine as _;
    authorize(&st, &headers, &id, Role::Edit).await?;
    check_content_type(&headers, GLB_CONTENT_TYPE, true)?;
    let expected = parse_if_match(&headers)?;
    let query = query.as_deref();
    let alpha = number_param(query, "alpha", 0.3)?;
    let beta = number_param(query, "beta", 0.5)?;
    let material = number_param(query, "material", 0.0)?;
    if material.fract() != 0.0 || !(0.0..=f64::from(u16::MAX)).contains(&material) {
        return Err(AppError::bad_request(
            code::BAD_PARAMETER,
            "material",
            "material must be an integer id in 0..=65535",
        ));
    }
    if body.len() > MAX_GLB_BYTES {
        return Err(AppError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            code::PAYLOAD_TOO_LARGE,
            format!(
                "the glb is {} bytes; at most {MAX_GLB_BYTES} are accepted",
                body.len()
            ),
        )
        .with_field("body"));
    }
    let triangles = glb_triangles(&body, None, MAX_VOLUME_TRIANGLES)
        .map_err(|e| AppError::bad_request(code::BAD_BODY, "body", format!("bad glb: {e}")))?
        .len();
    let entry = json!({
        "glb_base64": base64::engine::general_purpose::STANDARD.encode(&body),
        "alpha": alpha,
        "beta": beta,
        "material": material as u16,
    });
    // The mesh's index and the patch are built from the version the patch commits on.
    let (applied, k) = commit_on_head(&st, &id, expected, |scene, version| {
        let (i, element) = element_in(scene, &vid).ok_or_else(|| no_volume(&id, &vid, version))?;
        let mut meshes = element
            .get("meshes")
            .and_then(Value::as_array)
            .cloned()
            .unwrap_or_default();
        let k = meshes.len();
        let had_meshes = element.get("meshes").is_some();
        meshes.push(entry.clone());
        if let Err((pointer, message)) = check_element(element, "meshes", json!(meshes)) {
            return Err(AppError::bad_request(
                code::INVALID_SCENE,
                format!("/volumes/{i}{pointer}"),
                format!("the volume would be invalid: {message}"),
            ));
        }
        let add = if had_meshes {
            json!({ "op": "add", "path": format!("/volumes/{i}/meshes/-"), "value": entry })
        } else {
            json!({ "op": "add", "path": format!("/volumes/{i}/meshes"), "value": [entry] })
        };
        let patch = patch(json!([
            { "op": "test", "path": format!("/volumes/{i}/id"), "value": vid },
            add,
        ]))?;
        Ok((patch, k))
    })
    .await?;
    let mut res = json_response(
        StatusCode::CREATED,
        json!({ "id": id, "version": applied.version, "volume": vid, "mesh": k,
                "triangles": triangles, "dirty": applied.dirty }),
        "no-store",
    );
    set_version_headers(&mut res, applied.version, true);
    Ok(res)
}
