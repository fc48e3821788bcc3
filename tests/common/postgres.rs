//! A throwaway PostgreSQL cluster for the tests of the PostgreSQL store: `initdb` in a temporary
//! directory, `postgres` on a free loopback port, started on first use by each test binary and
//! stopped (its directory removed) when the binary exits. Each caller of [`database`] gets a new
//! empty database in it, so tests do not see each other's worlds.
//!
//! The binaries are Debian's (`/usr/lib/postgresql/<major>/bin`, package `postgresql`), or
//! those of the directory `STRATA_PG_BIN`. Without them the tests fail with a message that says
//! so: they never skip. As root (CI), the cluster runs as the `postgres` user, since PostgreSQL
//! refuses to run as root.

use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::OnceLock;
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
}

static CLUSTER: OnceLock<Cluster> = OnceLock::new();
static PID: AtomicU32 = AtomicU32::new(0);
static NEXT_DB: AtomicU32 = AtomicU32::new(0);

/// The PostgreSQL `bin` directory: `STRATA_PG_BIN`, else the newest `/usr/lib/postgresql/*/bin`.
///
/// # Panics
/// Neither has `initdb` and `postgres`: the message says how to install them.
pub fn bin_dir() -> PathBuf {
    if let Ok(dir) = std::env::var("STRATA_PG_BIN") {
        let dir = PathBuf::from(dir);
        assert!(
            dir.join("initdb").is_file() && dir.join("postgres").is_file(),
            "STRATA_PG_BIN={} has no initdb and postgres",
            dir.display()
        );
        return dir;
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
    found.pop().map(|(_, bin)| bin).unwrap_or_else(|| {
        panic!(
            "the PostgreSQL tests need PostgreSQL's server binaries, and there are none in \
             /usr/lib/postgresql/*/bin: install Debian's `postgresql` package (.ci/run does), \
             or set STRATA_PG_BIN to a directory holding initdb and postgres"
        )
    })
}

/// The uid and gid of the `postgres` user, when this process is root (PostgreSQL refuses to run
/// as root); `None` otherwise.
fn run_as() -> Option<(u32, u32)> {
    // SAFETY: `geteuid` has no preconditions.
    if unsafe { libc::geteuid() } != 0 {
        return None;
    }
    // SAFETY: the name is a NUL-terminated constant; the returned record is read at once, before
    // any other call could reuse its static storage.
    let pw = unsafe { libc::getpwnam(c"postgres".as_ptr()) };
    assert!(
        !pw.is_null(),
        "running as root, the PostgreSQL tests run the cluster as the `postgres` user, and there \
         is none: install Debian's `postgresql` package (it creates the user)"
    );
    // SAFETY: `pw` is non-null and points to a valid passwd record.
    Some(unsafe { ((*pw).pw_uid, (*pw).pw_gid) })
}

fn as_user(cmd: &mut Command, user: Option<(u32, u32)>) -> &mut Command {
    use std::os::unix::process::CommandExt;
    if let Some((uid, gid)) = user {
        cmd.uid(uid).gid(gid);
    }
    cmd
}

fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free loopback port")
        .port()
}

/// Stops the cluster and removes its directory when the test binary exits.
extern "C" fn stop_at_exit() {
    let pid = PID.load(Ordering::SeqCst);
    if pid == 0 {
        return;
    }
    // SAFETY: signalling a process id this binary started; SIGQUIT is PostgreSQL's immediate
    // shutdown, which also ends its children.
    unsafe { libc::kill(pid as libc::pid_t, libc::SIGQUIT) };
    let deadline = Instant::now() + Duration::from_secs(10);
    // The thread that started it reaps it; then the process id no longer exists.
    // SAFETY: signal 0 only checks that the process exists.
    while unsafe { libc::kill(pid as libc::pid_t, 0) } == 0 && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(20));
    }
    if let Some(c) = CLUSTER.get() {
        let _ = std::fs::remove_dir_all(&c.dir);
    }
}

fn start() -> Cluster {
    let bin = bin_dir();
    let user = run_as();
    let dir =
        std::env::temp_dir().join(format!("strata-pg-{}-{}", std::process::id(), free_port()));
    std::fs::create_dir_all(&dir).expect("create the cluster directory");
    if let Some((uid, gid)) = user {
        std::os::unix::fs::chown(&dir, Some(uid), Some(gid)).expect("chown the cluster directory");
    }
    let data = dir.join("data");
    let out = as_user(&mut Command::new(bin.join("initdb")), user)
        .args(["--auth=trust", "--no-sync", "--encoding=UTF8", "--locale=C"])
        .arg(format!("--username={USER}"))
        .arg("-D")
        .arg(&data)
        .stdin(Stdio::null())
        .output()
        .expect("run initdb");
    assert!(
        out.status.success(),
        "initdb failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let port = free_port();
    let (tx, rx) = std::sync::mpsc::channel();
    let postgres = bin.join("postgres");
    let (d, s) = (data.clone(), dir.clone());
    // The postmaster's parent is this long-lived thread, so PR_SET_PDEATHSIG ends it when the
    // test binary exits, even if the exit handler does not run.
    std::thread::spawn(move || {
        use std::os::unix::process::CommandExt;
        let mut cmd = Command::new(postgres);
        as_user(&mut cmd, user)
            .arg("-D")
            .arg(&d)
            .arg("-k")
            .arg(&s)
            .args(["-p", &port.to_string(), "-c", "listen_addresses=127.0.0.1"])
            // A throwaway cluster: speed over surviving a crash of the machine.
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
        .expect("the cluster thread answers")
        .expect("start postgres");
    PID.store(pid, Ordering::SeqCst);
    // SAFETY: registers a plain `extern "C"` function.
    unsafe { libc::atexit(stop_at_exit) };
    Cluster { port, dir, bin }
}

/// The cluster of this test binary, started on first use.
pub fn cluster() -> &'static Cluster {
    CLUSTER.get_or_init(start)
}

/// `postgres://strata@127.0.0.1:<port>/<db>`.
pub fn url(db: &str) -> String {
    format!("postgres://{USER}@127.0.0.1:{}/{db}", cluster().port)
}

/// Connects to database `db`, waiting up to 30 s for the cluster to accept connections.
///
/// # Panics
/// It does not within 30 s.
pub async fn connect(db: &str) -> tokio_postgres::Client {
    let deadline = Instant::now() + Duration::from_secs(30);
    loop {
        match tokio_postgres::connect(&url(db), tokio_postgres::NoTls).await {
            Ok((client, conn)) => {
                tokio::spawn(conn);
                return client;
            }
            Err(e) if Instant::now() > deadline => {
                panic!("the throwaway PostgreSQL cluster does not accept connections: {e}")
            }
            Err(_) => tokio::time::sleep(Duration::from_millis(50)).await,
        }
    }
}

/// A new empty database in the cluster; returns its URL.
pub async fn database() -> String {
    let name = format!(
        "t{}_{}",
        std::process::id(),
        NEXT_DB.fetch_add(1, Ordering::SeqCst)
    );
    let admin = connect("postgres").await;
    admin
        .batch_execute(&format!("CREATE DATABASE {name}"))
        .await
        .expect("create a test database");
    url(&name)
}
