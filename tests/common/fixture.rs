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

/// The lines of fixture `name`'s hash file `file`, each `first key blake3` (the first column
/// names the version or the format): every line's body, from the path `path(first, key)`, must
/// have that hash. Returns the number of lines checked.
pub async fn check_pinned(
    server: &super::Server,
    name: &str,
    file: &str,
    path_of: impl Fn(&str, &str) -> String,
) -> usize {
    let expected = std::fs::read_to_string(path(name, file)).expect("fixture hashes");
    let mut checked = 0;
    for line in expected.lines() {
        let parts: Vec<&str> = line.split_whitespace().collect();
        let [first, key, hash] = parts[..] else {
            panic!("bad fixture line {line:?}");
        };
        pinned_get(server, &path_of(first, key), hash).await;
        checked += 1;
    }
    checked
}

/// `GET path` from `addr`: the status and the body.
pub async fn get(addr: &str, path: &str) -> (u16, Vec<u8>) {
    strata::bench::http::http_get(addr, path)
        .await
        .expect("request")
}
