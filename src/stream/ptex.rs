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
//!   highest level first, and faces that left their detail level are announced in a `ptex`
//!   message;
//! - pages are baked in **batches** of one level, at most [`BATCH_PAGES`] pages and
//!   [`BATCH_TEXELS`] interior texels each (one 256² page), one frame of kind 3 each; the session
//!   interleaves them with tile and chunk frames, at most one batch per [`PTEX_EVERY`] frames
//!   while tiles or chunks wait, every frame spending a credit;
//! - an **edit** queues again the vista and detail pages of exactly the faces whose reach (the
//!   face's footprint grown by its tile's input margin and one lattice cell, which its border
//!   texels read from the neighbours) meets the dirty region.
//!
//! Each session's budget is granted from the server's ([`PtexPool`]) when the client opts in and
//! given back when the session ends or a view leaves `ptex` out.

use crate::ptex::budget::{Bake, Budget, BudgetConfig, FaceBounds, View, LEVEL_RES};
use crate::ptex::face::{TileFaceKey, TILE_FACES};
use crate::scene::{margin_m, Rect};
use crate::terrain::{TileKey, WorldParams};
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

/// One page of a batch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BatchPage {
    /// The session's index of the face.
    pub index: u32,
    /// The face.
    pub face: TileFaceKey,
    /// Its tile's seam flags `n, e, s, w`.
    pub seams: [bool; 4],
    /// Layer of the level's texture array (the face's index at the vista level).
    pub slot: u32,
}

/// Pages of one level to bake into one frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PtexBatch {
    /// Level, 0 (vista) … 5.
    pub level: u8,
    /// The pages.
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
    /// `[lod, fx, fz]` of the faces that left their detail level (their slot is free).
    pub to_vista: Vec<[i64; 3]>,
}

#[derive(Clone, Copy, Debug)]
struct Held {
    key: TileFaceKey,
    seams: [bool; 4],
    bounds: Option<FaceBounds>,
}

/// One session's Ptex state.
#[derive(Debug)]
pub struct PtexSession {
    grant: PtexGrant,
    budget: Budget,
    faces: Vec<Option<Held>>,
    index: HashMap<TileFaceKey, u32>,
    free: BTreeSet<u32>,
    view: Option<View>,
    due: bool,
    vista: VecDeque<u32>,
    detail: Vec<Bake>,
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
            free: BTreeSet::new(),
            view: None,
            due: false,
            vista: VecDeque::new(),
            detail: Vec::new(),
            announced: None,
            refused: false,
        }
    }

    /// The budget (for tests and metrics).
    pub fn budget(&self) -> &Budget {
        &self.budget
    }

    /// The client's new view.
    pub fn set_view(&mut self, view: View) {
        self.view = Some(view);
        self.due = true;
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
            if let Some(&i) = self.index.get(&face) {
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
            let i = self.free.pop_first().unwrap_or(self.faces.len() as u32);
            if self.budget.hold(i as usize).is_err() {
                self.free.insert(i);
                fits = false;
                continue;
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
        }
        self.due = true;
        let refused_now = !fits && !self.refused;
        self.refused |= !fits;
        !refused_now
    }

    /// Releases the faces of the tiles `keep` rejects (they left the view).
    pub fn retain_tiles(&mut self, keep: impl Fn(TileKey) -> bool) {
        let gone: Vec<(TileFaceKey, u32)> = self
            .index
            .iter()
            .filter(|(f, _)| !keep(f.tile()))
            .map(|(f, i)| (*f, *i))
            .collect();
        for (f, i) in gone {
            self.budget.release(i as usize);
            self.index.remove(&f);
            self.faces[i as usize] = None;
            self.free.insert(i);
            self.due = true;
        }
        let faces = &self.faces;
        self.vista
            .retain(|&i| faces.get(i as usize).is_some_and(Option::is_some));
    }

    /// Queues again the pages of the held faces `touched` accepts; returns how many faces.
    pub fn invalidate(&mut self, touched: impl Fn(TileFaceKey) -> bool) -> usize {
        let mut hit: Vec<u32> = self
            .index
            .iter()
            .filter(|(f, _)| touched(**f))
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

    fn sort_detail(&mut self) {
        self.detail
            .sort_by(|a, b| b.level.cmp(&a.level).then(a.face.cmp(&b.face)));
        self.detail.dedup();
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
                .map(|h| [i64::from(h.key.lod), h.key.fx, h.key.fz])
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

    fn take_batch(&mut self) -> Option<PtexBatch> {
        let mut pages = Vec::new();
        while pages.len() < BATCH_PAGES {
            let Some(i) = self.vista.pop_front() else {
                break;
            };
            if let Some(p) = self.page(i, i) {
                pages.push(p);
            }
        }
        if !pages.is_empty() {
            return Some(PtexBatch { level: 0, pages });
        }
        let mut level = 0u8;
        let mut texels = 0u64;
        let mut taken = 0;
        for b in &self.detail {
            let current = self.budget.is_held(b.face as usize)
                && self.budget.level(b.face as usize) == b.level
                && self.budget.slot(b.face as usize) == Some(b.slot);
            if !current {
                taken += 1;
                continue;
            }
            let res = u64::from(LEVEL_RES[b.level as usize]);
            if level == 0 {
                level = b.level;
            }
            if b.level != level || texels + res * res > BATCH_TEXELS || pages.len() >= BATCH_PAGES {
                break;
            }
            texels += res * res;
            taken += 1;
            if let Some(p) = self.page(b.face, b.slot) {
                pages.push(p);
            }
        }
        self.detail.drain(..taken);
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
