//! The scene store's contract (`src/store/mod.rs`), run against every backend: SQLite in a
//! temporary directory and PostgreSQL in a throwaway cluster (`common::postgres`; these fail,
//! never skip, without PostgreSQL). Each contract test is one function over a [`Backend`]; the
//! `contract!` macro makes a `sqlite` and a `postgres` test of it.

mod common;

use serde_json::{json, Value};
use std::sync::Arc;
use strata::scene::{Dirty, Rect};
use strata::store::{
    hash_token, new_world_id, Admission, JobQuota, JobRecord, JobUpdate, NewWorld, PostgresStore,
    Role, SceneStore, SqliteStore, StoreError, TokenGrant, MAX_WORLD_IMAGES, SNAPSHOT_EVERY,
};

/// Where a contract test's store lives; [`Backend::open`] may be called again to reopen it.
enum Backend {
    Sqlite(tempfile::TempDir),
    Postgres(String),
}

impl Backend {
    async fn sqlite() -> Self {
        Backend::Sqlite(tempfile::tempdir().expect("tmp"))
    }

    async fn postgres() -> Self {
        Backend::Postgres(common::postgres::database().await)
    }

    /// A new handle on the store: a new SQLite connection or a new PostgreSQL pool.
    async fn open(&self) -> Arc<dyn SceneStore> {
        match self {
            Backend::Sqlite(dir) => Arc::new(SqliteStore::open_in_dir(dir.path()).expect("open")),
            Backend::Postgres(url) => Arc::new(PostgresStore::connect(url).await.expect("connect")),
        }
    }
}

/// `sqlite` and `postgres` tests of the contract test `$name`.
macro_rules! contract {
    ($($name:ident),* $(,)?) => {$(
        mod $name {
            #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
            async fn sqlite() {
                super::$name(super::Backend::sqlite().await).await;
            }

            #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
            async fn postgres() {
                super::$name(super::Backend::postgres().await).await;
            }
        }
    )*};
}

contract!(
    versions_replay_across_snapshots_and_reopen,
    refused_edits_change_nothing,
    racing_edits_with_one_expected_version_one_wins,
    concurrent_edits_each_get_their_own_version,
    tokens_and_access,
    missing_worlds_and_duplicate_ids,
    the_edit_log_pages_by_version,
    export_jobs_are_kept_and_updated_only_by_their_owner,
    a_stale_export_job_is_claimed_by_exactly_one_replica,
    admissions_count_every_stored_job_and_racing_ones_take_the_room_once,
    done_jobs_expire_once_whoever_asks,
    images_are_kept_by_hash_and_edits_name_only_stored_ones,
);

fn patch(v: Value) -> json_patch::Patch {
    serde_json::from_value(v).expect("patch")
}

async fn world(store: &dyn SceneStore) -> String {
    let id = new_world_id().expect("id");
    store
        .create_world(NewWorld {
            id: id.clone(),
            seed: u64::MAX,
            scene: json!({}),
            public: false,
            admin_token: hash_token(&format!("t{id}")),
        })
        .await
        .expect("create");
    id
}

/// Boxes with decimal fractions, so a scene that drifted by a float parse/print cycle would
/// fail the replay's hash check.
fn add_region(i: u64) -> json_patch::Patch {
    let x = i as f64 * 0.1 + 0.03;
    patch(json!([{"op": "add", "path": "/regions/-", "value":
        {"id": format!("r{i}"), "bbox": {"min": [x, 0.7], "max": [x + 1.0, 1.3]}}}]))
}

/// Every version replays from its snapshot and log to the scene it was, after the store is
/// reopened; the seed's 64 bits survive.
async fn versions_replay_across_snapshots_and_reopen(backend: Backend) {
    let store = backend.open().await;
    let id = world(&*store).await;
    let n = 2 * SNAPSHOT_EVERY + 5;
    for i in 2..=n {
        let a = store.apply_edit(&id, add_region(i), Some(i - 1)).await;
        assert_eq!(a.expect("edit").version, i);
    }
    let meta = store.meta(&id).await.expect("meta");
    assert_eq!((meta.version, meta.seed), (n, u64::MAX));
    drop(store);
    let store = backend.open().await;
    for v in 1..=n {
        let s = store.scene_at(&id, v).await.expect("version");
        let regions = s["regions"].as_array().expect("array");
        assert_eq!(regions.len() as u64, v - 1, "version {v}");
        if v > 1 {
            assert_eq!(regions[v as usize - 2]["id"], json!(format!("r{v}")));
        }
    }
    assert_eq!(
        store.head(&id).await.expect("head").scene,
        store.scene_at(&id, n).await.expect("latest")
    );
    assert!(matches!(
        store.scene_at(&id, n + 1).await,
        Err(StoreError::VersionNotFound { latest, .. }) if latest == n
    ));
    assert!(matches!(
        store.scene_at(&id, 0).await,
        Err(StoreError::VersionNotFound { version: 0, .. })
    ));
}

/// A conflicting, failing or invalid edit leaves the world as it was; the next good one makes
/// version 2 and reports what it changed.
async fn refused_edits_change_nothing(backend: Backend) {
    let store = backend.open().await;
    let id = world(&*store).await;
    assert_eq!(
        store.apply_edit(&id, add_region(1), Some(7)).await,
        Err(StoreError::Conflict {
            expected: 7,
            latest: 1
        })
    );
    let bad = patch(json!([{"op": "add", "path": "/regions/-", "value":
        {"id": "ok", "bbox": {"min": [0, 0], "max": [1, 1]}}},
        {"op": "remove", "path": "/nope"}]));
    assert!(matches!(
        store.apply_edit(&id, bad, None).await,
        Err(StoreError::Patch { operation: 1, .. })
    ));
    let invalid = patch(json!([{"op": "replace",
        "path": "/world/earth/gain", "value": 5}]));
    match store.apply_edit(&id, invalid, None).await {
        Err(StoreError::Invalid(e)) => assert_eq!(e.pointer, "/world/earth/gain"),
        other => panic!("{other:?}"),
    }
    let head = store.head(&id).await.expect("head");
    assert_eq!(head.meta.version, 1);
    assert_eq!(head.scene["regions"], json!([]));
    assert!(store.edit_log(&id, 0, 10).await.expect("log").is_empty());
    let a = store
        .apply_edit(&id, add_region(3), None)
        .await
        .expect("ok");
    assert_eq!(a.version, 2);
    assert_eq!(
        a.dirty,
        Dirty::Rects(vec![Rect {
            min: [3.0 * 0.1 + 0.03, 0.7],
            max: [3.0 * 0.1 + 0.03 + 1.0, 1.3]
        }])
    );
}

/// Eight editors send an edit expecting version 1 at once, each through its own handle on the
/// store (as replicas would): exactly one is applied, the others are told version 2 is there.
async fn racing_edits_with_one_expected_version_one_wins(backend: Backend) {
    let first = backend.open().await;
    let id = world(&*first).await;
    let mut stores = vec![first];
    for _ in 1..8 {
        stores.push(backend.open().await);
    }
    let tasks: Vec<_> = stores
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let (s, id) = (s.clone(), id.clone());
            tokio::spawn(async move { s.apply_edit(&id, add_region(i as u64), Some(1)).await })
        })
        .collect();
    let mut won = 0;
    for t in tasks {
        match t.await.expect("task") {
            Ok(a) => {
                assert_eq!(a.version, 2);
                won += 1;
            }
            Err(e) => assert_eq!(
                e,
                StoreError::Conflict {
                    expected: 1,
                    latest: 2
                }
            ),
        }
    }
    assert_eq!(won, 1);
    let head = stores[0].head(&id).await.expect("head");
    assert_eq!(head.meta.version, 2);
    assert_eq!(head.scene["regions"].as_array().map(Vec::len), Some(1));
}

/// Edits without an expected version, sent at once through several handles, are all applied,
/// each as its own version, and the log and scene hold every one of them.
async fn concurrent_edits_each_get_their_own_version(backend: Backend) {
    let first = backend.open().await;
    let id = world(&*first).await;
    let mut tasks = Vec::new();
    for i in 0..8u64 {
        let s = if i % 2 == 0 {
            first.clone()
        } else {
            backend.open().await
        };
        let id = id.clone();
        tasks.push(tokio::spawn(async move {
            s.apply_edit(&id, add_region(i), None).await
        }));
    }
    let mut versions = Vec::new();
    for t in tasks {
        versions.push(t.await.expect("task").expect("edit").version);
    }
    versions.sort_unstable();
    assert_eq!(versions, (2..=9).collect::<Vec<u64>>());
    let log = first.edit_log(&id, 0, 100).await.expect("log");
    assert_eq!(
        log.iter().map(|e| e.version).collect::<Vec<_>>(),
        (2..=9).collect::<Vec<u64>>()
    );
    let scene = first.scene_at(&id, 9).await.expect("scene");
    let mut ids: Vec<String> = scene["regions"]
        .as_array()
        .expect("regions")
        .iter()
        .map(|r| r["id"].as_str().expect("id").to_string())
        .collect();
    ids.sort();
    assert_eq!(ids, (0..8).map(|i| format!("r{i}")).collect::<Vec<_>>());
}

/// Tokens are found by their hash with their role; visibility changes; every world is listed.
async fn tokens_and_access(backend: Backend) {
    let store = backend.open().await;
    let id = world(&*store).await;
    let other = world(&*store).await;
    assert_eq!(
        store
            .token(hash_token(&format!("t{id}")))
            .await
            .expect("token"),
        Some(TokenGrant {
            world: id.clone(),
            role: Role::Admin
        })
    );
    store
        .add_token(&id, hash_token("r"), Role::Read)
        .await
        .expect("add");
    store
        .add_token(&other, hash_token("e"), Role::Edit)
        .await
        .expect("add");
    assert_eq!(
        store.token(hash_token("r")).await.expect("token"),
        Some(TokenGrant {
            world: id.clone(),
            role: Role::Read
        })
    );
    assert_eq!(
        store.token(hash_token("e")).await.expect("token"),
        Some(TokenGrant {
            world: other.clone(),
            role: Role::Edit
        })
    );
    assert_eq!(store.token(hash_token("x")).await.expect("token"), None);
    assert!(store.set_public(&id, true).await.expect("public").public);
    assert!(store.meta(&id).await.expect("meta").public);
    assert!(!store.set_public(&id, false).await.expect("private").public);
    let mut listed: Vec<String> = store
        .list_worlds()
        .await
        .expect("list")
        .into_iter()
        .map(|m| m.id)
        .collect();
    listed.sort();
    let mut both = vec![id, other];
    both.sort();
    assert_eq!(listed, both);
}

/// Every operation on an unknown world says so; a taken id is refused and the first world is
/// left as it was.
async fn missing_worlds_and_duplicate_ids(backend: Backend) {
    let store = backend.open().await;
    let gone = || StoreError::WorldNotFound("nope".into());
    assert_eq!(store.meta("nope").await, Err(gone()));
    assert_eq!(store.head("nope").await.map(|h| h.meta), Err(gone()));
    assert_eq!(store.scene_at("nope", 1).await, Err(gone()));
    assert_eq!(
        store.apply_edit("nope", add_region(1), None).await,
        Err(gone())
    );
    assert_eq!(store.edit_log("nope", 0, 10).await, Err(gone()));
    assert_eq!(store.set_public("nope", true).await, Err(gone()));
    assert_eq!(
        store.add_token("nope", hash_token("n"), Role::Read).await,
        Err(gone())
    );
    assert_eq!(store.token(hash_token("n")).await, Ok(None));
    let id = world(&*store).await;
    let again = store
        .create_world(NewWorld {
            id: id.clone(),
            seed: 7,
            scene: json!({}),
            public: true,
            admin_token: hash_token("other"),
        })
        .await;
    assert_eq!(again.map(|m| m.id), Err(StoreError::Duplicate(id.clone())));
    let meta = store.meta(&id).await.expect("meta");
    assert_eq!((meta.seed, meta.public, meta.version), (u64::MAX, false, 1));
    assert_eq!(store.token(hash_token("other")).await, Ok(None));
}

/// The log returns the patches after a version, oldest first, at most `limit` of them.
async fn the_edit_log_pages_by_version(backend: Backend) {
    let store = backend.open().await;
    let id = world(&*store).await;
    for i in 2..=6 {
        store
            .apply_edit(&id, add_region(i), Some(i - 1))
            .await
            .expect("edit");
    }
    let page = store.edit_log(&id, 1, 2).await.expect("log");
    assert_eq!(page.iter().map(|e| e.version).collect::<Vec<_>>(), [2, 3]);
    assert_eq!(
        page[0].patch,
        serde_json::to_value(add_region(2)).expect("json")
    );
    let rest = store.edit_log(&id, 3, 10).await.expect("log");
    assert_eq!(
        rest.iter().map(|e| e.version).collect::<Vec<_>>(),
        [4, 5, 6]
    );
    assert!(store.edit_log(&id, 6, 10).await.expect("log").is_empty());
    assert!(store
        .edit_log(&id, u64::MAX, 10)
        .await
        .expect("log")
        .is_empty());
}

/// A queued job of world `world` owned by `owner` until `lease_until_ms`.
fn job(id: &str, world: &str, owner: &str, lease_until_ms: i64, created_at: i64) -> JobRecord {
    JobRecord {
        id: id.to_string(),
        world: world.to_string(),
        version: 1,
        spec: r#"{"spec":{"lod":0},"shard":{"index":0,"count":1}}"#.to_string(),
        status: "queued".to_string(),
        done: 0,
        total: 12,
        error: None,
        reserved: 1 << 40,
        bytes: 0,
        owner: owner.to_string(),
        lease_until_ms,
        created_at,
        finished_at: None,
    }
}

fn progress(status: &str, done: u64, lease_until_ms: i64) -> JobUpdate {
    JobUpdate {
        status: status.to_string(),
        done,
        total: 12,
        error: None,
        bytes: 0,
        lease_until_ms,
        finished_at: None,
    }
}

/// A stored job reads back as written (after a reopen), its id is unique, it needs its world,
/// and only its owner may change it.
async fn export_jobs_are_kept_and_updated_only_by_their_owner(backend: Backend) {
    let store = backend.open().await;
    let w = world(&*store).await;
    let a = job(&"a1".repeat(16), &w, "owner-a", 5_000, 100);
    store.insert_job(&a).await.expect("insert");
    assert_eq!(
        store.insert_job(&a).await,
        Err(StoreError::Duplicate(a.id.clone()))
    );
    assert_eq!(
        store
            .insert_job(&job(&"b2".repeat(16), "nope", "o", 0, 0))
            .await,
        Err(StoreError::WorldNotFound("nope".into()))
    );
    assert_eq!(store.job(&a.id).await, Ok(Some(a.clone())));
    assert_eq!(store.job(&"c3".repeat(16)).await, Ok(None));

    // Another owner's write is refused and changes nothing.
    let running = progress("running", 5, 9_000);
    assert_eq!(
        store.update_job(&a.id, "owner-b", &running).await,
        Ok(false)
    );
    assert_eq!(store.job(&a.id).await, Ok(Some(a.clone())));
    assert_eq!(store.update_job(&a.id, "owner-a", &running).await, Ok(true));
    let done = JobUpdate {
        status: "done".into(),
        done: 12,
        bytes: 123_456,
        finished_at: Some(1_700_000_000),
        ..running
    };
    assert_eq!(store.update_job(&a.id, "owner-a", &done).await, Ok(true));
    let reopened = backend.open().await;
    let stored = reopened.job(&a.id).await.expect("job").expect("kept");
    assert_eq!(
        (
            stored.status.as_str(),
            stored.done,
            stored.bytes,
            stored.lease_until_ms,
            stored.finished_at
        ),
        ("done", 12, 123_456, 9_000, Some(1_700_000_000))
    );
    assert_eq!((stored.reserved, stored.spec), (a.reserved, a.spec));
    // A finished job is never claimed, however old its lease.
    assert_eq!(reopened.claim_job("owner-c", i64::MAX, 1).await, Ok(None));
}

/// Only queued or running jobs whose lease has passed are claimed, oldest first; the claim makes
/// the job the claimer's, queued from the start, and locks the old owner out; of many replicas
/// claiming at once, each job goes to exactly one.
async fn a_stale_export_job_is_claimed_by_exactly_one_replica(backend: Backend) {
    let store = backend.open().await;
    let w = world(&*store).await;
    let old = job(&"01".repeat(16), &w, "dead", 1_000, 10);
    let young = job(&"02".repeat(16), &w, "dead", 1_000, 20);
    let live = job(&"03".repeat(16), &w, "alive", 50_000, 5);
    for j in [&old, &young, &live] {
        store.insert_job(j).await.expect("insert");
    }
    assert_eq!(
        store
            .update_job(&old.id, "dead", &progress("running", 7, 1_000))
            .await,
        Ok(true)
    );
    // Before the leases end, nothing is claimed.
    assert_eq!(store.claim_job("c", 1_000, 2_000).await, Ok(None));

    // Eight claimers at once, on their own connections: the two stale jobs go to two of them.
    let mut tasks = Vec::new();
    for k in 0..8 {
        let s = backend.open().await;
        tasks.push(tokio::spawn(async move {
            s.claim_job(&format!("c{k}"), 2_000, 60_000).await
        }));
    }
    let mut claimed = Vec::new();
    for t in tasks {
        if let Some(r) = t.await.expect("task").expect("claim") {
            claimed.push(r);
        }
    }
    claimed.sort_by_key(|r| r.created_at);
    assert_eq!(
        claimed.iter().map(|r| r.id.as_str()).collect::<Vec<_>>(),
        [old.id.as_str(), young.id.as_str()]
    );
    assert_ne!(claimed[0].owner, claimed[1].owner);
    for r in &claimed {
        assert_eq!(
            (r.status.as_str(), r.done, r.lease_until_ms),
            ("queued", 0, 60_000)
        );
    }
    // The old owner is locked out; the new one writes.
    assert_eq!(
        store
            .update_job(&old.id, "dead", &progress("running", 9, 70_000))
            .await,
        Ok(false)
    );
    assert_eq!(
        store
            .update_job(&old.id, &claimed[0].owner, &progress("running", 1, 70_000))
            .await,
        Ok(true)
    );
    assert_eq!(store.claim_job("late", 2_000, 60_000).await, Ok(None));
    assert_eq!(
        store.job(&live.id).await.expect("job").map(|r| r.owner),
        Some("alive".into())
    );
}

/// Admission counts every stored job (queued and running at their bound, done at their bytes,
/// failed at nothing), per world and in all, and the queued ones; of eight admissions racing
/// on their own connections for room for two, exactly two are stored.
async fn admissions_count_every_stored_job_and_racing_ones_take_the_room_once(backend: Backend) {
    let store = backend.open().await;
    let (w, other) = (world(&*store).await, world(&*store).await);
    let sized = |id: &str, world: &str, reserved: u64| JobRecord {
        reserved,
        ..job(&id.repeat(16), world, "o", 1_000, 1)
    };
    let quota = JobQuota {
        world_bytes: 1_000,
        disk_bytes: 1_500,
        max_queued: 4,
    };
    // A done job at its bytes, a failed one at nothing, a running one at its bound.
    for (id, status, bytes, finished) in
        [("d1", "done", 300, Some(50)), ("f1", "failed", 0, Some(60))]
    {
        let r = sized(id, &w, 700);
        assert_eq!(store.admit_job(&r, &quota).await, Ok(Admission::Admitted));
        let end = JobUpdate {
            status: status.into(),
            bytes,
            finished_at: finished,
            ..progress(status, 12, 1_000)
        };
        assert_eq!(store.update_job(&r.id, "o", &end).await, Ok(true));
    }
    assert_eq!(
        store.admit_job(&sized("r1", &w, 400), &quota).await,
        Ok(Admission::Admitted)
    );
    // The world holds 700 bytes: 301 more do not fit, and the refusal says what is held.
    assert_eq!(
        store.admit_job(&sized("x1", &w, 301), &quota).await,
        Ok(Admission::OverQuota {
            world: true,
            used: 700,
            oldest_done_s: Some(50)
        })
    );
    // Another world: its own budget, the store's shared (700 held of 1500).
    assert_eq!(
        store.admit_job(&sized("x2", &other, 801), &quota).await,
        Ok(Admission::OverQuota {
            world: false,
            used: 700,
            oldest_done_s: Some(50)
        })
    );
    assert_eq!(
        store.job(&"x1".repeat(16)).await,
        Ok(None),
        "a refusal stores nothing"
    );
    // Eight racing admissions of 300 bytes in the other world: room for two (1500 - 700).
    let mut tasks = Vec::new();
    for k in 0..8 {
        let s = backend.open().await;
        let r = sized(&format!("{k}{k}"), &other, 300);
        tasks.push(tokio::spawn(async move { s.admit_job(&r, &quota).await }));
    }
    let mut admitted = 0;
    for t in tasks {
        match t.await.expect("task").expect("admit") {
            Admission::Admitted => admitted += 1,
            Admission::OverQuota { world: false, .. } => {}
            refused => panic!("unexpected {refused:?}"),
        }
    }
    assert_eq!(admitted, 2);
    // Four queued (r1 and the two admitted count; one more makes four): the fifth waits.
    let small = JobQuota {
        disk_bytes: u64::MAX,
        world_bytes: u64::MAX,
        ..quota
    };
    assert_eq!(
        store.admit_job(&sized("q1", &w, 1), &small).await,
        Ok(Admission::Admitted)
    );
    assert_eq!(
        store.admit_job(&sized("q2", &w, 1), &small).await,
        Ok(Admission::TooMany { queued: 4 })
    );
}

/// Done jobs finished at or before the cut become expired, each reported to one caller only;
/// others keep their status.
async fn done_jobs_expire_once_whoever_asks(backend: Backend) {
    let store = backend.open().await;
    let w = world(&*store).await;
    for (id, status, finished) in [
        ("e1", "done", 100),
        ("e2", "done", 200),
        ("e3", "failed", 50),
    ] {
        let r = job(&id.repeat(16), &w, "o", 1_000, 1);
        store.insert_job(&r).await.expect("insert");
        let end = JobUpdate {
            status: status.into(),
            finished_at: Some(finished),
            ..progress(status, 12, 1_000)
        };
        assert_eq!(store.update_job(&r.id, "o", &end).await, Ok(true));
    }
    let other = backend.open().await;
    assert_eq!(other.expire_jobs(150).await, Ok(vec!["e1".repeat(16)]));
    assert_eq!(store.expire_jobs(150).await, Ok(vec![]));
    let status = |id: &str| {
        let s = store.clone();
        let id = id.repeat(16);
        async move { s.job(&id).await.expect("job").expect("kept").status }
    };
    assert_eq!(status("e1").await, "expired");
    assert_eq!(status("e2").await, "done");
    assert_eq!(status("e3").await, "failed");
}

/// Images are kept per world under their hash, survive a reopen, are counted against the
/// world's limit, and an edit may name only an image its world holds (refused edits change
/// nothing).
async fn images_are_kept_by_hash_and_edits_name_only_stored_ones(backend: Backend) {
    let store = backend.open().await;
    let (a, b) = (world(&*store).await, world(&*store).await);
    let png = b"\x89PNG bytes for the store, not decoded here".to_vec();
    let hash = *blake3::hash(&png).as_bytes();
    assert_eq!(store.put_image(&a, hash, png.clone()).await, Ok(true));
    assert_eq!(store.put_image(&a, hash, png.clone()).await, Ok(false));
    assert_eq!(store.image(&a, hash).await, Ok(Some(png.clone())));
    assert_eq!(
        store.image(&b, hash).await,
        Ok(None),
        "images belong to a world"
    );
    assert_eq!(
        store.put_image("nope", hash, png.clone()).await,
        Err(StoreError::WorldNotFound("nope".into()))
    );
    let hex: String = hash.iter().map(|x| format!("{x:02x}")).collect();
    let decal = |id: &str| {
        patch(
            json!([{"op": "add", "path": "/decals/-", "value": {"id": id,
            "bbox": {"min": [-10, -10], "max": [10, 10]}, "image": hex,
            "center": [0, 0], "size_m": [4, 4]}}]),
        )
    };
    assert_eq!(
        store
            .apply_edit(&a, decal("d"), None)
            .await
            .map(|e| e.version),
        Ok(2)
    );
    match store.apply_edit(&b, decal("d"), None).await {
        Err(StoreError::Invalid(e)) => assert_eq!(e.pointer, "/decals/0/image"),
        other => panic!("{other:?}"),
    }
    assert_eq!(store.meta(&b).await.expect("meta").version, 1);
    let reopened = backend.open().await;
    assert_eq!(reopened.image(&a, hash).await, Ok(Some(png)));
    for i in 1..MAX_WORLD_IMAGES {
        let h = *blake3::hash(&i.to_le_bytes()).as_bytes();
        assert_eq!(reopened.put_image(&a, h, vec![i as u8]).await, Ok(true));
    }
    let over = *blake3::hash(b"one too many").as_bytes();
    assert_eq!(
        reopened.put_image(&a, over, vec![0]).await,
        Err(StoreError::TooManyImages {
            limit: MAX_WORLD_IMAGES
        })
    );
}
