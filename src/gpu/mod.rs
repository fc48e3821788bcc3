//! The compute device: one task owns the wgpu `Device` and `Queue`; stages send jobs over a
//! channel and await the results.
//!
//! (Work in progress: the device task and the WGSL twins land next.)

use crate::compute::AdapterInfo;
use crate::terrain::tile::Field;
use crate::terrain::WorldPlan;
use std::sync::Arc;

/// Handle to the device task.
#[derive(Clone, Debug)]
pub struct GpuHandle {}

impl GpuHandle {
    /// Whether the device was lost.
    pub fn is_lost(&self) -> bool {
        true
    }

    /// The adapter in use.
    pub fn adapter_info(&self) -> AdapterInfo {
        AdapterInfo { name: String::new(), backend: String::new(), device_type: String::new() }
    }

    /// Computes a field on the device.
    pub async fn field(&self, _plan: Arc<WorldPlan>, _lod: u32, _gx0: i64, _gz0: i64, _w: usize, _h: usize) -> anyhow::Result<Field> {
        anyhow::bail!("no device")
    }
}
