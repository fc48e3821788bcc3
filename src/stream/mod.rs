//! WebSocket streaming of tiles around a client's view (protocol: `api/stream_protocol_v1.md`).

pub mod view;
