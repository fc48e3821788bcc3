//! What stream clients that never read cost the server (issue 18, finding 11): the resident set
//! of this process (the server runs in it, on a real socket) grows by less than the stated
//! bound per client, and clients of one view share their frames instead of holding a copy each.
//!
//! One test in its own binary: the resident set is the process's, so nothing else may run
//! beside it. The clients shrink their receive buffers to 4 KiB, so the server's writes block
//! after a few frames instead of filling megabytes of kernel buffers first (those are not in
//! the resident set either way, but the test would wait for them).

use futures::SinkExt;
use std::sync::atomic::Ordering;
use std::time::{Duration, Instant};
use strata::compute::Compute;
use strata::server::budget::MemoryBudget;
use strata::server::{app, AppState};
use strata::stream::session::{CLIENT_MEMORY_BOUND, STATS};
use tokio_tungstenite::tungstenite::Message;

type Ws = tokio_tungstenite::WebSocketStream<tokio::net::TcpStream>;

/// Resident set of this process, bytes.
fn rss() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").expect("/proc/self/status");
    let kib: u64 = status
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))
        .and_then(|v| v.split_whitespace().next()?.parse().ok())
        .expect("VmRSS");
    kib << 10
}

const MIB: u64 = 1 << 20;

/// A client with a 4 KiB receive buffer that sends one view of `rings` around `(x, z)` in the
/// `bin` format and never reads.
async fn silent(addr: &str, x: f64, z: f64, rings: &[u32]) -> Ws {
    let socket = tokio::net::TcpSocket::new_v4().expect("socket");
    socket.set_recv_buffer_size(4096).expect("SO_RCVBUF");
    let stream = socket
        .connect(addr.parse().expect("addr"))
        .await
        .expect("connect");
    let (mut ws, _) =
        tokio_tungstenite::client_async(format!("ws://{addr}/v1/seeds/42/stream"), stream)
            .await
            .expect("handshake");
    let view = serde_json::json!({"type": "view", "x": x, "z": z, "rings": rings, "format": "bin"});
    ws.send(Message::Text(view.to_string().into()))
        .await
        .expect("send the view");
    ws
}

/// Waits until the server has produced no frame for a second (every client's queue is full or
/// its view done), at most `limit`.
async fn settle(limit: Duration) {
    let start = Instant::now();
    let mut last = STATS.frames.load(Ordering::Relaxed);
    let mut still = Instant::now();
    while start.elapsed() < limit {
        tokio::time::sleep(Duration::from_millis(100)).await;
        let now = STATS.frames.load(Ordering::Relaxed);
        if now != last {
            (last, still) = (now, Instant::now());
        } else if still.elapsed() >= Duration::from_secs(1) {
            return;
        }
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn silent_clients_stay_within_the_per_client_bound_and_share_their_frames() {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind");
    let addr = listener.local_addr().expect("addr").to_string();
    // A small cache budget, so the caches' growth is small beside the clients'.
    let state = AppState::new(Compute::cpu()).with_memory_budget(MemoryBudget::from_mb(64));
    tokio::spawn(async move { axum::serve(listener, app(state)).await });

    // One reading client takes the shared view's tiles (about 15 MiB of frames: more than the
    // socket buffers take, so the queues fill), so the caches hold their frames.
    let rings = [4u32, 4];
    {
        let mut ws = silent(&addr, 0.0, 0.0, &rings).await;
        loop {
            let msg =
                tokio::time::timeout(Duration::from_secs(120), futures::StreamExt::next(&mut ws))
                    .await
                    .expect("a message within 120 s")
                    .expect("open")
                    .expect("message");
            if let Message::Text(t) = msg {
                if t.contains("\"idle\"") {
                    break;
                }
            }
        }
    }
    tokio::time::sleep(Duration::from_millis(500)).await;

    // Clients of one view share its frames: each holds at most the frame its socket is writing
    // (the WebSocket's write buffer), not a queue of copies. A copy each would be 16 frames of
    // about 114 KiB, 1.8 MiB a client.
    const SHARED: u64 = 64;
    const SHARED_BOUND: u64 = 512 << 10;
    let before = rss();
    let mut clients = Vec::new();
    for _ in 0..SHARED {
        clients.push(silent(&addr, 0.0, 0.0, &rings).await);
    }
    settle(Duration::from_secs(6)).await;
    let grew = rss().saturating_sub(before);
    eprintln!(
        "{SHARED} clients of one view: resident set +{} MiB",
        grew / MIB
    );
    assert!(
        grew <= SHARED * SHARED_BOUND + 16 * MIB,
        "{SHARED} clients of one view grew the resident set by {} MiB; at most {} KiB each (plus 16 MiB) was expected",
        grew / MIB,
        SHARED_BOUND >> 10
    );
    drop(clients);
    tokio::time::sleep(Duration::from_secs(1)).await;

    // Clients of different views each hold at most CLIENT_MEMORY_BOUND; the caches (64 MiB)
    // and allocator slack come on top.
    const DISTINCT: u64 = 16;
    let before = rss();
    let mut clients = Vec::new();
    for i in 0..DISTINCT {
        clients.push(silent(&addr, 40_000.0 * (i + 1) as f64, -20_000.0, &rings).await);
    }
    settle(Duration::from_secs(8)).await;
    let grew = rss().saturating_sub(before);
    let bound = DISTINCT * CLIENT_MEMORY_BOUND as u64 + 64 * MIB + 16 * MIB;
    eprintln!(
        "{DISTINCT} clients of different views: resident set +{} MiB (bound {} MiB)",
        grew / MIB,
        bound / MIB
    );
    assert!(
        grew <= bound,
        "{DISTINCT} clients of different views grew the resident set by {} MiB, over the bound of {} MiB",
        grew / MIB,
        bound / MIB
    );
    drop(clients);
}
