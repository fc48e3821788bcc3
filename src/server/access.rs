//! Who is calling, and what they may do.
//!
//! Callers present `Authorization: Bearer <token>`. The server admin token (`--admin-token` or
//! `STRATA_ADMIN_TOKEN`) may create worlds and is admin of every world; world tokens grant one
//! [`Role`] on one world. Anyone may read a public world. A request with a token the server does
//! not know is refused with 401 wherever the route checks access, even where no token is needed.
//!
//! Tokens are compared and stored as `blake3(token)`; they never appear in logs or errors
//! ([`Secret`] hides them from `Debug`).

use super::error::{code, AppError};
use crate::store::{hash_token, Role, SceneStore, TokenHash, WorldMeta};
use axum::http::{header, HeaderMap, StatusCode};

/// A secret string (the admin token) whose `Debug` does not show it.
#[derive(Clone, PartialEq, Eq)]
pub struct Secret(String);

impl Secret {
    /// Wraps a secret.
    pub fn new(s: impl Into<String>) -> Self {
        Self(s.into())
    }

    /// The secret itself.
    pub fn expose(&self) -> &str {
        &self.0
    }
}

impl std::fmt::Debug for Secret {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Secret(<redacted>)")
    }
}

impl std::str::FromStr for Secret {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        if s.is_empty() {
            return Err("the admin token must not be empty".into());
        }
        Ok(Self(s.to_string()))
    }
}

/// The identity a request proves.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Caller {
    /// No `Authorization` header.
    Anonymous,
    /// The server admin token.
    ServerAdmin,
    /// A world token.
    World {
        /// Its world.
        world: String,
        /// Its role there.
        role: Role,
    },
}

fn unauthenticated(message: &str) -> AppError {
    AppError::new(StatusCode::UNAUTHORIZED, code::UNAUTHENTICATED, message)
}

/// 403 `forbidden`.
pub fn forbidden(message: impl Into<String>) -> AppError {
    AppError::new(StatusCode::FORBIDDEN, code::FORBIDDEN, message)
}

/// The bearer token of a request, if any; `Err` if `Authorization` is there but is not a
/// well-formed bearer token.
fn bearer(headers: &HeaderMap) -> Result<Option<&str>, AppError> {
    let mut values = headers.get_all(header::AUTHORIZATION).iter();
    let Some(value) = values.next() else {
        return Ok(None);
    };
    if values.next().is_some() {
        return Err(unauthenticated("send one Authorization header"));
    }
    let value = value
        .to_str()
        .map_err(|_| unauthenticated("Authorization must be `Bearer <token>`"))?;
    let (scheme, token) = value
        .trim()
        .split_once(' ')
        .ok_or_else(|| unauthenticated("Authorization must be `Bearer <token>`"))?;
    let token = token.trim();
    if !scheme.eq_ignore_ascii_case("bearer") || token.is_empty() {
        return Err(unauthenticated("Authorization must be `Bearer <token>`"));
    }
    Ok(Some(token))
}

/// Resolves the caller of a request: the server admin when the token hashes to `admin`, a
/// world token from the store, or 401 for a token nobody issued.
pub async fn caller(
    headers: &HeaderMap,
    admin: Option<&TokenHash>,
    store: &dyn SceneStore,
) -> Result<Caller, AppError> {
    let Some(token) = bearer(headers)? else {
        return Ok(Caller::Anonymous);
    };
    let hash = hash_token(token);
    if let Some(admin) = admin {
        // `blake3::Hash` equality is constant-time.
        if blake3::Hash::from(hash) == blake3::Hash::from(*admin) {
            return Ok(Caller::ServerAdmin);
        }
    }
    match store.token(hash).await {
        Ok(Some(grant)) => Ok(Caller::World {
            world: grant.world,
            role: grant.role,
        }),
        Ok(None) => Err(unauthenticated("unknown token")),
        Err(e) => {
            tracing::error!("token lookup failed: {e}");
            Err(AppError::internal("token lookup failed"))
        }
    }
}

impl Caller {
    /// The caller's role on world `id`.
    pub fn role_on(&self, id: &str) -> Option<Role> {
        match self {
            Caller::Anonymous => None,
            Caller::ServerAdmin => Some(Role::Admin),
            Caller::World { world, role } => (world == id).then_some(*role),
        }
    }

    /// Allows reading a public world to anyone and `need` on `world` to callers with at least
    /// that role; else 401 for anonymous callers and 403 for the others.
    pub fn require(&self, world: &WorldMeta, need: Role) -> Result<(), AppError> {
        if need == Role::Read && world.public {
            return Ok(());
        }
        match (self, self.role_on(&world.id)) {
            (_, Some(have)) if have >= need => Ok(()),
            (Caller::Anonymous, _) => Err(unauthenticated(&format!(
                "this operation needs a bearer token with the {} role",
                need.as_str()
            ))),
            (_, have) => Err(forbidden(format!(
                "this operation needs the {} role on world {}; the token has {}",
                need.as_str(),
                world.id,
                have.map(Role::as_str).unwrap_or("none")
            ))),
        }
    }

    /// Allows creating worlds: to the server admin, or to anyone when no admin token is set.
    pub fn require_creator(&self, admin_configured: bool) -> Result<(), AppError> {
        match self {
            _ if !admin_configured => Ok(()),
            Caller::ServerAdmin => Ok(()),
            Caller::Anonymous => Err(unauthenticated(
                "creating a world needs the server admin token",
            )),
            Caller::World { .. } => Err(forbidden("creating a world needs the server admin token")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use axum::http::HeaderValue;

    #[test]
    fn bearer_forms() {
        let h = |v: &str| {
            let mut m = HeaderMap::new();
            m.insert(
                header::AUTHORIZATION,
                HeaderValue::from_str(v).expect("value"),
            );
            m
        };
        assert_eq!(bearer(&HeaderMap::new()).expect("none"), None);
        assert_eq!(bearer(&h("Bearer abc")).expect("ok"), Some("abc"));
        assert_eq!(bearer(&h("bearer  abc ")).expect("ok"), Some("abc"));
        for bad in ["Basic abc", "Bearer", "Bearer ", "abc"] {
            assert_eq!(
                bearer(&h(bad)).expect_err(bad).status,
                StatusCode::UNAUTHORIZED
            );
        }
        assert_eq!(
            format!("{:?}", Secret::new("hunter2")),
            "Secret(<redacted>)"
        );
    }
}
