//! The real `strata hillshade` command: a PNG of the square asked for, the same bytes on every
//! run, the world settings of a file when given, and clear refusals of bad options; and
//! `strata world-settings`, which prints the settings such a file starts from.

use std::path::Path;
use std::process::{Command, Output};
use strata::terrain::WorldParams;

fn strata(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_strata"))
        .args(args)
        .env("NO_COLOR", "1")
        .env("RUST_BACKTRACE", "0")
        .output()
        .expect("run strata")
}

fn ok(o: &Output) -> String {
    assert!(
        o.status.success(),
        "strata failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Width, height and RGB pixels of a PNG.
fn decode(path: &Path) -> (u32, u32, Vec<u8>) {
    let file = std::fs::File::open(path).expect("png written");
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .expect("a png");
    let mut buf = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut buf).expect("frame");
    assert_eq!(info.color_type, png::ColorType::Rgb);
    buf.truncate(info.buffer_size());
    (info.width, info.height, buf)
}

#[test]
fn hillshade_writes_the_square_asked_for_and_its_figures() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (a, b) = (dir.path().join("a.png"), dir.path().join("b.png"));
    let args = |out: &Path| {
        [
            "hillshade",
            "--lod",
            "6",
            "--x",
            "-120000",
            "--z",
            "-40000",
            "--tiles",
            "2",
            "--json",
            "--out",
            out.to_str().expect("utf-8 path"),
        ]
        .map(str::to_string)
    };
    let a_args = args(&a);
    let out = ok(&strata(&a_args.each_ref().map(String::as_str)));
    let v: serde_json::Value = serde_json::from_str(out.trim()).expect("one JSON object");
    assert_eq!(v["spacing_m"], 64.0);
    assert_eq!(
        (v["samples_w"].as_u64(), v["samples_h"].as_u64()),
        (Some(128), Some(128))
    );
    let median = v["slope_median_deg"].as_f64().expect("a slope median");
    assert!(median > 0.0 && median < 90.0, "median slope {median}");
    let water = v["water_fraction_of_land"].as_f64().expect("a water share");
    assert!((0.0..=1.0).contains(&water), "water {water}");
    let (w, h, pixels) = decode(&a);
    assert_eq!((w, h), (128, 128));
    // Shaded relief, not one flat colour.
    let distinct: std::collections::BTreeSet<&[u8]> = pixels.chunks(3).collect();
    assert!(distinct.len() > 100, "{} colours", distinct.len());
    // The same bytes on a second run.
    let b_args = args(&b);
    ok(&strata(&b_args.each_ref().map(String::as_str)));
    assert_eq!(std::fs::read(&a).expect("a"), std::fs::read(&b).expect("b"));
}

/// `--depressions` tints red exactly the land the closed-depression figure counts: the tinted
/// share of the land pixels is the printed fraction, and the other pixels keep their colours.
#[test]
fn hillshade_tints_the_closed_depressions_it_counts() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (plain, tinted) = (dir.path().join("plain.png"), dir.path().join("tinted.png"));
    // LOD 12 (4 km) around the origin: uncarved, with closed basins.
    let run = |out: &Path, extra: &[&str]| -> serde_json::Value {
        let path = out.to_str().expect("utf-8 path");
        let mut args = vec![
            "hillshade",
            "--lod",
            "12",
            "--tiles",
            "2",
            "--json",
            "--out",
            path,
        ];
        args.extend_from_slice(extra);
        serde_json::from_str(ok(&strata(&args)).trim()).expect("one JSON object")
    };
    let v = run(&plain, &[]);
    run(&tinted, &["--depressions"]);
    let fraction = v["depression_fraction_deeper_than_2m"]
        .as_f64()
        .expect("a depression fraction");
    assert!(fraction > 0.0, "the square should hold closed basins");
    let (_, _, a) = decode(&plain);
    let (_, _, b) = decode(&tinted);
    let mut red = 0usize;
    for (p, q) in a.chunks(3).zip(b.chunks(3)) {
        if p != q {
            assert_eq!(
                q,
                [p[0] / 2 + 128, p[1] / 2, p[2] / 2],
                "{p:?} is tinted red"
            );
            red += 1;
        }
    }
    // The figure's land: every cell above the sea, lakes and rivers too.
    let cells = (a.len() / 3) as f64;
    let land = (v["land_fraction"].as_f64().expect("land") * cells).round();
    assert_eq!(
        red as f64,
        (fraction * land).round(),
        "{red} tinted of {land} land cells against the figure {fraction}"
    );
}

#[test]
fn hillshade_reads_the_world_settings_of_a_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut params = WorldParams::default();
    params
        .earth
        .as_mut()
        .and_then(|e| e.rivers.as_mut())
        .expect("the default world has rivers")
        .enabled = false;
    let world = dir.path().join("world.json");
    std::fs::write(&world, serde_json::to_vec(&params).expect("json")).expect("write world.json");
    let (with, without) = (dir.path().join("with.png"), dir.path().join("without.png"));
    let common = ["hillshade", "--lod", "5", "--tiles", "2", "--x", "3000"];
    let mut a: Vec<&str> = common.to_vec();
    a.extend(["--out", with.to_str().expect("utf-8 path")]);
    ok(&strata(&a));
    let mut b: Vec<&str> = common.to_vec();
    b.extend([
        "--world",
        world.to_str().expect("utf-8 path"),
        "--out",
        without.to_str().expect("utf-8 path"),
    ]);
    let text = ok(&strata(&b));
    assert!(text.contains("slope median"), "{text}");
    assert_ne!(
        decode(&with).2,
        decode(&without).2,
        "the rivers' carve changes the picture"
    );
}

#[test]
fn hillshade_refuses_bad_options_by_name() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("x.png");
    let out = out.to_str().expect("utf-8 path");
    let o = strata(&["hillshade", "--tiles", "33", "--out", out]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--tiles must be 1 to 32"));
    let o = strata(&["hillshade", "--lod", "13", "--out", out]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("--lod must be 0 to 12"));
    let junk = dir.path().join("junk.json");
    std::fs::write(&junk, b"{\"cell_m\": \"one\"}").expect("write junk.json");
    let o = strata(&[
        "hillshade",
        "--world",
        junk.to_str().expect("utf-8 path"),
        "--out",
        out,
    ]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("is not a world's settings"));
    assert!(!Path::new(out).exists(), "no picture for a refused command");
}

#[test]
fn world_settings_prints_the_settings_of_new_worlds_in_full() {
    let dir = tempfile::tempdir().expect("tempdir");
    let text = ok(&strata(&["world-settings"]));
    let printed: WorldParams = serde_json::from_str(&text).expect("world settings");
    assert_eq!(printed, WorldParams::default());
    // Given back, the file is checked and printed the same; and it shades the picture the
    // defaults shade.
    let file = dir.path().join("world.json");
    std::fs::write(&file, &text).expect("write world.json");
    let path = file.to_str().expect("utf-8 path");
    assert_eq!(ok(&strata(&["world-settings", "--world", path])), text);
    let (a, b) = (dir.path().join("a.png"), dir.path().join("b.png"));
    let shade = |out: &Path, world: Option<&str>| {
        let mut args = vec!["hillshade", "--lod", "4", "--tiles", "2", "--out"];
        args.push(out.to_str().expect("utf-8 path"));
        if let Some(w) = world {
            args.extend(["--world", w]);
        }
        ok(&strata(&args));
    };
    shade(&a, None);
    shade(&b, Some(path));
    assert_eq!(decode(&a), decode(&b));
    // Settings a world would refuse are refused here too, naming the file.
    let mut bad: serde_json::Value = serde_json::from_str(&text).expect("json");
    bad["cell_m"] = serde_json::json!(-1.0);
    std::fs::write(&file, bad.to_string()).expect("write world.json");
    let o = strata(&["world-settings", "--world", path]);
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("cell_m"), "{err}");
}
