//! The Node side of the tests (`tests/js`): its packages, installed with `npm ci --prefix
//! tests/js` when one is missing, and the browser harness (Node.js, Debian's Chromium, the built
//! viewer served by the real binary, a script run with a time limit). Without them the calling
//! test fails: it never skips.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

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

/// Fails the calling test unless Node.js starts (`node --version`).
pub fn require_node() {
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
            "Node.js is required for the browser viewer tests but `node` could not be started \
             ({e}). Install Node.js 18 or newer (with npm) and put it on PATH."
        ),
    }
}

/// Fails the calling test unless Debian's Chromium is installed.
pub fn require_chromium() {
    let chromium = Path::new("/usr/bin/chromium");
    assert!(
        chromium.exists(),
        "{} is missing: the viewer tests drive Debian's Chromium headless \
         (`apt-get install -y chromium`; .ci/run installs it). They never download a browser.",
        chromium.display()
    );
}

/// What a browser test needs: Node.js, Chromium, `tests/js`'s packages and the built viewer
/// (`web/dist`, whose path it returns).
pub fn browser_ready() -> PathBuf {
    require_node();
    require_chromium();
    ensure_packages(&["playwright-core", "pngjs"]);
    let web = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("web")
        .join("dist");
    assert!(
        web.join("index.html").is_file(),
        "{} is missing: build the viewer with `npm ci --prefix web && npm run --prefix web build`",
        web.display()
    );
    web
}

/// `strata serve` with its data in `data` and the viewer of `web`.
pub fn serve_viewer(data: &Path, web: &Path) -> super::Server {
    super::start(
        [
            std::ffi::OsStr::new("--data"),
            data.as_os_str(),
            std::ffi::OsStr::new("--web"),
            web.as_os_str(),
        ],
        &[],
    )
}

/// A path as the UTF-8 argument of a script.
pub fn arg(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

/// Runs `node tests/js/<script> <args>` with a time limit of `limit` (a hung browser must not
/// hang the suite); returns whether it succeeded and its output.
pub fn run_node(script: &str, args: &[&str], limit: Duration) -> (bool, String) {
    let t0 = Instant::now();
    let mut child = Command::new("node")
        .arg(js_dir().join(script))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("start node tests/js/{script}: {e}"));
    // Drain the pipes while waiting, so a chatty script never blocks on a full one.
    let mut stdout = child.stdout.take().expect("stdout");
    let mut stderr = child.stderr.take().expect("stderr");
    let out = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stdout.read_to_string(&mut s);
        s
    });
    let err = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stderr.read_to_string(&mut s);
        s
    });
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait for node") {
            break status;
        }
        if t0.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("node tests/js/{script} did not finish within {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let text = format!(
        "{}{}",
        out.join().unwrap_or_default(),
        err.join().unwrap_or_default()
    );
    println!("{script} took {:.1} s:\n{text}", t0.elapsed().as_secs_f64());
    (status.success(), text)
}
