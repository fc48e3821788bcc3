//! The route table: the router is built through [`RouteTable`], which records each method and
//! path template it registers, so the list of served routes cannot drift from what is served.
//!
//! axum's `Router` cannot list its routes, and a hand-kept list beside the registrations would
//! drift. Registering through this table keeps one source: `tests/openapi_routes.rs` compares
//! [`super::routes::table`]'s list with the paths of `api/openapi.yaml`.

use super::AppState;
use axum::handler::Handler;
use axum::http::Method;
use axum::routing::{self, MethodRouter};
use axum::Router;

/// One served route: a method and axum's path template (`{name}` captures a whole segment).
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Served {
    /// The method (`GET` also answers `HEAD`, as axum does).
    pub method: Method,
    /// The path template, as registered.
    pub path: &'static str,
}

/// A router under construction and the routes it has been given.
#[derive(Debug, Default)]
pub struct RouteTable {
    router: Router<AppState>,
    served: Vec<Served>,
}

impl RouteTable {
    /// An empty table.
    pub fn new() -> Self {
        Self::default()
    }

    /// Serves `GET path` with `handler`.
    pub fn get<H: Handler<T, AppState>, T: 'static>(self, path: &'static str, handler: H) -> Self {
        self.add(Method::GET, path, routing::get(handler))
    }

    /// Serves `POST path` with `handler`.
    pub fn post<H: Handler<T, AppState>, T: 'static>(self, path: &'static str, handler: H) -> Self {
        self.add(Method::POST, path, routing::post(handler))
    }

    /// Serves `PUT path` with `handler`.
    pub fn put<H: Handler<T, AppState>, T: 'static>(self, path: &'static str, handler: H) -> Self {
        self.add(Method::PUT, path, routing::put(handler))
    }

    /// Adds every route of `other`.
    pub fn merge(mut self, other: RouteTable) -> Self {
        self.router = self.router.merge(other.router);
        self.served.extend(other.served);
        self
    }

    /// The routes registered so far, in registration order.
    pub fn served(&self) -> &[Served] {
        &self.served
    }

    /// The router, for the middleware and state of [`super::routes::router`].
    pub fn into_router(self) -> Router<AppState> {
        self.router
    }

    /// Registers `method path`; axum merges method routers given for the same path.
    fn add(mut self, method: Method, path: &'static str, handler: MethodRouter<AppState>) -> Self {
        self.router = self.router.route(path, handler);
        self.served.push(Served { method, path });
        self
    }
}
