//! Three `strata serve` replicas on one PostgreSQL database (a throwaway cluster,
//! `common::postgres`) behind Debian's nginx as the load balancer, all on loopback: stream
//! sessions opened through the balancer (nginx's round robin puts them on different replicas)
//! all see an edit made through it; two editors racing through it with the same `If-Match` get
//! one 200 and one 409; every replica serves the same bytes for the same URL. Without nginx
//! (`apt-get install nginx-light`; `.ci/run` installs it) this fails, never skips.

mod common;

use futures::{SinkExt, StreamExt};
use serde_json::{json, Value};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};
use tokio_tungstenite::tungstenite::Message;

const ADMIN: &str = "st_balancer_admin";

type Ws =
    tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>>;

/// nginx in the foreground, killed when dropped.
struct Nginx {
    child: Child,
    addr: String,
}

impl Drop for Nginx {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free port")
        .port()
}

/// nginx on a free loopback port, proxying HTTP and WebSockets round robin to `upstreams`.
fn nginx(dir: &Path, upstreams: &[&str]) -> Nginx {
    let bin = ["/usr/sbin/nginx", "/usr/bin/nginx"]
        .into_iter()
        .find(|p| Path::new(p).is_file())
        .unwrap_or_else(|| {
            panic!("the balancer tests need nginx: apt-get install nginx-light (.ci/run does)")
        });
    let port = free_port();
    let servers: String = upstreams.iter().map(|u| format!("server {u};\n")).collect();
    let d = dir.display();
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
  upstream strata {{ {servers} }}
  map $http_upgrade $connection_upgrade {{ default upgrade; '' close; }}
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
    let path = dir.join("nginx.conf");
    std::fs::write(&path, conf).expect("write nginx.conf");
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
        .expect("start nginx");
    let addr = format!("127.0.0.1:{port}");
    let deadline = Instant::now() + Duration::from_secs(30);
    while std::net::TcpStream::connect(&addr).is_err() {
        assert!(
            Instant::now() < deadline,
            "nginx does not listen: {}",
            std::fs::read_to_string(dir.join("error.log")).unwrap_or_default()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    Nginx { child, addr }
}

async fn call(
    addr: &str,
    method: &'static str,
    path: String,
    headers: Vec<(&'static str, String)>,
    body: Vec<u8>,
) -> (u16, Vec<u8>) {
    let addr = addr.to_string();
    tokio::task::spawn_blocking(move || {
        let bearer = format!("Bearer {ADMIN}");
        let mut h: Vec<(&str, &str)> = vec![("authorization", &bearer)];
        h.extend(headers.iter().map(|(k, v)| (*k, v.as_str())));
        common::raw::request(&addr, method, &path, &h, &body)
            .unwrap_or_else(|e| panic!("{method} {path}: {e}"))
    })
    .await
    .expect("request task")
}

async fn edit(addr: &str, id: &str, if_match: u64, region: &str) -> (u16, Value) {
    let patch = json!([{"op": "add", "path": "/regions/-", "value":
        {"id": region, "bbox": {"min": [10.0, 10.0], "max": [20.0, 20.0]}}}]);
    let (status, body) = call(
        addr,
        "POST",
        format!("/v1/worlds/{id}/edits"),
        vec![
            ("content-type", "application/json-patch+json".into()),
            ("if-match", if_match.to_string()),
        ],
        serde_json::to_vec(&patch).expect("json"),
    )
    .await;
    (status, serde_json::from_slice(&body).unwrap_or(Value::Null))
}

async fn next_json(ws: &mut Ws) -> Value {
    loop {
        let m = tokio::time::timeout(Duration::from_secs(60), ws.next())
            .await
            .expect("a message within 60 s")
            .expect("stream open")
            .expect("message");
        if let Message::Text(t) = m {
            return serde_json::from_str(&t).expect("JSON");
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn three_replicas_behind_nginx_share_edits_streams_and_bytes() {
    let url = common::postgres::database().await;
    let dirs: Vec<tempfile::TempDir> = (0..4).map(|_| tempfile::tempdir().expect("tmp")).collect();
    let replicas: Vec<common::Server> = dirs[..3]
        .iter()
        .map(|d| {
            common::start(
                [
                    "--data",
                    d.path().to_str().expect("utf-8"),
                    "--admin-token",
                    ADMIN,
                    "--store",
                    &url,
                ],
                &[],
            )
        })
        .collect();
    let addrs: Vec<&str> = replicas.iter().map(|r| r.addr.as_str()).collect();
    let lb = nginx(dirs[3].path(), &addrs);

    let (status, body) = call(
        &lb.addr,
        "POST",
        "/v1/worlds".into(),
        vec![("content-type", "application/json".into())],
        br#"{"seed": 11}"#.to_vec(),
    )
    .await;
    assert_eq!(status, 201, "{}", String::from_utf8_lossy(&body));
    let w: Value = serde_json::from_slice(&body).expect("json");
    let id = w["id"].as_str().expect("id").to_string();
    let token = w["tokens"]["admin"].as_str().expect("token").to_string();

    // Three sessions through the balancer: round robin spreads them over the replicas.
    let mut sessions = Vec::new();
    for _ in 0..3 {
        let (mut ws, _) = tokio_tungstenite::connect_async(format!(
            "ws://{}/v1/worlds/{id}/stream?token={token}",
            lb.addr
        ))
        .await
        .expect("connect through nginx");
        assert_eq!(next_json(&mut ws).await["type"], "hello");
        ws.send(Message::Text(
            json!({"type": "view", "x": 16, "z": 16, "rings": [1]})
                .to_string()
                .into(),
        ))
        .await
        .expect("send");
        while next_json(&mut ws).await["type"] != "idle" {}
        sessions.push(ws);
    }

    // Two editors through the balancer, both expecting version 1: one wins.
    let (lb_a, lb_b, id_a, id_b) = (lb.addr.clone(), lb.addr.clone(), id.clone(), id.clone());
    let a = tokio::spawn(async move { edit(&lb_a, &id_a, 1, "a").await });
    let b = tokio::spawn(async move { edit(&lb_b, &id_b, 1, "b").await });
    let mut statuses = [a.await.expect("a").0, b.await.expect("b").0];
    statuses.sort_unstable();
    assert_eq!(statuses, [200, 409]);

    for ws in &mut sessions {
        loop {
            let m = next_json(ws).await;
            if m["type"] == "invalidate" {
                assert_eq!(m["version"], 2, "{m}");
                break;
            }
        }
    }

    // The same URL gives the same bytes on every replica and through the balancer.
    let path = format!("/v1/worlds/{id}/tiles/0/0/0.bin?v=2");
    let mut bodies = Vec::new();
    for addr in addrs.iter().copied().chain([lb.addr.as_str()]) {
        let (status, body) = call(addr, "GET", path.clone(), Vec::new(), Vec::new()).await;
        assert_eq!(status, 200, "{addr}: {}", String::from_utf8_lossy(&body));
        bodies.push(body);
    }
    assert!(bodies[0].len() > 1000);
    assert!(
        bodies.iter().all(|b| *b == bodies[0]),
        "every replica serves the same bytes"
    );
}
