//! What an edit changed: the dirty region between two scenes.

use super::{Element, Rect, Scene};
use serde::{Deserialize, Serialize};
use std::collections::{HashMap, HashSet};

/// The part of the world whose products an edit may have changed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", content = "rects", rename_all = "snake_case")]
pub enum Dirty {
    /// Nothing changed.
    Nothing,
    /// The world settings changed: every product.
    Everything,
    /// The union of these rectangles (none is inside another).
    Rects(Vec<Rect>),
}

impl Dirty {
    /// Whether a product whose footprint is `rect` may have changed.
    pub fn touches(&self, rect: &Rect) -> bool {
        match self {
            Dirty::Nothing => false,
            Dirty::Everything => true,
            Dirty::Rects(rs) => rs.iter().any(|r| r.intersects(rect)),
        }
    }

    /// Whether nothing changed.
    pub fn is_nothing(&self) -> bool {
        matches!(self, Dirty::Nothing)
    }
}

/// Ids of the elements of one array whose relative order among the ids present in both
/// versions moved.
fn reordered<'a>(old: &'a [Element], new: &'a [Element]) -> Vec<&'a str> {
    let in_new: HashSet<&str> = new.iter().map(|e| e.id.as_str()).collect();
    let in_old: HashSet<&str> = old.iter().map(|e| e.id.as_str()).collect();
    let a: Vec<&str> = old
        .iter()
        .map(|e| e.id.as_str())
        .filter(|id| in_new.contains(id))
        .collect();
    let b: Vec<&str> = new
        .iter()
        .map(|e| e.id.as_str())
        .filter(|id| in_old.contains(id))
        .collect();
    a.iter()
        .zip(&b)
        .filter(|(x, y)| x != y)
        .flat_map(|(x, y)| [*x, *y])
        .collect()
}

/// The dirty region of an edit from `old` to `new`: [`Dirty::Everything`] when the world
/// settings or the `materials` elements differ (a material applies wherever its id is, so its
/// `bbox` says nothing); else the bounding boxes of the elements added (new box), removed (old box)
/// or changed — any field, or their order relative to the other surviving elements of their
/// array — (old and new boxes); [`Dirty::Nothing`] when the scenes are equal.
pub fn dirty_region(old: &Scene, new: &Scene) -> Dirty {
    if old.world != new.world || old.materials != new.materials {
        return Dirty::Everything;
    }
    let mut rects: Vec<Rect> = Vec::new();
    for ((_, olds), (_, news)) in old.kinds().into_iter().zip(new.kinds()) {
        let old_by_id: HashMap<&str, &Element> = olds.iter().map(|e| (e.id.as_str(), e)).collect();
        let new_by_id: HashMap<&str, &Element> = news.iter().map(|e| (e.id.as_str(), e)).collect();
        let moved = reordered(olds, news);
        for e in olds {
            match new_by_id.get(e.id.as_str()) {
                None => rects.push(e.bbox.rect()),
                Some(n) if *n != e || moved.contains(&e.id.as_str()) => {
                    rects.push(e.bbox.rect());
                    rects.push(n.bbox.rect());
                }
                Some(_) => {}
            }
        }
        for e in news {
            if !old_by_id.contains_key(e.id.as_str()) {
                rects.push(e.bbox.rect());
            }
        }
    }
    if rects.is_empty() {
        return Dirty::Nothing;
    }
    // Drop duplicates and rectangles inside others; keep the first of equal ones.
    let mut kept: Vec<Rect> = Vec::with_capacity(rects.len());
    for (i, r) in rects.iter().enumerate() {
        let covered = rects
            .iter()
            .enumerate()
            .any(|(j, o)| j != i && o.contains(r) && (!r.contains(o) || j < i));
        if !covered {
            kept.push(*r);
        }
    }
    Dirty::Rects(kept)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn scene(v: serde_json::Value) -> Scene {
        Scene::from_value(&v).expect("valid scene")
    }

    fn el(id: &str, x0: f64, x1: f64, extra: i64) -> serde_json::Value {
        json!({"id": id, "bbox": {"min": [x0, 0.0], "max": [x1, 10.0]},
               "ops": [{"op": "freeze", "center": [x0, 5.0], "radius_m": extra}]})
    }

    fn r(x0: f64, x1: f64) -> Rect {
        Rect {
            min: [x0, 0.0],
            max: [x1, 10.0],
        }
    }

    #[test]
    fn equal_scenes_are_clean() {
        let a = scene(json!({"regions": [el("a", 0.0, 1.0, 0)]}));
        assert_eq!(dirty_region(&a, &a.clone()), Dirty::Nothing);
    }

    #[test]
    fn world_change_is_everything() {
        let a = Scene::default();
        let mut b = a.clone();
        b.world.sea_level_m = 3.0;
        assert_eq!(dirty_region(&a, &b), Dirty::Everything);
    }

    #[test]
    fn added_removed_changed() {
        let a = scene(
            json!({"regions": [el("a", 0.0, 1.0, 0), el("b", 5.0, 6.0, 0)],
                             "decals": [el("d", 20.0, 21.0, 0)]}),
        );
        let b = scene(
            json!({"regions": [el("a", 0.0, 1.0, 0), el("b", 7.0, 8.0, 1)],
                             "decals": [el("e", 30.0, 31.0, 0)]}),
        );
        assert_eq!(
            dirty_region(&a, &b),
            Dirty::Rects(vec![r(5.0, 6.0), r(7.0, 8.0), r(20.0, 21.0), r(30.0, 31.0)])
        );
        // A field other than the box changes: the box is dirty once.
        let c = scene(
            json!({"regions": [el("a", 0.0, 1.0, 9), el("b", 5.0, 6.0, 0)],
                             "decals": [el("d", 20.0, 21.0, 0)]}),
        );
        assert_eq!(dirty_region(&a, &c), Dirty::Rects(vec![r(0.0, 1.0)]));
        // The same id in another array is another element.
        let d = scene(
            json!({"regions": [el("a", 0.0, 1.0, 0), el("b", 5.0, 6.0, 0), el("d", 40.0, 41.0, 0)],
                             "decals": [el("d", 20.0, 21.0, 0)]}),
        );
        assert_eq!(dirty_region(&a, &d), Dirty::Rects(vec![r(40.0, 41.0)]));
        // A material applies wherever its id is: any change of one is everything.
        let e = scene(
            json!({"regions": [el("a", 0.0, 1.0, 0), el("b", 5.0, 6.0, 0)],
                             "materials": [el("m", 40.0, 41.0, 0)],
                             "decals": [el("d", 20.0, 21.0, 0)]}),
        );
        assert_eq!(dirty_region(&a, &e), Dirty::Everything);
    }

    #[test]
    fn order_matters_insertion_does_not_move_others() {
        let a = scene(json!({"regions": [el("a", 0.0, 1.0, 0), el("b", 5.0, 6.0, 0)]}));
        let swapped = scene(json!({"regions": [el("b", 5.0, 6.0, 0), el("a", 0.0, 1.0, 0)]}));
        assert_eq!(
            dirty_region(&a, &swapped),
            Dirty::Rects(vec![r(0.0, 1.0), r(5.0, 6.0)])
        );
        let inserted = scene(
            json!({"regions": [el("c", 9.0, 9.5, 0), el("a", 0.0, 1.0, 0),
                                                el("b", 5.0, 6.0, 0)]}),
        );
        assert_eq!(dirty_region(&a, &inserted), Dirty::Rects(vec![r(9.0, 9.5)]));
    }

    #[test]
    fn touches_and_serialisation() {
        let d = Dirty::Rects(vec![r(0.0, 1.0)]);
        assert!(d.touches(&r(1.0, 2.0)));
        assert!(!d.touches(&r(1.5, 2.0)));
        assert!(Dirty::Everything.touches(&r(1e6, 1e6 + 1.0)));
        assert!(!Dirty::Nothing.touches(&r(0.0, 1.0)));
        assert_eq!(
            serde_json::to_value(&d).expect("json"),
            json!({"kind": "rects", "rects": [{"min": [0.0, 0.0], "max": [1.0, 10.0]}]})
        );
        assert_eq!(
            serde_json::to_value(Dirty::Everything).expect("json"),
            json!({"kind": "everything"})
        );
    }
}
