//! The Khronos glTF validator (npm `gltf-validator`, driven by `tests/js/validate.mjs`) for the
//! tests that write glb. Installs the validator with [`super::js::ensure_packages`]. Without
//! Node.js the calling test fails: it never skips.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn require_node() {
    match Command::new("node").arg("--version").output() {
        Ok(out) if out.status.success() => {}
        Ok(out) => panic!(
            "`node --version` failed ({}): {}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        ),
        Err(e) => panic!(
            "Node.js is required to run the glTF validator but `node` could not be started ({e}). \
             Install Node.js 18 or newer (with npm) and put it on PATH."
        ),
    }
}

/// Validates each `(name, glb bytes)` and returns the validator's reports in the same order
/// (`errors`, `warnings`, `vertices`, `triangles`, …); the messages are printed. `tag` names the
/// temporary directory. Panics if the validator cannot run or gives no report for a file.
pub fn validate(tag: &str, files: &[(String, Vec<u8>)]) -> Vec<Value> {
    require_node();
    super::js::ensure_packages(&["gltf-validator"]);
    let dir =
        Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("strata-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let paths: Vec<PathBuf> = files
        .iter()
        .map(|(name, bytes)| {
            let path = dir.join(name);
            std::fs::write(&path, bytes).expect("write glb");
            path
        })
        .collect();
    let out = Command::new("node")
        .arg(super::js::js_dir().join("validate.mjs"))
        .args(&paths)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run node");
    let stdout = String::from_utf8_lossy(&out.stdout);
    println!("{stdout}");
    eprintln!("{}", String::from_utf8_lossy(&out.stderr));
    let reports: Vec<Value> = stdout
        .lines()
        .filter_map(|l| l.strip_prefix("STRATA_GLTF_REPORT "))
        .map(|j| serde_json::from_str(j).expect("report JSON"))
        .collect();
    assert_eq!(reports.len(), files.len(), "one report per file");
    assert!(
        out.status.success(),
        "validate.mjs exited with {}",
        out.status
    );
    std::fs::remove_dir_all(&dir).ok();
    reports
}
