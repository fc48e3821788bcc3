//! The real `strata export` command (issue 18, finding 10): `--region x0,z0,x1,z1` as the README
//! documents it, negative coordinates included, writes the archive the server's export job writes
//! for the same region; bad arguments are clap errors (exit code 2); `--help` reads cleanly.

use axum::http::{Method, StatusCode};
use serde_json::json;
use std::process::{Command, Output};
use std::time::Duration;
use strata::compute::Compute;
use strata::server::{app, AppState};

mod common;
use common::oneshot::send;

fn strata(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_strata"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .expect("run strata")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The archive of the server's export job of seed 7's world at LOD 1 over `region`.
async fn server_archive(jobs: &std::path::Path, region: [i64; 4]) -> Vec<u8> {
    let app = app(AppState::new(Compute::cpu()).with_jobs_dir(jobs));
    let json_type = [("content-type", "application/json".to_string())];
    let r = send(
        &app,
        Method::POST,
        "/v1/worlds",
        &json_type,
        Some(br#"{"seed":7}"#),
    )
    .await;
    let world = r.status_is(StatusCode::CREATED).json();
    let id = world["id"].as_str().expect("id");
    let auth = format!(
        "Bearer {}",
        world["tokens"]["admin"].as_str().expect("token")
    );
    let body = json!({"lod": 1, "region": region, "products": ["tiles", "scatter"],
                      "formats": ["bin", "json"]})
    .to_string();
    let headers = [
        ("content-type", "application/json".to_string()),
        ("authorization", auth.clone()),
    ];
    let r = send(
        &app,
        Method::POST,
        &format!("/v1/worlds/{id}/exports"),
        &headers,
        Some(body.as_bytes()),
    )
    .await;
    let job = r.status_is(StatusCode::ACCEPTED).json();
    let auth = [("authorization", auth)];
    let deadline = tokio::time::Instant::now() + Duration::from_secs(300);
    loop {
        let status_url = job["status_url"].as_str().expect("status url");
        let v = send(&app, Method::GET, status_url, &auth, None)
            .await
            .json();
        if v["status"] == "done" {
            break;
        }
        assert_ne!(v["status"], "failed", "{v}");
        assert!(tokio::time::Instant::now() < deadline, "job stuck: {v}");
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    let download = job["download_url"].as_str().expect("download url");
    let r = send(&app, Method::GET, download, &auth, None).await;
    r.status_is(StatusCode::OK).body.clone()
}

#[tokio::test]
async fn export_with_negative_coordinates_matches_the_servers_archive() {
    let dir = tempfile::tempdir().expect("tmp");
    let out = dir.path().join("cli.tar");
    let o = strata(&[
        "export",
        "--seed",
        "7",
        "--lod",
        "1",
        "--region",
        "-2,-1,1,1",
        "--products",
        "tiles,scatter",
        "--formats",
        "bin,json",
        "--threads",
        "2",
        "-o",
        out.to_str().expect("utf-8 path"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let local = std::fs::read(&out).expect("the CLI's archive");
    let members = strata::export::tar::read_members(&local).expect("tar");
    // 3 × 2 tiles, each with two tile formats and scatter, and the manifest.
    assert_eq!(members.len(), 6 * 3 + 1);
    assert!(members.iter().any(|(n, _)| n == "tiles/1/-2/-1.bin"));
    let served = server_archive(&dir.path().join("jobs"), [-2, -1, 1, 1]).await;
    assert!(
        local == served,
        "the CLI's archive equals the server's export job archive, byte for byte"
    );
}

#[test]
fn bad_arguments_are_clap_errors_with_exit_code_2() {
    let dir = tempfile::tempdir().expect("tmp");
    let out = dir.path().join("x.tar");
    let out = out.to_str().expect("utf-8 path");
    for (args, says) in [
        (vec!["--region", "0,0,4"], "4 comma-separated integers"),
        (vec!["--region", "0,0,a,4"], "\"a\" is not an integer"),
        (vec!["--region", "2,0,1,1"], "need x0 < x1 and z0 < z1"),
        (
            vec!["--region", "0,0,9223372036854775808,1"],
            "is not an integer",
        ),
        (vec![], "--region <X0,Z0,X1,Z1>"),
        (vec!["--region", "0,0,1,1", "--lod", "13"], "--lod"),
        (vec!["--region", "0,0,1,1", "--formats", "tiff"], "tiff"),
        (
            vec!["--region", "0,0,1,1", "--products", "meshes"],
            "meshes",
        ),
        (vec!["--region", "0,0,1,1", "--shard", "4/3"], "--shard"),
        (vec!["--region", "0,0,1,1", "--threads", "0"], "--threads"),
    ] {
        let mut all = vec!["export", "--seed", "1", "-o", out];
        all.extend(&args);
        let o = strata(&all);
        let text = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {text}");
        assert!(text.starts_with("error:"), "{args:?}: a clap error: {text}");
        assert!(text.contains(says), "{args:?}: says {says:?}: {text}");
    }
    assert!(
        !std::path::Path::new(out).exists(),
        "nothing is written for refused arguments"
    );
}

#[test]
fn export_help_reads_cleanly() {
    let o = strata(&["export", "--help"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let help = String::from_utf8_lossy(&o.stdout);
    for word in [
        "--region <X0,Z0,X1,Z1>",
        "-2,-2,2,2",
        "- tiles:",
        "- scatter:",
        "- glb:",
    ] {
        assert!(help.contains(word), "the help shows {word:?}:\n{help}");
    }
    for internal in [
        "WorldParams",
        "ExportSpec",
        "Vec<",
        "Option<",
        "i64",
        "u32",
        "1-based",
    ] {
        assert!(
            !help.contains(internal),
            "the help does not say {internal:?}:\n{help}"
        );
    }
}

/// Shards `i/3` of seed 7's LOD 1 tiles over `region`, written into `dir` as `s{i}.tar`.
fn shards(dir: &std::path::Path, seed: &str, region: &str) -> Vec<String> {
    (1..=3)
        .map(|i| {
            let out = dir.join(format!("s{seed}-{i}.tar"));
            let out = out.to_str().expect("utf-8 path").to_string();
            let shard = format!("{i}/3");
            let o = strata(&[
                "export", "--seed", seed, "--lod", "1", "--region", region, "--shard", &shard,
                "-o", &out,
            ]);
            assert!(o.status.success(), "{}", stderr(&o));
            out
        })
        .collect()
}

#[test]
fn export_join_writes_the_whole_export_and_refuses_an_incomplete_or_mixed_set() {
    let dir = tempfile::tempdir().expect("tmp");
    let parts = shards(dir.path(), "7", "-2,-1,1,1");
    let whole = dir.path().join("whole.tar");
    let o = strata(&[
        "export",
        "--seed",
        "7",
        "--lod",
        "1",
        "--region",
        "-2,-1,1,1",
        "-o",
        whole.to_str().expect("utf-8 path"),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let joined = dir.path().join("joined.tar");
    let joined = joined.to_str().expect("utf-8 path");
    let o = strata(&["export-join", "-o", joined, &parts[2], &parts[0], &parts[1]]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        std::fs::read(joined).expect("joined") == std::fs::read(&whole).expect("whole"),
        "the joined shards are the unsharded archive, byte for byte"
    );
    let other = shards(dir.path(), "8", "-2,-1,1,1");
    let whole_path = whole.to_str().expect("utf-8 path");
    for (set, says) in [
        (
            vec![&parts[0], &parts[1]],
            "each of 1..=3 must be given once",
        ),
        (
            vec![&parts[0], &parts[1], &parts[1]],
            "each of 1..=3 must be given once",
        ),
        (vec![&parts[0], &parts[1], &other[2]], "another export"),
        (
            vec![&parts[0], &parts[1], &parts[2], &whole_path.to_string()],
            "another export",
        ),
    ] {
        let mut args = vec!["export-join", "-o", joined];
        args.extend(set.iter().map(|s| s.as_str()));
        let o = strata(&args);
        assert_eq!(o.status.code(), Some(1), "{set:?}");
        assert!(stderr(&o).contains(says), "{set:?}: {}", stderr(&o));
    }
    assert!(
        std::fs::read(joined).expect("joined") == std::fs::read(&whole).expect("whole"),
        "a refused join leaves the earlier output as it was"
    );
    let o = strata(&["export-join", "-o", joined]);
    assert_eq!(o.status.code(), Some(2), "no shards is a usage error");
}
