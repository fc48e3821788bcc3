//! Real components started on loopback for the tests with real parts and for `strata bench
//! scale`: a throwaway PostgreSQL cluster ([`postgres`]), Debian's nginx as the load balancer
//! of several replicas or as a static file server ([`nginx`]), and `strata serve` replicas
//! ([`replica`]). Both fail with a message naming the Debian package when the
//! binaries are missing; nothing here skips.

pub mod nginx;
pub mod postgres;
pub mod replica;

/// A free TCP port on 127.0.0.1 (bound, read and released: another process may take it).
///
/// # Errors
/// No port can be bound.
pub fn free_port() -> std::io::Result<u16> {
    std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .map(|a| a.port())
}
