//! WebSocket streaming of tiles around a client's view (protocol: `api/stream_protocol_v1.md`).
//!
//! [`view`] picks the tiles of a view (Choroś & Topolski's LOD rings, nearest first),
//! [`protocol`] defines messages and frames, [`session`] runs one client on a
//! [`session::StreamSource`]. The endpoints that mount `/v1/seeds/{seed}/stream` and
//! `/v1/worlds/{id}/stream` and implement the sources on the server's state are
//! `server::stream_routes`, one layer up.

pub mod protocol;
pub mod session;
pub mod view;
