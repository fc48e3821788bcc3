//! The edit service: an edit is committed to the store ([`commit_edit`], or [`commit_on_head`]
//! for edits built from the scene they change), then announced: to the stream sessions of the
//! edited world with the new version's view, built once ([`EditChannels::subscribe_world`],
//! [`WorldEdit`]), and on an in-process broadcast of every world's edits ([`EditEvent`],
//! [`EditChannels::subscribe`]). Edits other replicas commit are announced here too
//! (`server::replicas`).

use super::error::{code, AppError};
use super::http::{json_response, set_version_headers, store_error};
use super::view::WorldView;
use super::worlds::Worlds;
use super::AppState;
use crate::scene::Dirty;
use crate::store::StoreError;
use crate::terrain::WorldPlan;
use axum::http::StatusCode;
use axum::response::Response;
use serde_json::{json, Value};
use std::collections::HashMap;
use std::sync::atomic::Ordering;
use std::sync::{Arc, Mutex};
use tokio::sync::broadcast;

/// Edit events buffered per subscriber before the slowest one lags.
pub const EDIT_CHANNEL_CAPACITY: usize = 1024;

/// An accepted edit, as broadcast to every subscriber of [`Worlds::subscribe`] after its commit.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct EditEvent {
    /// World id.
    pub world: String,
    /// The version the edit made.
    pub version: u64,
    /// What it changed.
    pub dirty: crate::scene::Dirty,
}

/// A stream session's view of a world version ([`crate::stream::session::SourceView`]): the
/// version a stream reports (1 for a bare seed) and the world's view.
#[derive(Clone, Debug)]
pub struct StreamView {
    /// The version the stream reports.
    pub version: u64,
    /// The world at that version.
    pub view: Arc<WorldView>,
}

impl crate::stream::session::SourceView for StreamView {
    fn version(&self) -> u64 {
        self.version
    }

    fn plan(&self) -> &Arc<WorldPlan> {
        &self.view.plan
    }

    fn volume_boxes(&self) -> Vec<crate::stream::chunks::Box3> {
        self.view
            .inputs
            .volumes()
            .iter()
            .map(|v| {
                let s = &v.spec;
                [
                    [s.min[0], f64::from(s.y_m[0]), s.min[1]],
                    [s.max[0], f64::from(s.y_m[1]), s.max[1]],
                ]
            })
            .collect()
    }

    fn cave_sites(
        &self,
        area: [f64; 4],
        centre: [f64; 2],
    ) -> Vec<crate::subsurface::openings::CaveSite> {
        let rect = crate::scene::Rect {
            min: [area[0], area[1]],
            max: [area[2], area[3]],
        };
        let geos = self.view.inputs.strata_meeting(self.view.seed(), &rect);
        crate::subsurface::openings::cave_sites(&geos, area, centre)
    }
}

/// An edit of one world as its stream sessions receive it.
pub type WorldEdit = crate::stream::session::WorldEdit<StreamView>;

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
    st.worlds
        .edits
        .announce(&st.worlds, id, applied.version, &applied.dirty)
        .await;
    Ok(applied)
}

/// The channels accepted edits are announced on.
#[derive(Debug)]
pub struct EditChannels {
    all: broadcast::Sender<EditEvent>,
    /// Per world with stream sessions: the channel its edits reach them on.
    worlds: Mutex<HashMap<String, broadcast::Sender<WorldEdit>>>,
    /// Per streamed world: the highest version announced to its sessions, for the catch-up of
    /// `server::replicas`.
    announced: Mutex<HashMap<String, u64>>,
}

impl Default for EditChannels {
    fn default() -> Self {
        Self {
            all: broadcast::channel(EDIT_CHANNEL_CAPACITY).0,
            worlds: Mutex::default(),
            announced: Mutex::default(),
        }
    }
}

impl EditChannels {
    fn worlds(&self) -> std::sync::MutexGuard<'_, HashMap<String, broadcast::Sender<WorldEdit>>> {
        self.worlds.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// A new receiver of every world's [`EditEvent`]s.
    pub fn subscribe(&self) -> broadcast::Receiver<EditEvent> {
        self.all.subscribe()
    }

    /// Current receivers of every world's edits.
    pub fn subscribers(&self) -> usize {
        self.all.receiver_count()
    }

    /// A new receiver of world `id`'s edits, each with the view of the version it made.
    pub fn subscribe_world(&self, id: &str) -> broadcast::Receiver<WorldEdit> {
        let mut worlds = self.worlds();
        worlds.retain(|_, tx| tx.receiver_count() > 0);
        self.announced
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .retain(|w, _| worlds.contains_key(w));
        worlds
            .entry(id.to_owned())
            .or_insert_with(|| broadcast::channel(EDIT_CHANNEL_CAPACITY).0)
            .subscribe()
    }

    /// The worlds stream sessions of this process follow, each with the highest version
    /// announced to them (0 when none is recorded).
    pub fn streamed_worlds(&self) -> Vec<(String, u64)> {
        let streamed: Vec<String> = self
            .worlds()
            .iter()
            .filter(|(_, tx)| tx.receiver_count() > 0)
            .map(|(id, _)| id.clone())
            .collect();
        let announced = self.announced.lock().unwrap_or_else(|p| p.into_inner());
        streamed
            .into_iter()
            .map(|id| {
                let v = announced.get(&id).copied().unwrap_or(0);
                (id, v)
            })
            .collect()
    }

    /// Announces the edit that made `version` of world `id` (committed here, or by another
    /// replica: `server::replicas`): to every subscriber, and to the world's stream sessions with
    /// the version's view from `worlds`, built once for all of them (not built when no session
    /// streams the world).
    pub(super) async fn announce(&self, worlds: &Worlds, id: &str, version: u64, dirty: &Dirty) {
        let stream = self
            .worlds()
            .get(id)
            .filter(|tx| tx.receiver_count() > 0)
            .cloned();
        if let Some(tx) = stream {
            // Only worlds with sessions are recorded (and `subscribe_world` forgets the others),
            // so the record stays as small as the streamed worlds.
            {
                let mut announced = self.announced.lock().unwrap_or_else(|p| p.into_inner());
                let v = announced.entry(id.to_owned()).or_insert(0);
                *v = (*v).max(version);
            }
            match worlds.view_of(id, version).await {
                // A session that left since is not an error.
                Ok(view) => {
                    // An edit of the Ptex elements only leaves the tiles and chunks as they were:
                    // the sessions re-send none of them (the previous version's view is usually
                    // still cached; without it, everything `dirty` says is stale).
                    let before = match version.checked_sub(1).filter(|v| *v > 0) {
                        Some(v) => worlds.view_of(id, v).await.ok(),
                        None => None,
                    };
                    let surface = match before {
                        Some(b) if b.inputs.surface_digest() == view.inputs.surface_digest() => {
                            Dirty::Nothing
                        }
                        _ => dirty.clone(),
                    };
                    let _ = tx.send(WorldEdit {
                        view: StreamView { version, view },
                        dirty: dirty.clone(),
                        surface,
                    });
                }
                Err(e) => {
                    tracing::warn!(world = %id, version, "stream sessions miss an edit: {e}")
                }
            }
        }
        // No receivers is not an error: nobody is listening to this process's edits.
        let _ = self.all.send(EditEvent {
            world: id.to_string(),
            version,
            dirty: dirty.clone(),
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;
    use crate::store::{hash_token, new_token, new_world_id, NewWorld};

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
            serde_json::from_value(json!([{ "op": "add", "path": "/regions/-", "value":
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
            let seen = scene["regions"].as_array().map_or(0, Vec::len);
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
}
