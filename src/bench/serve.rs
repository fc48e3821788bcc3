//! `strata bench serve`: the service under load (issue 3, Done-when 8).
//!
//! 1. Cached-tile requests per second and p50/p99 latency at 64 concurrent connections, measured
//!    with `wrk` against this server, and the same load against Debian's nginx serving the same
//!    tile bytes from files, in the same run; the ratio's target is ≥ 0.5.
//! 2. The time from an edit's acknowledgement (the HTTP 200) to its invalidation reaching each of
//!    100 subscribed WebSocket clients, for tiles and for volume chunks (`serve_edits.rs`); the
//!    target is p99 ≤ 50 ms.
//!
//! 3. Resident memory under an uncached load: `wrk` asks for a new tile with every request (a
//!    script walks the keys), so every cache fills to its share of the memory budget
//!    (`server::budget`); the process's peak resident set (`VmHWM` of `/proc/self/status`, the
//!    server being in this process) is reported against the budget, as a ratio, and what it
//!    holds beyond the budget is the fixed overhead (code, runtime, the `earth-1` river block
//!    caches, requests in flight, allocator slack).
//!
//! The server runs in this process on loopback with the CPU backend and an in-memory store; `wrk`
//! and `nginx` are separate processes (`apt-get install wrk nginx-light`).

use super::emit;
use super::http::http_get;
use super::serve_edits::{self, SUBSCRIBERS, TARGET_INVALIDATION_P99_MS};
use crate::bench::BenchArgs;
use crate::compute::Compute;
use crate::server::{app, AppState};
use anyhow::{bail, Context};
use serde_json::json;
use std::process::{Command, Stdio};

/// Target: our requests per second over nginx's.
pub const TARGET_RATIO: f64 = 0.5;
/// Concurrent connections of the throughput test.
pub const CONNECTIONS: usize = 64;
/// The tile requested by the throughput test.
const TILE_PATH: &str = "/v1/seeds/42/tiles/0/3/-2.bin";

/// What `wrk` reported.
#[derive(Debug, Clone, Copy)]
pub(crate) struct WrkFigures {
    /// Requests per second.
    pub requests_per_s: f64,
    /// Median latency, milliseconds.
    pub p50_ms: f64,
    /// 99th percentile latency, milliseconds.
    pub p99_ms: f64,
}

pub(crate) fn need(tool: &str) -> anyhow::Result<()> {
    match Command::new(tool)
        .arg("-v")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
    {
        Ok(_) => Ok(()),
        Err(_) => bail!("`{tool}` is not installed; on Debian: apt-get install wrk nginx-light"),
    }
}

fn parse_ms(s: &str) -> Option<f64> {
    let s = s.trim();
    let (num, unit) = s.split_at(s.find(|c: char| c.is_ascii_alphabetic())?);
    let v: f64 = num.parse().ok()?;
    Some(match unit {
        "us" => v / 1000.0,
        "ms" => v,
        "s" => v * 1000.0,
        "m" => v * 60_000.0,
        _ => return None,
    })
}

pub(crate) fn wrk(url: &str, seconds: u32) -> anyhow::Result<WrkFigures> {
    wrk_with(url, seconds, None)
}

/// `wrk` with a request script, if any.
pub(crate) fn wrk_with(
    url: &str,
    seconds: u32,
    script: Option<&std::path::Path>,
) -> anyhow::Result<WrkFigures> {
    let mut cmd = Command::new("wrk");
    cmd.args([
        "-t2",
        &format!("-c{CONNECTIONS}"),
        &format!("-d{seconds}s"),
        "--latency",
    ]);
    if let Some(script) = script {
        cmd.arg("-s").arg(script);
    }
    let out = cmd.arg(url).output().context("running wrk")?;
    let text = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() {
        bail!("wrk failed: {text}{}", String::from_utf8_lossy(&out.stderr));
    }
    let mut f = WrkFigures {
        requests_per_s: 0.0,
        p50_ms: f64::NAN,
        p99_ms: f64::NAN,
    };
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["Requests/sec:", v, ..] => f.requests_per_s = v.parse().unwrap_or(0.0),
            ["50%", v, ..] => f.p50_ms = parse_ms(v).unwrap_or(f64::NAN),
            ["99%", v, ..] => f.p99_ms = parse_ms(v).unwrap_or(f64::NAN),
            _ => {}
        }
    }
    if text.contains("Non-2xx") {
        bail!("wrk saw error responses:\n{text}");
    }
    Ok(f)
}

/// A `wrk` script asking for a tile key of seed `seed` per request, distinct across wrk's
/// threads: every request misses every cache.
pub(crate) fn uncached_script(seed: u64) -> String {
    UNCACHED_SCRIPT.replace("/v1/seeds/43/", &format!("/v1/seeds/{seed}/"))
}

/// [`uncached_script`] of seed 43.
const UNCACHED_SCRIPT: &str = r#"
local threads = 0
function setup(thread)
  thread:set("id", threads)
  threads = threads + 1
end
function init(args)
  n = 0
end
function request()
  n = n + 1
  local k = n * 2 + id
  local x = k % 2000 - 1000
  local z = math.floor(k / 2000) - 1000
  return wrk.format("GET", "/v1/seeds/43/tiles/0/" .. x .. "/" .. z .. ".bin")
end
"#;

/// A figure of `/proc/self/status` (`VmRSS`, `VmHWM`), bytes; 0 where there is none.
fn proc_status_bytes(field: &str) -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix(field)?.strip_prefix(':').map(str::to_owned))
        })
        .and_then(|v| v.split_whitespace().next()?.parse::<u64>().ok())
        .map_or(0, |kib| kib << 10)
}

/// Runs `strata bench serve`.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    need("wrk")?;
    need("nginx")?;
    let rt = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()?;
    let state = AppState::new(Compute::cpu());
    let budget = state.memory_budget().total as f64;
    let listener = rt.block_on(tokio::net::TcpListener::bind("127.0.0.1:0"))?;
    let addr = listener.local_addr()?;
    rt.spawn(async move {
        let _ = axum::serve(listener, app(state)).await;
    });
    let seconds = 10;

    // The same bytes from nginx.
    let dir = std::env::temp_dir().join(format!("strata-bench-nginx-{}", std::process::id()));
    let root = dir.join("root");
    let tile_file = root.join(TILE_PATH.trim_start_matches('/'));
    std::fs::create_dir_all(tile_file.parent().context("tile dir")?)?;
    let body = rt.block_on(async {
        let (status, body) = http_get(&addr.to_string(), TILE_PATH).await?;
        anyhow::ensure!(status == 200, "warm-up request answered {status}");
        anyhow::Ok(body)
    })?;
    std::fs::write(&tile_file, &body)?;
    let nginx = crate::harness::nginx::static_files(&dir, &root)?;
    let ours = wrk(&format!("http://{addr}{TILE_PATH}"), seconds);
    let theirs = wrk(&format!("http://{}{TILE_PATH}", nginx.addr), seconds);
    drop(nginx);
    let _ = std::fs::remove_dir_all(&dir);
    let (ours, theirs) = (ours?, theirs?);
    let ratio = ours.requests_per_s / theirs.requests_per_s;
    emit(
        args,
        json!({"bench":"serve","figure":"cached_tile","connections":CONNECTIONS,"tile_bytes":body.len(),
               "requests_per_s":ours.requests_per_s,"p50_ms":ours.p50_ms,"p99_ms":ours.p99_ms,
               "nginx_requests_per_s":theirs.requests_per_s,"nginx_p50_ms":theirs.p50_ms,"nginx_p99_ms":theirs.p99_ms,
               "ratio":ratio,"target_ratio":TARGET_RATIO,"meets_target":ratio >= TARGET_RATIO}),
        format!(
            "serve: cached {}-byte tile, {CONNECTIONS} connections, {seconds} s each\n  strata: {:.0} req/s, p50 {:.2} ms, p99 {:.2} ms\n  nginx:  {:.0} req/s, p50 {:.2} ms, p99 {:.2} ms\n  ratio {ratio:.2} (target ≥ {TARGET_RATIO})",
            body.len(),
            ours.requests_per_s,
            ours.p50_ms,
            ours.p99_ms,
            theirs.requests_per_s,
            theirs.p50_ms,
            theirs.p99_ms
        ),
    );

    let script =
        std::env::temp_dir().join(format!("strata-bench-uncached-{}.lua", std::process::id()));
    std::fs::write(&script, UNCACHED_SCRIPT)?;
    let before = proc_status_bytes("VmRSS") as f64;
    let uncached = wrk_with(&format!("http://{addr}/"), 2 * seconds, Some(&script));
    let _ = std::fs::remove_file(&script);
    let uncached = uncached?;
    let (rss, peak) = (
        proc_status_bytes("VmRSS") as f64,
        proc_status_bytes("VmHWM") as f64,
    );
    let mib = |b: f64| b / f64::from(1u32 << 20);
    emit(
        args,
        json!({"bench":"serve","figure":"uncached_memory","connections":CONNECTIONS,"seconds":2 * seconds,
               "requests_per_s":uncached.requests_per_s,"p50_ms":uncached.p50_ms,"p99_ms":uncached.p99_ms,
               "memory_budget_mib":mib(budget),"rss_before_mib":mib(before),"rss_mib":mib(rss),"peak_rss_mib":mib(peak),
               "peak_rss_over_budget":peak / budget,"overhead_mib":mib(peak - budget)}),
        format!(
            "  uncached tiles, {CONNECTIONS} connections, {} s: {:.0} req/s, p50 {:.2} ms, p99 {:.2} ms\n  resident memory: peak {:.0} MiB, now {:.0} MiB, {:.0} MiB before the load, against a cache budget of {:.0} MiB: peak/budget {:.2}, fixed overhead {:.0} MiB",
            2 * seconds,
            uncached.requests_per_s,
            uncached.p50_ms,
            uncached.p99_ms,
            mib(peak),
            mib(rss),
            mib(before),
            mib(budget),
            peak / budget,
            mib(peak - budget)
        ),
    );

    for (figure, what, lat) in [
        (
            "edit_to_invalidation",
            "tiles",
            rt.block_on(serve_edits::tile_latency(addr.to_string(), 20))?,
        ),
        (
            "edit_to_chunk_invalidation",
            "chunks",
            rt.block_on(serve_edits::chunk_latency(addr.to_string(), 10))?,
        ),
    ] {
        let (p50, p99, max) = serve_edits::percentiles(&lat);
        emit(
            args,
            json!({"bench":"serve","figure":figure,"subscribers":SUBSCRIBERS,"samples":lat.len(),
                   "p50_ms":p50,"p99_ms":p99,"max_ms":max,"target_p99_ms":TARGET_INVALIDATION_P99_MS,
                   "meets_target":p99 <= TARGET_INVALIDATION_P99_MS}),
            format!(
                "  edit → invalidation of {what} at {SUBSCRIBERS} clients: p50 {p50:.2} ms, p99 {p99:.2} ms, max {max:.2} ms over {} deliveries (target p99 ≤ {TARGET_INVALIDATION_P99_MS} ms)",
                lat.len()
            ),
        );
    }
    Ok(())
}
