//! The level-of-detail budget of Ptex pages (Becher §4.7, "hierarchical texturing solution"): a
//! vista level of 8 × 8 texels for every face a client holds, and detail levels of 16² … 256²
//! sharing the rest of a memory budget equally, assigned each update to the faces in view,
//! nearest first.
//!
//! # Rules
//!
//! - A page of resolution `r` costs `(r + 2)² × 12` bytes (the three planes of
//!   `api/ptex_pages_v1.md` with their border). The vista level holds every face:
//!   `faces × cost(8)` bytes, which must fit the budget. The rest is split equally between the
//!   detail levels `16, 32, 64, 128, 256`; level `l` has `⌊share / cost(r_l)⌋` slots.
//! - **Classification** (each update): a face is in view when its bounding sphere meets the view
//!   cone (`cos` of the half angle, out to `far_m`); faces in view are sorted by distance from the
//!   eye to the sphere (ties by face index) and, from the highest level down, the nearest take
//!   that level's slots, but only while their distance is below the level's threshold
//!   (`thresholds_m[l]`): beyond it a face falls to lower levels even if slots remain. The rest
//!   keep the vista level only.
//! - **Slots**: a face that leaves a detail level frees its slot; a face entering a level takes
//!   the lowest free slot; a face that keeps its level keeps its slot and is not re-baked. The
//!   update lists the `(face, level, slot)` to bake and the faces back at the vista level, so a
//!   client's copy of the slots stays exact.
//! - **Edits**: [`Budget::invalidate`] lists exactly the touched faces' pages (vista and, where
//!   they hold one, their detail slot) for re-baking.
//! - **Held faces** (a stream session's faces come and go with its tiles): [`Budget::hold`] adds
//!   a face at the vista level, refused when the vista pages of the held faces would exceed the
//!   budget; [`Budget::release`] frees a face and its slot. The detail levels share what the
//!   held faces' vista pages leave, so their slot counts follow the held faces: when they shrink,
//!   the faces in the slots beyond the new count fall back to the vista level (listed in the
//!   next update's `to_vista`). Faces never held (indices past the held ones, or released) are
//!   not classified.
//! - **Highest level of a face**: a face may be held with a highest detail level
//!   ([`Budget::hold_up_to`]; 5 by default): the classification passes it over at the levels
//!   above, where the next nearest faces take the slots, and it may take a slot from its highest
//!   level down. A volume chunk's face is one lattice cell, a sixteenth of a tile face's side:
//!   held up to 16² it has the texel density of a tile face's 256² page, and it does not take a
//!   finer level's few slots from the tile faces around it.
//!
//! Pure and deterministic: the same faces and views give the same assignments.

/// Face resolutions by level: level 0 is the vista level.
pub const LEVEL_RES: [u32; 6] = [8, 16, 32, 64, 128, 256];

/// Bytes of one page of resolution `res` with its border (three planes, 12 bytes a texel).
pub fn page_bytes(res: u32) -> u64 {
    let s = u64::from(res) + 2;
    s * s * 12
}

/// A face as the budget sees it: a bounding sphere, metres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceBounds {
    /// Centre, metres.
    pub centre: [f32; 3],
    /// Radius, metres.
    pub radius: f32,
}

/// A client's view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Eye position, metres.
    pub eye: [f32; 3],
    /// Unit view direction.
    pub forward: [f32; 3],
    /// Cosine of the view cone's half angle.
    pub cos_half_angle: f32,
    /// Far distance, metres.
    pub far_m: f32,
}

/// Budget settings (per client session or per server).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BudgetConfig {
    /// Total bytes of pages.
    pub bytes: u64,
    /// Largest distance at which a face may hold detail level `l` (index `l − 1`), metres.
    pub thresholds_m: [f32; 5],
}

/// One page to bake: a face at a level in a slot of that level.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Bake {
    /// Face index.
    pub face: u32,
    /// Level (0 vista, 1..=5 detail).
    pub level: u8,
    /// Slot in that level's texture array (the face index for the vista level).
    pub slot: u32,
}

/// What an update changes.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Update {
    /// Pages to bake, by level (highest first) then face.
    pub bake: Vec<Bake>,
    /// Faces that left their detail level for the vista level (their slots are free), ascending.
    pub to_vista: Vec<u32>,
}

/// Why a budget cannot hold the faces.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{faces} faces need {need} bytes at the vista level; the budget is {budget}")]
pub struct BudgetError {
    /// Faces held.
    pub faces: usize,
    /// Bytes their vista pages need.
    pub need: u64,
    /// The budget.
    pub budget: u64,
}

/// The assignment of levels and slots to the faces of one client.
#[derive(Clone, Debug, PartialEq)]
pub struct Budget {
    config: BudgetConfig,
    /// Slots per detail level (index `l − 1`).
    capacity: [usize; 5],
    /// Level of each face (0: vista only).
    level: Vec<u8>,
    /// Slot of each face in its detail level (`u32::MAX` at the vista level).
    slot: Vec<u32>,
    /// Which face holds each slot of each detail level.
    owners: [Vec<Option<u32>>; 5],
    /// Whether each face is held.
    held: Vec<bool>,
    /// The highest detail level each face may hold.
    max_level: Vec<u8>,
    /// Faces held.
    held_count: usize,
    /// Faces that fell back to the vista level outside an update (their slots shrank away).
    evicted: Vec<u32>,
}

impl Budget {
    /// A budget for `faces` faces, all at the vista level (to be baked: see [`Budget::vista`]).
    ///
    /// # Errors
    /// The vista level alone exceeds the budget.
    pub fn new(config: BudgetConfig, faces: usize) -> Result<Self, BudgetError> {
        let need = faces as u64 * page_bytes(LEVEL_RES[0]);
        if need > config.bytes {
            return Err(BudgetError {
                faces,
                need,
                budget: config.bytes,
            });
        }
        let capacity = Self::capacity_for(&config, faces);
        Ok(Self {
            config,
            capacity,
            level: vec![0; faces],
            slot: vec![u32::MAX; faces],
            owners: std::array::from_fn(|l| vec![None; capacity[l]]),
            held: vec![true; faces],
            max_level: vec![5; faces],
            held_count: faces,
            evicted: Vec::new(),
        })
    }

    /// A budget holding no face yet (see [`Budget::hold`]).
    pub fn empty(config: BudgetConfig) -> Self {
        let capacity = Self::capacity_for(&config, 0);
        Self {
            config,
            capacity,
            level: Vec::new(),
            slot: Vec::new(),
            owners: std::array::from_fn(|l| vec![None; capacity[l]]),
            held: Vec::new(),
            max_level: Vec::new(),
            held_count: 0,
            evicted: Vec::new(),
        }
    }

    /// Slots per detail level when `faces` faces hold vista pages: each level gets a fifth of
    /// the rest of the budget.
    fn capacity_for(config: &BudgetConfig, faces: usize) -> [usize; 5] {
        let need = faces as u64 * page_bytes(LEVEL_RES[0]);
        let share = config.bytes.saturating_sub(need) / 5;
        std::array::from_fn(|l| (share / page_bytes(LEVEL_RES[l + 1])) as usize)
    }

    /// The settings.
    pub fn config(&self) -> &BudgetConfig {
        &self.config
    }

    /// Faces held.
    pub fn held(&self) -> usize {
        self.held_count
    }

    /// Whether face `f` is held.
    pub fn is_held(&self, f: usize) -> bool {
        self.held.get(f).copied().unwrap_or(false)
    }

    /// Holds face `f` at the vista level (its vista page is the caller's to bake). Holding a held
    /// face changes nothing.
    ///
    /// # Errors
    /// The vista pages of the held faces and this one would exceed the budget.
    pub fn hold(&mut self, f: usize) -> Result<(), BudgetError> {
        self.hold_up_to(f, 5)
    }

    /// [`Budget::hold`] a face that may hold detail levels up to `max_level` only (1..=5; 0: the
    /// vista level only). Holding a held face changes nothing.
    ///
    /// # Errors
    /// The vista pages of the held faces and this one would exceed the budget.
    pub fn hold_up_to(&mut self, f: usize, max_level: u8) -> Result<(), BudgetError> {
        if self.is_held(f) {
            return Ok(());
        }
        let need = (self.held_count as u64 + 1) * page_bytes(LEVEL_RES[0]);
        if need > self.config.bytes {
            return Err(BudgetError {
                faces: self.held_count + 1,
                need,
                budget: self.config.bytes,
            });
        }
        if f >= self.level.len() {
            self.level.resize(f + 1, 0);
            self.max_level.resize(f + 1, 5);
            self.slot.resize(f + 1, u32::MAX);
            self.held.resize(f + 1, false);
        }
        self.held[f] = true;
        self.max_level[f] = max_level.min(5);
        self.held_count += 1;
        self.recapacity();
        Ok(())
    }

    /// Releases face `f` and its detail slot, if it holds one.
    pub fn release(&mut self, f: usize) {
        if !self.is_held(f) {
            return;
        }
        self.free_slot(f);
        self.held[f] = false;
        self.held_count -= 1;
        self.evicted.retain(|&e| e as usize != f);
        self.recapacity();
    }

    /// Frees face `f`'s detail slot; it is at the vista level after.
    fn free_slot(&mut self, f: usize) {
        let old = self.level[f];
        if old > 0 {
            let owners = &mut self.owners[old as usize - 1];
            if let Some(o) = owners.get_mut(self.slot[f] as usize) {
                *o = None;
            }
            self.slot[f] = u32::MAX;
            self.level[f] = 0;
        }
    }

    /// Sizes the detail levels for the held faces; faces in slots that no longer exist fall
    /// back to the vista level.
    fn recapacity(&mut self) {
        let capacity = Self::capacity_for(&self.config, self.held_count);
        for (l, &cap) in capacity.iter().enumerate() {
            while self.owners[l].len() > cap {
                if let Some(Some(f)) = self.owners[l].pop() {
                    self.level[f as usize] = 0;
                    self.slot[f as usize] = u32::MAX;
                    self.evicted.push(f);
                }
            }
            self.owners[l].resize(cap, None);
        }
        self.capacity = capacity;
    }

    /// Slots per detail level (16² … 256²).
    pub fn capacity(&self) -> [usize; 5] {
        self.capacity
    }

    /// The level of face `f`.
    pub fn level(&self, f: usize) -> u8 {
        self.level[f]
    }

    /// The detail slot of face `f`, if it holds one.
    pub fn slot(&self, f: usize) -> Option<u32> {
        self.slot.get(f).copied().filter(|&s| s != u32::MAX)
    }

    /// Bytes of the pages held now: every held face's vista page and every occupied detail
    /// slot.
    pub fn bytes_held(&self) -> u64 {
        let vista = self.held_count as u64 * page_bytes(LEVEL_RES[0]);
        let detail: u64 = (0..5)
            .map(|l| {
                self.owners[l].iter().filter(|o| o.is_some()).count() as u64
                    * page_bytes(LEVEL_RES[l + 1])
            })
            .sum();
        vista + detail
    }

    /// The vista pages of every held face (the first bake of a session).
    pub fn vista(&self) -> Vec<Bake> {
        (0..self.level.len() as u32)
            .filter(|&f| self.held[f as usize])
            .map(|f| Bake {
                face: f,
                level: 0,
                slot: f,
            })
            .collect()
    }

    /// Classifies `faces` for `view` and returns the pages to bake and the faces back at the
    /// vista level. `faces` longer or shorter than the budget's face count reads only the common
    /// part.
    pub fn update(&mut self, faces: &[FaceBounds], view: &View) -> Update {
        self.update_with(|f| faces.get(f).copied(), view)
    }

    /// [`Budget::update`] over the held faces whose bounds `bounds(f)` knows (a face without
    /// bounds is classified out of view).
    pub fn update_with(
        &mut self,
        bounds: impl Fn(usize) -> Option<FaceBounds>,
        view: &View,
    ) -> Update {
        let mut visible: Vec<(f32, u32)> = Vec::new();
        for f in 0..self.level.len() {
            if !self.held[f] {
                continue;
            }
            if let Some(d) = bounds(f).and_then(|b| distance_in_view(&b, view)) {
                visible.push((d, f as u32));
            }
        }
        visible.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        // From the highest level down, the nearest faces not yet placed that may hold the level
        // take its slots while their distance is below its threshold (the list is sorted by
        // distance: past the threshold, so are the rest).
        let mut wanted = vec![0u8; self.level.len()];
        let mut placed = vec![false; visible.len()];
        for l in (0..5).rev() {
            let level = l as u8 + 1;
            let mut taken = 0;
            for (k, &(d, f)) in visible.iter().enumerate() {
                if taken >= self.capacity[l] || d > self.config.thresholds_m[l] {
                    break;
                }
                if placed[k] || self.max_level[f as usize] < level {
                    continue;
                }
                wanted[f as usize] = level;
                placed[k] = true;
                taken += 1;
            }
        }
        // Free the slots of faces leaving their level, then fill the entering ones.
        let mut to_vista = std::mem::take(&mut self.evicted);
        for (f, &new) in wanted.iter().enumerate() {
            let old = self.level[f];
            if old != new && old > 0 {
                self.owners[old as usize - 1][self.slot[f] as usize] = None;
                self.slot[f] = u32::MAX;
                if new == 0 {
                    to_vista.push(f as u32);
                }
            }
        }
        let mut bakes = Vec::new();
        for (f, &new) in wanted.iter().enumerate() {
            let old = self.level[f];
            self.level[f] = new;
            if old == new || new == 0 {
                continue;
            }
            let owners = &mut self.owners[new as usize - 1];
            // A free slot exists: the level took at most its capacity.
            if let Some(s) = owners.iter().position(Option::is_none) {
                owners[s] = Some(f as u32);
                self.slot[f] = s as u32;
                bakes.push(Bake {
                    face: f as u32,
                    level: new,
                    slot: s as u32,
                });
            }
        }
        bakes.sort_by(|a, b| b.level.cmp(&a.level).then(a.face.cmp(&b.face)));
        // An evicted face that took a slot again is not back at the vista level.
        to_vista.retain(|&f| self.level[f as usize] == 0);
        to_vista.sort_unstable();
        to_vista.dedup();
        Update {
            bake: bakes,
            to_vista,
        }
    }

    /// The pages to re-bake after an edit touched `faces`: each one's vista page and its
    /// detail page, if it holds one.
    pub fn invalidate(&self, faces: &[u32]) -> Vec<Bake> {
        let mut out = Vec::new();
        for &f in faces {
            let Some(&level) = self.level.get(f as usize) else {
                continue;
            };
            if !self.held[f as usize] {
                continue;
            }
            out.push(Bake {
                face: f,
                level: 0,
                slot: f,
            });
            if level > 0 {
                out.push(Bake {
                    face: f,
                    level,
                    slot: self.slot[f as usize],
                });
            }
        }
        out
    }
}

/// The distance from `eye` to a face's sphere (0 inside it), and the offset from `eye` to the
/// sphere's centre with its length.
pub fn sphere_distance(b: &FaceBounds, eye: [f32; 3]) -> (f32, [f32; 3], f32) {
    let d: [f32; 3] = std::array::from_fn(|c| b.centre[c] - eye[c]);
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    ((len - b.radius).max(0.0), d, len)
}

/// The distance from the eye to a face's sphere when the sphere meets the view cone and lies
/// within the far distance.
pub fn distance_in_view(b: &FaceBounds, view: &View) -> Option<f32> {
    let (dist, d, len) = sphere_distance(b, view.eye);
    if dist > view.far_m {
        return None;
    }
    if len <= b.radius {
        return Some(0.0);
    }
    let along = d[0] * view.forward[0] + d[1] * view.forward[1] + d[2] * view.forward[2];
    // The sphere meets the cone when the angle to its centre is within the half angle plus the
    // sphere's angular radius.
    let cos_c = along / len;
    let sin_r = (b.radius / len).min(1.0);
    let cos_r = (1.0 - sin_r * sin_r).sqrt();
    let sin_a = (1.0 - view.cos_half_angle * view.cos_half_angle)
        .max(0.0)
        .sqrt();
    // cos(a + r) = cos a cos r − sin a sin r.
    let cos_limit = view.cos_half_angle * cos_r - sin_a * sin_r;
    (cos_c >= cos_limit).then_some(dist)
}
