//! A stream client's text message (`stream::protocol::ClientMessage::parse`) and, for a view,
//! its validation and tile selection (`stream::session::view_of`): any text is refused with an
//! error naming a field (at most 64 characters of it), or selects a bounded set of tiles.
#![no_main]

use libfuzzer_sys::fuzz_target;
use strata::stream::protocol::{ClientMessage, Protocol};
use strata::stream::session::{view_of, MAX_MESSAGE_BYTES};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if text.len() > MAX_MESSAGE_BYTES {
        return;
    }
    let protocol = if data.first().is_some_and(|b| b % 2 == 0) {
        Protocol::V1
    } else {
        Protocol::V2
    };
    match ClientMessage::parse(text, protocol) {
        // The field is a top-level key of the message; an unknown key may be any text, even
        // empty, and is echoed truncated.
        Err(bad) => {
            assert!(bad.field.chars().count() <= 64);
            assert!(!bad.message.is_empty());
        }
        Ok(ClientMessage::View {
            x,
            z,
            rings,
            format,
            ..
        }) => {
            if let Ok((tiles, _)) = view_of(x, z, &rings, format.as_deref(), 1.0) {
                assert!(tiles.len() <= 100_000, "{} tiles", tiles.len());
            }
        }
        Ok(ClientMessage::Credit { frames }) => {
            assert!((1..=strata::stream::protocol::MAX_CREDITS).contains(&frames));
        }
        Ok(ClientMessage::Edit { patch, .. }) => {
            let _ = serde_json::from_value::<json_patch::Patch>(patch);
        }
    }
});
