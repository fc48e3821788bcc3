//! Parsing of the path segments and query of product URLs.
//!
//! Pure functions from strings to values or an [`AppError`] naming the field; they never panic,
//! whatever the input (see the fuzz test below). Checks run in the order seed, lod, x, z, format,
//! seams, the format version (`?format=`), so a URL with several mistakes always reports the
//! same one.

use super::error::{code, truncate, AppError};
use crate::encode::{Format, TileVersion};
use crate::terrain::{TileKey, WorldPlan, MAX_LOD};

/// Longest decimal integer accepted before it is judged out of range without parsing.
const MAX_DIGITS: usize = 40;

/// `seed`: one to 20 ASCII digits, at most `u64::MAX`.
pub fn parse_seed(s: &str) -> Result<u64, AppError> {
    let bad = || {
        AppError::bad_request(
            code::BAD_SEED,
            "seed",
            format!(
                "seed must be a decimal integer in 0..={}, got {:?}",
                u64::MAX,
                truncate(s, 40)
            ),
        )
    };
    if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad());
    }
    s.parse::<u64>().map_err(|_| bad())
}

/// An optionally negative decimal integer: `Ok(Some(v))`, `Ok(None)` if it is an integer that
/// does not fit an `i64`, `Err(())` if it is not an integer.
fn parse_integer(s: &str) -> Result<Option<i64>, ()> {
    let digits = s.strip_prefix('-').unwrap_or(s);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(());
    }
    if digits.len() > MAX_DIGITS {
        return Ok(None);
    }
    Ok(s.parse::<i64>().ok())
}

/// `lod`: an integer in `0..=MAX_LOD`.
pub fn parse_lod(s: &str) -> Result<u32, AppError> {
    let range = || {
        AppError::bad_request(
            code::LOD_OUT_OF_RANGE,
            "lod",
            format!("lod must be in 0..={MAX_LOD}, got {}", truncate(s, 40)),
        )
    };
    match parse_integer(s) {
        Err(()) => Err(AppError::bad_request(
            code::BAD_LOD,
            "lod",
            format!("lod must be an integer, got {:?}", truncate(s, 40)),
        )),
        Ok(Some(v)) if (0..=MAX_LOD as i64).contains(&v) => Ok(v as u32),
        Ok(_) => Err(range()),
    }
}

/// `x` or `z`: an integer; magnitudes beyond `i64` are out of range.
pub fn parse_coord(s: &str, field: &'static str) -> Result<i64, AppError> {
    match parse_integer(s) {
        Err(()) => Err(AppError::bad_request(
            code::BAD_COORDINATE,
            field,
            format!("{field} must be an integer, got {:?}", truncate(s, 40)),
        )),
        Ok(Some(v)) => Ok(v),
        Ok(None) => Err(AppError::bad_request(
            code::COORDINATE_OUT_OF_RANGE,
            field,
            format!(
                "{field} = {} is outside the supported world",
                truncate(s, 40)
            ),
        )),
    }
}

/// Splits the last segment `"{z}.{ext}"` at its last dot; the extension is `None` without one.
pub fn split_extension(segment: &str) -> (&str, Option<&str>) {
    match segment.rfind('.') {
        Some(dot) => (&segment[..dot], Some(&segment[dot + 1..])),
        None => (segment, None),
    }
}

/// The format named by an extension.
pub fn parse_format(ext: Option<&str>) -> Result<Format, AppError> {
    let names = Format::ALL.map(Format::extension).join(", ");
    match ext {
        None => Err(AppError::bad_request(
            code::UNKNOWN_FORMAT,
            "format",
            format!("the last segment must end in .{{{names}}}"),
        )),
        Some(e) => Format::from_extension(e).ok_or_else(|| {
            AppError::bad_request(
                code::UNKNOWN_FORMAT,
                "format",
                format!("unknown format {:?}; known: {names}", truncate(e, 40)),
            )
        }),
    }
}

/// The tile address and format of a product URL's last three segments (`{lod}/{x}/{z}.{ext}`),
/// checked against the bounds of the world `plan`.
pub fn parse_tile_path(
    plan: &WorldPlan,
    lod: &str,
    x: &str,
    z_ext: &str,
) -> Result<(TileKey, Format), AppError> {
    let lod = parse_lod(lod)?;
    let x = parse_coord(x, "x")?;
    let (z, ext) = split_extension(z_ext);
    let z = parse_coord(z, "z")?;
    let format = parse_format(ext)?;
    let key = TileKey { lod, x, z };
    check_bounds(plan, key)?;
    Ok((key, format))
}

/// Checks `|x|, |z| ≤ plan.max_tile_coord(lod)`.
pub fn check_bounds(plan: &WorldPlan, key: TileKey) -> Result<(), AppError> {
    let max = plan.max_tile_coord(key.lod);
    for (field, v) in [("x", key.x), ("z", key.z)] {
        if v.unsigned_abs() > max.unsigned_abs() {
            return Err(AppError::bad_request(
                code::COORDINATE_OUT_OF_RANGE,
                field,
                format!(
                    "{field} = {v} is outside the supported world: |{field}| ≤ {max} at lod {}",
                    key.lod
                ),
            ));
        }
    }
    Ok(())
}

/// Decodes `%XX` escapes and `+` (as a space, form style); `None` if an escape is malformed or the
/// result is not UTF-8.
pub(super) fn percent_decode(s: &str) -> Option<String> {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'%' => {
                let hex = b.get(i + 1..i + 3)?;
                let hex = std::str::from_utf8(hex).ok()?;
                out.push(u8::from_str_radix(hex, 16).ok()?);
                i += 3;
            }
            b'+' => {
                out.push(b' ');
                i += 1;
            }
            c => {
                out.push(c);
                i += 1;
            }
        }
    }
    String::from_utf8(out).ok()
}

/// `?seams=n,e,s,w`: four flags `0`/`1` saying which edges to snap to the coarser neighbour
/// (north, east, south, west). Absent means `0,0,0,0`; other query parameters are ignored; a
/// repeated or malformed `seams` is an error.
pub fn parse_seams(query: Option<&str>) -> Result<[bool; 4], AppError> {
    let bad = |got: &str| {
        AppError::bad_request(
            code::BAD_SEAMS,
            "seams",
            format!(
                "seams must be four comma-separated 0/1 flags n,e,s,w, got {:?}",
                truncate(got, 40)
            ),
        )
    };
    let mut found: Option<[bool; 4]> = None;
    for pair in query.unwrap_or("").split('&').filter(|p| !p.is_empty()) {
        let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
        if percent_decode(k).as_deref() != Some("seams") {
            continue;
        }
        if found.is_some() {
            return Err(bad("seams given more than once"));
        }
        let v = percent_decode(v).ok_or_else(|| bad(v))?;
        let mut flags = [false; 4];
        let mut n = 0;
        for part in v.split(',') {
            let slot = flags.get_mut(n).ok_or_else(|| bad(&v))?;
            *slot = match part {
                "0" => false,
                "1" => true,
                _ => return Err(bad(&v)),
            };
            n += 1;
        }
        if n != 4 {
            return Err(bad(&v));
        }
        found = Some(flags);
    }
    Ok(found.unwrap_or([false; 4]))
}

/// `?format=1|2`: the version of the tile encoding ([`TileVersion`]; absent means 1) for a tile
/// of `format`. Other query parameters are ignored. A value that names no version, a repeated
/// `format`, or version 2 of `.png` or `.glb` (which have version 1 only) is 400
/// `bad_parameter` naming `format` and the allowed values.
pub fn parse_tile_version(query: Option<&str>, format: Format) -> Result<TileVersion, AppError> {
    let bad = |message: String| AppError::bad_request(code::BAD_PARAMETER, "format", message);
    let allowed = |f: Format| {
        TileVersion::ALL
            .iter()
            .filter(|v| v.has(f))
            .map(|v| v.number().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut found: Option<TileVersion> = None;
    for pair in query.unwrap_or("").split('&').filter(|p| !p.is_empty()) {
        let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
        if percent_decode(k).as_deref() != Some("format") {
            continue;
        }
        if found.is_some() {
            return Err(bad(format!(
                "format given more than once; allowed values: {}",
                allowed(Format::Json)
            )));
        }
        let decoded = percent_decode(v);
        let version = decoded.as_deref().and_then(|d| {
            TileVersion::ALL
                .into_iter()
                .find(|v| v.number().to_string() == d)
        });
        let Some(version) = version else {
            return Err(bad(format!(
                "format must be one of {}, got {:?}",
                allowed(Format::Json),
                truncate(decoded.as_deref().unwrap_or(v), 40)
            )));
        };
        found = Some(version);
    }
    let version = found.unwrap_or_default();
    if !version.has(format) {
        return Err(bad(format!(
            "format={} is not defined for .{}; allowed: {}",
            version.number(),
            format.extension(),
            allowed(format)
        )));
    }
    Ok(version)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn good_paths() {
        let plan = crate::encode::test_util::plan();
        let r = parse_tile_path(plan, "3", "-2", "5.glb").expect("valid");
        assert_eq!(
            r,
            (
                TileKey {
                    lod: 3,
                    x: -2,
                    z: 5
                },
                Format::Glb
            )
        );
        assert_eq!(parse_seed("18446744073709551615"), Ok(u64::MAX));
        let r = parse_tile_path(plan, "0", "0", "-0.json").expect("valid");
        assert_eq!(r.0.z, 0);
    }

    #[test]
    fn errors_name_the_field() {
        let case = |s: &str, l: &str, x: &str, z: &str| {
            parse_seed(s)
                .and_then(|_| parse_tile_path(crate::encode::test_util::plan(), l, x, z))
                .map(|_| ())
                .map_err(|e| match e.field {
                    Some(std::borrow::Cow::Borrowed(f)) => (e.code, Some(f)),
                    other => panic!("parameter errors name a static field: {other:?}"),
                })
        };
        assert_eq!(
            case("-1", "0", "0", "0.json"),
            Err((code::BAD_SEED, Some("seed")))
        );
        assert_eq!(
            case("18446744073709551616", "0", "0", "0.json"),
            Err((code::BAD_SEED, Some("seed")))
        );
        assert_eq!(
            case("+1", "0", "0", "0.json"),
            Err((code::BAD_SEED, Some("seed")))
        );
        assert_eq!(
            case("1", "13", "0", "0.json"),
            Err((code::LOD_OUT_OF_RANGE, Some("lod")))
        );
        assert_eq!(
            case("1", "-1", "0", "0.json"),
            Err((code::LOD_OUT_OF_RANGE, Some("lod")))
        );
        assert_eq!(
            case("1", "x", "0", "0.json"),
            Err((code::BAD_LOD, Some("lod")))
        );
        assert_eq!(
            case("1", "0", "1.5", "0.json"),
            Err((code::BAD_COORDINATE, Some("x")))
        );
        assert_eq!(
            case("1", "0", "0", "1.5.json"),
            Err((code::BAD_COORDINATE, Some("z")))
        );
        assert_eq!(
            case("1", "0", "99999999999999999999", "0.json"),
            Err((code::COORDINATE_OUT_OF_RANGE, Some("x")))
        );
        assert_eq!(
            case("1", "0", "0", "0.tiff"),
            Err((code::UNKNOWN_FORMAT, Some("format")))
        );
        assert_eq!(
            case("1", "0", "0", "0"),
            Err((code::UNKNOWN_FORMAT, Some("format")))
        );
        assert_eq!(
            case("1", "0", "0", ".json"),
            Err((code::BAD_COORDINATE, Some("z")))
        );
    }

    #[test]
    fn seams() {
        assert_eq!(parse_seams(None), Ok([false; 4]));
        assert_eq!(
            parse_seams(Some("seams=1,0,0,1")),
            Ok([true, false, false, true])
        );
        assert_eq!(
            parse_seams(Some("foo=bar&seams=0%2C1%2c0%2C0")),
            Ok([false, true, false, false])
        );
        for bad in [
            "seams=2,0,0,0",
            "seams=1,0,0",
            "seams=1,0,0,0,0",
            "seams=",
            "seams",
            "seams=1,,0,0",
            "seams=%zz",
            "seams=0,0,0,0&seams=0,0,0,0",
            "seams=%FF,0,0,0",
        ] {
            let e = parse_seams(Some(bad)).expect_err(bad);
            assert_eq!(
                (e.code, e.field.as_deref()),
                (code::BAD_SEAMS, Some("seams")),
                "{bad}"
            );
        }
    }

    #[test]
    fn tile_versions() {
        assert_eq!(parse_tile_version(None, Format::Bin), Ok(TileVersion::V1));
        assert_eq!(
            parse_tile_version(Some("seams=0,0,0,0&format=2"), Format::Bin),
            Ok(TileVersion::V2)
        );
        assert_eq!(
            parse_tile_version(Some("format=1"), Format::Glb),
            Ok(TileVersion::V1)
        );
        assert_eq!(
            parse_tile_version(Some("format=%32"), Format::Json),
            Ok(TileVersion::V2)
        );
        for (bad, format) in [
            ("format=3", Format::Bin),
            ("format=0", Format::Bin),
            ("format=", Format::Bin),
            ("format", Format::Json),
            ("format=v2", Format::Json),
            ("format=02", Format::Json),
            ("format=+2", Format::Json),
            ("format=1&format=1", Format::Json),
            ("format=%zz", Format::Json),
            ("format=2", Format::Png),
            ("format=2", Format::Glb),
        ] {
            let e = parse_tile_version(Some(bad), format).expect_err(bad);
            assert_eq!(
                (e.code, e.field.as_deref()),
                (code::BAD_PARAMETER, Some("format")),
                "{bad}"
            );
            assert!(e.message.contains('1'), "{bad}: names the allowed values");
        }
    }

    #[test]
    fn bounds() {
        let plan = crate::terrain::WorldPlan::new(1, crate::terrain::WorldParams::default())
            .expect("plan");
        let max = plan.max_tile_coord(4);
        assert!(check_bounds(
            &plan,
            TileKey {
                lod: 4,
                x: max,
                z: -max
            }
        )
        .is_ok());
        let e = check_bounds(
            &plan,
            TileKey {
                lod: 4,
                x: 0,
                z: -max - 1,
            },
        )
        .expect_err("out");
        assert_eq!(
            (e.code, e.field.as_deref()),
            (code::COORDINATE_OUT_OF_RANGE, Some("z"))
        );
        let e = check_bounds(
            &plan,
            TileKey {
                lod: 4,
                x: i64::MIN,
                z: 0,
            },
        )
        .expect_err("out");
        assert_eq!(e.field.as_deref(), Some("x"));
    }

    /// Odd strings and a deterministic pseudo-random stream of them never panic, and every
    /// failure is a 4xx with a field.
    #[test]
    fn fuzz_never_panics() {
        let (long9, dashes) = ("9".repeat(5000), "-".repeat(3000));
        let odd = [
            "",
            ".",
            "..",
            "...",
            "-",
            "--1",
            "-0",
            "+",
            "%",
            "%%",
            "%2",
            "%zz",
            "%00",
            "\0",
            "1e3",
            "0x10",
            " 1",
            "1 ",
            "١٢",
            "😀",
            "é.json",
            long9.as_str(),
            dashes.as_str(),
            "../../etc/passwd",
            "1.json.json",
            "1..json",
            "1.",
            ".json",
            "NaN",
            "inf",
            "18446744073709551616",
            "-9223372036854775808",
            "9223372036854775808",
            "4294967296",
            "12\u{0301}",
        ];
        let check = |s: &str, l: &str, x: &str, z: &str, q: &str| {
            let parsed = parse_seed(s)
                .and_then(|_| parse_tile_path(crate::encode::test_util::plan(), l, x, z));
            if let Err(e) = parsed {
                assert!(e.status.is_client_error() && e.field.is_some(), "{e:?}");
            }
            if let Err(e) = parse_seams(Some(q)) {
                assert!(e.status.is_client_error() && e.field.as_deref() == Some("seams"));
            }
            if let Err(e) = parse_tile_version(Some(q), Format::Bin) {
                assert!(e.status.is_client_error() && e.field.as_deref() == Some("format"));
            }
        };
        for a in odd {
            for b in odd {
                check(a, b, a, b, a);
                check("1", "0", a, b, &format!("seams={a}"));
                check("1", "0", a, b, &format!("format={a}"));
            }
        }
        let alphabet: Vec<char> = "0123456789-.,%+=&ajsonbpgtf /😀é\0".chars().collect();
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for _ in 0..20_000 {
            let mut parts: [String; 5] = Default::default();
            for p in parts.iter_mut() {
                let len = (next() % 12) as usize;
                *p = (0..len)
                    .map(|_| alphabet[(next() % alphabet.len() as u64) as usize])
                    .collect();
            }
            check(&parts[0], &parts[1], &parts[2], &parts[3], &parts[4]);
        }
    }
}
