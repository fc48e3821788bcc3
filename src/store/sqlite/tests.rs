//! Unit tests of the SQLite store ([`super`]): versions replayed across snapshots, refused
//! edits, tokens and access.

use super::*;
use crate::store::hash_token;
use serde_json::json;

fn patch(v: Value) -> json_patch::Patch {
    serde_json::from_value(v).expect("patch")
}

async fn world(store: &SqliteStore) -> String {
    let id = crate::store::new_world_id().expect("id");
    store
        .create_world(NewWorld {
            id: id.clone(),
            seed: u64::MAX,
            scene: json!({}),
            public: false,
            admin_token: hash_token("t"),
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

#[tokio::test]
async fn versions_replay_across_snapshots_and_reopen() {
    let dir = tempfile::tempdir().expect("tmp");
    let store = SqliteStore::open_in_dir(dir.path()).expect("open");
    let id = world(&store).await;
    let n = 2 * SNAPSHOT_EVERY + 5;
    for i in 2..=n {
        let a = store.apply_edit(&id, add_region(i), Some(i - 1)).await;
        assert_eq!(a.expect("edit").version, i);
    }
    let meta = store.meta(&id).await.expect("meta");
    assert_eq!((meta.version, meta.seed), (n, u64::MAX));
    drop(store);
    let store = SqliteStore::open_in_dir(dir.path()).expect("reopen");
    for v in 1..=n {
        let s = store.scene_at(&id, v).await.expect("version");
        let regions = s["regions"].as_array().expect("array");
        assert_eq!(regions.len() as u64, v - 1, "version {v}");
    }
    assert!(matches!(
        store.scene_at(&id, n + 1).await,
        Err(StoreError::VersionNotFound { latest, .. }) if latest == n
    ));
    let log = store.edit_log(&id, n - 3, 10).await.expect("log");
    assert_eq!(
        log.iter().map(|e| e.version).collect::<Vec<_>>(),
        [n - 2, n - 1, n]
    );
}

#[tokio::test]
async fn refused_edits_change_nothing() {
    let store = SqliteStore::open_in_memory().expect("open");
    let id = world(&store).await;
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
    let a = store
        .apply_edit(&id, add_region(3), None)
        .await
        .expect("ok");
    assert_eq!(a.version, 2);
    assert_eq!(
        a.dirty,
        crate::scene::Dirty::Rects(vec![crate::scene::Rect {
            min: [3.0 * 0.1 + 0.03, 0.7],
            max: [3.0 * 0.1 + 0.03 + 1.0, 1.3]
        }])
    );
}

#[tokio::test]
async fn tokens_and_access() {
    let store = SqliteStore::open_in_memory().expect("open");
    let id = world(&store).await;
    assert_eq!(
        store.token(hash_token("t")).await.expect("token"),
        Some(TokenGrant {
            world: id.clone(),
            role: Role::Admin
        })
    );
    store
        .add_token(&id, hash_token("r"), Role::Read)
        .await
        .expect("add");
    assert_eq!(
        store
            .token(hash_token("r"))
            .await
            .expect("token")
            .map(|g| g.role),
        Some(Role::Read)
    );
    assert_eq!(store.token(hash_token("x")).await.expect("token"), None);
    assert!(store.set_public(&id, true).await.expect("public").public);
    assert_eq!(store.list_worlds().await.expect("list").len(), 1);
    assert!(matches!(
        store.meta("nope").await,
        Err(StoreError::WorldNotFound(_))
    ));
}
