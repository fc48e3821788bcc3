//! The routes the server serves are the routes `api/openapi.yaml` documents: every served route
//! is documented and every documented route is served, compared by method and path template.
//!
//! axum's `Router` cannot list its routes, so the router is built from one list that can:
//! `strata::server::routes::table()` registers every route through
//! `server::route_table::RouteTable`, which records the method and path of each registration
//! and hands the same registrations to axum. What this test reads is therefore what the router
//! serves, not a second list kept by hand.
//!
//! The specification is read as text, not with a YAML library: its path items are the lines
//! indented by two spaces under `paths:` that end with `:`, and its operations the lines
//! indented by four spaces beneath them that name an HTTP method. `the_spec_reader_sees_every_path_item`
//! checks that reading against the number of `operationId`s.
//!
//! Two differences of notation are mapped before comparing. axum captures whole segments only,
//! so a segment the specification writes as `{z}.{format}` or `{z}.json` is served as `{z_ext}`
//! and the handler parses the extension (its refusals are tested in `tests/http.rs`). And the
//! specification's `/{file}` (the viewer directory) is the router's fallback, not a route:
//! `tests/http.rs` serves a file through it.

use std::collections::BTreeSet;

const METHODS: [&str; 7] = ["get", "put", "post", "delete", "patch", "head", "options"];

/// The viewer directory's path item, served by the router's fallback.
const FALLBACK: &str = "/{file}";

fn spec_text() -> String {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/api/openapi.yaml");
    std::fs::read_to_string(path).expect("api/openapi.yaml is readable")
}

/// `(METHOD, path)` of every operation under the specification's `paths:`.
fn documented(spec: &str) -> BTreeSet<(String, String)> {
    let mut out = BTreeSet::new();
    let mut in_paths = false;
    let mut path: Option<String> = None;
    for line in spec.lines() {
        if !line.starts_with(' ') && !line.is_empty() {
            in_paths = line == "paths:";
            path = None;
            continue;
        }
        if !in_paths {
            continue;
        }
        if let Some(p) = line.strip_prefix("  /").and_then(|p| p.strip_suffix(':')) {
            path = Some(format!("/{p}"));
        } else if let Some(m) = line.strip_prefix("    ").and_then(|m| m.strip_suffix(':')) {
            if let (Some(p), true) = (&path, METHODS.contains(&m)) {
                out.insert((m.to_uppercase(), p.clone()));
            }
        }
    }
    out
}

/// A specification path in axum's notation: a segment `{name}.suffix` becomes `{name_ext}`.
fn as_served(path: &str) -> String {
    path.split('/')
        .map(|segment| match segment.strip_prefix('{') {
            Some(rest) if !segment.ends_with('}') || segment.matches('{').count() > 1 => {
                let name = rest.split('}').next().unwrap_or(rest);
                format!("{{{name}_ext}}")
            }
            _ => segment.to_owned(),
        })
        .collect::<Vec<_>>()
        .join("/")
}

fn served() -> BTreeSet<(String, String)> {
    strata::server::routes::table()
        .served()
        .iter()
        .map(|s| (s.method.as_str().to_owned(), s.path.to_owned()))
        .collect()
}

#[test]
fn every_served_route_is_documented_and_every_documented_route_is_served() {
    let spec = documented(&spec_text());
    let documented: BTreeSet<(String, String)> = spec
        .iter()
        .filter(|(_, p)| p != FALLBACK)
        .map(|(m, p)| (m.clone(), as_served(p)))
        .collect();
    let served = served();
    let undocumented: Vec<_> = served.difference(&documented).collect();
    let unserved: Vec<_> = documented.difference(&served).collect();
    assert!(
        undocumented.is_empty() && unserved.is_empty(),
        "served but not in api/openapi.yaml: {undocumented:?}\n\
         in api/openapi.yaml but not served: {unserved:?}"
    );
    assert!(
        spec.contains(&("GET".to_owned(), FALLBACK.to_owned())),
        "the viewer directory's {FALLBACK} is documented"
    );
}

#[test]
fn no_route_is_registered_twice() {
    let table = strata::server::routes::table();
    let all = table.served();
    let distinct: BTreeSet<_> = all.iter().collect();
    assert_eq!(all.len(), distinct.len(), "a route is registered twice");
}

#[test]
fn the_spec_reader_sees_every_path_item() {
    let text = spec_text();
    let operations = text
        .lines()
        .filter(|l| l.trim_start().starts_with("operationId:"))
        .count();
    assert_eq!(documented(&text).len(), operations);
    assert!(operations > 30, "only {operations} operations read");
}

#[test]
fn suffixed_segments_map_to_whole_segment_captures() {
    assert_eq!(
        as_served("/v1/seeds/{seed}/tiles/{lod}/{x}/{z}.{format}"),
        "/v1/seeds/{seed}/tiles/{lod}/{x}/{z_ext}"
    );
    assert_eq!(
        as_served("/v1/worlds/{id}/columns/{x}/{z}.json"),
        "/v1/worlds/{id}/columns/{x}/{z_ext}"
    );
    assert_eq!(
        as_served("/v1/worlds/{id}/volumes/{vid}/mesh.glb"),
        "/v1/worlds/{id}/volumes/{vid}/mesh.glb"
    );
}
