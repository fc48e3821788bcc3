//! Helpers shared by the integration tests: the real `strata` binary ([`start`], [`start_logged`])
//! and its raw HTTP client ([`raw`]), the GPU tests' device ([`device`]), requests to the router
//! in-process ([`oneshot`]), chunk columns from synthesised tiles ([`columns`]), a quad mesh's
//! Euler counts ([`topology`]), the seams of a block of tiles ([`seams`]), the arch volume element
//! ([`arch`]), a `strata` element with one cave opening to the ground ([`cave`]), the Khronos
//! glTF validator ([`gltf`]), stored-world fixtures ([`fixture`]), the Node packages of the
//! browser tests ([`js`]), tiles with river and lake water ([`water`]), PNG images ([`png`]),
//! a stream client ([`ws`]), a throwaway PostgreSQL cluster ([`postgres`]) and the tiles of a
//! mountain range ([`range`]).

#![allow(dead_code)] // Each test binary uses its own subset.

pub mod arch;
pub mod cave;
pub mod columns;
pub mod device;
pub mod fixture;
pub mod gltf;
pub mod js;
pub mod oneshot;
pub mod png;
pub mod postgres;
pub mod range;
pub mod raw;
pub mod replica;
pub mod seams;
pub mod topology;
pub mod water;
pub mod ws;

use std::ffi::OsStr;
use std::io::{BufRead, BufReader};
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};

/// A running `strata serve`, killed when dropped.
pub struct Server {
    /// The process (tests may SIGKILL it).
    pub child: Child,
    /// `host:port` it listens on.
    pub addr: String,
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Starts `strata serve --addr 127.0.0.1:0 --backend cpu <args>` with `envs`, and waits for the
/// address it logs (`listening on http://…`). The log is drained so the server never blocks on a
/// full pipe.
pub fn start<I, S>(args: I, envs: &[(&str, String)]) -> Server
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    launch(args, envs, None)
}

/// What a server started by [`start_logged`] writes after its address: its log on stdout and
/// panic messages on stderr.
pub struct Log {
    text: Arc<Mutex<String>>,
    readers: Vec<std::thread::JoinHandle<()>>,
}

impl Log {
    /// Everything written so far.
    pub fn now(&self) -> String {
        self.text
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .clone()
    }

    /// Everything written, once the process has exited (waits for the pipes to be drained).
    pub fn finish(mut self) -> String {
        for r in std::mem::take(&mut self.readers) {
            let _ = r.join();
        }
        self.now()
    }
}

/// As [`start`], with the server's output collected in a [`Log`].
pub fn start_logged<I, S>(args: I, envs: &[(&str, String)]) -> (Server, Log)
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    let mut log = Log {
        text: Arc::default(),
        readers: Vec::new(),
    };
    let server = launch(args, envs, Some(&mut log));
    (server, log)
}

fn launch<I, S>(args: I, envs: &[(&str, String)], log: Option<&mut Log>) -> Server
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    let mut child = Command::new(env!("CARGO_BIN_EXE_strata"))
        .args(["serve", "--addr", "127.0.0.1:0", "--backend", "cpu"])
        .args(args)
        .envs(envs.iter().map(|(k, v)| (*k, v.as_str())))
        .env("NO_COLOR", "1")
        .env("RUST_LOG", "strata=info")
        .stdout(Stdio::piped())
        .stderr(if log.is_some() {
            Stdio::piped()
        } else {
            Stdio::inherit()
        })
        .spawn()
        .expect("start strata serve");
    let stdout = child.stdout.take().expect("piped stdout");
    let mut lines = BufReader::new(stdout).lines();
    let addr = loop {
        let line = lines
            .next()
            .expect("server exited before listening")
            .expect("read server output");
        if let Some(addr) = strata::harness::replica::listening_addr(&line) {
            break addr;
        }
    };
    match log {
        None => {
            std::thread::spawn(move || for _ in lines.by_ref() {});
        }
        Some(log) => {
            let stderr = child.stderr.take().expect("piped stderr");
            let (out, err) = (log.text.clone(), log.text.clone());
            log.readers
                .push(std::thread::spawn(move || append_lines(lines, &out)));
            log.readers.push(std::thread::spawn(move || {
                append_lines(BufReader::new(stderr).lines(), &err)
            }));
        }
    }
    Server { child, addr }
}

fn append_lines(lines: impl Iterator<Item = std::io::Result<String>>, log: &Mutex<String>) {
    for line in lines.map_while(Result::ok) {
        let mut log = log
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        log.push_str(&line);
        log.push('\n');
    }
}
