//! `strata bench abuse`: what the most expensive requests cost, and what they do to everyone
//! else (issue 18, Done-when 3).
//!
//! 1. **Worst case per route.** One request per product route at its limits (the finest and the
//!    coarsest LOD, the largest sizes, a public world holding a region of 2049² samples with a
//!    hydraulic-erosion brush at its budget), each on a server that has cached nothing of it: the
//!    process CPU time the request took (the server runs in this process and nothing else does
//!    meanwhile, so the process clock counts the request's work, its background work included,
//!    and nothing else), its wall time and the growth of the resident set. Against
//!    [`ROUTE_CPU_BUDGET_MS`].
//! 2. **Noisy neighbours.** Cached-tile requests per second from `wrk` with
//!    [`CONNECTIONS`] connections alone, then while [`CONNECTIONS`] more connections hammer the
//!    most expensive anonymous route of (1) with a new key per request; the target is at least
//!    [`TARGET_HAMMERED_RATIO`] of the quiet figure.
//! 3. **Clients that never read.** [`SILENT_CLIENTS`] WebSocket clients of a seed's stream send
//!    a view and never read: the resident set before and [`SILENT_SECONDS`] s after, per client,
//!    and how many of them the server had closed by then.
//!
//! The server runs in this process on loopback with the CPU backend, a SQLite store in a
//! temporary directory and the accept loop of `strata serve`, with its defaults (the rate
//! limits included); `wrk` is a separate process
//! (`apt-get install wrk`).

use super::emit;
use super::http::{http, http_get};
use crate::bench::BenchArgs;
use crate::compute::Compute;
use crate::cpu_time::process_ms;
use crate::server::{app, AppState};
use crate::store::SqliteStore;
use crate::terrain::earth::rivers::MAX_CARVE_LOD;
use crate::terrain::MAX_LOD;
use crate::volume::chunk::MAX_CHUNK_LOD;
use anyhow::{bail, Context};
use futures::SinkExt;
use serde_json::json;
use std::process::Command;
use std::sync::Arc;
use std::time::{Duration, Instant};
use tokio_tungstenite::tungstenite::Message;

/// The CPU one request may take, milliseconds: two seconds of one core.
pub const ROUTE_CPU_BUDGET_MS: f64 = 2000.0;
/// Target: cached-tile requests per second under the hammer over the quiet figure.
pub const TARGET_HAMMERED_RATIO: f64 = 0.5;
/// Connections of each `wrk` load.
pub const CONNECTIONS: usize = 64;
/// Stream clients that never read.
pub const SILENT_CLIENTS: usize = 200;
/// How long the silent clients stay connected before the resident set is read, seconds.
pub const SILENT_SECONDS: u64 = 12;
/// The cached tile of the throughput figures.
const CACHED_TILE: &str = "/v1/seeds/42/tiles/0/3/-2.bin";

/// Resident set of this process (`VmRSS`), bytes; 0 where it cannot be read.
fn rss_bytes() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix("VmRSS:").map(str::to_owned))
        })
        .and_then(|v| v.split_whitespace().next()?.parse::<u64>().ok())
        .map_or(0, |kib| kib << 10)
}

fn mib(b: f64) -> f64 {
    b / f64::from(1u32 << 20)
}

/// `wrk` with a Lua script, if any, for `seconds`; returns requests per second and the count
/// of non-2xx answers (refusals are expected of a hammer).
fn wrk(url: &str, seconds: u32, script: Option<&std::path::Path>) -> anyhow::Result<(f64, u64)> {
    let mut cmd = Command::new("wrk");
    cmd.args(["-t1", &format!("-c{CONNECTIONS}"), &format!("-d{seconds}s")]);
    if let Some(s) = script {
        cmd.arg("-s").arg(s);
    }
    let out = cmd
        .arg(url)
        .output()
        .context("running wrk (apt-get install wrk)")?;
    let text = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() {
        bail!("wrk failed: {text}{}", String::from_utf8_lossy(&out.stderr));
    }
    let (mut rps, mut errors) = (0.0, 0);
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["Requests/sec:", v, ..] => rps = v.parse().unwrap_or(0.0),
            ["Non-2xx", "or", "3xx", "responses:", n, ..] => errors = n.parse().unwrap_or(0),
            _ => {}
        }
    }
    Ok((rps, errors))
}

/// A Lua script for `wrk` that asks for `prefix .. x .. suffix` with a new `x` per request.
fn walking_script(prefix: &str, suffix: &str) -> String {
    format!(
        "local threads = 0\nfunction setup(thread)\n  thread:set(\"id\", threads)\n  threads = threads + 1\nend\nfunction init(args)\n  n = 0\nend\nfunction request()\n  n = n + 1\n  return wrk.format(\"GET\", \"{prefix}\" .. (n * 7 + id) % 4000 .. \"{suffix}\")\nend\n"
    )
}

/// One route's worst case.
struct Probe {
    name: &'static str,
    path: String,
    /// Whether anyone may ask (seed routes and public worlds).
    anonymous: bool,
    /// For the hammer: the path before and after a varying tile column.
    walk: Option<(String, String)>,
}

/// Runs `strata bench abuse`.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    let dir = std::env::temp_dir().join(format!("strata-bench-abuse-{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let result = run_in(args, &dir);
    let _ = std::fs::remove_dir_all(&dir);
    result
}

fn run_in(args: &BenchArgs, dir: &std::path::Path) -> anyhow::Result<()> {
    let rt = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()?;
    let store = Arc::new(SqliteStore::open_in_dir(dir)?);
    let state = AppState::new(Compute::cpu()).with_worlds(store, None);
    let listener = rt.block_on(tokio::net::TcpListener::bind("127.0.0.1:0"))?;
    let addr = listener.local_addr()?.to_string();
    // The accept loop of `strata serve`: client addresses (which the rate limits key on), read
    // timeouts and the connection cap as a deployed server has them.
    let limits = state.limits();
    rt.spawn(crate::server::connections::serve(
        listener,
        app(state),
        limits,
        tokio_util::sync::CancellationToken::new(),
    ));

    // A public world with the heaviest region a scene may hold: 2049² samples over 8 km and a
    // hydraulic-erosion brush at the region's budget (droplets × steps = 4 194 304).
    let scene = json!({"regions": [{
        "id": "heavy", "bbox": {"min": [0.0, 0.0], "max": [8192.0, 8192.0]}, "samples": 2049,
        "ops": [{"op": "hydraulic_erosion", "center": [4096.0, 4096.0], "radius_m": 4000.0,
                 "droplets": 8192, "steps": 512}]}]});
    let body = json!({"seed": 42, "public": true, "scene": scene}).to_string();
    let (status, created) = rt.block_on(http(
        &addr,
        "POST",
        "/v1/worlds",
        &[("content-type", "application/json")],
        &body,
    ))?;
    anyhow::ensure!(
        status == 201,
        "creating the world answered {status}: {}",
        String::from_utf8_lossy(&created)
    );
    let world: serde_json::Value = serde_json::from_slice(&created)?;
    let id = world["id"].as_str().context("world id")?.to_string();

    let seed = |p: &str| format!("/v1/seeds/7{p}");
    let w = |p: &str| format!("/v1/worlds/{id}{p}");
    let probes = vec![
        Probe {
            name: "seed tile, LOD 0",
            path: seed("/tiles/0/11/-5.bin"),
            anonymous: true,
            walk: Some((seed("/tiles/0/"), "/-5.bin".into())),
        },
        Probe {
            name: "seed tile, finest carved LOD",
            path: seed(&format!("/tiles/{MAX_CARVE_LOD}/2/3.bin")),
            anonymous: true,
            walk: Some((seed(&format!("/tiles/{MAX_CARVE_LOD}/")), "/3.bin".into())),
        },
        Probe {
            name: "seed tile, coarsest LOD",
            path: seed(&format!("/tiles/{MAX_LOD}/0/0.bin")),
            anonymous: true,
            walk: None,
        },
        Probe {
            name: "seed scatter, coarsest LOD",
            path: seed(&format!("/scatter/{MAX_LOD}/0/0.json")),
            anonymous: true,
            walk: None,
        },
        Probe {
            name: "seed scatter, LOD 0",
            path: seed("/scatter/0/4/4.json"),
            anonymous: true,
            walk: Some((seed("/scatter/0/"), "/4.json".into())),
        },
        Probe {
            name: "seed rivers, coarsest LOD served",
            path: seed(&format!("/rivers/{MAX_CARVE_LOD}/1/1.json")),
            anonymous: true,
            walk: Some((seed(&format!("/rivers/{MAX_CARVE_LOD}/")), "/1.json".into())),
        },
        Probe {
            name: "seed chunk, coarsest chunk LOD",
            path: seed(&format!("/chunks/{MAX_CHUNK_LOD}/0/0/0.bin")),
            anonymous: true,
            walk: Some((
                seed(&format!("/chunks/{MAX_CHUNK_LOD}/")),
                "/0/0.bin".into(),
            )),
        },
        Probe {
            name: "world tile over the heavy region (solves it)",
            path: w("/tiles/0/32/32.bin"),
            anonymous: true,
            walk: None,
        },
        Probe {
            name: "world region heightmap.png",
            path: w("/regions/heavy/heightmap.png"),
            anonymous: true,
            walk: None,
        },
        Probe {
            name: "world region stats, whole region",
            path: w("/regions/heavy/stats?rect=0,0;8192,8192"),
            anonymous: true,
            walk: None,
        },
    ];

    let mut worst: Option<(f64, &Probe)> = None;
    for p in &probes {
        let (cpu0, rss0, t0) = (process_ms(), rss_bytes(), Instant::now());
        let (status, bytes) = rt.block_on(http_get(&addr, &p.path))?;
        let wall_ms = t0.elapsed().as_secs_f64() * 1e3;
        // Work the request left behind (a timed-out solve, say) would still be running: wait a
        // moment and count it too.
        std::thread::sleep(Duration::from_millis(200));
        let cpu_ms = process_ms() - cpu0;
        let grew = rss_bytes() as f64 - rss0 as f64;
        let ok = cpu_ms <= ROUTE_CPU_BUDGET_MS;
        // A refusal names its code and field: what the limit answered.
        let refusal = (status >= 400)
            .then(|| serde_json::from_slice::<serde_json::Value>(&bytes).ok())
            .flatten()
            .map(|e| {
                format!(
                    " {} ({})",
                    e["code"].as_str().unwrap_or("?"),
                    e["field"].as_str().unwrap_or("-")
                )
            })
            .unwrap_or_default();
        if p.anonymous && p.walk.is_some() && worst.is_none_or(|(c, _)| cpu_ms > c) {
            worst = Some((cpu_ms, p));
        }
        emit(
            args,
            json!({"bench":"abuse","figure":"route","route":p.name,"path":p.path,"status":status,
                   "bytes":bytes.len(),"refusal":refusal.trim(),"cpu_ms":cpu_ms,"wall_ms":wall_ms,"rss_growth_mib":mib(grew),
                   "budget_cpu_ms":ROUTE_CPU_BUDGET_MS,"meets_target":ok}),
            format!(
                "  {:<46} {status}  CPU {cpu_ms:>8.1} ms  wall {wall_ms:>8.1} ms  RSS {:+7.1} MiB  {}{refusal}",
                p.name,
                mib(grew),
                if ok { "✓" } else { "✗ over budget" }
            ),
        );
    }

    // Noisy neighbours: the cached tile alone, then under the hammer.
    rt.block_on(http_get(&addr, CACHED_TILE))?;
    let cached_url = format!("http://{addr}{CACHED_TILE}");
    let (quiet, _) = wrk(&cached_url, 8, None)?;
    let (_, hammer) = worst.context("no anonymous route to hammer")?;
    let (prefix, suffix) = hammer.walk.clone().context("walk")?;
    let script = dir.join("hammer.lua");
    std::fs::write(&script, walking_script(&prefix, &suffix))?;
    let hammer_url = format!("http://{addr}/");
    let hammer_thread = std::thread::spawn(move || wrk(&hammer_url, 12, Some(&script)));
    std::thread::sleep(Duration::from_secs(2));
    let (loud, _) = wrk(&cached_url, 8, None)?;
    let (hammer_rps, hammer_refused) = hammer_thread
        .join()
        .map_err(|_| anyhow::anyhow!("hammer thread panicked"))??;
    let ratio = loud / quiet;
    emit(
        args,
        json!({"bench":"abuse","figure":"noisy_neighbour","connections":CONNECTIONS,"hammered_route":hammer.name,
               "quiet_requests_per_s":quiet,"hammered_requests_per_s":loud,"ratio":ratio,
               "hammer_requests_per_s":hammer_rps,"hammer_refused":hammer_refused,
               "target_ratio":TARGET_HAMMERED_RATIO,"meets_target":ratio >= TARGET_HAMMERED_RATIO}),
        format!(
            "  cached tile, {CONNECTIONS} connections: {quiet:.0} req/s alone, {loud:.0} req/s while {CONNECTIONS} more hammer \"{}\" ({hammer_rps:.0} req/s, {hammer_refused} refused): ratio {ratio:.2} (target ≥ {TARGET_HAMMERED_RATIO})",
            hammer.name
        ),
    );

    // Clients that never read.
    let before = rss_bytes() as f64;
    let (after, closed) = rt.block_on(silent_clients(&addr))?;
    let per_client = (after - before) / SILENT_CLIENTS as f64;
    emit(
        args,
        json!({"bench":"abuse","figure":"silent_stream_clients","clients":SILENT_CLIENTS,"seconds":SILENT_SECONDS,
               "rss_before_mib":mib(before),"rss_after_mib":mib(after),"per_client_kib":per_client / 1024.0,
               "closed_by_server":closed}),
        format!(
            "  {SILENT_CLIENTS} stream clients that never read, after {SILENT_SECONDS} s: resident {:.0} → {:.0} MiB ({:.0} KiB a client), {closed} closed by the server",
            mib(before),
            mib(after),
            per_client / 1024.0
        ),
    );
    Ok(())
}

/// Connects [`SILENT_CLIENTS`] stream clients that each send one view and never read; returns
/// the resident set after [`SILENT_SECONDS`] and how many connections the server had closed
/// (a write to a closed connection fails).
async fn silent_clients(addr: &str) -> anyhow::Result<(f64, usize)> {
    let mut clients = Vec::with_capacity(SILENT_CLIENTS);
    for i in 0..SILENT_CLIENTS {
        let (mut ws, _) =
            tokio_tungstenite::connect_async(format!("ws://{addr}/v1/seeds/{}/stream", 100 + i))
                .await
                .context("connecting a stream client")?;
        ws.send(Message::Text(
            json!({"type":"view","x":0,"z":0,"rings":[2,2,2,2,2,2,2]})
                .to_string()
                .into(),
        ))
        .await?;
        clients.push(ws);
    }
    tokio::time::sleep(Duration::from_secs(SILENT_SECONDS)).await;
    let after = rss_bytes() as f64;
    let mut closed = 0;
    for ws in &mut clients {
        let ping = ws.send(Message::Ping(Vec::new().into())).await;
        closed += usize::from(ping.is_err());
    }
    Ok((after, closed))
}
