//! `strata bench scale`: replicas behind a load balancer (issue 21, Done-when 2 and "What to
//! build" 5).
//!
//! It starts a throwaway PostgreSQL cluster, three `strata serve` replicas of this binary on one
//! database (CPU backend, the rate limit lifted so the load is not refused) and Debian's nginx
//! in front of the first one, two and three of them ([`crate::harness`]), all on loopback, then
//! measures with `wrk` ([`super::serve`]'s runner, 64 connections, `--seconds` each, 10 by
//! default):
//!
//! 1. **Cached tiles** through the balancer with 1, 2 and 3 replicas (every replica has served
//!    the tile once), with the ratio to the 1-replica figure and to nginx serving the same
//!    bytes from a file (the peer, measured in the same run).
//! 2. **Uncached tiles** through the balancer: every request a new tile key, a new seed for each
//!    replica count so that no replica's cache holds it (its plan built on every replica
//!    before the run); ratio to the 1-replica figure.
//! 3. **Edit → invalidation across replicas**: [`super::serve_edits::SUBSCRIBERS`] stream subscribers
//!    spread round robin over the three replicas, edits made on the first; the time from each
//!    edit's acknowledgement to each subscriber's `invalidate`, p50 and p99 against
//!    [`TARGET_INVALIDATION_P99_MS`].
//!
//! On a machine with few cores the replicas, nginx and `wrk` share them, so the curve flattens;
//! the figures are what was measured, not extrapolated.

use super::emit;
use super::http::http_get;
use super::serve::{need, uncached_script, wrk, wrk_with};
use super::serve_edits::{tile_latency_across, SUBSCRIBERS};
use crate::bench::BenchArgs;
use crate::harness::{nginx, postgres::Cluster, replica};
use anyhow::Context;
use serde_json::json;

/// Target: p99 edit-to-invalidation latency across replicas, milliseconds.
pub const TARGET_INVALIDATION_P99_MS: f64 = 100.0;
/// Replicas started.
pub const REPLICAS: usize = 3;
/// The tile of the cached figures.
const TILE_PATH: &str = "/v1/seeds/42/tiles/0/3/-2.bin";
/// Edits of the invalidation figure.
const EDITS: usize = 20;

/// Runs `strata bench scale`.
pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    need("wrk")?;
    nginx::binary()?;
    let dir = std::env::temp_dir().join(format!("strata-bench-scale-{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let result = measure(args, &dir);
    let _ = std::fs::remove_dir_all(&dir);
    result
}

fn measure(args: &BenchArgs, dir: &std::path::Path) -> anyhow::Result<()> {
    let rt = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()?;
    let cluster = Cluster::start()?;
    let url = rt.block_on(cluster.database("bench_scale"))?;
    let exe = std::env::current_exe().context("the strata binary")?;
    let mut replicas = Vec::new();
    for i in 0..REPLICAS {
        let data = dir.join(format!("replica-{i}"));
        let data = data.to_str().context("a UTF-8 temporary directory")?;
        let web = dir.join("no-viewer");
        replicas.push(replica::start(
            &exe,
            &[
                "--data",
                data,
                "--store",
                &url,
                "--rate-limit",
                "1000000000",
                "--web",
                web.to_str().context("a UTF-8 temporary directory")?,
            ],
        )?);
    }
    let addrs: Vec<String> = replicas.iter().map(|r| r.addr.clone()).collect();
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    emit(
        args,
        json!({"bench":"scale","replicas":REPLICAS,"cores":cores,"connections":super::serve::CONNECTIONS,
               "seconds_per_run":args.seconds}),
        format!(
            "scale: {REPLICAS} replicas on one PostgreSQL, nginx in front, {cores} cores, {} connections, {} s per run",
            super::serve::CONNECTIONS,
            args.seconds
        ),
    );

    // Every replica serves the tile once, so the cached figures hit every replica's cache.
    let mut body = Vec::new();
    for addr in &addrs {
        let (status, b) = rt.block_on(http_get(addr, TILE_PATH))?;
        anyhow::ensure!(status == 200, "warm-up request to {addr} answered {status}");
        body = b;
    }
    let root = dir.join("static");
    let file = root.join(TILE_PATH.trim_start_matches('/'));
    std::fs::create_dir_all(file.parent().context("tile directory")?)?;
    std::fs::write(&file, &body)?;
    let peer_dir = dir.join("nginx-static");
    std::fs::create_dir_all(&peer_dir)?;
    let peer = {
        let nginx = nginx::static_files(&peer_dir, &root)?;
        wrk(&format!("http://{}{TILE_PATH}", nginx.addr), args.seconds)?
    };
    emit(
        args,
        json!({"bench":"scale","figure":"peer_nginx_static","tile_bytes":body.len(),
               "requests_per_s":peer.requests_per_s,"p50_ms":peer.p50_ms,"p99_ms":peer.p99_ms}),
        format!(
            "  peer: nginx serving the {}-byte tile from a file: {:.0} req/s, p50 {:.2} ms, p99 {:.2} ms",
            body.len(),
            peer.requests_per_s,
            peer.p50_ms,
            peer.p99_ms
        ),
    );

    let script = dir.join("uncached.lua");
    let mut first: Option<(f64, f64)> = None;
    for n in 1..=REPLICAS {
        let lb_dir = dir.join(format!("nginx-{n}"));
        std::fs::create_dir_all(&lb_dir)?;
        let upstreams: Vec<&str> = addrs[..n].iter().map(String::as_str).collect();
        let lb = nginx::balancer(&lb_dir, &upstreams)?;
        let cached = wrk(&format!("http://{}{TILE_PATH}", lb.addr), args.seconds)?;
        // A new seed for each replica count, its plan built on every replica first (a tile
        // outside the script's keys), so the run measures tiles, not the seed's first request.
        let seed = 100 + n as u64;
        for addr in &addrs[..n] {
            let (status, _) = rt.block_on(http_get(
                addr,
                &format!("/v1/seeds/{seed}/tiles/0/5000/0.bin"),
            ))?;
            anyhow::ensure!(status == 200, "warm-up request to {addr} answered {status}");
        }
        std::fs::write(&script, uncached_script(seed))?;
        let uncached = wrk_with(&format!("http://{}/", lb.addr), args.seconds, Some(&script))?;
        drop(lb);
        let (c1, u1) = *first.get_or_insert((cached.requests_per_s, uncached.requests_per_s));
        let over_one = ratio(cached.requests_per_s, c1);
        let over_peer = ratio(cached.requests_per_s, peer.requests_per_s);
        let uncached_over_one = ratio(uncached.requests_per_s, u1);
        emit(
            args,
            json!({"bench":"scale","figure":"tiles_through_balancer","replicas":n,
                   "cached_requests_per_s":cached.requests_per_s,"cached_p50_ms":cached.p50_ms,
                   "cached_p99_ms":cached.p99_ms,"cached_over_one_replica":over_one,
                   "cached_over_nginx_static":over_peer,
                   "uncached_requests_per_s":uncached.requests_per_s,"uncached_p50_ms":uncached.p50_ms,
                   "uncached_p99_ms":uncached.p99_ms,"uncached_over_one_replica":uncached_over_one}),
            format!(
                "  {n} replica(s): cached {:.0} req/s (p99 {:.2} ms; ×{} of 1 replica, ×{} of nginx static), uncached {:.0} req/s (p99 {:.2} ms; ×{} of 1 replica)",
                cached.requests_per_s,
                cached.p99_ms,
                shown(over_one),
                shown(over_peer),
                uncached.requests_per_s,
                uncached.p99_ms,
                shown(uncached_over_one)
            ),
        );
    }

    let deliveries = rt.block_on(tile_latency_across(addrs[0].clone(), &addrs, EDITS))?;
    let all = percentiles(deliveries.iter().map(|d| d.1).collect())?;
    // The subscribers of the other replicas: the edit reaches them through PostgreSQL.
    let remote = percentiles(
        deliveries
            .iter()
            .filter(|d| d.0 != 0)
            .map(|d| d.1)
            .collect(),
    )?;
    let meets = all.p99 <= TARGET_INVALIDATION_P99_MS;
    emit(
        args,
        json!({"bench":"scale","figure":"edit_to_invalidation_across_replicas","replicas":REPLICAS,
               "subscribers":SUBSCRIBERS,"edits":EDITS,"samples":all.n,"p50_ms":all.p50,"p99_ms":all.p99,
               "max_ms":all.max,"other_replicas_samples":remote.n,"other_replicas_p50_ms":remote.p50,
               "other_replicas_p99_ms":remote.p99,"target_p99_ms":TARGET_INVALIDATION_P99_MS,
               "meets_target":meets}),
        format!(
            "  edit → invalidation, {SUBSCRIBERS} subscribers over {REPLICAS} replicas, edits on the first: p50 {:.2} ms, p99 {:.2} ms (target ≤ {TARGET_INVALIDATION_P99_MS} ms{}), max {:.2} ms over {} deliveries; at the other replicas' {} deliveries: p50 {:.2} ms, p99 {:.2} ms",
            all.p50,
            all.p99,
            if meets { ", met" } else { ", NOT met" },
            all.max,
            all.n,
            remote.n,
            remote.p50,
            remote.p99
        ),
    );
    drop(replicas);
    drop(cluster);
    Ok(())
}

/// `a / b`, or `None` when `b` is not positive (a run that completed no request).
fn ratio(a: f64, b: f64) -> Option<f64> {
    (b > 0.0).then(|| a / b)
}

/// A ratio as printed: two decimals, or `n/a`.
fn shown(r: Option<f64>) -> String {
    r.map_or_else(|| "n/a".into(), |r| format!("{r:.2}"))
}

/// Percentiles of a set of latencies, milliseconds.
struct Percentiles {
    n: usize,
    p50: f64,
    p99: f64,
    max: f64,
}

fn percentiles(mut v: Vec<f64>) -> anyhow::Result<Percentiles> {
    anyhow::ensure!(!v.is_empty(), "no invalidation was measured");
    v.sort_by(f64::total_cmp);
    let at = |p: f64| v[((v.len() as f64 - 1.0) * p).round() as usize];
    Ok(Percentiles {
        n: v.len(),
        p50: at(0.5),
        p99: at(0.99),
        max: v[v.len() - 1],
    })
}
