//! Invariants of `ARCHITECTURE.md` that a test can check.

use std::path::Path;

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("readable source dir") {
        let path = entry.expect("dir entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn terrain_imports_no_tokio_axum_or_wgpu() {
    let mut files = Vec::new();
    rust_files(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("src/terrain"),
        &mut files,
    );
    assert!(files.len() >= 5, "src/terrain has its modules");
    for f in files {
        let text = std::fs::read_to_string(&f).expect("readable");
        for banned in [
            "tokio::",
            "axum::",
            "wgpu::",
            "crate::server",
            "crate::gpu",
            "crate::compute",
        ] {
            assert!(!text.contains(banned), "{} mentions {banned}", f.display());
        }
    }
}
