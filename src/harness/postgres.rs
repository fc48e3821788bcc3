//! A throwaway PostgreSQL cluster: `initdb` in a temporary directory and `postgres` on a free
//! loopback port with trust authentication, `fsync=off` (speed over surviving a crash of the
//! machine) and 200 connections. [`Cluster::stop`] (or dropping it) ends it and removes its
//! directory; the postmaster also ends when the thread that started it does (it is started with
//! `PR_SET_PDEATHSIG`), so a killed test or benchmark leaves no server behind.
//!
//! The binaries are Debian's (`/usr/lib/postgresql/<major>/bin`, package `postgresql`), or
//! those of the directory `STRATA_PG_BIN`. As root (CI), the cluster runs as the `postgres`
//! user, since PostgreSQL refuses to run as root.

use anyhow::{bail, ensure, Context};
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::{Duration, Instant};

/// The superuser of the throwaway cluster (trust authentication on loopback).
pub const USER: &str = "strata";

/// A running cluster.
#[derive(Debug)]
pub struct Cluster {
    /// TCP port on 127.0.0.1.
    pub port: u16,
    /// The directory that holds the data directory and the Unix socket.
    pub dir: PathBuf,
    /// `bin` directory of the PostgreSQL binaries.
    pub bin: PathBuf,
    /// The postmaster's process id; 0 once stopped.
    pid: AtomicU32,
}

/// The PostgreSQL `bin` directory: `STRATA_PG_BIN`, else the newest `/usr/lib/postgresql/*/bin`.
///
/// # Errors
/// Neither has `initdb` and `postgres`: the message says how to install them.
pub fn bin_dir() -> anyhow::Result<PathBuf> {
    if let Ok(dir) = std::env::var("STRATA_PG_BIN") {
        let dir = PathBuf::from(dir);
        ensure!(
            dir.join("initdb").is_file() && dir.join("postgres").is_file(),
            "STRATA_PG_BIN={} has no initdb and postgres",
            dir.display()
        );
        return Ok(dir);
    }
    let mut found: Vec<(u32, PathBuf)> = std::fs::read_dir("/usr/lib/postgresql")
        .into_iter()
        .flatten()
        .flatten()
        .filter_map(|e| {
            let major = e.file_name().to_str()?.parse::<u32>().ok()?;
            let bin = e.path().join("bin");
            (bin.join("initdb").is_file() && bin.join("postgres").is_file()).then_some((major, bin))
        })
        .collect();
    found.sort();
    found.pop().map(|(_, bin)| bin).context(
        "PostgreSQL's server binaries are needed, and there are none in \
         /usr/lib/postgresql/*/bin: install Debian's `postgresql` package (.ci/run does), or \
         set STRATA_PG_BIN to a directory holding initdb and postgres",
    )
}

/// The uid and gid of the `postgres` user, when this process is root (PostgreSQL refuses to run
/// as root); `None` otherwise.
fn run_as() -> anyhow::Result<Option<(u32, u32)>> {
    // SAFETY: `geteuid` has no preconditions.
    if unsafe { libc::geteuid() } != 0 {
        return Ok(None);
    }
    // SAFETY: the name is a NUL-terminated constant; the returned record is read at once, before
    // any other call could reuse its static storage.
    let pw = unsafe { libc::getpwnam(c"postgres".as_ptr()) };
    ensure!(
        !pw.is_null(),
        "running as root, the cluster runs as the `postgres` user, and there is none: install \
         Debian's `postgresql` package (it creates the user)"
    );
    // SAFETY: `pw` is non-null and points to a valid passwd record.
    Ok(Some(unsafe { ((*pw).pw_uid, (*pw).pw_gid) }))
}

fn as_user(cmd: &mut Command, user: Option<(u32, u32)>) -> &mut Command {
    use std::os::unix::process::CommandExt;
    if let Some((uid, gid)) = user {
        cmd.uid(uid).gid(gid);
    }
    cmd
}

impl Cluster {
    /// Initialises and starts a cluster; it accepts connections soon after (see
    /// [`Cluster::connect`], which waits for it).
    ///
    /// # Errors
    /// The binaries are missing, or `initdb` or `postgres` fails to start.
    pub fn start() -> anyhow::Result<Self> {
        let bin = bin_dir()?;
        let user = run_as()?;
        let dir = std::env::temp_dir().join(format!(
            "strata-pg-{}-{}",
            std::process::id(),
            super::free_port()?
        ));
        std::fs::create_dir_all(&dir).context("creating the cluster directory")?;
        if let Some((uid, gid)) = user {
            std::os::unix::fs::chown(&dir, Some(uid), Some(gid))
                .context("chown of the cluster directory")?;
        }
        let data = dir.join("data");
        let out = as_user(&mut Command::new(bin.join("initdb")), user)
            .args(["--auth=trust", "--no-sync", "--encoding=UTF8", "--locale=C"])
            .arg(format!("--username={USER}"))
            .arg("-D")
            .arg(&data)
            .stdin(Stdio::null())
            .output()
            .context("running initdb")?;
        if !out.status.success() {
            bail!("initdb failed: {}", String::from_utf8_lossy(&out.stderr));
        }
        let port = super::free_port()?;
        let (tx, rx) = std::sync::mpsc::channel();
        let postgres = bin.join("postgres");
        let (d, s) = (data.clone(), dir.clone());
        // The postmaster's parent is this long-lived thread, so PR_SET_PDEATHSIG ends it when the
        // process exits, even if no exit handler runs.
        std::thread::spawn(move || {
            use std::os::unix::process::CommandExt;
            let mut cmd = Command::new(postgres);
            as_user(&mut cmd, user)
                .arg("-D")
                .arg(&d)
                .arg("-k")
                .arg(&s)
                .args(["-p", &port.to_string(), "-c", "listen_addresses=127.0.0.1"])
                .args(["-c", "fsync=off", "-c", "max_connections=200"])
                .stdin(Stdio::null())
                .stdout(Stdio::null())
                .stderr(Stdio::null());
            // SAFETY: `prctl` is async-signal-safe and touches only this (child) process.
            unsafe {
                cmd.pre_exec(|| {
                    libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGQUIT);
                    Ok(())
                });
            }
            match cmd.spawn() {
                Ok(mut child) => {
                    let _ = tx.send(Ok(child.id()));
                    let _ = child.wait();
                    // Keep the thread (the parent) alive until the process exits.
                    loop {
                        std::thread::park();
                    }
                }
                Err(e) => {
                    let _ = tx.send(Err(e));
                }
            }
        });
        let pid = rx
            .recv()
            .context("the cluster thread answers")?
            .context("starting postgres")?;
        Ok(Self {
            port,
            dir,
            bin,
            pid: AtomicU32::new(pid),
        })
    }

    /// `postgres://strata@127.0.0.1:<port>/<db>`.
    pub fn url(&self, db: &str) -> String {
        format!("postgres://{USER}@127.0.0.1:{}/{db}", self.port)
    }

    /// Connects to database `db`, waiting up to 30 s for the cluster to accept connections.
    ///
    /// # Errors
    /// It does not within 30 s.
    pub async fn connect(&self, db: &str) -> anyhow::Result<tokio_postgres::Client> {
        let deadline = Instant::now() + Duration::from_secs(30);
        loop {
            match tokio_postgres::connect(&self.url(db), tokio_postgres::NoTls).await {
                Ok((client, conn)) => {
                    tokio::spawn(conn);
                    return Ok(client);
                }
                Err(e) if Instant::now() > deadline => {
                    bail!("the throwaway PostgreSQL cluster does not accept connections: {e}")
                }
                Err(_) => tokio::time::sleep(Duration::from_millis(50)).await,
            }
        }
    }

    /// Creates the empty database `name` (letters, digits and `_`); returns its URL.
    ///
    /// # Errors
    /// The cluster does not answer or refuses.
    pub async fn database(&self, name: &str) -> anyhow::Result<String> {
        ensure!(
            name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_'),
            "database name {name:?}"
        );
        let admin = self.connect("postgres").await?;
        admin
            .batch_execute(&format!("CREATE DATABASE {name}"))
            .await
            .context("creating a database")?;
        Ok(self.url(name))
    }

    /// Stops the postmaster (immediate shutdown, which also ends its children), waits up to
    /// 10 s for it to exit and removes the cluster's directory. Idempotent; safe in an exit
    /// handler.
    pub fn stop(&self) {
        let pid = self.pid.swap(0, Ordering::SeqCst);
        if pid == 0 {
            return;
        }
        // SAFETY: signalling the process id this cluster started; SIGQUIT is PostgreSQL's
        // immediate shutdown.
        unsafe { libc::kill(pid as libc::pid_t, libc::SIGQUIT) };
        let deadline = Instant::now() + Duration::from_secs(10);
        // The thread that started it reaps it; then the process id no longer exists.
        // SAFETY: signal 0 only checks that the process exists.
        while unsafe { libc::kill(pid as libc::pid_t, 0) } == 0 && Instant::now() < deadline {
            std::thread::sleep(Duration::from_millis(20));
        }
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

impl Drop for Cluster {
    fn drop(&mut self) {
        self.stop();
    }
}
