//! Error scopes of one GPU job, shared by every kernel host.

use anyhow::anyhow;

/// Error scopes of one job: validation, out-of-memory and internal errors are all caught.
pub(crate) struct Scopes(Vec<wgpu::ErrorScopeGuard>);

impl Scopes {
    /// Pushes the three scopes on `device`.
    pub(crate) fn push(device: &wgpu::Device) -> Self {
        Self(vec![
            device.push_error_scope(wgpu::ErrorFilter::Validation),
            device.push_error_scope(wgpu::ErrorFilter::OutOfMemory),
            device.push_error_scope(wgpu::ErrorFilter::Internal),
        ])
    }

    /// Pops the scopes (innermost first) and returns the first error caught.
    pub(crate) fn pop(mut self) -> anyhow::Result<()> {
        let mut first = None;
        while let Some(guard) = self.0.pop() {
            if let Some(e) = pollster::block_on(guard.pop()) {
                first.get_or_insert(e);
            }
        }
        match first {
            Some(e) => Err(anyhow!("wgpu error: {e}")),
            None => Ok(()),
        }
    }
}
