//! Rate limits of the expensive routes, per client address and per bearer token
//! (`strata serve --rate-limit N`, requests per minute; default
//! [`DEFAULT_RATE_LIMIT_PER_MINUTE`]).
//!
//! Each request to an expensive route is charged to its client's address (an IPv6 address by
//! its /64, which one host usually holds whole) and, when it carries `Authorization: Bearer`, to
//! the token as well (by its blake3 hash, so no token is kept in memory), so that neither many
//! addresses with one token nor many tokens from one address escape the limit. Each key may make
//! `N` requests at once and then one every `60 / N` seconds (a GCRA, the `governor` crate's
//! keyed limiter). A refused request is 429 `rate_limited` whose `field` is `rate_limit`, with
//! `Retry-After` the whole seconds until the key may make its next request. Requests without a
//! peer address (driven in-process, as the tests do with `oneshot`) are charged to their token
//! only.
//!
//! Charged routes: export creation, scatter, volume chunks, Ptex pages, a region's PNGs and
//! stats, a volume's `mesh.glb`
//! (each through the [`Charge`] extractor, before any other work), and a tile whose encoded body
//! is not in the body cache ([`AppState::tile_product`] is asked first): a cached tile is a
//! memory read and is never charged.
//!
//! Why `governor` directly and not `tower_governor`: its layer decides before the handler runs,
//! so it cannot tell a cached tile from one to synthesise; it takes one key per layer, where a
//! request here is charged to two; and its refusals are not this server's JSON error shape.
//! The keyed limiters' maps are pruned of keys back at full capacity every [`PRUNE_EVERY`]
//! checks, so idle clients hold no memory.

use super::error::{code, AppError};
use super::AppState;
use axum::extract::{ConnectInfo, FromRequestParts};
use axum::http::request::Parts;
use axum::http::{header, StatusCode};
use governor::clock::{Clock, DefaultClock};
use governor::{DefaultKeyedRateLimiter, Quota, RateLimiter};
use std::net::{IpAddr, SocketAddr};
use std::num::NonZeroU32;
use std::sync::atomic::{AtomicU64, Ordering};

/// Default of `--rate-limit`, requests per minute per address and per token.
pub const DEFAULT_RATE_LIMIT_PER_MINUTE: u32 = 600;
/// Checks between two prunings of the limiters' key maps.
pub const PRUNE_EVERY: u64 = 4096;

/// Who a request comes from, as the rate limits key it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Client {
    /// The peer address (IPv6 by its /64), when the request came over a socket.
    pub addr: Option<IpAddr>,
    /// blake3 of the bearer token, when there is one.
    pub token: Option<[u8; 32]>,
}

impl Client {
    /// The client of a request: its peer address ([`ConnectInfo`], set by
    /// [`super::connections::serve`]) and its bearer token.
    pub fn of(parts: &Parts) -> Self {
        let addr = parts
            .extensions
            .get::<ConnectInfo<SocketAddr>>()
            .map(|c| prefix(c.0.ip()));
        let token = parts
            .headers
            .get(header::AUTHORIZATION)
            .and_then(|v| v.to_str().ok())
            .and_then(|v| v.strip_prefix("Bearer "))
            .map(|t| *blake3::hash(t.trim().as_bytes()).as_bytes());
        Self { addr, token }
    }
}

/// An IPv4 address, or the /64 network of an IPv6 one (an IPv4-mapped address as IPv4).
fn prefix(ip: IpAddr) -> IpAddr {
    match ip {
        IpAddr::V4(v4) => IpAddr::V4(v4),
        IpAddr::V6(v6) => match v6.to_ipv4_mapped() {
            Some(v4) => IpAddr::V4(v4),
            None => {
                let s = v6.segments();
                IpAddr::V6(std::net::Ipv6Addr::new(s[0], s[1], s[2], s[3], 0, 0, 0, 0))
            }
        },
    }
}

/// The limiters of a server.
#[derive(Debug)]
pub struct RateLimits {
    per_minute: NonZeroU32,
    by_addr: DefaultKeyedRateLimiter<IpAddr>,
    by_token: DefaultKeyedRateLimiter<[u8; 32]>,
    checks: AtomicU64,
}

impl Default for RateLimits {
    fn default() -> Self {
        Self::new(DEFAULT_RATE_LIMIT_PER_MINUTE)
    }
}

impl RateLimits {
    /// `per_minute` requests per minute per address and per token (at least 1).
    pub fn new(per_minute: u32) -> Self {
        let per_minute = NonZeroU32::new(per_minute).unwrap_or(NonZeroU32::MIN);
        let quota = Quota::per_minute(per_minute);
        Self {
            per_minute,
            by_addr: RateLimiter::keyed(quota),
            by_token: RateLimiter::keyed(quota),
            checks: AtomicU64::new(0),
        }
    }

    /// Requests per minute per key.
    pub fn per_minute(&self) -> u32 {
        self.per_minute.get()
    }

    /// Charges one request to `client`'s address and token: 429 `rate_limited` when either has
    /// used up its rate. The address is charged first, so a request its token's limit refuses
    /// has still used one of its address's allowance.
    pub fn check(&self, client: &Client) -> Result<(), AppError> {
        if self.checks.fetch_add(1, Ordering::Relaxed) % PRUNE_EVERY == PRUNE_EVERY - 1 {
            self.by_addr.retain_recent();
            self.by_addr.shrink_to_fit();
            self.by_token.retain_recent();
            self.by_token.shrink_to_fit();
        }
        let refused = |who: &str, not_until: governor::NotUntil<_>| {
            let wait = not_until.wait_time_from(DefaultClock::default().now());
            let seconds = wait.as_secs() + u64::from(wait.subsec_nanos() > 0);
            AppError::new(
                StatusCode::TOO_MANY_REQUESTS,
                code::RATE_LIMITED,
                format!(
                    "{who} made more than the rate_limit of {} expensive requests per minute; \
                     retry in {} s",
                    self.per_minute,
                    seconds.max(1)
                ),
            )
            .with_field("rate_limit")
            .with_retry_after(seconds.max(1))
        };
        if let Some(addr) = &client.addr {
            self.by_addr
                .check_key(addr)
                .map_err(|n| refused("this address", n))?;
        }
        if let Some(token) = &client.token {
            self.by_token
                .check_key(token)
                .map_err(|n| refused("this token", n))?;
        }
        Ok(())
    }
}

/// An extractor that charges the request to its client ([`RateLimits::check`]); put it first
/// in an expensive handler's arguments, so a refused request does no other work.
#[derive(Clone, Copy, Debug)]
pub struct Charge;

impl FromRequestParts<AppState> for Charge {
    type Rejection = AppError;

    async fn from_request_parts(parts: &mut Parts, st: &AppState) -> Result<Self, AppError> {
        st.rate.check(&Client::of(parts))?;
        Ok(Charge)
    }
}

/// An extractor of the request's [`Client`], for handlers that charge only some requests.
impl FromRequestParts<AppState> for Client {
    type Rejection = std::convert::Infallible;

    async fn from_request_parts(
        parts: &mut Parts,
        _: &AppState,
    ) -> Result<Self, std::convert::Infallible> {
        Ok(Client::of(parts))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_burst_is_refused_per_key_with_the_limit_and_a_wait() {
        let limits = RateLimits::new(3);
        let a = Client {
            addr: Some("10.0.0.1".parse().expect("ip")),
            token: None,
        };
        let b = Client {
            addr: Some("10.0.0.2".parse().expect("ip")),
            token: None,
        };
        for _ in 0..3 {
            limits.check(&a).expect("within the burst");
        }
        let e = limits.check(&a).expect_err("over the burst");
        assert_eq!(
            (e.status, e.code),
            (StatusCode::TOO_MANY_REQUESTS, "rate_limited")
        );
        assert_eq!(e.field.as_deref(), Some("rate_limit"));
        assert!(e.message.contains("rate_limit of 3"), "{}", e.message);
        assert!(matches!(e.retry_after_s, Some(1..=20)), "{e:?}");
        limits.check(&b).expect("another address");
        let v6 = |s: &str| prefix(s.parse().expect("ip"));
        assert_eq!(v6("2001:db8::1"), v6("2001:db8::ffff:2"));
        assert_ne!(v6("2001:db8::1"), v6("2001:db8:0:1::1"));
    }
}
