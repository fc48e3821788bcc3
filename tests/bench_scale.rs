//! `strata bench scale` runs end to end with its real parts (a throwaway PostgreSQL cluster,
//! three replicas, nginx, `wrk`) and prints every figure it promises, one JSON object per line
//! with units in the key names. Short runs (`--seconds 1`): the figures themselves are the
//! benchmark's business, not this test's (no timing is asserted).

use serde_json::Value;
use std::process::Command;

#[test]
fn bench_scale_prints_every_figure() {
    let out = Command::new(env!("CARGO_BIN_EXE_strata"))
        .args(["bench", "scale", "--json", "--seconds", "1"])
        .output()
        .expect("run strata bench scale");
    assert!(
        out.status.success(),
        "strata bench scale failed: {}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<Value> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{l:?} is not JSON: {e}")))
        .collect();
    assert!(lines.iter().all(|l| l["bench"] == "scale"));
    let figure =
        |name: &str| -> Vec<&Value> { lines.iter().filter(|l| l["figure"] == name).collect() };
    let positive = |v: &Value, key: &str| {
        let x = v[key]
            .as_f64()
            .unwrap_or_else(|| panic!("{key} missing: {v}"));
        assert!(x > 0.0 && x.is_finite(), "{key} = {x}: {v}");
        x
    };
    let peer = figure("peer_nginx_static");
    assert_eq!(peer.len(), 1);
    positive(peer[0], "requests_per_s");

    let tiles = figure("tiles_through_balancer");
    assert_eq!(
        tiles
            .iter()
            .map(|t| t["replicas"].as_u64())
            .collect::<Vec<_>>(),
        [Some(1), Some(2), Some(3)]
    );
    for t in &tiles {
        for key in [
            "cached_requests_per_s",
            "cached_p99_ms",
            "cached_over_one_replica",
            "cached_over_nginx_static",
        ] {
            positive(t, key);
        }
        // An uncached tile may take longer than a one-second run on a loaded machine: the figure
        // is there, and its ratio is a number or null (no request completed with one replica).
        let uncached = t["uncached_requests_per_s"]
            .as_f64()
            .expect("uncached figure");
        assert!(uncached >= 0.0, "{t}");
        let r = &t["uncached_over_one_replica"];
        assert!(r.is_null() || r.as_f64().is_some_and(|r| r >= 0.0), "{t}");
    }
    assert_eq!(tiles[0]["cached_over_one_replica"], 1.0);
    let ratio =
        positive(tiles[2], "cached_requests_per_s") / positive(tiles[0], "cached_requests_per_s");
    assert!((positive(tiles[2], "cached_over_one_replica") - ratio).abs() < 1e-9);

    let inv = figure("edit_to_invalidation_across_replicas");
    assert_eq!(inv.len(), 1);
    let inv = inv[0];
    assert_eq!(inv["replicas"], 3);
    assert_eq!(inv["subscribers"], 100);
    // Every subscriber, on every replica, was told of every edit.
    assert_eq!(
        inv["samples"].as_u64(),
        Some(100 * inv["edits"].as_u64().expect("edits"))
    );
    assert_eq!(inv["target_p99_ms"], 100.0);
    // Subscriber i is on replica i mod 3: 66 of the 100 are on the replicas the edits (made on
    // the first) reach through PostgreSQL.
    assert_eq!(
        inv["other_replicas_samples"].as_u64(),
        Some(66 * inv["edits"].as_u64().expect("edits"))
    );
    let ms = |key: &str| {
        let x = inv[key]
            .as_f64()
            .unwrap_or_else(|| panic!("{key} missing: {inv}"));
        assert!(x >= 0.0 && x.is_finite(), "{key} = {x}");
        x
    };
    assert!(ms("p50_ms") <= ms("p99_ms") && ms("p99_ms") <= ms("max_ms"));
    assert!(ms("other_replicas_p50_ms") <= ms("other_replicas_p99_ms"));
    assert!(ms("other_replicas_p99_ms") <= ms("max_ms"));
}
