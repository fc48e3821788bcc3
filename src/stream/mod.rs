//! WebSocket streaming of tiles and volume chunks around a client's view (protocols:
//! `api/stream_protocol_v1.md`, `api/stream_protocol_v2.md`).
//!
//! [`view`] picks the tiles of a view (Choroś & Topolski's LOD rings, nearest first),
//! [`chunks`] the volume chunks of a v2 view (3D rings meeting the volume regions),
//! [`cave_chunks`] those of its caves near the ground, [`work`]
//! merges them nearest first, [`protocol`] defines messages and frames, [`session`] runs one
//! client on a [`session::StreamSource`], its [`outbox`] holds what waits for the socket and
//! [`writer`] writes it. The endpoints that mount `/v1/seeds/{seed}/stream` and
//! `/v1/worlds/{id}/stream` and implement the sources on the server's state are
//! `server::stream_routes`, one layer up.

pub mod cave_chunks;
pub mod chunks;
pub mod outbox;
pub mod protocol;
pub mod ptex;
pub mod ptex_frame;
pub mod session;
pub mod view;
pub mod work;
pub mod writer;
