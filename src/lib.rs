//! strata: a terrain-generation server.
//!
//! See `ARCHITECTURE.md` for the map. [`terrain`] is the world function (pure, CPU reference);
//! [`gpu`] owns the compute device and the WGSL twins; [`encode`] turns products into wire formats;
//! [`server`] is the HTTP service; [`scene`] is the scene document and [`store`] keeps worlds,
//! their versions and tokens durably; [`cache`] keeps finished tiles under the hash of their
//! inputs; [`edits`] are what a tile applies on top of the procedural field (authored regions,
//! cave breaches).

pub mod authoring;
pub mod bench;
pub mod cache;
pub mod cli;
pub mod compute;
pub mod cpu_time;
pub mod edits;
pub mod element;
pub mod encode;
pub mod export;
pub mod glb;
pub mod gpu;
pub mod harness;
pub mod ptex;
pub mod scene;
pub mod server;
pub mod store;
pub mod stream;
pub mod subsurface;
pub mod terrain;
pub mod volume;
