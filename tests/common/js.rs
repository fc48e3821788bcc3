//! The Node side of the tests (`tests/js`): its packages, installed with `npm ci --prefix
//! tests/js` when one is missing. Without npm the calling test fails: it never skips.

use std::path::{Path, PathBuf};
use std::process::Command;

/// `tests/js` of the repository.
pub fn js_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("js")
}

/// Installs `tests/js`'s locked packages unless every one of `packages` is already there.
pub fn ensure_packages(packages: &[&str]) {
    let js = js_dir();
    let modules = js.join("node_modules");
    if packages.iter().all(|p| modules.join(p).is_dir()) {
        return;
    }
    println!(
        "installing tests/js packages: npm ci --prefix {}",
        js.display()
    );
    let out = Command::new("npm")
        .args(["ci", "--no-audit", "--no-fund", "--prefix"])
        .arg(&js)
        .output()
        .unwrap_or_else(|e| {
            panic!("`npm` could not be started ({e}); install npm (it ships with Node.js)")
        });
    assert!(
        out.status.success(),
        "`npm ci --prefix {}` failed ({}):\n{}\n{}",
        js.display(),
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}
