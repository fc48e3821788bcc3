//! `GET /metrics`: a few counters and histograms in the Prometheus text format (version 0.0.4).
//!
//! Hand-rolled (a mutex-guarded map per family) to keep dependencies small:
//!
//! | metric | labels |
//! |---|---|
//! | `strata_http_requests_total` (counter) | `method`, `route` (the route pattern), `status` |
//! | `strata_http_request_duration_seconds` (histogram, to the response head) | `route` |
//! | `strata_edits_total` (counter) | `result`: `applied`, `conflict`, `refused` |
//! | `strata_plan_cache_hits_total`, `strata_plan_cache_misses_total` (counters) | `cache`: `seeds`, `worlds` |
//! | `strata_worlds_created_total` (counter) | |
//! | `strata_edit_subscribers` (gauge) | |
//! | `strata_synthesis_timeouts_total` (counter), `strata_synthesis_after_timeout` (gauge: syntheses still running whose request timed out, until they are cancelled), `strata_synthesis_cancelled_total` (counter: started syntheses cancelled because no request waited for them; see [`super::overrun`]) | |
//! | `strata_work_after_cancel` (gauge: blocking computations — tile stages, region and volume solves, Ptex bakes — still running after every request waiting for them had gone), `strata_work_after_cancel_total` (counter: how those ended; see [`crate::compute::work`]) | `end`: `stopped` (at a check of their cancellation flag), `finished` (ran to their end) |
//! | `strata_stage_cache_hits_total` (counter) | `tier`: `memory`, `disk`, `inflight` (joined a computation under way) |
//! | `strata_stage_cache_misses_total` (counter): tiles computed | |
//! | `strata_stage_runs_total` (counter) | `stage`: `field`, `snap`, `finish` |
//! | `strata_stage_seconds_total` (counter) | `stage` |
//! | `strata_stage_cache_evictions_total`, `strata_stage_cache_disk_writes_total`, `strata_stage_cache_disk_errors_total` (counters) | |
//! | `strata_stage_cache_bytes`, `strata_stage_cache_budget_bytes`, `strata_stage_cache_entries` (gauges) | |
//! | `strata_cache_bytes`, `strata_cache_budget_bytes` (gauges): every cache's share of `--memory-budget` | `cache`: `stage`, `bodies`, `images`, `chunk_meshes`, `regions`, `volumes`, `seed_plans`, `world_plans` |
//! | `strata_memory_budget_bytes` (gauge): `--memory-budget` | |
//! | `strata_device_jobs_total` (counter): jobs of the stages with a WGSL twin sent for the GPU device | `stage`: `field`, `poisson`, `diffusion`, `propagation`, `bitangents`, `meshing`; `result`: `device` (ran there), `failed` (recomputed on the CPU; the device is then lost), `skipped` (not sent: device lost, or input beyond the kernel's limits) |

use super::AppState;
use axum::extract::{MatchedPath, Request, State};
use axum::http::{header, HeaderValue};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use std::collections::BTreeMap;
use std::fmt::{Display, Write};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

/// Upper bounds of the latency histogram buckets, seconds.
pub const LATENCY_BUCKETS: [f64; 12] = [
    0.0005, 0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 5.0,
];

#[derive(Debug, Default, Clone)]
struct Histogram {
    buckets: [u64; LATENCY_BUCKETS.len()],
    count: u64,
    sum: f64,
}

/// The counters of one [`AppState`].
#[derive(Debug, Default)]
pub struct Metrics {
    requests: Mutex<BTreeMap<(String, String, u16), u64>>,
    latency: Mutex<BTreeMap<String, Histogram>>,
    /// Edits applied.
    pub edits_applied: AtomicU64,
    /// Edits refused with 409.
    pub edits_conflict: AtomicU64,
    /// Edits refused for any other reason (bad patch, invalid scene, …).
    pub edits_refused: AtomicU64,
    /// Worlds created.
    pub worlds_created: AtomicU64,
    /// Syntheses whose request timed out ([`super::overrun`]).
    pub overruns: Arc<super::overrun::Overruns>,
}

fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|p| p.into_inner())
}

/// Writes a metric family's `# HELP` and `# TYPE` lines.
fn family_header(out: &mut String, name: &str, kind: &str, help: &str) {
    let _ = writeln!(out, "# HELP {name} {help}\n# TYPE {name} {kind}");
}

/// Writes a metric family with one sample and no labels: its `# HELP` and `# TYPE` lines, then
/// `name value`.
fn single(out: &mut String, name: &str, kind: &str, help: &str, value: impl Display) {
    family_header(out, name, kind, help);
    let _ = writeln!(out, "{name} {value}");
}

/// Writes a metric family with one label: its `# HELP` and `# TYPE` lines, then one sample
/// `name{label="value"} sample` per row, in the order given. The label values are written as
/// they are, so they must be plain words that need no escaping.
fn labelled<L: Display, V: Display>(
    out: &mut String,
    (name, kind, help): (&str, &str, &str),
    label: &str,
    rows: impl IntoIterator<Item = (L, V)>,
) {
    family_header(out, name, kind, help);
    for (value, sample) in rows {
        let _ = writeln!(out, "{name}{{{label}=\"{value}\"}} {sample}");
    }
}

fn escape(v: &str) -> String {
    v.replace('\\', "\\\\")
        .replace('"', "\\\"")
        .replace('\n', "\\n")
}

impl Metrics {
    /// Counts one answered request.
    pub fn observe(&self, method: &str, route: &str, status: u16, seconds: f64) {
        *lock(&self.requests)
            .entry((method.to_string(), route.to_string(), status))
            .or_default() += 1;
        let mut lat = lock(&self.latency);
        let h = lat.entry(route.to_string()).or_default();
        for (b, le) in h.buckets.iter_mut().zip(LATENCY_BUCKETS) {
            if seconds <= le {
                *b += 1;
            }
        }
        h.count += 1;
        h.sum += seconds;
    }

    /// The text exposition of these metrics plus `extra` lines (already formatted).
    pub fn render(&self, extra: &str) -> String {
        let mut out = String::new();
        out.push_str("# HELP strata_http_requests_total HTTP requests answered.\n");
        out.push_str("# TYPE strata_http_requests_total counter\n");
        for ((method, route, status), n) in lock(&self.requests).iter() {
            let _ = writeln!(
                out,
                "strata_http_requests_total{{method=\"{}\",route=\"{}\",status=\"{status}\"}} {n}",
                escape(method),
                escape(route)
            );
        }
        out.push_str(
            "# HELP strata_http_request_duration_seconds Time to the response head, by route.\n",
        );
        out.push_str("# TYPE strata_http_request_duration_seconds histogram\n");
        for (route, h) in lock(&self.latency).iter() {
            let route = escape(route);
            for (b, le) in h.buckets.iter().zip(LATENCY_BUCKETS) {
                let _ = writeln!(
                    out,
                    "strata_http_request_duration_seconds_bucket{{route=\"{route}\",le=\"{le}\"}} {b}"
                );
            }
            let _ = writeln!(
                out,
                "strata_http_request_duration_seconds_bucket{{route=\"{route}\",le=\"+Inf\"}} {}",
                h.count
            );
            let _ = writeln!(
                out,
                "strata_http_request_duration_seconds_sum{{route=\"{route}\"}} {}",
                h.sum
            );
            let _ = writeln!(
                out,
                "strata_http_request_duration_seconds_count{{route=\"{route}\"}} {}",
                h.count
            );
        }
        labelled(
            &mut out,
            ("strata_edits_total", "counter", "Scene edits by result."),
            "result",
            [
                ("applied", &self.edits_applied),
                ("conflict", &self.edits_conflict),
                ("refused", &self.edits_refused),
            ]
            .map(|(result, c)| (result, c.load(Ordering::Relaxed))),
        );
        single(
            &mut out,
            "strata_worlds_created_total",
            "counter",
            "Worlds created.",
            self.worlds_created.load(Ordering::Relaxed),
        );
        out.push_str(extra);
        out
    }
}

/// Middleware counting every request under its route pattern (`unmatched` for the fallback).
pub async fn track(State(m): State<Arc<Metrics>>, req: Request, next: Next) -> Response {
    let start = Instant::now();
    let method = req.method().as_str().to_string();
    let route = req
        .extensions()
        .get::<MatchedPath>()
        .map(|p| p.as_str().to_string())
        .unwrap_or_else(|| "unmatched".to_string());
    let res = next.run(req).await;
    m.observe(
        &method,
        &route,
        res.status().as_u16(),
        start.elapsed().as_secs_f64(),
    );
    res
}

/// The device's job counts by stage and result (zeros without a device, so the family always
/// has every series).
fn device_jobs(out: &mut String, counts: Option<&crate::gpu::jobs::JobCounts>) {
    use crate::gpu::jobs::{DeviceStage, JobResult};
    let name = "strata_device_jobs_total";
    family_header(
        out,
        name,
        "counter",
        "Jobs of the stages with a WGSL twin sent for the GPU device, by stage and result.",
    );
    for stage in DeviceStage::ALL {
        for result in JobResult::ALL {
            let n = counts.map_or(0, |c| c.get(stage, result));
            let _ = writeln!(
                out,
                "{name}{{stage=\"{}\",result=\"{}\"}} {n}",
                stage.name(),
                result.name()
            );
        }
    }
}

/// The stage cache's lines.
fn stage_cache(out: &mut String, s: &crate::cache::CacheStats) {
    use crate::cache::Stage;
    labelled(
        out,
        (
            "strata_stage_cache_hits_total",
            "counter",
            "Tiles found in the stage cache, by tier.",
        ),
        "tier",
        [
            ("memory", s.hits),
            ("disk", s.disk_hits),
            ("inflight", s.joined),
        ],
    );
    labelled(
        out,
        (
            "strata_stage_runs_total",
            "counter",
            "Stage runs of tile synthesis, by stage.",
        ),
        "stage",
        Stage::ALL.map(|stage| (stage.name(), s.runs_of(stage))),
    );
    labelled(
        out,
        (
            "strata_stage_seconds_total",
            "counter",
            "Time spent in each stage of tile synthesis.",
        ),
        "stage",
        Stage::ALL.map(|stage| (stage.name(), format!("{:.6}", s.seconds_of(stage)))),
    );
    for (name, kind, help, v) in [
        (
            "strata_stage_cache_misses_total",
            "counter",
            "Tiles not found in the stage cache and computed.",
            s.misses,
        ),
        (
            "strata_stage_cache_evictions_total",
            "counter",
            "Tiles evicted from memory to stay within the budget.",
            s.evictions,
        ),
        (
            "strata_stage_cache_disk_writes_total",
            "counter",
            "Tiles written to the disk tier.",
            s.disk_writes,
        ),
        (
            "strata_stage_cache_disk_errors_total",
            "counter",
            "Unreadable, corrupt or unwritable disk tier files.",
            s.disk_errors,
        ),
        (
            "strata_stage_cache_bytes",
            "gauge",
            "Bytes of the tiles in memory.",
            s.bytes,
        ),
        (
            "strata_stage_cache_budget_bytes",
            "gauge",
            "Byte budget of the memory tier.",
            s.budget_bytes,
        ),
        (
            "strata_stage_cache_entries",
            "gauge",
            "Tiles in memory.",
            s.entries,
        ),
    ] {
        single(out, name, kind, help, v);
    }
}

/// Encoded-body cache, stream clients and their frames, export job queue.
fn service_gauges(out: &mut String, st: &AppState) {
    use crate::stream::session::STATS;
    let (entries, bytes) = st.bodies.size();
    let lines: [(&str, &str, &str, String); 12] = [
        (
            "strata_body_cache_hits_total",
            "counter",
            "Product requests answered from the encoded-body cache.",
            st.bodies.hits.load(Ordering::Relaxed).to_string(),
        ),
        (
            "strata_body_cache_misses_total",
            "counter",
            "Product requests that encoded a body.",
            st.bodies.misses.load(Ordering::Relaxed).to_string(),
        ),
        (
            "strata_body_cache_entries",
            "gauge",
            "Encoded bodies held.",
            entries.to_string(),
        ),
        (
            "strata_body_cache_bytes",
            "gauge",
            "Bytes of encoded bodies held.",
            bytes.to_string(),
        ),
        (
            "strata_stream_clients",
            "gauge",
            "Connected WebSocket stream clients.",
            STATS.sessions.load(Ordering::Relaxed).to_string(),
        ),
        (
            "strata_stream_frames_total",
            "counter",
            "Tile frames produced for stream clients.",
            STATS.frames.load(Ordering::Relaxed).to_string(),
        ),
        (
            "strata_stream_dropped_slow_total",
            "counter",
            "Stream clients closed for not keeping up.",
            STATS.dropped_slow.load(Ordering::Relaxed).to_string(),
        ),
        (
            "strata_synthesis_timeouts_total",
            "counter",
            "Requests answered 503 synthesis_timeout.",
            st.metrics
                .overruns
                .timeouts
                .load(Ordering::Relaxed)
                .to_string(),
        ),
        (
            "strata_synthesis_after_timeout",
            "gauge",
            "Syntheses running whose request timed out, until they are cancelled.",
            st.metrics
                .overruns
                .running
                .load(Ordering::Relaxed)
                .to_string(),
        ),
        (
            "strata_synthesis_cancelled_total",
            "counter",
            "Started syntheses cancelled because no request waited for them any more.",
            st.metrics
                .overruns
                .cancelled
                .load(Ordering::Relaxed)
                .to_string(),
        ),
        (
            "strata_export_jobs_queued",
            "gauge",
            "Export jobs waiting to run.",
            st.jobs.counts().0.to_string(),
        ),
        (
            "strata_export_jobs_running",
            "gauge",
            "Export jobs running.",
            st.jobs.counts().1.to_string(),
        ),
    ];
    for (name, kind, help, value) in lines {
        single(out, name, kind, help, value);
    }
}

/// Bytes held and budgets of the eight caches, and the process-wide budget.
fn cache_sizes(out: &mut String, st: &AppState, stage: &crate::cache::CacheStats) {
    let (_, body_bytes) = st.bodies.size();
    let (_, region_bytes, region_budget) = st.regions.size();
    let (_, volume_bytes, volume_budget) = st.volumes.size();
    let (_, seed_bytes, seed_budget) = st.plans.size();
    let (_, world_bytes, world_budget) = st.worlds.plan_size();
    let images = st.images.stats();
    let meshes = st.chunk_meshes.stats();
    let rows = [
        ("stage", stage.bytes, stage.budget_bytes),
        ("bodies", body_bytes as u64, st.bodies.budget_bytes() as u64),
        ("images", images.bytes, images.budget_bytes),
        ("chunk_meshes", meshes.bytes, meshes.budget_bytes),
        ("regions", region_bytes, region_budget),
        ("volumes", volume_bytes, volume_budget),
        ("seed_plans", seed_bytes, seed_budget),
        ("world_plans", world_bytes, world_budget),
    ];
    labelled(
        out,
        (
            "strata_cache_bytes",
            "gauge",
            "Bytes counted in each cache (what its entries hold).",
        ),
        "cache",
        rows.map(|(name, bytes, _)| (name, bytes)),
    );
    labelled(
        out,
        (
            "strata_cache_budget_bytes",
            "gauge",
            "Byte budget of each cache, its share of the memory budget.",
        ),
        "cache",
        rows.map(|(name, _, budget)| (name, budget)),
    );
    single(
        out,
        "strata_memory_budget_bytes",
        "gauge",
        "The process-wide memory budget of the caches (--memory-budget).",
        st.memory_budget().total,
    );
}

/// Blocking work that outlived the requests waiting for it ([`crate::compute::work`]).
fn abandoned_work(out: &mut String) {
    let a = &crate::compute::work::ABANDONED;
    single(
        out,
        "strata_work_after_cancel",
        "gauge",
        "Blocking computations still running after every request waiting for them had gone.",
        a.running.load(Ordering::Relaxed),
    );
    labelled(
        out,
        (
            "strata_work_after_cancel_total",
            "counter",
            "Blocking computations whose requests had all gone, by how they ended: stopped at a check of their cancellation flag, or finished (ran to their end).",
        ),
        "end",
        [
            ("stopped", a.stopped.load(Ordering::Relaxed)),
            ("finished", a.finished.load(Ordering::Relaxed)),
        ],
    );
}

/// `GET /metrics`.
pub async fn render(State(st): State<AppState>) -> Response {
    let (seed_hits, seed_misses) = st.plans.stats();
    let (world_hits, world_misses) = st.worlds.plan_stats();
    let mut extra = String::new();
    labelled(
        &mut extra,
        (
            "strata_plan_cache_hits_total",
            "counter",
            "World plans found in the cache.",
        ),
        "cache",
        [("seeds", seed_hits), ("worlds", world_hits)],
    );
    labelled(
        &mut extra,
        (
            "strata_plan_cache_misses_total",
            "counter",
            "World plans built.",
        ),
        "cache",
        [("seeds", seed_misses), ("worlds", world_misses)],
    );
    single(
        &mut extra,
        "strata_edit_subscribers",
        "gauge",
        "Receivers of the in-process edit broadcast.",
        st.worlds.edits.subscribers(),
    );
    abandoned_work(&mut extra);
    let stage = st.cache.stats();
    stage_cache(&mut extra, &stage);
    device_jobs(&mut extra, st.compute.device_jobs());
    cache_sizes(&mut extra, &st, &stage);
    service_gauges(&mut extra, &st);
    let mut res = st.metrics.render(&extra).into_response();
    let h = res.headers_mut();
    h.insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static("text/plain; version=0.0.4; charset=utf-8"),
    );
    h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    res
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exposition() {
        let m = Metrics::default();
        m.observe("GET", "/v1/x/{id}", 200, 0.003);
        m.observe("GET", "/v1/x/{id}", 200, 2.0);
        m.edits_applied.fetch_add(2, Ordering::Relaxed);
        let t = m.render("");
        assert!(t.contains(
            "strata_http_requests_total{method=\"GET\",route=\"/v1/x/{id}\",status=\"200\"} 2"
        ));
        assert!(t.contains(
            "strata_http_request_duration_seconds_bucket{route=\"/v1/x/{id}\",le=\"0.005\"} 1"
        ));
        assert!(t.contains(
            "strata_http_request_duration_seconds_bucket{route=\"/v1/x/{id}\",le=\"+Inf\"} 2"
        ));
        assert!(t.contains(concat!(
            "# HELP strata_edits_total Scene edits by result.\n",
            "# TYPE strata_edits_total counter\n",
            "strata_edits_total{result=\"applied\"} 2\n",
            "strata_edits_total{result=\"conflict\"} 0\n",
            "strata_edits_total{result=\"refused\"} 0\n",
            "# HELP strata_worlds_created_total Worlds created.\n",
            "# TYPE strata_worlds_created_total counter\n",
            "strata_worlds_created_total 0\n",
        )));
    }

    /// The family writers give the exact text format: `# HELP`, `# TYPE`, then the samples, one
    /// line each, in the order given.
    #[test]
    fn family_writers() {
        let mut out = String::new();
        labelled(
            &mut out,
            ("x_total", "counter", "Xs by kind."),
            "kind",
            [("a", 1), ("b", 2)],
        );
        single(&mut out, "y", "gauge", "Ys.", 3.5);
        assert_eq!(
            out,
            concat!(
                "# HELP x_total Xs by kind.\n",
                "# TYPE x_total counter\n",
                "x_total{kind=\"a\"} 1\n",
                "x_total{kind=\"b\"} 2\n",
                "# HELP y Ys.\n",
                "# TYPE y gauge\n",
                "y 3.5\n",
            )
        );
    }
}
