//! strata: a terrain-generation server.
//!
//! See `ARCHITECTURE.md` for the map. [`terrain`] is the world function (pure, CPU reference);
//! [`gpu`] owns the compute device and the WGSL twins; [`encode`] turns products into wire formats;
//! [`server`] is the HTTP service.

pub mod bench;
pub mod cli;
pub mod compute;
pub mod encode;
pub mod gpu;
pub mod server;
pub mod terrain;
