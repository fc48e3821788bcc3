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
fn pure_modules_import_no_tokio_axum_or_wgpu() {
    // The CPU references: the world function, authored regions, the subsurface and the volume
    // stages. They run anywhere (tests, exports, other hosts) and stay free of the service.
    for (dir, min_files) in [
        ("src/terrain", 5),
        ("src/authoring", 4),
        ("src/subsurface", 3),
        ("src/volume", 2),
        ("src/edits.rs", 1),
    ] {
        let mut files = Vec::new();
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
        if path.is_file() {
            files.push(path);
        } else {
            rust_files(&path, &mut files);
        }
        assert!(files.len() >= min_files, "{dir} has its modules");
        for f in files {
            // Code only: docs may name the GPU twin or the service that uses the module.
            let text: String = std::fs::read_to_string(&f)
                .expect("readable")
                .lines()
                .filter(|l| !l.trim_start().starts_with("//"))
                .collect::<Vec<_>>()
                .join("\n");
            for banned in [
                "tokio::",
                "axum::",
                "wgpu::",
                "crate::server",
                "crate::gpu",
                "crate::compute",
                "crate::stream",
                "crate::store",
            ] {
                assert!(!text.contains(banned), "{} mentions {banned}", f.display());
            }
        }
    }
}
