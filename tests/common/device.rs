//! The one device setup of the GPU twin tests: the wgpu adapter `--backend gpu` would use (any
//! adapter, software included: lavapipe or llvmpipe here). Without one a test fails with the
//! instructions, it never skips.

use strata::gpu::{request_device, BackendChoice};

/// The adapter, device and queue, or a panic naming `test` and how to install an adapter.
pub fn software_device(test: &str) -> (wgpu::Adapter, wgpu::Device, wgpu::Queue) {
    match pollster::block_on(request_device(BackendChoice::Gpu)) {
        Ok(Some(d)) => d,
        Ok(None) => panic!("request_device(Gpu) returned no device"),
        Err(e) => panic!(
            "{test} needs a wgpu adapter; install Mesa's lavapipe (apt-get install \
             mesa-vulkan-drivers libvulkan1) and set XDG_RUNTIME_DIR. Error: {e:#}"
        ),
    }
}

/// The device and queue of [`software_device`].
pub fn device(test: &str) -> (wgpu::Device, wgpu::Queue) {
    let (_, device, queue) = software_device(test);
    (device, queue)
}

/// The device task `--backend gpu` would open ([`strata::gpu::open`]), or a panic naming `test`
/// and how to install an adapter.
pub async fn handle(test: &str) -> strata::gpu::GpuHandle {
    match strata::gpu::open(BackendChoice::Gpu).await {
        Ok(Some(h)) => h,
        Ok(None) => panic!("open(Gpu) returned no device"),
        Err(e) => panic!(
            "{test} needs a wgpu adapter; install Mesa's lavapipe (apt-get install \
             mesa-vulkan-drivers libvulkan1) and set XDG_RUNTIME_DIR. Error: {e:#}"
        ),
    }
}
