//! Debian's nginx (`nginx-light`) in the foreground on a free loopback port, with its
//! configuration, logs and temporary files in a directory of the caller's: as the load balancer
//! of `strata serve` replicas ([`balancer`]: HTTP and WebSockets proxied round robin, keep-alive
//! connections to the replicas) or serving files ([`static_files`], the peer of the benchmarks).

use anyhow::{bail, Context};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A running nginx, stopped when dropped.
#[derive(Debug)]
pub struct Nginx {
    child: Child,
    /// `127.0.0.1:<port>` it listens on.
    pub addr: String,
    /// Its directory and configuration file.
    dir: PathBuf,
    conf: PathBuf,
}

impl Drop for Nginx {
    fn drop(&mut self) {
        // `-s stop` makes a master stop its workers (a killed master would orphan them).
        let _ = Command::new(self.child_bin())
            .arg("-p")
            .arg(&self.dir)
            .arg("-c")
            .arg(&self.conf)
            .args(["-s", "stop"])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status();
        let deadline = Instant::now() + Duration::from_secs(5);
        while matches!(self.child.try_wait(), Ok(None)) && Instant::now() < deadline {
            std::thread::sleep(Duration::from_millis(20));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Nginx {
    fn child_bin(&self) -> &'static str {
        binary().unwrap_or("nginx")
    }
}

/// The nginx binary of Debian's package.
///
/// # Errors
/// None is installed: the message says how to install it.
pub fn binary() -> anyhow::Result<&'static str> {
    ["/usr/sbin/nginx", "/usr/bin/nginx"]
        .into_iter()
        .find(|p| Path::new(p).is_file())
        .context("nginx is not installed: apt-get install nginx-light (.ci/run does)")
}

/// nginx proxying HTTP and WebSockets round robin to `upstreams` (`host:port` each), with its
/// files in `dir`; returns once it accepts connections (within 30 s).
///
/// # Errors
/// nginx is missing, cannot be started or does not listen.
pub fn balancer(dir: &Path, upstreams: &[&str]) -> anyhow::Result<Nginx> {
    let bin = binary()?;
    let port = super::free_port()?;
    let servers: String = upstreams.iter().map(|u| format!("server {u};\n")).collect();
    let d = dir.display();
    // Keep-alive connections to the replicas, so the balancer does not open one per request.
    let conf = format!(
        "daemon off;
master_process off;
pid {d}/nginx.pid;
error_log {d}/error.log warn;
events {{ worker_connections 1024; }}
http {{
  access_log off;
  client_body_temp_path {d}/body;
  proxy_temp_path {d}/proxy;
  fastcgi_temp_path {d}/fastcgi;
  uwsgi_temp_path {d}/uwsgi;
  scgi_temp_path {d}/scgi;
  upstream strata {{ {servers} keepalive 64; }}
  map $http_upgrade $connection_upgrade {{ default upgrade; '' ''; }}
  server {{
    listen 127.0.0.1:{port};
    location / {{
      proxy_pass http://strata;
      proxy_http_version 1.1;
      proxy_set_header Upgrade $http_upgrade;
      proxy_set_header Connection $connection_upgrade;
      proxy_read_timeout 300s;
    }}
  }}
}}
"
    );
    run(bin, dir, port, &conf)
}

/// nginx serving the files under `root` (with a long-lived `Cache-Control` and an `ETag`, as
/// strata's products), with `auto` worker processes and its other files in `dir`.
///
/// # Errors
/// nginx is missing, cannot be started or does not listen.
pub fn static_files(dir: &Path, root: &Path) -> anyhow::Result<Nginx> {
    let bin = binary()?;
    let port = super::free_port()?;
    let d = dir.display();
    let conf = format!(
        "worker_processes auto;
daemon off;
pid {d}/nginx.pid;
error_log {d}/error.log warn;
events {{ worker_connections 1024; }}
http {{
  access_log off;
  sendfile on;
  keepalive_requests 100000;
  client_body_temp_path {d}/body;
  proxy_temp_path {d}/proxy;
  fastcgi_temp_path {d}/fastcgi;
  uwsgi_temp_path {d}/uwsgi;
  scgi_temp_path {d}/scgi;
  server {{
    listen 127.0.0.1:{port};
    root {root};
    location / {{ etag on; add_header Cache-Control \"public, max-age=31536000, immutable\"; }}
  }}
}}
",
        root = root.display()
    );
    run(bin, dir, port, &conf)
}

/// Writes `conf` to `dir/nginx.conf`, starts nginx and waits up to 30 s for it to listen on
/// `port`.
fn run(bin: &str, dir: &Path, port: u16, conf: &str) -> anyhow::Result<Nginx> {
    let path = dir.join("nginx.conf");
    std::fs::write(&path, conf).context("writing nginx.conf")?;
    let child = Command::new(bin)
        .arg("-p")
        .arg(dir)
        .arg("-c")
        .arg(&path)
        .arg("-e")
        .arg(dir.join("error.log"))
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .context("starting nginx")?;
    let nginx = Nginx {
        child,
        addr: format!("127.0.0.1:{port}"),
        dir: dir.to_path_buf(),
        conf: path,
    };
    let deadline = Instant::now() + Duration::from_secs(30);
    while std::net::TcpStream::connect(&nginx.addr).is_err() {
        if Instant::now() > deadline {
            bail!(
                "nginx does not listen: {}",
                std::fs::read_to_string(dir.join("error.log")).unwrap_or_default()
            );
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    Ok(nginx)
}
