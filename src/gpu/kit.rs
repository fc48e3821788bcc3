//! What every kernel host does the same way: compile a WGSL module with one bind group of
//! buffers, build its entry points, and read a result back after a submission.

use super::scopes::Scopes;
use anyhow::{anyhow, bail};
use std::time::Duration;

/// How a kernel binds one buffer of group 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Binding {
    /// A `var<uniform>` parameter struct.
    Uniform,
    /// A `var<storage, read>` array.
    Read,
    /// A `var<storage, read_write>` array.
    ReadWrite,
}

/// A compiled WGSL module whose bindings `0..n` of group 0 are buffers, with the layouts its
/// pipelines share.
pub(crate) struct Program {
    module: wgpu::ShaderModule,
    /// The layout of group 0, for the host's bind groups.
    pub(crate) layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
}

impl Program {
    /// Compiles `source`; binding `i` of group 0 is `bindings[i]`. Errors surface in the caller's
    /// error scopes.
    pub(crate) fn new(
        device: &wgpu::Device,
        label: &str,
        source: &str,
        bindings: &[Binding],
    ) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(label),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let entries: Vec<wgpu::BindGroupLayoutEntry> = bindings
            .iter()
            .zip(0u32..)
            .map(|(&b, binding)| wgpu::BindGroupLayoutEntry {
                binding,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer {
                    ty: match b {
                        Binding::Uniform => wgpu::BufferBindingType::Uniform,
                        Binding::Read => wgpu::BufferBindingType::Storage { read_only: true },
                        Binding::ReadWrite => wgpu::BufferBindingType::Storage { read_only: false },
                    },
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            })
            .collect();
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(label),
            entries: &entries,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(label),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        Self {
            module,
            layout,
            pipeline_layout,
        }
    }

    /// The compute pipeline of entry point `entry`.
    pub(crate) fn pipeline(&self, device: &wgpu::Device, entry: &str) -> wgpu::ComputePipeline {
        device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: Some(&self.pipeline_layout),
            module: &self.module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            cache: None,
        })
    }
}

/// Waits for `submission` (at most `timeout`; `None`: indefinitely), pops the job's `scopes`
/// and returns the contents of `readback` (a `MAP_READ` buffer the submission copied into).
///
/// # Errors
/// If the device reports an error in the scopes, times out, is lost or fails to map the buffer.
pub(crate) fn read_back<T: bytemuck::Pod>(
    device: &wgpu::Device,
    readback: &wgpu::Buffer,
    submission: wgpu::SubmissionIndex,
    timeout: Option<Duration>,
    scopes: Scopes,
) -> anyhow::Result<Vec<T>> {
    let (tx, rx) = std::sync::mpsc::channel();
    readback.slice(..).map_async(wgpu::MapMode::Read, move |r| {
        // The receiver outlives the poll below; a failed send cannot happen.
        let _ = tx.send(r);
    });
    let polled = device.poll(wgpu::PollType::Wait {
        submission_index: Some(submission),
        timeout,
    });
    // Pop the scopes before acting on anything else so they never leak into the next job.
    let scoped = scopes.pop();
    polled.map_err(|e| anyhow!("waiting for the device: {e}"))?;
    scoped?;
    match rx.try_recv() {
        Ok(Ok(())) => {}
        Ok(Err(e)) => bail!("mapping the result failed: {e}"),
        Err(_) => bail!("the result was not mapped after the submission completed"),
    }
    let data = {
        let view = readback
            .slice(..)
            .get_mapped_range()
            .map_err(|e| anyhow!("reading the result: {e}"))?;
        bytemuck::pod_collect_to_vec(&view)
    };
    readback.unmap();
    Ok(data)
}

/// A buffer of `usage` (plus `COPY_DST`) holding `contents`, padded to whole words. Filled with
/// `write_buffer` rather than mapped at creation: on a lost device mapping panics inside wgpu,
/// while a write is only an error the job's scopes catch.
pub(crate) fn upload(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    label: &str,
    contents: &[u8],
    usage: wgpu::BufferUsages,
) -> wgpu::Buffer {
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: (contents.len() as u64).max(4).next_multiple_of(4),
        usage: usage | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    queue.write_buffer(&buffer, 0, contents);
    buffer
}

/// An uninitialised storage buffer of `bytes` (at least one word), with `extra` usages.
pub(crate) fn storage(
    device: &wgpu::Device,
    label: &str,
    bytes: u64,
    extra: wgpu::BufferUsages,
) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: bytes.max(4),
        usage: wgpu::BufferUsages::STORAGE | extra,
        mapped_at_creation: false,
    })
}

/// A mappable buffer of `bytes` that results are copied into for [`read_back`].
pub(crate) fn readback(device: &wgpu::Device, label: &str, bytes: u64) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: bytes.max(4),
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

/// A bind group of `layout` binding `buffers[i]` whole at binding `i`.
pub(crate) fn bind_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    label: &str,
    buffers: &[&wgpu::Buffer],
) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry> = buffers
        .iter()
        .zip(0u32..)
        .map(|(buf, binding)| wgpu::BindGroupEntry {
            binding,
            resource: buf.as_entire_binding(),
        })
        .collect();
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(label),
        layout,
        entries: &entries,
    })
}

/// Most workgroups per dispatch dimension (WebGPU's default limit).
pub(crate) const MAX_GROUPS: u32 = 65_535;

/// Dispatches enough workgroups of `workgroup` invocations for `invocations` linear indices,
/// folded into two dimensions when one would exceed [`MAX_GROUPS`] (the shader recovers the
/// linear index from `global_invocation_id` and `num_workgroups` and skips those past the end).
pub(crate) fn dispatch_linear(pass: &mut wgpu::ComputePass<'_>, invocations: u32, workgroup: u32) {
    let groups = invocations.div_ceil(workgroup);
    let x = groups.clamp(1, MAX_GROUPS);
    pass.dispatch_workgroups(x, groups.div_ceil(x), 1);
}
