//! What every scene element is, below the element kinds and the scene that lists them: an
//! [`Element`] (an `id`, a world-space [`BBox`] and its other fields verbatim), the ground-plane
//! [`Rect`], the coordinate and id limits, and the JSON-pointer helpers element parsers name an
//! offending value with. `scene` re-exports all of it; `authoring`, `volume` and `subsurface`
//! parse their elements from it without importing the scene above them.
//!
//! Pure code: no tokio, no axum, no I/O.

use serde::{Deserialize, Serialize};
use serde_json::Value;

/// Longest element id, bytes.
pub const MAX_ID_LEN: usize = 128;
/// Largest coordinate magnitude of a bounding box, metres.
pub const MAX_COORD_M: f64 = 1.0e9;

/// An axis-aligned world-space rectangle on the ground plane, metres: `x` east, `z` south.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BBox {
    /// `[x, z]` of the west-north corner.
    pub min: [f64; 2],
    /// `[x, z]` of the east-south corner.
    pub max: [f64; 2],
}

impl BBox {
    /// As a [`Rect`].
    pub fn rect(&self) -> Rect {
        Rect {
            min: self.min,
            max: self.max,
        }
    }
}

/// One scene element. Only `id` and `bbox` are interpreted here.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Element {
    /// Unique within its array; `[A-Za-z0-9._:-]`, 1 to [`MAX_ID_LEN`] bytes.
    pub id: String,
    /// Where the element has an effect.
    pub bbox: BBox,
    /// Every other field, kept verbatim.
    #[serde(flatten)]
    pub rest: serde_json::Map<String, Value>,
}

/// An axis-aligned rectangle on the ground plane, metres (`[x, z]` corners, inclusive).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Rect {
    /// `[x, z]` of the west-north corner.
    pub min: [f64; 2],
    /// `[x, z]` of the east-south corner.
    pub max: [f64; 2],
}

impl Rect {
    /// Whether the two closed rectangles share a point.
    pub fn intersects(&self, other: &Rect) -> bool {
        (0..2).all(|a| self.min[a] <= other.max[a] && other.min[a] <= self.max[a])
    }

    /// Whether `other` lies inside `self`.
    pub fn contains(&self, other: &Rect) -> bool {
        (0..2).all(|a| self.min[a] <= other.min[a] && other.max[a] <= self.max[a])
    }
}

/// Escapes one reference token of a JSON pointer (`~` → `~0`, `/` → `~1`).
pub fn escape_token(token: &str) -> String {
    token.replace('~', "~0").replace('/', "~1")
}

/// The JSON pointer (RFC 6901) of the value a `serde_path_to_error` path leads to.
pub(crate) fn path_pointer(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    let mut out = String::new();
    for seg in path.iter() {
        match seg {
            Segment::Seq { index } => {
                out.push('/');
                out.push_str(&index.to_string());
            }
            Segment::Map { key } => {
                out.push('/');
                out.push_str(&escape_token(key));
            }
            Segment::Enum { variant } => {
                out.push('/');
                out.push_str(&escape_token(variant));
            }
            Segment::Unknown => {}
        }
    }
    out
}
