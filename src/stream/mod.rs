//! WebSocket streaming of tiles around a client's view (protocol: `api/stream_protocol_v1.md`).
//!
//! [`view`] picks the tiles of a view (Choroś & Topolski's LOD rings, nearest first),
//! [`protocol`] defines messages and frames, [`session`] runs one client, [`routes`] mounts
//! `/v1/seeds/{seed}/stream` and `/v1/worlds/{id}/stream`.

pub mod protocol;
pub mod routes;
pub mod session;
pub mod view;
