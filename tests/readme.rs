//! The README's walk-through (issue 19, Done-when 5): the `sh` code blocks of its "Using it"
//! section are read from `README.md` and run in order, command by command, in one `bash` against
//! the real `strata` binary (on `PATH`, as the README assumes), and each command's answer is
//! checked. The one change made to the text is the port: `localhost:8080` becomes a free loopback
//! port and `strata serve` listens there. The commands run in a scratch directory whose `docs`
//! links to the repository's, so the files the README names (`docs/examples/…`) are found and
//! what the commands write (`data/`, `tile.glb`, …) stays out of the repository.
//!
//! The test first writes those example files, as the viewer tests write the screenshots:
//! `docs/examples/arch.json` (a JSON Patch adding the arch volume element on the ground of
//! seed 42) and `docs/examples/rock.glb` (a boulder of 20 triangles at its foot), so they stay
//! what the code makes.
//!
//! Every command must exit 0 and match one rule of [`RULES`], which checks its output; a command
//! with no rule fails the test, so the README and the test change together.

use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{channel, Receiver};
use std::time::Duration;

mod common;

use serde_json::{json, Value};
use strata::edits::{synthesize, TileEdits};
use strata::terrain::{TileKey, WorldParams, WorldPlan};
use strata::volume::mesh_import::{triangles_to_glb, IDENTITY};
use strata::volume::pipeline::scenes::arch_element;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The ground of seed 42 at world `(x, z)` (LOD-0 tile 0, 0), metres.
fn ground_42(x: usize, z: usize) -> f32 {
    let plan = WorldPlan::new(42, WorldParams::default()).expect("default world");
    let t = synthesize(&plan, TileKey { lod: 0, x: 0, z: 0 }, &TileEdits::default());
    t.heights[z * 65 + x]
}

/// An icosahedron of radius 1 with its vertices pushed in and out by a fixed pattern: a rough
/// boulder, counter-clockwise seen from outside.
fn boulder() -> Vec<[[f32; 3]; 3]> {
    let p = (1.0 + 5f32.sqrt()) / 2.0;
    let raw = [
        [-1.0, p, 0.0],
        [1.0, p, 0.0],
        [-1.0, -p, 0.0],
        [1.0, -p, 0.0],
        [0.0, -1.0, p],
        [0.0, 1.0, p],
        [0.0, -1.0, -p],
        [0.0, 1.0, -p],
        [p, 0.0, -1.0],
        [p, 0.0, 1.0],
        [-p, 0.0, -1.0],
        [-p, 0.0, 1.0],
    ];
    let bumps = [
        1.0, 0.85, 1.1, 0.9, 1.05, 0.8, 1.15, 0.95, 0.9, 1.1, 0.85, 1.0,
    ];
    let v: Vec<[f32; 3]> = raw
        .iter()
        .zip(bumps)
        .map(|(a, s)| {
            let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
            [a[0] / n * s, a[1] / n * s * 0.7, a[2] / n * s]
        })
        .collect();
    let faces: [[usize; 3]; 20] = [
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    faces.iter().map(|f| f.map(|i| v[i])).collect()
}

/// Writes `docs/examples/arch.json` and `docs/examples/rock.glb`.
fn write_examples() {
    let dir = root().join("docs").join("examples");
    std::fs::create_dir_all(&dir).expect("docs/examples");
    let ground = ground_42(32, 24);
    let patch = json!([{"op": "add", "path": "/volumes/-", "value": arch_element(ground)}]);
    let text = serde_json::to_string_pretty(&patch).expect("JSON") + "\n";
    std::fs::write(dir.join("arch.json"), text).expect("write arch.json");
    // A 5 m boulder half buried at the arch's east foot.
    let mut m = IDENTITY;
    m[0] = 5.0;
    m[5] = 5.0;
    m[10] = 5.0;
    m[12] = 52.0;
    m[13] = ground + 1.0;
    m[14] = 34.0;
    std::fs::write(dir.join("rock.glb"), triangles_to_glb(&boulder(), Some(&m)))
        .expect("write rock.glb");
    std::fs::write(dir.join("puddle.png"), puddle_png()).expect("write puddle.png");
}

/// `docs/examples/puddle.png`: 64 × 64 RGBA, muddy water, its alpha 1 inside an oval and falling
/// to 0 over the outer fifth of its radius.
fn puddle_png() -> Vec<u8> {
    common::png::rgba(64, 64, |x, y| {
        let (u, v) = ((x as f32 + 0.5) / 32.0 - 1.0, (y as f32 + 0.5) / 32.0 - 1.0);
        let r = (u * u + v * v).sqrt();
        let a = ((1.0 - r) / 0.2).clamp(0.0, 1.0);
        [52, 58, 62, (a * 255.0).round() as u8]
    })
}

/// The planes of a tile's pack (`api/ptex_pages_v1.md`): albedo, normal and displacement bytes.
fn tile_planes(pack: &[u8]) -> [&[u8]; 3] {
    let side = u32::from_le_bytes(pack[56..60].try_into().expect("S")) as usize;
    let faces = u32::from_le_bytes(pack[52..56].try_into().expect("F")) as usize;
    let plane = faces * side * side * 4;
    let start = 64 + 40 * faces;
    [0, 1, 2].map(|k| &pack[start + k * plane..start + (k + 1) * plane])
}

/// The commands of the `sh` blocks of the README section `heading`, in order: a command ends at
/// a line end outside quotes that does not follow a backslash; comment lines are left out.
fn commands(readme: &str, heading: &str) -> Vec<String> {
    let start = readme
        .find(&format!("\n## {heading}\n"))
        .unwrap_or_else(|| panic!("README has no \"## {heading}\" section"));
    let section = &readme[start + 1..];
    let end = section[3..].find("\n## ").map_or(section.len(), |e| e + 3);
    let section = &section[..end];
    let mut out = Vec::new();
    let mut in_block = false;
    let mut cmd = String::new();
    let mut quote: Option<char> = None;
    for line in section.lines() {
        if !in_block {
            in_block = line.trim_start() == "```sh";
            continue;
        }
        if quote.is_none() && cmd.is_empty() && line.trim_start() == "```" {
            in_block = false;
            continue;
        }
        if quote.is_none() && cmd.is_empty() && line.trim_start().starts_with('#') {
            continue;
        }
        let mut escaped = false;
        let mut prev = ' ';
        for c in line.chars() {
            match quote {
                Some(q) if c == q && !(q == '"' && escaped) => quote = None,
                // A comment runs to the end of the line.
                None if c == '#' && prev.is_whitespace() => break,
                None if (c == '\'' || c == '"') && !escaped => quote = Some(c),
                _ => {}
            }
            escaped = c == '\\' && !escaped;
            prev = c;
        }
        cmd.push_str(line);
        cmd.push('\n');
        if quote.is_none() && !line.ends_with('\\') {
            if !cmd.trim().is_empty() {
                out.push(cmd.trim_end().to_string());
            }
            cmd.clear();
        }
    }
    assert!(cmd.is_empty(), "unterminated command in the README: {cmd}");
    out
}

/// One `bash` reading commands on its stdin; each command's output (stdout and stderr) and exit
/// status are read back up to a marker line.
struct Shell {
    child: Child,
    stdin: ChildStdin,
    lines: Receiver<String>,
}

const MARK: &str = "@@readme-status ";

impl Shell {
    fn start(dir: &Path, path: &str) -> Shell {
        let mut child = Command::new("bash")
            .args(["--noprofile", "--norc"])
            .current_dir(dir)
            .env("PATH", path)
            .env_remove("STRATA_ADMIN_TOKEN")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("start bash");
        let mut stdin = child.stdin.take().expect("stdin");
        writeln!(stdin, "exec 2>&1").expect("bash");
        let stdout = child.stdout.take().expect("stdout");
        let (tx, lines) = channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines() {
                let Ok(line) = line else { return };
                if tx.send(line).is_err() {
                    return;
                }
            }
        });
        Shell {
            child,
            stdin,
            lines,
        }
    }

    /// Runs `cmd`; its output and exit status.
    fn run(&mut self, cmd: &str) -> (String, i32) {
        writeln!(self.stdin, "{cmd}\nprintf '\\n{MARK}%s\\n' $?").expect("bash stdin");
        self.stdin.flush().expect("flush");
        let mut out = String::new();
        loop {
            let line = self
                .lines
                .recv_timeout(Duration::from_secs(180))
                .unwrap_or_else(|_| {
                    panic!("no answer within 180 s to:\n{cmd}\noutput so far:\n{out}")
                });
            if let Some(status) = line.strip_prefix(MARK) {
                return (out, status.trim().parse().expect("status"));
            }
            out.push_str(&line);
            out.push('\n');
        }
    }
}

impl Drop for Shell {
    fn drop(&mut self) {
        // The README starts the server in the background: stop every job of the shell.
        let _ = writeln!(self.stdin, "kill $(jobs -p) 2>/dev/null; wait; exit");
        let _ = self.stdin.flush();
        for _ in 0..100 {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(Duration::from_millis(100));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The JSON document at the start of `out`.
fn json_of(out: &str, cmd: &str) -> Value {
    serde_json::Deserializer::from_str(out.trim_start())
        .into_iter::<Value>()
        .next()
        .and_then(Result::ok)
        .unwrap_or_else(|| panic!("not JSON:\n{out}\nfrom:\n{cmd}"))
}

/// What the checks read: the scratch directory, the server and the world the walk-through made.
struct Ctx {
    dir: PathBuf,
    addr: String,
    world: String,
}

/// A check of a command's output (given the output and the command as the README has it).
type Check = fn(&str, &str, &mut Ctx);

fn file(ctx: &Ctx, name: &str) -> Vec<u8> {
    std::fs::read(ctx.dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn version(out: &str, cmd: &str) -> u64 {
    json_of(out, cmd)["version"]
        .as_u64()
        .unwrap_or_else(|| panic!("no version in {out} from {cmd}"))
}

/// The peak of the README (900 m at (-1536, 512), the centre vertex of LOD-4 tile (-2, 0)) at
/// version 3 is a mountain, not a needle: the summit is the tile's highest vertex (within the
/// flanks' 1 m: the peak's rounded top sits on the ground's own slope, so a vertex beside the
/// summit may stand centimetres higher), within 5 m of 900 m; along the four axes the heights
/// fall from it, every step down or level within 1 m, for 20 vertices (320 m); and 160 m out
/// the ground is still over a third of the way up from the foot (the height 480 m out) to the
/// summit.
fn peak_is_a_peak(ctx: &Ctx) {
    let path = format!("/v1/worlds/{}/tiles/4/-2/0.json?v=3", ctx.world);
    let (status, body) = common::raw::get(&ctx.addr, &path);
    assert_eq!(status, 200, "{}", String::from_utf8_lossy(&body));
    let tile: Value = serde_json::from_slice(&body).expect("tile JSON");
    let h: Vec<f64> = tile["heights"]
        .as_array()
        .expect("heights")
        .iter()
        .map(|v| v.as_f64().expect("height"))
        .collect();
    let at = |i: i64, j: i64| h[(j * 65 + i) as usize];
    let top = at(32, 32);
    let max = h.iter().copied().fold(f64::MIN, f64::max);
    println!("peak: summit {top:.1} m, tile maximum {max:.1} m");
    assert!(
        (top - 900.0).abs() <= 5.0 && top >= max - 1.0,
        "summit {top} m, tile maximum {max} m"
    );
    for (di, dj) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
        let line: Vec<f64> = (0..=30).map(|k| at(32 + di * k, 32 + dj * k)).collect();
        println!(
            "peak profile ({di}, {dj}): {:?}",
            line.iter().map(|v| v.round()).collect::<Vec<_>>()
        );
        for k in 1..=20 {
            assert!(
                line[k] <= line[k - 1] + 1.0,
                "the flank rises at {} m: {line:?}",
                16 * k
            );
        }
        let foot = line[30];
        assert!(line[10] - foot >= (top - foot) / 3.0, "a needle: {line:?}");
    }
}

/// The rules, most specific first.
const RULES: &[(&str, Check)] = &[
    ("export STRATA_ADMIN_TOKEN=", |_, _, _| {}),
    ("strata serve", |_, _, _| {}),
    ("/healthz", |_, _, _| {}),
    ("/v1/info", |out, cmd, _| {
        assert!(json_of(out, cmd)["limits"].is_object(), "{out}");
    }),
    ("tiles/0/0/0.json | head -c 300", |out, _, _| {
        assert!(out.starts_with("{\"format\":\"strata.tile.v1\""), "{out}");
    }),
    ("-so tile.glb localhost", |_, _, ctx| {
        assert_eq!(&file(ctx, "tile.glb")[..4], b"glTF");
    }),
    ("-so tile.png", |_, _, ctx| {
        assert_eq!(&file(ctx, "tile.png")[1..4], b"PNG");
    }),
    (".bin?seams=0,1,0,0' | od", |out, _, _| {
        assert!(
            out.contains("S   T   R   T") || out.contains("53 54 52 54"),
            "{out}"
        );
    }),
    ("/scatter/0/0/0.json", |out, _, _| {
        assert!(
            out.starts_with("{\"") && out.contains("\"points\""),
            "{out}"
        );
    }),
    (".bin?format=2' | od", |out, _, _| {
        assert!(out.contains("53 54 52 54"), "{out}");
    }),
    ("/rivers/6/-1/1.json", |out, _, _| {
        assert!(out.contains("\"lines\""), "{out}");
    }),
    ("ID=$(", |_, _, _| {}),
    ("WORLD_ADMIN=$(", |_, _, _| {}),
    ("W=$(curl", |_, _, _| {}),
    ("echo \"$W\"", |out, cmd, ctx| {
        let w = json_of(out, cmd);
        assert_eq!(w["version"], 1, "{out}");
        assert!(w["tokens"]["admin"].is_string(), "{out}");
        ctx.world = w["id"].as_str().expect("id").to_string();
    }),
    ("/versions/1", |out, _, _| {
        assert!(
            out.starts_with("{\"id\":\"") && out.contains("\"scene\":{"),
            "{out}"
        );
    }),
    ("-so tile.glb \"localhost", |_, _, ctx| {
        assert_eq!(&file(ctx, "tile.glb")[..4], b"glTF");
    }),
    ("/exports", |out, cmd, _| {
        assert!(json_of(out, cmd)["job"].is_string(), "{out}");
    }),
    ("/metrics", |out, _, _| {
        assert!(out.contains("strata_"), "{out}");
    }),
    ("\"/world/sea_level_m\"", |out, cmd, _| {
        assert_eq!(version(out, cmd), 2, "{out}");
    }),
    ("\"id\":\"peak\"", |out, cmd, ctx| {
        assert_eq!(version(out, cmd), 3, "{out}");
        peak_is_a_peak(ctx);
    }),
    ("\"id\":\"continent\"", |out, cmd, _| {
        assert_eq!(version(out, cmd), 4, "{out}");
    }),
    ("\"id\":\"dunes\"", |out, cmd, _| {
        assert_eq!(version(out, cmd), 5, "{out}");
    }),
    ("\"id\":\"rock\"", |out, cmd, _| {
        assert_eq!(version(out, cmd), 6, "{out}");
    }),
    ("/columns/", |out, _, _| {
        assert!(out.contains("\"limits\""), "{out}");
    }),
    ("/materials/query", |out, cmd, _| {
        let doc = json_of(out, cmd);
        let results = doc["results"].as_array().expect("results");
        assert!(!results.is_empty(), "{out}");
        for r in results {
            assert!(
                !r["composition"].as_array().is_none_or(Vec::is_empty),
                "a point without material: {out}"
            );
        }
    }),
    ("@docs/examples/arch.json", |out, cmd, _| {
        assert_eq!(version(out, cmd), 7, "{out}");
    }),
    ("/chunks/", |out, _, _| {
        let count = |name: &str| {
            out.lines()
                .find_map(|l| l.strip_prefix(&format!("\"{name}\":")))
                .and_then(|n| n.trim().parse::<u64>().ok())
                .unwrap_or_else(|| panic!("no {name} in {out}"))
        };
        assert!(
            count("vertex_count") > 100 && count("quad_count") > 100,
            "an empty chunk: {out}"
        );
    }),
    ("/ptex/0/0/5/0", |_, _, ctx| {
        let pack = file(ctx, "chunk.stpx");
        assert_eq!(&pack[..4], b"STPX");
        let faces = u32::from_le_bytes(pack[52..56].try_into().expect("face count"));
        assert!(faces > 100, "the arch's chunk has quads: {faces} faces");
    }),
    ("echo \"$IMG\"", |out, _, _| {
        let hash = out.trim();
        assert!(
            hash.len() == 64 && hash.bytes().all(|b| b.is_ascii_hexdigit()),
            "not an image hash: {out}"
        );
    }),
    ("IMG=$(", |_, _, _| {}),
    ("\"id\":\"puddle\"", |out, cmd, _| {
        assert_eq!(version(out, cmd), 10, "{out}");
    }),
    ("-o tile-before.stpx", |_, _, ctx| {
        assert_eq!(&file(ctx, "tile-before.stpx")[..4], b"STPX");
    }),
    ("-o tile-decal.stpx", |_, _, ctx| {
        let (before, after) = (file(ctx, "tile-before.stpx"), file(ctx, "tile-decal.stpx"));
        let ([a0, n0, d0], [a1, n1, d1]) = (tile_planes(&before), tile_planes(&after));
        let changed = a0
            .chunks(4)
            .zip(a1.chunks(4))
            .filter(|(x, y)| x != y)
            .count();
        // The puddle covers about 300 m² of the tile's 4,096 at 16 texels a m².
        assert!(
            (1_000..20_000).contains(&changed),
            "{changed} texels changed"
        );
        assert_eq!(
            (n0, d0),
            (n1, d1),
            "a decal changes albedo and roughness only"
        );
    }),
    ("\"id\":\"lush\"", |out, cmd, _| {
        assert_eq!(version(out, cmd), 11, "{out}");
    }),
    ("/ptex/tiles/", |_, _, ctx| {
        let pack = file(ctx, "tile.stpx");
        assert_eq!(&pack[..4], b"STPX");
        let faces = u32::from_le_bytes(pack[52..56].try_into().expect("face count"));
        assert_eq!(faces, 16, "a tile's 4 × 4 faces");
    }),
    ("@docs/examples/rock.glb", |out, cmd, _| {
        let doc = json_of(out, cmd);
        assert_eq!(doc["version"], 8, "{out}");
        assert_eq!(doc["triangles"], 20, "{out}");
    }),
    ("/mesh.glb -o arch.glb", |_, _, ctx| {
        assert_eq!(&file(ctx, "arch.glb")[..4], b"glTF");
    }),
    ("> curves.json", |_, _, ctx| {
        let c: Value = serde_json::from_slice(&file(ctx, "curves.json")).expect("curves JSON");
        assert!(c.to_string().contains("control_points"), "{c}");
    }),
    ("-XPUT", |out, cmd, _| {
        assert_eq!(version(out, cmd), 9, "{out}");
    }),
];

#[test]
fn the_readme_walk_through_runs_in_order_and_every_answer_shows_something() {
    let curl = Command::new("curl").arg("--version").output();
    assert!(
        curl.is_ok_and(|o| o.status.success()),
        "the README's commands use curl: apt-get install curl"
    );
    write_examples();
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let port = std::net::TcpListener::bind("127.0.0.1:0")
        .expect("a free port")
        .local_addr()
        .expect("addr")
        .port();
    let addr = format!("127.0.0.1:{port}");
    let cmds = commands(&readme, "Using it");
    assert!(
        cmds.len() > 20,
        "only {} commands in \"Using it\"",
        cmds.len()
    );

    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("readme-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    std::os::unix::fs::symlink(root().join("docs"), dir.join("docs")).expect("link docs");
    let bin = Path::new(env!("CARGO_BIN_EXE_strata"))
        .parent()
        .expect("bin dir");
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let mut ctx = Ctx {
        dir: dir.clone(),
        addr: addr.clone(),
        world: String::new(),
    };
    let mut shell = Shell::start(&dir, &path);
    for cmd in &cmds {
        let run = cmd.replace("localhost:8080", &addr).replace(
            "strata serve",
            &format!("strata serve --addr {addr} --backend cpu"),
        );
        let (out, status) = shell.run(&run);
        println!("$ {cmd}\n{out}");
        assert_eq!(status, 0, "exit status {status} of:\n{cmd}\n{out}");
        let (_, check) = RULES
            .iter()
            .find(|(needle, _)| cmd.contains(needle))
            .unwrap_or_else(|| panic!("no check for the README command:\n{cmd}"));
        check(&out, cmd, &mut ctx);
    }
    drop(shell);
    let _ = std::fs::remove_dir_all(&dir);
}
