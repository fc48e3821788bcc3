//! The world at one version, as every product sees it ([`WorldView`]), and the one preamble of
//! every product route ([`WorldAt`]: access, version, view).
//!
//! A view is a bare seed's default world or a stored world at one version: its plan
//! ([`WorldPlan`]) and what its products' input hashes are made of ([`SceneInputs`]: the parsed
//! scene's authored regions, `strata` and volume regions). Stored worlds' views are built once
//! per `(world, version)` and shared through the view cache of [`super::worlds::Worlds`]; a bare
//! seed's view is made per request on its cached plan (two reference counts). The tile routes,
//! scatter, rivers, chunks, geology, region I/O and stats, volume exports, export jobs and stream
//! sessions all take one. What a tile applies on top of the field is assembled here and nowhere
//! else ([`WorldView::tile_edits`]); the tile itself comes through [`AppState::tile`].

use super::access::Caller;
use super::error::{code, AppError};
use super::http::{authorize, product_headers, query_param, requested_version};
use super::params::parse_seed;
use super::AppState;
use crate::authoring::Displacement;
use crate::edits::TileEdits;
use crate::element::Rect;
use crate::scene::{RegionInput, SceneInputs};
use crate::store::{Role, WorldMeta};
use crate::terrain::{TileKey, WorldPlan};
use axum::extract::{FromRequestParts, RawPathParams};
use axum::http::request::Parts;
use axum::http::StatusCode;
use axum::response::Response;
use std::sync::Arc;

/// A world at one version: a bare seed's default world or a stored world's scene at a version.
#[derive(Debug)]
pub struct WorldView {
    /// The stored world and the version, `None` for a bare seed.
    pub world: Option<(String, u64)>,
    /// The plan of the world's settings and seed.
    pub plan: Arc<WorldPlan>,
    /// The parsed scene's elements and digests.
    pub inputs: Arc<SceneInputs>,
}

impl WorldView {
    /// The view of stored world `id` at `version`.
    pub fn stored(id: &str, version: u64, plan: Arc<WorldPlan>, inputs: Arc<SceneInputs>) -> Self {
        Self {
            world: Some((id.to_owned(), version)),
            plan,
            inputs,
        }
    }

    /// The view of a bare seed's world with `plan`'s settings and no elements.
    pub fn bare(plan: Arc<WorldPlan>) -> Self {
        let inputs = super::bare_inputs(&plan.params);
        Self {
            world: None,
            plan,
            inputs,
        }
    }

    /// The world's seed.
    pub fn seed(&self) -> u64 {
        self.plan.seed
    }

    /// The version of a stored world; 0 for a bare seed.
    pub fn version(&self) -> u64 {
        self.world.as_ref().map_or(0, |w| w.1)
    }

    /// The input hash of tile `key` with `seams`: what keys it in the stage and body caches.
    pub fn tile_hash(&self, key: TileKey, seams: [bool; 4]) -> [u8; 32] {
        self.inputs.tile(self.plan.seed, key, seams)
    }

    /// What tile `key` applies on top of the procedural field: the solved authored regions that
    /// touch it, the `strata` elements that touch it and the volume regions meeting its reach
    /// (the reach, not the footprint: a box touching the tile's edge marks the edge's vertices
    /// in both neighbours, and the reach's elements are in the tile's input hash).
    pub async fn tile_edits(&self, st: &AppState, key: TileKey) -> TileEdits {
        let foot = crate::scene::tile_reach(self.inputs.world(), key);
        let volumes = self
            .inputs
            .volumes_meeting(
                [foot.min[0], f64::MIN, foot.min[1]],
                [foot.max[0], f64::MAX, foot.max[1]],
            )
            .into_iter()
            .map(|v| v.spec)
            .collect();
        TileEdits {
            displacements: self.solved(st, self.inputs.regions_touching(key)).await,
            strata: self.inputs.strata_touching(self.plan.seed, key),
            volumes,
            materials: None,
        }
    }

    /// The solved displacements of `regions` (in their order) from the state's region cache;
    /// a region the solver refused is left out (logged there).
    async fn solved(&self, st: &AppState, regions: Vec<RegionInput>) -> Vec<Arc<Displacement>> {
        let mut out = Vec::with_capacity(regions.len());
        for region in regions {
            if let Some(d) = st
                .regions
                .get(&self.plan, &region, st.compute.offload())
                .await
            {
                out.push(d);
            }
        }
        out
    }

    /// What the tiles `keys` apply, as one set (an export applies it to each of its tiles): the
    /// solved authored regions, `strata` elements and volume regions meeting the union of the
    /// tiles' reaches, in document order like [`WorldView::tile_edits`]. An element that meets
    /// none of a tile's samples changes none of its bits, so each tile equals the tile route's.
    pub async fn edits_over(&self, st: &AppState, keys: &[TileKey]) -> TileEdits {
        let world = self.inputs.world();
        let Some(first) = keys.first() else {
            return TileEdits::default();
        };
        let mut reach = crate::scene::tile_reach(world, *first);
        for key in &keys[1..] {
            let r = crate::scene::tile_reach(world, *key);
            reach.min = [reach.min[0].min(r.min[0]), reach.min[1].min(r.min[1])];
            reach.max = [reach.max[0].max(r.max[0]), reach.max[1].max(r.max[1])];
        }
        let mut edits = self.ground_edits(st, &reach).await;
        edits.volumes = self
            .inputs
            .volumes_meeting(
                [reach.min[0], f64::MIN, reach.min[1]],
                [reach.max[0], f64::MAX, reach.max[1]],
            )
            .into_iter()
            .map(|v| v.spec)
            .collect();
        // The Ptex pages of an export bake with the world's materials. If they cannot be loaded
        // (a store failure) the pages fall back to the default set, and the failure is logged.
        edits.materials = match super::images::world_materials(st, self).await {
            Ok(m) => Some(m),
            Err(e) => {
                tracing::error!("export materials: {}", e.message);
                None
            }
        };
        edits
    }

    /// What the ground of the rectangle `rect` takes from the scene: the solved authored regions
    /// and the `strata` elements meeting it (no volume marks: this is the ground a volume region
    /// is solved over).
    pub async fn ground_edits(&self, st: &AppState, rect: &Rect) -> TileEdits {
        TileEdits {
            displacements: self.solved(st, self.inputs.regions_meeting(rect)).await,
            strata: self.inputs.strata_meeting(self.plan.seed, rect),
            volumes: Vec::new(),
            materials: None,
        }
    }
}

/// The world a product request names, with access checked and its version resolved: the first
/// extractor of every product route.
///
/// On `/v1/seeds/{seed}/…` it is the seed's default world. On `/v1/worlds/{id}/…` the caller
/// must have the read role on the world (404 `world_not_found`, 401 or 403 otherwise) and
/// `?v=N` names the version (the latest without; a version after the latest is 404
/// `version_not_found` naming `v`).
#[derive(Debug)]
pub struct WorldAt {
    /// The view the request is answered from.
    pub view: Arc<WorldView>,
    /// The stored world, its caller and whether `?v=N` pinned the version; `None` for a seed.
    pub stored: Option<Stored>,
}

/// The stored-world part of a [`WorldAt`].
#[derive(Debug)]
pub struct Stored {
    /// The world as the store has it now.
    pub meta: WorldMeta,
    /// Who asked.
    pub caller: Caller,
    /// Whether `?v=N` named the version (the answer is then immutable).
    pub pinned: bool,
}

impl WorldAt {
    /// The view of stored world `id` at the version `query` names, for a caller with `need`.
    pub async fn stored(
        st: &AppState,
        headers: &axum::http::HeaderMap,
        id: &str,
        query: Option<&str>,
        need: Role,
    ) -> Result<Self, AppError> {
        let (meta, caller) = authorize(st, headers, id, need).await?;
        let version = requested_version(&meta, query)?;
        let pinned = query_param(query, "v").is_some();
        let view = st.worlds.view(&meta, version).await?;
        Ok(Self {
            view,
            stored: Some(Stored {
                meta,
                caller,
                pinned,
            }),
        })
    }

    /// The default world of `seed`.
    pub async fn seed(st: &AppState, seed: u64) -> Result<Self, AppError> {
        Ok(Self {
            view: st.bare_view(seed).await?,
            stored: None,
        })
    }

    /// The answer `res` with the caching headers of this world's products: a stored world's
    /// version header and `Cache-Control` (immutable when pinned, short-lived otherwise,
    /// private unless the world is public); a seed's answer is left as it is (immutable).
    pub fn finish(&self, mut res: Response) -> Response {
        if let Some(s) = &self.stored {
            product_headers(&mut res, &s.meta, self.view.version(), s.pinned);
        }
        res
    }
}

impl FromRequestParts<AppState> for WorldAt {
    type Rejection = AppError;

    async fn from_request_parts(parts: &mut Parts, st: &AppState) -> Result<Self, AppError> {
        let params = RawPathParams::from_request_parts(parts, st)
            .await
            .map_err(|e| {
                AppError::new(
                    StatusCode::BAD_REQUEST,
                    code::BAD_PATH,
                    format!("invalid path: {e}"),
                )
            })?;
        let param = |name: &str| {
            params
                .iter()
                .find(|(k, _)| *k == name)
                .map(|(_, v)| v.to_owned())
        };
        if let Some(id) = param("id") {
            let query = parts.uri.query().map(str::to_owned);
            return Self::stored(st, &parts.headers, &id, query.as_deref(), Role::Read).await;
        }
        match param("seed") {
            Some(seed) => Self::seed(st, parse_seed(&seed)?).await,
            None => Err(AppError::internal("a product route without {seed} or {id}")),
        }
    }
}
