//! The same URL gives the same bytes across requests, server restarts and thread counts: the real
//! `strata` binary is started twice (one worker thread, then three) and asked for the same
//! products over real TCP.

mod common;

use common::raw::get;
use common::Server;

fn start(worker_threads: usize, data: &std::path::Path) -> Server {
    common::start(
        [std::ffi::OsStr::new("--data"), data.as_os_str()],
        &[("TOKIO_WORKER_THREADS", worker_threads.to_string())],
    )
}

#[test]
fn bytes_are_identical_across_restarts_and_thread_counts() {
    let paths = [
        "/v1/seeds/42/tiles/0/0/0.bin",
        "/v1/seeds/42/tiles/0/-3/5.json",
        "/v1/seeds/7/tiles/2/-1/-1.glb",
        "/v1/seeds/7/tiles/4/3/-2.png",
        "/v1/seeds/7/tiles/1/2/2.bin?seams=1,1,0,0",
        "/v1/seeds/99/scatter/0/1/1.json",
    ];
    let data = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("restart-{}", std::process::id()));
    let mut runs = Vec::new();
    for threads in [1, 3] {
        let server = start(threads, &data);
        let bodies: Vec<Vec<u8>> = paths
            .iter()
            .map(|p| {
                let (status, body) = get(&server.addr, p);
                assert_eq!(status, 200, "{p}");
                assert!(!body.is_empty(), "{p}");
                // Twice within one run too.
                assert_eq!(get(&server.addr, p).1, body, "{p} changed between requests");
                body
            })
            .collect();
        runs.push(bodies);
    }
    for (i, p) in paths.iter().enumerate() {
        assert_eq!(
            runs[0][i], runs[1][i],
            "{p} differs after a restart with another thread count"
        );
    }
}
