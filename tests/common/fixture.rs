//! Stored-world fixtures (`tests/fixtures/<name>/`): a database written by an earlier binary,
//! served by today's, and the blake3 of the bytes that binary answered.

use std::path::{Path, PathBuf};

/// The path of file `file` of fixture `name`.
pub fn path(name: &str, file: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(name)
        .join(file)
}

/// The real binary serving a copy of fixture `name`'s `strata.db` (the directory lives as long
/// as the returned guard).
pub fn serve(name: &str) -> (tempfile::TempDir, super::Server) {
    let data = tempfile::tempdir().expect("temp dir");
    std::fs::copy(path(name, "strata.db"), data.path().join("strata.db")).expect("copy fixture");
    let server = super::start(
        [std::ffi::OsStr::new("--data"), data.path().as_os_str()],
        &[],
    );
    (data, server)
}

/// `GET path`, which must answer 200 with bytes whose blake3 is `hash`; the body.
pub async fn pinned_get(server: &super::Server, path: &str, hash: &str) -> Vec<u8> {
    let (status, body) = get(&server.addr, path).await;
    assert_eq!(status, 200, "{path}: {}", String::from_utf8_lossy(&body));
    assert_eq!(
        blake3::hash(&body).to_hex().as_str(),
        hash,
        "{path} changed its bytes"
    );
    body
}

/// `GET path` from `addr`: the status and the body.
pub async fn get(addr: &str, path: &str) -> (u16, Vec<u8>) {
    strata::bench::http::http_get(addr, path)
        .await
        .expect("request")
}
