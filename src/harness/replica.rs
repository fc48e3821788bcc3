//! `strata serve` processes started by the tests and benchmarks with real parts: the address a
//! server prints once it listens, and replicas of one store on loopback.

use anyhow::Context;
use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Child, Command, Stdio};

/// The `host:port` of a `listening on http://…` log line, if `line` is one.
pub fn listening_addr(line: &str) -> Option<String> {
    let rest = line.split("listening on http://").nth(1)?;
    Some(
        rest.split(|c: char| c.is_whitespace() || c == '\u{1b}')
            .next()
            .unwrap_or_default()
            .to_string(),
    )
}

/// A running `strata serve`, killed when dropped.
#[derive(Debug)]
pub struct Replica {
    /// The process.
    pub child: Child,
    /// `127.0.0.1:<port>` it listens on.
    pub addr: String,
}

impl Drop for Replica {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Starts `bin serve --addr 127.0.0.1:0 --backend cpu` with `args` and returns once it listens;
/// its log is read and dropped.
///
/// # Errors
/// It cannot be started or exits before listening.
pub fn start(bin: &Path, args: &[&str]) -> anyhow::Result<Replica> {
    let mut child = Command::new(bin)
        .args(["serve", "--addr", "127.0.0.1:0", "--backend", "cpu"])
        .args(args)
        .env("NO_COLOR", "1")
        .env("RUST_LOG", "strata=info")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .with_context(|| format!("starting {} serve", bin.display()))?;
    let stdout = child.stdout.take().context("piped stdout")?;
    let mut lines = BufReader::new(stdout).lines();
    let addr = loop {
        let line = lines
            .next()
            .context("strata serve exited before listening")?
            .context("reading its output")?;
        if let Some(addr) = listening_addr(&line) {
            break addr;
        }
    };
    std::thread::spawn(move || for _ in lines.by_ref() {});
    Ok(Replica { child, addr })
}
