//! A stream session's Ptex pages (protocol v2, `api/stream_protocol_v2.md`, "Ptex pages"): the
//! level-of-detail budget of [`crate::ptex::budget`] driven by the client's views.
//!
//! A v2 client opts in with a `ptex` object in its view (its view direction, cone and far
//! distance). From then on:
//!
//! - every face of every tile the session sends ([`TILE_FACES`]² per tile) is **held**: it gets
//!   an index (reused once its tile leaves the view) and a vista page of 8² texels, baked nearest
//!   tile first; a face whose vista page would not fit the session's budget is not held (the
//!   client is told once, with an `error`);
//! - each **update** (before a batch is produced, when a view or new face bounds arrived since
//!   the last) classifies the held faces whose vista page has been baked (their bounds come from
//!   their samples) by frustum and distance with the budget's thresholds: detail pages are queued
//!   nearest face first (by the distance from the eye to the face's bounding sphere; ties:
//!   higher level first, then face index), and faces that left their detail level are announced
//!   in a `ptex` message;
//! - pages are baked in **batches** of one level, at most [`BATCH_PAGES`] pages and
//!   [`BATCH_TEXELS`] interior texels each (one 256² page), one frame of kind 3 each: the level
//!   and kind of the nearest queued page, then the next queued pages of that level and kind in
//!   queue order (the others wait for later batches); vista and detail batches alternate
//!   while both kinds of page wait; the session interleaves them with tile and chunk frames,
//!   at most one batch per [`PTEX_EVERY`] frames while tiles or chunks wait, every frame
//!   spending a credit;
//! - an **edit** queues again the vista and detail pages of exactly the faces whose reach (the
//!   face's footprint grown by its tile's input margin and one lattice cell, which its border
//!   texels read from the neighbours) meets the dirty region;
//! - with `chunks: true` in the view's `ptex`, the faces of the volume chunks the session sends
//!   (one per surface-nets quad, [`crate::ptex::face::chunk_faces`]) are held too, in the same
//!   budget and by the same rules, from the chunk frame on ([`PtexSession::hold_chunk`]); a
//!   chunk sent again (an edit touched it) queues its faces' pages again, all of them, as its
//!   quads may have changed (a new quad count releases the old faces and holds the new ones).
//!   A chunk's face holds detail levels up to [`CHUNK_FACE_MAX_LEVEL`] (16²) only.
//!   A batch holds faces of one kind, tile or chunk (their frames' records differ).
//!
//! Each session's budget is granted from the server's ([`PtexPool`]) when the client opts in and
//! given back when the session ends or a view leaves `ptex` out.

use crate::ptex::budget::{
    sphere_distance, Bake, Budget, BudgetConfig, FaceBounds, View, LEVEL_RES,
};
use crate::ptex::face::{ChunkFaceKey, TileFaceKey, TILE_FACES};
use crate::scene::{margin_m, Rect};
use crate::terrain::{TileKey, WorldParams};
use crate::volume::chunk::ChunkKey;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeSet, HashMap, VecDeque};
use std::sync::{Arc, Mutex};

/// Most pages in one batch (one frame).
pub const BATCH_PAGES: usize = 256;
/// Most interior texels in one batch: one 256² page, four 128² pages, …
pub const BATCH_TEXELS: u64 = 1 << 16;
/// While tiles or chunks wait, at most one Ptex batch per this many frames.
pub const PTEX_EVERY: u32 = 4;
/// Default budget of one session's pages, MiB.
pub const DEFAULT_SESSION_BUDGET_MB: u64 = 64;
/// Default budget of all sessions' pages on one server, MiB.
pub const DEFAULT_SERVER_BUDGET_MB: u64 = 1024;
/// Default distance thresholds of the detail levels 16² … 256², metres: a face may hold level
/// `l` only nearer than `thresholds_m[l − 1]`.
pub const DEFAULT_THRESHOLDS_M: [f32; 5] = [2048.0, 1024.0, 512.0, 256.0, 128.0];
/// The finest detail level of a volume chunk's face (16²): a surface-nets quad is one lattice
/// cell, and 16 texels a cell is the density of a tile face's finest page (256² over 16 cells).
/// A finer page would spend a tile face's worth of texels on one cell, and the near chunks'
/// quads would take the finest levels' few slots from the ground around them.
pub const CHUNK_FACE_MAX_LEVEL: u8 = 1;
/// Largest `far_m` of a view's `ptex`, metres.
pub const MAX_FAR_M: f64 = 65_536.0;

/// The server's Ptex settings (`strata serve --ptex-session-budget`, `--ptex-server-budget`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PtexSettings {
    /// Bytes of pages one session may hold.
    pub session_bytes: u64,
    /// Bytes of pages all sessions together may hold.
    pub server_bytes: u64,
    /// Distance thresholds of the detail levels, metres.
    pub thresholds_m: [f32; 5],
}

impl Default for PtexSettings {
    fn default() -> Self {
        Self {
            session_bytes: DEFAULT_SESSION_BUDGET_MB << 20,
            server_bytes: DEFAULT_SERVER_BUDGET_MB << 20,
            thresholds_m: DEFAULT_THRESHOLDS_M,
        }
    }
}

/// The server's budget of pages, granted to sessions whole.
#[derive(Debug)]
pub struct PtexPool {
    settings: PtexSettings,
    free: Mutex<u64>,
}

impl PtexPool {
    /// A pool of `settings.server_bytes`.
    pub fn new(settings: PtexSettings) -> Self {
        Self {
            settings,
            free: Mutex::new(settings.server_bytes),
        }
    }

    /// The settings.
    pub fn settings(&self) -> PtexSettings {
        self.settings
    }

    /// Bytes not granted now.
    pub fn free_bytes(&self) -> u64 {
        *self.free.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// A session's budget, or `None` when the server's has less left.
    pub fn grant(self: &Arc<Self>) -> Option<PtexGrant> {
        let want = self.settings.session_bytes;
        let mut free = self.free.lock().unwrap_or_else(|e| e.into_inner());
        if *free < want {
            return None;
        }
        *free -= want;
        Some(PtexGrant {
            pool: self.clone(),
            bytes: want,
        })
    }
}

/// A session's share of the server's budget, given back when dropped.
#[derive(Debug)]
pub struct PtexGrant {
    pool: Arc<PtexPool>,
    bytes: u64,
}

impl PtexGrant {
    /// Bytes granted.
    pub fn bytes(&self) -> u64 {
        self.bytes
    }
}

impl Drop for PtexGrant {
    fn drop(&mut self) {
        *self.pool.free.lock().unwrap_or_else(|e| e.into_inner()) += self.bytes;
    }
}

/// The `ptex` object of a v2 view: the client wants pages, and how it looks.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PtexView {
    /// View direction `[x, y, z]` (any length but zero).
    pub forward: [f64; 3],
    /// Half angle of the view cone, degrees, in `(0, 90]` (default 45).
    #[serde(default = "default_half_angle")]
    pub half_angle_deg: f64,
    /// Far distance, metres, in `(0, MAX_FAR_M]` (default 8192).
    #[serde(default = "default_far")]
    pub far_m: f64,
    /// Whether the faces of the session's volume chunks get pages too (default false: a client
    /// that does not ask gets tile faces only, as before chunk pages existed).
    #[serde(default)]
    pub chunks: bool,
}

fn default_half_angle() -> f64 {
    45.0
}

fn default_far() -> f64 {
    8192.0
}

impl PtexView {
    /// The budget's view from the camera at `eye`, or the field to blame and why.
    pub fn view(&self, eye: [f64; 3]) -> Result<View, (&'static str, String)> {
        let f = self.forward;
        let len = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
        if !len.is_finite() || len == 0.0 {
            return Err((
                "forward",
                "forward must be a finite, non-zero vector".into(),
            ));
        }
        if !(self.half_angle_deg > 0.0 && self.half_angle_deg <= 90.0) {
            return Err(("half_angle_deg", "half_angle_deg must be in (0, 90]".into()));
        }
        if !(self.far_m > 0.0 && self.far_m <= MAX_FAR_M) {
            return Err(("far_m", format!("far_m must be in (0, {MAX_FAR_M}]")));
        }
        Ok(View {
            eye: eye.map(|c| c as f32),
            forward: f.map(|c| (c / len) as f32),
            cos_half_angle: self.half_angle_deg.to_radians().cos() as f32,
            far_m: self.far_m as f32,
        })
    }
}

/// A face a session holds: a height tile's or a volume chunk's.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PageFace {
    /// A face of a height tile's 4 × 4 grid.
    Tile(TileFaceKey),
    /// A surface-nets quad of a volume chunk.
    Chunk(ChunkFaceKey),
}

impl PageFace {
    /// Whether this is a chunk's face.
    pub fn is_chunk(self) -> bool {
        matches!(self, PageFace::Chunk(_))
    }

    /// How the `ptex` message names the face: `[lod, fx, fz]` for a tile's, `[lod, x, y, z,
    /// quad]` for a chunk's.
    pub fn address(self) -> Vec<i64> {
        match self {
            PageFace::Tile(f) => vec![i64::from(f.lod), f.fx, f.fz],
            PageFace::Chunk(f) => {
                let c = f.chunk;
                vec![i64::from(c.lod), c.x, c.y, c.z, i64::from(f.quad)]
            }
        }
    }
}

/// One page of a batch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BatchPage {
    /// The session's index of the face.
    pub index: u32,
    /// The face.
    pub face: PageFace,
    /// Its tile's seam flags `n, e, s, w` (a chunk face: none).
    pub seams: [bool; 4],
    /// Layer of the level's texture array (the face's index at the vista level).
    pub slot: u32,
}

/// Pages of one level and one kind of face to bake into one frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PtexBatch {
    /// Level, 0 (vista) … 5.
    pub level: u8,
    /// The pages: all tile faces or all chunk faces.
    pub pages: Vec<BatchPage>,
}

impl PtexBatch {
    /// The pages' resolution.
    pub fn res(&self) -> u32 {
        LEVEL_RES[self.level as usize]
    }
}

/// A baked batch: the frame and the bounds of each page's face (from its samples).
#[derive(Clone, Debug)]
pub struct PtexBaked {
    /// The frame of kind 3 ([`super::ptex_frame`]).
    pub bytes: axum::body::Bytes,
    /// Each page's face's bounding sphere.
    pub bounds: Vec<FaceBounds>,
}

/// The `ptex` message: the session's budget now, and the faces back at the vista level.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PtexMessage {
    /// Always `"ptex"`.
    #[serde(rename = "type")]
    pub kind: &'static str,
    /// The session's budget, bytes.
    pub budget_bytes: u64,
    /// Bytes of the pages the client holds once the queued ones arrive.
    pub held_bytes: u64,
    /// Faces held (each with a vista page).
    pub faces: usize,
    /// Slots of the detail levels 16² … 256².
    pub capacity: [usize; 5],
    /// The faces that left their detail level (their slot is free): `[lod, fx, fz]` for a tile's
    /// face, `[lod, x, y, z, quad]` for a chunk's.
    pub to_vista: Vec<Vec<i64>>,
}

#[derive(Clone, Copy, Debug)]
struct Held {
    key: PageFace,
    seams: [bool; 4],
    bounds: Option<FaceBounds>,
}

/// One session's Ptex state.
#[derive(Debug)]
pub struct PtexSession {
    grant: PtexGrant,
    budget: Budget,
    faces: Vec<Option<Held>>,
    index: HashMap<PageFace, u32>,
    /// The faces' indices of each held chunk, in quad order.
    chunks: HashMap<ChunkKey, Vec<u32>>,
    /// Whether the client asked for chunk faces' pages.
    chunk_pages: bool,
    free: BTreeSet<u32>,
    view: Option<View>,
    due: bool,
    vista: VecDeque<u32>,
    detail: Vec<Bake>,
    /// Whether the next batch is a detail batch when both vista and detail pages wait (they
    /// alternate).
    detail_turn: bool,
    announced: Option<[usize; 5]>,
    refused: bool,
}

impl PtexSession {
    /// A session with `grant` bytes and the detail levels' `thresholds_m`.
    pub fn new(grant: PtexGrant, thresholds_m: [f32; 5]) -> Self {
        let config = BudgetConfig {
            bytes: grant.bytes(),
            thresholds_m,
        };
        let budget = Budget::empty(config);
        Self {
            grant,
            budget,
            faces: Vec::new(),
            index: HashMap::new(),
            chunks: HashMap::new(),
            chunk_pages: false,
            free: BTreeSet::new(),
            view: None,
            due: false,
            vista: VecDeque::new(),
            detail: Vec::new(),
            detail_turn: false,
            announced: None,
            refused: false,
        }
    }

    /// The budget (for tests and metrics).
    pub fn budget(&self) -> &Budget {
        &self.budget
    }

    /// The client's new view; `chunks`: whether it wants chunk faces' pages (turning them off
    /// releases the chunk faces held).
    pub fn set_view(&mut self, view: View, chunks: bool) {
        self.view = Some(view);
        self.due = true;
        if self.chunk_pages && !chunks {
            self.retain(|f| !f.is_chunk());
        }
        self.chunk_pages = chunks;
    }

    /// Whether the client asked for chunk faces' pages.
    pub fn chunk_pages(&self) -> bool {
        self.chunk_pages
    }

    /// Holds a new face: its index and vista page, or false when it does not fit the budget. A
    /// chunk's face is held up to [`CHUNK_FACE_MAX_LEVEL`].
    fn hold_new(&mut self, face: PageFace, seams: [bool; 4]) -> Option<u32> {
        let i = self.free.pop_first().unwrap_or(self.faces.len() as u32);
        let max = if face.is_chunk() {
            CHUNK_FACE_MAX_LEVEL
        } else {
            5
        };
        if self.budget.hold_up_to(i as usize, max).is_err() {
            self.free.insert(i);
            return None;
        }
        if i as usize >= self.faces.len() {
            self.faces.resize(i as usize + 1, None);
        }
        self.faces[i as usize] = Some(Held {
            key: face,
            seams,
            bounds: None,
        });
        self.index.insert(face, i);
        self.vista.push_back(i);
        Some(i)
    }

    /// Notes, once per session, that a face did not fit: true unless this is the first time.
    fn refuse(&mut self, fits: bool) -> bool {
        let refused_now = !fits && !self.refused;
        self.refused |= !fits;
        !refused_now
    }

    /// Holds the `quads` faces of chunk `key`, just sent (or sent again): a chunk held with as
    /// many faces queues all their pages again, one held with another count releases them and
    /// holds the new ones. Does nothing unless the client asked for chunk pages. Returns false,
    /// once per session, when a face did not fit the budget.
    pub fn hold_chunk(&mut self, key: ChunkKey, quads: u32) -> bool {
        if !self.chunk_pages {
            return true;
        }
        if let Some(held) = self.chunks.get(&key) {
            if held.len() == quads as usize {
                let held = held.clone();
                self.requeue(&held);
                self.due = true;
                return true;
            }
            self.retain(|f| !matches!(f, PageFace::Chunk(c) if c.chunk == key));
        }
        let mut fits = true;
        let mut held = Vec::with_capacity(quads as usize);
        for quad in 0..quads {
            match self.hold_new(
                PageFace::Chunk(ChunkFaceKey { chunk: key, quad }),
                [false; 4],
            ) {
                Some(i) => held.push(i),
                None => {
                    fits = false;
                    break;
                }
            }
        }
        // A chunk whose faces did not all fit holds none: a client draws a chunk's pages only
        // with every face's.
        if fits {
            self.chunks.insert(key, held);
        } else {
            for i in held {
                self.release(i);
            }
            let faces = &self.faces;
            self.vista
                .retain(|&i| faces.get(i as usize).is_some_and(Option::is_some));
        }
        self.due = true;
        self.refuse(fits)
    }

    /// Holds the faces of tile `key` drawn with `seams` (a face already held with other seams is
    /// baked again). Returns false, once per session, when a face did not fit the budget.
    pub fn hold_tile(&mut self, key: TileKey, seams: [bool; 4]) -> bool {
        let t = TILE_FACES as i64;
        let mut fits = true;
        for id in 0..t * t {
            let face = TileFaceKey {
                lod: key.lod,
                fx: key.x * t + id % t,
                fz: key.z * t + id / t,
            };
            if let Some(&i) = self.index.get(&PageFace::Tile(face)) {
                let redrawn = match self.faces[i as usize].as_mut() {
                    Some(h) if h.seams != seams => {
                        h.seams = seams;
                        true
                    }
                    _ => false,
                };
                if redrawn {
                    self.requeue(&[i]);
                }
                continue;
            }
            if self.hold_new(PageFace::Tile(face), seams).is_none() {
                fits = false;
            }
        }
        self.due = true;
        self.refuse(fits)
    }

    /// Releases face `i`.
    fn release(&mut self, i: u32) {
        let Some(h) = self.faces.get(i as usize).copied().flatten() else {
            return;
        };
        self.budget.release(i as usize);
        self.index.remove(&h.key);
        self.faces[i as usize] = None;
        self.free.insert(i);
        self.due = true;
    }

    /// Releases the faces `keep` rejects.
    fn retain(&mut self, keep: impl Fn(PageFace) -> bool) {
        let gone: Vec<u32> = self
            .index
            .iter()
            .filter(|(f, _)| !keep(**f))
            .map(|(_, i)| *i)
            .collect();
        for i in gone {
            self.release(i);
        }
        let faces = &self.faces;
        // A chunk's faces are released together: its first tells.
        self.chunks.retain(|c, held| {
            held.first().is_some_and(|&i| {
                matches!(faces.get(i as usize).copied().flatten(),
                    Some(Held { key: PageFace::Chunk(f), .. }) if f.chunk == *c)
            })
        });
        self.vista
            .retain(|&i| faces.get(i as usize).is_some_and(Option::is_some));
    }

    /// Releases the faces of the tiles `tile` rejects and of the chunks `chunk` rejects (they
    /// left the view).
    pub fn retain_products(
        &mut self,
        tile: impl Fn(TileKey) -> bool,
        chunk: impl Fn(ChunkKey) -> bool,
    ) {
        self.retain(|f| match f {
            PageFace::Tile(t) => tile(t.tile()),
            PageFace::Chunk(c) => chunk(c.chunk),
        });
    }

    /// Queues again the pages of the held tile faces `touched` accepts (chunk faces are queued
    /// again when their chunk is sent again, [`PtexSession::hold_chunk`]); returns how many faces.
    pub fn invalidate(&mut self, touched: impl Fn(TileFaceKey) -> bool) -> usize {
        let mut hit: Vec<u32> = self
            .index
            .iter()
            .filter(|(f, _)| matches!(f, PageFace::Tile(t) if touched(*t)))
            .map(|(_, i)| *i)
            .collect();
        hit.sort_unstable();
        self.requeue(&hit);
        hit.len()
    }

    fn requeue(&mut self, faces: &[u32]) {
        let bakes = self.budget.invalidate(faces);
        let set: BTreeSet<u32> = faces.iter().copied().collect();
        self.vista.retain(|f| !set.contains(f));
        self.detail.retain(|b| !set.contains(&b.face));
        for b in bakes.iter().rev() {
            if b.level == 0 {
                self.vista.push_front(b.face);
            }
        }
        self.detail.extend(bakes.iter().filter(|b| b.level > 0));
        self.sort_detail();
    }

    /// Sorts the detail queue nearest face first (the distance from the eye to the face's
    /// bounding sphere; faces without bounds, or all of them without a view, last), ties by
    /// level, highest first, then face index, and drops repeated pages.
    fn sort_detail(&mut self) {
        let (faces, view) = (&self.faces, self.view);
        let distance = |face: u32| -> f32 {
            let bounds = faces
                .get(face as usize)
                .copied()
                .flatten()
                .and_then(|h| h.bounds);
            match (bounds, view) {
                (Some(b), Some(v)) => sphere_distance(&b, v.eye).0,
                _ => f32::INFINITY,
            }
        };
        // Distances are at least 0, where the bits of an f32 order as the numbers do.
        self.detail.sort_by_cached_key(|b| {
            (
                distance(b.face).to_bits(),
                std::cmp::Reverse(b.level),
                b.face,
                b.slot,
            )
        });
        self.detail.dedup();
    }

    /// The pages queued now and their interior texels: the vista pages of held faces and the
    /// detail pages whose face still holds that level and slot (what later batches bake).
    pub fn queued(&self) -> (usize, u64) {
        let vista = self
            .vista
            .iter()
            .filter(|&&i| self.faces.get(i as usize).is_some_and(Option::is_some))
            .count();
        let texels = |level: u8| u64::from(LEVEL_RES[level as usize]).pow(2);
        self.detail
            .iter()
            .filter(|b| self.current(b))
            .fold((vista, vista as u64 * texels(0)), |(n, t), b| {
                (n + 1, t + texels(b.level))
            })
    }

    /// Whether detail page `b` is still its face's: held at that level in that slot.
    fn current(&self, b: &Bake) -> bool {
        self.budget.is_held(b.face as usize)
            && self.budget.level(b.face as usize) == b.level
            && self.budget.slot(b.face as usize) == Some(b.slot)
    }

    /// Whether an update or a batch may be due.
    pub fn has_work(&self) -> bool {
        (self.due && self.view.is_some()) || !self.vista.is_empty() || !self.detail.is_empty()
    }

    /// Runs the update if one is due and takes the next batch: the `ptex` message to send first
    /// (when faces left their detail level or the slot counts changed), and the batch.
    pub fn next_batch(&mut self) -> (Option<PtexMessage>, Option<PtexBatch>) {
        let mut message = None;
        if self.due {
            if let Some(view) = self.view {
                self.due = false;
                let faces = &self.faces;
                let update = self.budget.update_with(
                    |f| faces.get(f).copied().flatten().and_then(|h| h.bounds),
                    &view,
                );
                let changed: BTreeSet<u32> = update.bake.iter().map(|b| b.face).collect();
                self.detail
                    .retain(|b| !changed.contains(&b.face) && !update.to_vista.contains(&b.face));
                self.detail.extend(update.bake.iter().copied());
                self.sort_detail();
                let capacity = self.budget.capacity();
                if !update.to_vista.is_empty() || self.announced != Some(capacity) {
                    self.announced = Some(capacity);
                    message = Some(self.message(&update.to_vista));
                }
            }
        }
        (message, self.take_batch())
    }

    fn message(&self, to_vista: &[u32]) -> PtexMessage {
        PtexMessage {
            kind: "ptex",
            budget_bytes: self.grant.bytes(),
            held_bytes: self.budget.bytes_held(),
            faces: self.budget.held(),
            capacity: self.budget.capacity(),
            to_vista: to_vista
                .iter()
                .filter_map(|&f| self.faces.get(f as usize).copied().flatten())
                .map(|h| h.key.address())
                .collect(),
        }
    }

    fn page(&self, index: u32, slot: u32) -> Option<BatchPage> {
        let h = self.faces.get(index as usize).copied().flatten()?;
        Some(BatchPage {
            index,
            face: h.key,
            seams: h.seams,
            slot,
        })
    }

    /// The next batch: vista and detail batches alternate while both kinds of page wait, so a
    /// client still receiving its far tiles' vista pages gets the nearest faces' detail pages
    /// meanwhile (vista first would leave the faces under the camera at 8² until every tile of
    /// the view had arrived, minutes for a client that renders at a few frames a second).
    fn take_batch(&mut self) -> Option<PtexBatch> {
        let batch = if self.detail_turn {
            self.take_detail().or_else(|| self.take_vista())
        } else {
            self.take_vista().or_else(|| self.take_detail())
        };
        if let Some(b) = &batch {
            self.detail_turn = b.level == 0;
        }
        batch
    }

    /// A batch of queued vista pages, in queue order, of one kind of face.
    fn take_vista(&mut self) -> Option<PtexBatch> {
        let mut pages: Vec<BatchPage> = Vec::new();
        while pages.len() < BATCH_PAGES {
            let Some(&i) = self.vista.front() else {
                break;
            };
            let Some(p) = self.page(i, i) else {
                self.vista.pop_front();
                continue;
            };
            if pages
                .first()
                .is_some_and(|q| q.face.is_chunk() != p.face.is_chunk())
            {
                break;
            }
            self.vista.pop_front();
            pages.push(p);
        }
        (!pages.is_empty()).then_some(PtexBatch { level: 0, pages })
    }

    /// A batch of queued detail pages: the nearest current page sets the batch's level and
    /// kind; later pages of another level or kind keep their place in the queue, pages no
    /// longer their face's are dropped.
    fn take_detail(&mut self) -> Option<PtexBatch> {
        let mut pages: Vec<BatchPage> = Vec::new();
        let mut level = 0u8;
        let mut chunk = None;
        let mut texels = 0u64;
        let mut full = false;
        let mut waiting = Vec::with_capacity(self.detail.len());
        for b in std::mem::take(&mut self.detail) {
            if full {
                waiting.push(b);
                continue;
            }
            if !self.current(&b) {
                continue;
            }
            let Some(p) = self.page(b.face, b.slot) else {
                continue;
            };
            let res = u64::from(LEVEL_RES[b.level as usize]);
            if level == 0 {
                level = b.level;
            }
            let kind = *chunk.get_or_insert(p.face.is_chunk());
            if b.level != level || kind != p.face.is_chunk() {
                waiting.push(b);
                continue;
            }
            if texels + res * res > BATCH_TEXELS || pages.len() >= BATCH_PAGES {
                full = true;
                waiting.push(b);
                continue;
            }
            texels += res * res;
            pages.push(p);
        }
        self.detail = waiting;
        (!pages.is_empty()).then_some(PtexBatch { level, pages })
    }

    /// Takes the bounds of a baked batch's faces (those still held by the same face).
    pub fn baked(&mut self, batch: &PtexBatch, bounds: &[FaceBounds]) {
        for (p, b) in batch.pages.iter().zip(bounds) {
            if let Some(Some(h)) = self.faces.get_mut(p.index as usize) {
                if h.key == p.face && h.bounds != Some(*b) {
                    h.bounds = Some(*b);
                    self.due = true;
                }
            }
        }
    }

    /// The message announcing the session's budget (sent when the client opts in).
    pub fn hello(&mut self) -> PtexMessage {
        self.announced = Some(self.budget.capacity());
        self.message(&[])
    }
}

/// The number of quads of a chunk frame's chunk (`api/chunk_format_v1.md`: `Q` of the `bin`
/// header, `quad_count` of the `json` document and of the `glb` node's `extras`), or `None` for
/// a frame it cannot read.
pub fn chunk_frame_quads(frame: &[u8]) -> Option<u32> {
    use super::protocol::FRAME_HEADER_BYTES;
    let payload = frame.get(FRAME_HEADER_BYTES..)?;
    let u32_at = |b: &[u8], o: usize| -> Option<u32> {
        Some(u32::from_le_bytes(b.get(o..o + 4)?.try_into().ok()?))
    };
    let from_json = |doc: &serde_json::Value| {
        doc.get("quad_count")
            .and_then(serde_json::Value::as_u64)
            .and_then(|q| u32::try_from(q).ok())
    };
    match payload.get(..4)? {
        b"STCK" => u32_at(payload, 84),
        b"glTF" => {
            // The JSON chunk follows the 12-byte header: its length, its type, the document.
            let len = u32_at(payload, 12)? as usize;
            let doc: serde_json::Value = serde_json::from_slice(payload.get(20..20 + len)?).ok()?;
            let extras = doc.get("nodes")?.get(0)?.get("extras")?;
            from_json(extras)
        }
        _ => from_json(&serde_json::from_slice(payload).ok()?),
    }
}

/// The ground rectangle whose edits may change face `f`'s pages: its footprint grown by its
/// tile's input margin and one lattice cell (its border texels read the neighbours' samples
/// next to the edge).
pub fn face_reach(world: &WorldParams, f: TileFaceKey) -> Rect {
    let cell = f64::from(world.cell_m) * (1u64 << f.lod.min(62)) as f64;
    let size = cell * crate::ptex::TILE_FACE_CELLS as f64;
    let m = margin_m(world, f.lod) + cell;
    Rect {
        min: [f.fx as f64 * size - m, f.fz as f64 * size - m],
        max: [(f.fx + 1) as f64 * size + m, (f.fz + 1) as f64 * size + m],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A session with the default settings, looking straight down from `eye` (metres), that
    /// holds LOD-0 tiles (0, 0) and (1, 0).
    fn session_over_two_tiles(eye: [f32; 3]) -> PtexSession {
        let settings = PtexSettings::default();
        let pool = Arc::new(PtexPool::new(settings));
        let grant = pool.grant().expect("grant");
        let mut session = PtexSession::new(grant, settings.thresholds_m);
        let view = View {
            eye,
            forward: [0.0, -1.0, 0.0],
            cos_half_angle: 0.5,
            far_m: 4000.0,
        };
        session.set_view(view, false);
        for x in 0..2 {
            session.hold_tile(TileKey { lod: 0, x, z: 0 }, [false; 4]);
        }
        session
    }

    /// The bounds of a page's face of [`session_over_two_tiles`] (16 m faces on the ground).
    fn bounds(p: &BatchPage) -> FaceBounds {
        match p.face {
            PageFace::Tile(f) => FaceBounds {
                centre: [f.fx as f32 * 16.0 + 8.0, 0.0, f.fz as f32 * 16.0 + 8.0],
                radius: 11.4,
            },
            PageFace::Chunk(_) => unreachable!("no chunk faces held"),
        }
    }

    #[test]
    fn the_queued_pages_are_what_the_later_batches_bake() {
        let mut session = session_over_two_tiles([8.0, 40.0, 8.0]);
        assert_eq!(session.queued(), (32, 32 * 64));
        let (mut pages, mut texels, mut first) = (0usize, 0u64, None);
        while let (_, Some(batch)) = session.next_batch() {
            let bounds: Vec<FaceBounds> = batch.pages.iter().map(bounds).collect();
            session.baked(&batch, &bounds);
            if batch.level == 0 {
                assert_eq!(batch.pages.len(), 32, "every vista page in one batch");
                continue;
            }
            // The first update after the vista pages queued every detail page at once.
            first.get_or_insert_with(|| {
                let (n, t) = session.queued();
                (
                    n + batch.pages.len(),
                    t + u64::from(batch.res().pow(2)) * batch.pages.len() as u64,
                )
            });
            pages += batch.pages.len();
            texels += u64::from(batch.res().pow(2)) * batch.pages.len() as u64;
        }
        assert!(pages > 0, "faces under the eye take detail levels");
        assert_eq!(first, Some((pages, texels)));
        assert_eq!(session.queued(), (0, 0));
    }

    #[test]
    fn detail_batches_alternate_with_vista_batches_while_both_wait() {
        // The eye 20 m above face (7, 3): once the first vista batch gave the bounds, the
        // nearest faces' detail pages are queued; then 40 more tiles arrive (640 vista pages,
        // three batches). The detail pages do not wait for them: batches alternate.
        let mut session = session_over_two_tiles([7.0 * 16.0 + 8.0, 20.0, 3.0 * 16.0 + 8.0]);
        let (_, first) = session.next_batch();
        let first = first.expect("the vista batch of the first two tiles");
        assert_eq!((first.level, first.pages.len()), (0, 32));
        let b: Vec<FaceBounds> = first.pages.iter().map(bounds).collect();
        session.baked(&first, &b);
        for x in 2..42 {
            session.hold_tile(TileKey { lod: 0, x, z: 0 }, [false; 4]);
        }
        let mut levels = Vec::new();
        let mut vista_pages = 0;
        while let (_, Some(batch)) = session.next_batch() {
            let b: Vec<FaceBounds> = batch.pages.iter().map(bounds).collect();
            session.baked(&batch, &b);
            if batch.level == 0 {
                vista_pages += batch.pages.len();
            }
            levels.push(batch.level);
        }
        assert_eq!(vista_pages, 640, "every new face's vista page");
        assert_eq!(
            levels[0], 5,
            "the nearest face's 256² page first: {levels:?}"
        );
        // While vista pages waited (the first five batches at least), every other batch was a
        // detail batch.
        let last_vista = levels.iter().rposition(|&l| l == 0).expect("vista batches");
        for (k, l) in levels[..=last_vista].iter().enumerate() {
            assert_eq!(*l == 0, k % 2 == 1, "batch {k} in {levels:?}");
        }
    }

    #[test]
    fn the_first_detail_batch_holds_the_nearest_queued_face() {
        // The eye 20 m above the centre of face (7, 3), the last of the two tiles' faces: the
        // 256² level holds several faces of lower index, and its batch holds one page.
        let mut session = session_over_two_tiles([7.0 * 16.0 + 8.0, 20.0, 3.0 * 16.0 + 8.0]);
        let mut first = None;
        while let (_, Some(batch)) = session.next_batch() {
            let b: Vec<FaceBounds> = batch.pages.iter().map(bounds).collect();
            session.baked(&batch, &b);
            if batch.level > 0 {
                first = Some(batch);
                break;
            }
        }
        let first = first.expect("a detail batch");
        assert_eq!(first.level, 5, "the nearest face holds 256²");
        let faces: Vec<PageFace> = first.pages.iter().map(|p| p.face).collect();
        let nearest = PageFace::Tile(TileFaceKey {
            lod: 0,
            fx: 7,
            fz: 3,
        });
        assert_eq!(faces, [nearest]);
    }
}
