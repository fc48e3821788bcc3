//! The glb tiles pass the Khronos glTF validator (npm `gltf-validator`) without errors.
//!
//! Writes tiles (LOD 0, 3 and 12, with and without seams, negative coordinates) to a temporary
//! directory and runs `node tests/js/validate.mjs <files>`. Installs the validator with
//! `npm ci --prefix tests/js` when `tests/js/node_modules` is missing. Without Node.js the test
//! fails: it never skips.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Arc;
use strata::compute::Compute;
use strata::encode::glb;
use strata::terrain::{TileKey, WorldParams, WorldPlan};

fn js_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("js")
}

fn require_node() {
    match Command::new("node").arg("--version").output() {
        Ok(out) if out.status.success() => {
            println!("node {}", String::from_utf8_lossy(&out.stdout).trim());
        }
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

fn ensure_validator_installed() {
    let js = js_dir();
    if js.join("node_modules").join("gltf-validator").is_dir() {
        return;
    }
    println!(
        "installing gltf-validator: npm ci --prefix {}",
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

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn glb_tiles_pass_the_khronos_validator() {
    require_node();
    ensure_validator_installed();

    let dir =
        Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("strata-glb-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let plan = Arc::new(WorldPlan::new(20_240_611, WorldParams::default()).expect("default world"));
    let compute = Compute::cpu();
    let edge = plan.max_tile_coord(0);
    let cases: [(u32, i64, i64, [bool; 4]); 8] = [
        (0, 0, 0, [false; 4]),
        (0, -1, -2, [true; 4]),
        (0, 5, -7, [true, false, true, false]),
        (3, -2, 1, [false; 4]),
        (3, 2, -3, [false, true, false, true]),
        (3, -40, -40, [true; 4]),
        (12, -3, 3, [true; 4]),
        (0, edge, -edge, [true; 4]),
    ];
    let mut files = Vec::new();
    for (lod, x, z, seams) in cases {
        let tile = compute
            .tile(plan.clone(), TileKey { lod, x, z }, seams)
            .await;
        let bytes = glb::encode(&plan, &tile);
        let flags: String = seams.iter().map(|&s| if s { '1' } else { '0' }).collect();
        let path = dir.join(format!("tile_{lod}_{x}_{z}_seams{flags}.glb"));
        std::fs::write(&path, &bytes).expect("write glb");
        files.push(path);
    }

    let out = Command::new("node")
        .arg(js_dir().join("validate.mjs"))
        .args(&files)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run node");
    let stdout = String::from_utf8_lossy(&out.stdout);
    println!("{stdout}");
    eprintln!("{}", String::from_utf8_lossy(&out.stderr));

    let reports: Vec<serde_json::Value> = stdout
        .lines()
        .filter_map(|l| l.strip_prefix("STRATA_GLTF_REPORT "))
        .map(|j| serde_json::from_str(j).expect("report JSON"))
        .collect();
    assert_eq!(reports.len(), files.len(), "one report per file");
    let mut warnings = 0;
    for r in &reports {
        assert_eq!(r["errors"], 0, "validator errors: {r}");
        assert_eq!(r["vertices"], glb::VERTEX_COUNT, "{r}");
        assert_eq!(
            r["triangles"],
            glb::SURFACE_TRIANGLES + glb::SKIRT_TRIANGLES,
            "{r}"
        );
        warnings += r["warnings"].as_u64().unwrap_or(0);
    }
    if warnings > 0 {
        println!("{warnings} validator warnings (allowed), listed above");
    }
    assert!(
        out.status.success(),
        "validate.mjs exited with {}",
        out.status
    );
    std::fs::remove_dir_all(&dir).ok();
}
