//! strata: a terrain-generation server.
//!
//! See `ARCHITECTURE.md` for the map. [`terrain`] is the world function (pure, CPU reference);
//! [`gpu`] owns the compute device and the WGSL twins; [`encode`] turns products into wire formats;
//! [`server`] is the HTTP service.

pub mod terrain;
pub mod compute;
pub mod gpu;
pub mod bench;
pub mod cli;
pub mod encode;
pub mod server;
