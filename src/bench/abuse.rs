//! `strata bench abuse`: what the most expensive requests cost, and what they do to everyone
//! else (issue 18, Done-when 3).
//!
//! 1. **Worst case per route.** One request per product route at its limits (the finest and the
//!    coarsest LOD, the largest sizes, a public world holding the heaviest region a scene may
//!    accept: the most samples, erosion with the rest of its work budget; the Ptex pages of a
//!    tile at the largest `res` that fits and over it, and of a chunk over its limit, then at
//!    the largest `res` the refusal names), each on a server that has cached nothing of it (but
//!    the chunk page at its limit, whose tiles its refusal cached): the
//!    process CPU time the request took (the server runs in this process and nothing else does
//!    meanwhile, so the process clock counts the request's work, its background work included,
//!    and nothing else), its wall time and the growth of the resident set. Against
//!    [`ROUTE_CPU_BUDGET_MS`].
//! 2. **Noisy neighbours.** Cached-tile requests per second from `wrk` with
//!    [`CONNECTIONS`] connections alone, then while [`CONNECTIONS`] more connections hammer the
//!    most expensive anonymous route of (1) with a new key per request; the target is at least
//!    [`TARGET_HAMMERED_RATIO`] of the quiet figure. The peer in the same run: the cached-tile
//!    figure while the same connections ask for `/healthz`, the cheapest route, which is what
//!    any load costs on this machine (the `wrk`s share its cores with the server).
//! 3. **Clients that never read.** [`SILENT_CLIENTS`] WebSocket clients, each of its own seed,
//!    connect, then send a view and never read: the resident set, less the caches' growth (which
//!    their budget bounds), per client once connected and [`SILENT_SECONDS`] s after the views,
//!    against [`crate::stream::session::CLIENT_MEMORY_BOUND`], and how many of them the server
//!    had closed by then.
//!
//! The server runs in this process on loopback with the CPU backend, a SQLite store in a
//! temporary directory and the accept loop of `strata serve`, with its defaults (the rate
//! limits included); `wrk` is a separate process
//! (`apt-get install wrk`).

use super::emit;
use super::http::{http, http_get};
use crate::authoring::spec_tools::{MAX_ACCEPTED_SAMPLES, MAX_REGION_CELL_STEPS, SOLVE_CELL_STEPS};
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
#[derive(Clone)]
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

    // A public world with the heaviest region a scene may hold: the most samples a region may
    // be given over 8 km, a gradient brush (so the thermal brush after it reads a real solve),
    // then thermal erosion with the rest of the region's work budget (its sweeps cost 10 ns a
    // cell step, the unit of the budget, and hydraulic droplet steps less than their share).
    let samples = MAX_ACCEPTED_SAMPLES;
    let cells = (samples * samples) as u64;
    let iterations = (MAX_REGION_CELL_STEPS - 2 * SOLVE_CELL_STEPS * cells) / cells;
    let scene = json!({"regions": [{
        "id": "heavy", "bbox": {"min": [0.0, 0.0], "max": [8192.0, 8192.0]}, "samples": samples,
        "ops": [{"op": "amplify", "center": [4096.0, 4096.0], "radius_m": 2000.0, "factor": 1.5},
                {"op": "erosion", "center": [4096.0, 4096.0], "radius_m": 4000.0,
                 "iterations": iterations}]}]});
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
            name: "seed Ptex tile page, largest res (128)",
            path: seed("/ptex/tiles/0/5/-3?res=128"),
            anonymous: true,
            walk: Some((seed("/ptex/tiles/0/"), "/-3?res=128".into())),
        },
        Probe {
            name: "seed Ptex tile page, res 256 (over its limit)",
            path: seed("/ptex/tiles/0/6/-3?res=256"),
            anonymous: true,
            walk: None,
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

    let mut worst: Option<(f64, Probe)> = None;
    for p in &probes {
        measure(args, &rt, &addr, p, &mut worst)?;
    }
    // A Ptex chunk page: first over its limit (refused after meshing, naming the largest res
    // that fits), then at that res (its tiles cached by the refusal; the bake is the cost).
    let y = ground_chunk_y(PTEX_CHUNK_SEED)?;
    let over = Probe {
        name: "seed Ptex chunk page, res 256 (over its limit)",
        path: format!("/v1/seeds/{PTEX_CHUNK_SEED}/ptex/0/0/{y}/0?res=256"),
        anonymous: true,
        walk: None,
    };
    let refusal = measure(args, &rt, &addr, &over, &mut worst)?;
    let fits = refusal
        .split("res ")
        .last()
        .and_then(|r| r.strip_suffix(" fits"))
        .and_then(|r| r.parse::<u32>().ok());
    if let Some(res) = fits {
        let at_limit = Probe {
            name: "seed Ptex chunk page, largest res that fits",
            path: format!("/v1/seeds/{PTEX_CHUNK_SEED}/ptex/0/0/{y}/0?res={res}"),
            anonymous: true,
            walk: Some((
                format!("/v1/seeds/{PTEX_CHUNK_SEED}/ptex/0/"),
                format!("/{y}/0?res={res}"),
            )),
        };
        measure(args, &rt, &addr, &at_limit, &mut worst)?;
    }

    // Noisy neighbours: the cached tile alone, then under the hammer.
    rt.block_on(http_get(&addr, CACHED_TILE))?;
    let cached_url = format!("http://{addr}{CACHED_TILE}");
    let (quiet, _) = wrk(&cached_url, 8, None)?;
    // The peer: the same load on the cheapest route there is (`/healthz`), so the figure below
    // can be read as what any 64 connections take from 2 cores shared with two `wrk`s.
    let control_thread = {
        let url = format!("http://{addr}/healthz");
        std::thread::spawn(move || wrk(&url, 12, None))
    };
    std::thread::sleep(Duration::from_secs(2));
    let (control, _) = wrk(&cached_url, 8, None)?;
    control_thread
        .join()
        .map_err(|_| anyhow::anyhow!("control thread panicked"))??;
    let (_, hammer) = worst.context("no anonymous route to hammer")?;
    let hammer = &hammer;
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
    let control_ratio = control / quiet;
    emit(
        args,
        json!({"bench":"abuse","figure":"noisy_neighbour","connections":CONNECTIONS,"hammered_route":hammer.name,
               "quiet_requests_per_s":quiet,"hammered_requests_per_s":loud,"ratio":ratio,
               "hammer_requests_per_s":hammer_rps,"hammer_refused":hammer_refused,
               "healthz_loaded_requests_per_s":control,"healthz_loaded_ratio":control_ratio,
               "target_ratio":TARGET_HAMMERED_RATIO,"meets_target":ratio >= TARGET_HAMMERED_RATIO}),
        format!(
            "  cached tile, {CONNECTIONS} connections: {quiet:.0} req/s alone, {loud:.0} req/s while {CONNECTIONS} more hammer \"{}\" ({hammer_rps:.0} req/s, {hammer_refused} refused): ratio {ratio:.2} (target ≥ {TARGET_HAMMERED_RATIO}); \
             {control:.0} req/s while {CONNECTIONS} more ask for /healthz: ratio {control_ratio:.2}",
            hammer.name
        ),
    );

    // Clients that never read: first connected (each on its own seed, so each holds its own
    // world plan), then each with a view it never reads. The caches' growth (within their
    // budget) is taken out of the per-client figure.
    let silent = rt.block_on(silent_clients(&addr))?;
    let per_client = |a: &Snapshot, b: &Snapshot| {
        ((b.rss - a.rss) - (b.caches - a.caches)) / SILENT_CLIENTS as f64
    };
    let (connected, viewing) = (
        per_client(&silent[0], &silent[1]),
        per_client(&silent[1], &silent[2]),
    );
    let bound = crate::stream::session::CLIENT_MEMORY_BOUND as f64;
    let closed = silent[2].closed;
    emit(
        args,
        json!({"bench":"abuse","figure":"silent_stream_clients","clients":SILENT_CLIENTS,"seconds":SILENT_SECONDS,
               "rss_before_mib":mib(silent[0].rss),"rss_after_mib":mib(silent[2].rss),
               "cache_growth_mib":mib(silent[2].caches - silent[0].caches),
               "connected_per_client_kib":connected / 1024.0,"viewing_per_client_kib":viewing / 1024.0,
               "client_memory_bound_kib":bound / 1024.0,"closed_by_server":closed,
               "meets_target":viewing <= bound}),
        format!(
            "  {SILENT_CLIENTS} stream clients of distinct seeds that never read: resident {:.0} → {:.0} MiB, caches +{:.0} MiB; \
             per client {:.0} KiB connected (its seed's plan), {:.0} KiB more with a view after {SILENT_SECONDS} s \
             (bound {:.0} KiB); {closed} closed by the server",
            mib(silent[0].rss),
            mib(silent[2].rss),
            mib(silent[2].caches - silent[0].caches),
            connected / 1024.0,
            viewing / 1024.0,
            bound / 1024.0
        ),
    );
    Ok(())
}

/// Measures one request of `p` on the server at `addr` and prints its row; keeps in `worst`
/// the costliest anonymous probe that can be hammered. The refusal's message, if refused.
fn measure(
    args: &BenchArgs,
    rt: &tokio::runtime::Runtime,
    addr: &str,
    p: &Probe,
    worst: &mut Option<(f64, Probe)>,
) -> anyhow::Result<String> {
    let (cpu0, rss0, t0) = (process_ms(), rss_bytes(), Instant::now());
    let (status, bytes) = rt.block_on(http_get(addr, &p.path))?;
    let wall_ms = t0.elapsed().as_secs_f64() * 1e3;
    // Work the request left behind (a timed-out solve, say) would still be running: wait a
    // moment and count it too.
    std::thread::sleep(Duration::from_millis(200));
    let cpu_ms = process_ms() - cpu0;
    let grew = rss_bytes() as f64 - rss0 as f64;
    let ok = cpu_ms <= ROUTE_CPU_BUDGET_MS;
    // A refusal names its code and field: what the limit answered.
    let error = (status >= 400)
        .then(|| serde_json::from_slice::<serde_json::Value>(&bytes).ok())
        .flatten()
        .map(|e| e["error"].clone());
    let refusal = error
        .as_ref()
        .map(|e| {
            format!(
                " {} ({})",
                e["code"].as_str().unwrap_or("?"),
                e["field"].as_str().unwrap_or("-")
            )
        })
        .unwrap_or_default();
    if p.anonymous && p.walk.is_some() && worst.as_ref().is_none_or(|(c, _)| cpu_ms > *c) {
        *worst = Some((cpu_ms, p.clone()));
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
    Ok(error
        .and_then(|e| e["message"].as_str().map(str::to_owned))
        .unwrap_or_default())
}

/// The seed of the Ptex chunk probes; no other probe reads it.
const PTEX_CHUNK_SEED: u64 = 9;

/// The LOD-0 chunk layer `y` holding the ground at the middle of chunk column (0, 0) of `seed`,
/// from one tile synthesised in this process (which warms the river network near it).
fn ground_chunk_y(seed: u64) -> anyhow::Result<i64> {
    let plan = crate::terrain::WorldPlan::new(seed, crate::terrain::WorldParams::default())
        .map_err(|e| anyhow::anyhow!("the default world of seed {seed}: {e}"))?;
    let tile =
        crate::terrain::tile::synthesize(&plan, crate::terrain::TileKey { lod: 0, x: 0, z: 0 });
    Ok((tile.heights[16 * 65 + 16] / 32.0).floor() as i64)
}

/// The process's resident set and the caches' bytes at one moment, and how many silent clients
/// the server had closed by then.
struct Snapshot {
    rss: f64,
    caches: f64,
    closed: usize,
}

/// The bytes the server's caches count (`strata_cache_bytes` summed over caches, from
/// `/metrics`).
async fn cache_bytes(addr: &str) -> anyhow::Result<f64> {
    let (_, body) = http_get(addr, "/metrics").await?;
    Ok(String::from_utf8_lossy(&body)
        .lines()
        .filter(|l| l.starts_with("strata_cache_bytes{"))
        .filter_map(|l| l.rsplit(' ').next()?.parse::<f64>().ok())
        .sum())
}

async fn snapshot(addr: &str, closed: usize) -> anyhow::Result<Snapshot> {
    Ok(Snapshot {
        rss: rss_bytes() as f64,
        caches: cache_bytes(addr).await?,
        closed,
    })
}

/// Connects [`SILENT_CLIENTS`] stream clients of distinct seeds; then each sends one view and
/// never reads. Snapshots before, once connected, and [`SILENT_SECONDS`] after the views (with
/// how many connections the server had closed: a write to a closed connection fails).
async fn silent_clients(addr: &str) -> anyhow::Result<[Snapshot; 3]> {
    let start = snapshot(addr, 0).await?;
    let mut clients = Vec::with_capacity(SILENT_CLIENTS);
    for i in 0..SILENT_CLIENTS {
        let (ws, _) =
            tokio_tungstenite::connect_async(format!("ws://{addr}/v1/seeds/{}/stream", 100 + i))
                .await
                .context("connecting a stream client")?;
        clients.push(ws);
    }
    tokio::time::sleep(Duration::from_secs(1)).await;
    let connected = snapshot(addr, 0).await?;
    for ws in &mut clients {
        ws.send(Message::Text(
            json!({"type":"view","x":0,"z":0,"rings":[2,2,2,2,2,2,2]})
                .to_string()
                .into(),
        ))
        .await?;
    }
    tokio::time::sleep(Duration::from_secs(SILENT_SECONDS)).await;
    let mut closed = 0;
    let viewing_rss = rss_bytes() as f64;
    for ws in &mut clients {
        let ping = ws.send(Message::Ping(Vec::new().into())).await;
        closed += usize::from(ping.is_err());
    }
    let mut viewing = snapshot(addr, closed).await?;
    viewing.rss = viewing_rss;
    Ok([start, connected, viewing])
}
