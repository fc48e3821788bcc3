//! Every `shaders/*.wgsl` file parses and validates with naga, and the structs shared with the
//! host have the layout of their `#[repr(C)]` twins in `strata::gpu::layout`.
//!
//! A shader that builds on others names them on a `// requires: a.wgsl, b.wgsl` line; the test
//! prepends those files (recursively) before validating, as the crate does at load time. New
//! files are covered automatically because the test enumerates the directory.
//!
//! A shader whose constants the host generates names the generator on a `// preamble: path()`
//! line (`earth.wgsl` and `rivers.wgsl`: `strata::gpu::earth::constants_wgsl()`); the test
//! validates the source the crate loads for it, and checks that naga reads every generated
//! constant as the Rust `f32`.

use std::collections::BTreeMap;
use std::mem::{offset_of, size_of};
use std::path::{Path, PathBuf};
use strata::gpu::layout::{
    GpuBiomeMap, GpuCarveParams, GpuEarthLayer, GpuEarthOctave, GpuEarthParams, GpuFractal,
    GpuOctave, GpuParams,
};
use strata::terrain::earth::rivers::Piece;

fn shader_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders")
}

fn shader_files() -> BTreeMap<String, String> {
    let mut files = BTreeMap::new();
    for entry in std::fs::read_dir(shader_dir()).expect("shaders/ exists") {
        let path = entry.expect("directory entry").path();
        if path.extension().is_some_and(|e| e == "wgsl") {
            let name = path
                .file_name()
                .expect("file name")
                .to_string_lossy()
                .into_owned();
            let text = std::fs::read_to_string(&path)
                .unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
            files.insert(name, text);
        }
    }
    files
}

fn requires(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|l| l.trim().strip_prefix("// requires:"))
        .flat_map(|list| list.split(',').map(|s| s.trim().to_string()))
        .filter(|s| !s.is_empty())
        .collect()
}

/// The file with its requirements prepended, each file once, dependencies first.
fn compose(
    name: &str,
    files: &BTreeMap<String, String>,
    out: &mut Vec<String>,
    stack: &mut Vec<String>,
) {
    if out.iter().any(|n| n == name) {
        return;
    }
    assert!(
        !stack.iter().any(|n| n == name),
        "cyclic `// requires:` through {name}: {stack:?}"
    );
    let text = files
        .get(name)
        .unwrap_or_else(|| panic!("{name} is required (by {stack:?}) but not in shaders/"));
    stack.push(name.to_string());
    for dep in requires(text) {
        compose(&dep, files, out, stack);
    }
    stack.pop();
    out.push(name.to_string());
}

fn validate(label: &str, source: &str) -> naga::Module {
    let module = naga::front::wgsl::parse_str(source)
        .unwrap_or_else(|e| panic!("{label} does not parse:\n{}", e.emit_to_string(source)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::default(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{label} does not validate:\n{}", e.emit_to_string(source)));
    module
}

#[test]
fn every_shader_parses_and_validates() {
    let files = shader_files();
    assert!(
        !files.is_empty(),
        "no .wgsl files in {}",
        shader_dir().display()
    );
    for (name, text) in &files {
        if let Some(generator) = text
            .lines()
            .find_map(|l| l.trim().strip_prefix("// preamble:"))
        {
            let source = match (name.as_str(), generator.trim()) {
                ("earth.wgsl", "strata::gpu::earth::constants_wgsl()") => {
                    strata::gpu::earth_shader_source()
                }
                ("rivers.wgsl", "strata::gpu::earth::constants_wgsl()") => {
                    strata::gpu::rivers_shader_source()
                }
                other => panic!("{name}: no host source known for preamble {other:?}"),
            };
            validate(&format!("{} + {name}", generator.trim()), &source);
            println!("ok: {} + {name}", generator.trim());
            continue;
        }
        let mut order = Vec::new();
        compose(name, &files, &mut order, &mut Vec::new());
        let source = order
            .iter()
            .map(|n| files[n].as_str())
            .collect::<Vec<_>>()
            .join("\n");
        validate(&order.join(" + "), &source);
        println!("ok: {}", order.join(" + "));
    }
}

#[test]
fn the_source_the_crate_loads_validates_and_has_the_entry_points() {
    let source = strata::gpu::tile_shader_source();
    let module = validate("gpu::tile_shader_source()", &source);
    let entries: Vec<&str> = module
        .entry_points
        .iter()
        .map(|e| e.name.as_str())
        .collect();
    for name in ["block_corners", "biome_ids", "blur_h", "blur_v"] {
        assert!(
            entries.contains(&name),
            "entry point {name} missing: {entries:?}"
        );
    }
}

/// `(member name, offset)` of a WGSL struct, and its size.
fn wgsl_struct(module: &naga::Module, name: &str) -> (Vec<(String, u32)>, u32) {
    for (_, ty) in module.types.iter() {
        if ty.name.as_deref() == Some(name) {
            if let naga::TypeInner::Struct { members, span } = &ty.inner {
                let m = members
                    .iter()
                    .map(|m| (m.name.clone().unwrap_or_default(), m.offset))
                    .collect();
                return (m, *span);
            }
        }
    }
    panic!("struct {name} not found in the shader");
}

macro_rules! check_layout {
    ($module:expr, $wgsl:literal, $rust:ty, [$($field:ident),* $(,)?]) => {{
        let (members, span) = wgsl_struct($module, $wgsl);
        assert_eq!(span as usize, size_of::<$rust>(), "size of {} vs {}", $wgsl, stringify!($rust));
        let rust: Vec<(&str, usize)> = vec![$((stringify!($field), offset_of!($rust, $field))),*];
        for (name, offset) in &members {
            if name.starts_with('_') {
                continue;
            }
            let r = rust.iter().find(|(n, _)| n == name).unwrap_or_else(|| {
                panic!("{}.{name} has no counterpart in {}", $wgsl, stringify!($rust))
            });
            assert_eq!(*offset as usize, r.1, "offset of {}.{name}", $wgsl);
        }
        assert_eq!(members.iter().filter(|(n, _)| !n.starts_with('_')).count(), rust.len(), "{} fields", $wgsl);
    }};
}

#[test]
fn host_structs_match_the_wgsl_layout() {
    let module = validate("tile", &strata::gpu::tile_shader_source());
    check_layout!(&module, "Octave", GpuOctave, [freq, amp, seed]);
    check_layout!(
        &module,
        "Fractal",
        GpuFractal,
        [
            inv_scale,
            base_m,
            amplitude_m,
            octave_count,
            warp,
            rough0,
            lever,
            about_origin,
            c1,
            c2,
            t,
            r0,
            t0,
            octaves
        ]
    );
    check_layout!(
        &module,
        "BiomeMap",
        GpuBiomeMap,
        [inv_cell, speed, dispersion, latitude, count, seed_x, seed_z, seed_value]
    );
    check_layout!(
        &module,
        "Params",
        GpuParams,
        [
            gx0,
            gz0,
            w,
            h,
            bgx0,
            bgz0,
            bw,
            bh,
            bx0,
            bz0,
            cw,
            ch,
            taps,
            k,
            spacing,
            rounding_key,
            map
        ]
    );
}

#[test]
fn the_earth_sources_have_their_entry_points_and_the_rust_constants() {
    for (label, source, entry) in [
        (
            "gpu::earth_shader_source()",
            strata::gpu::earth_shader_source(),
            "earth_heights",
        ),
        (
            "gpu::rivers_shader_source()",
            strata::gpu::rivers_shader_source(),
            "river_carve",
        ),
    ] {
        check_entry_and_constants(label, &source, entry);
    }
}

fn check_entry_and_constants(label: &str, source: &str, entry: &str) {
    let module = validate(label, source);
    assert!(
        module.entry_points.iter().any(|e| e.name == entry),
        "entry point {entry} missing from {label}"
    );
    for (name, value) in strata::gpu::earth::constants() {
        let (_, c) = module
            .constants
            .iter()
            .find(|(_, c)| c.name.as_deref() == Some(name))
            .unwrap_or_else(|| panic!("constant {name} missing from {label}"));
        match module.global_expressions[c.init] {
            naga::Expression::Literal(naga::Literal::F32(v)) => {
                assert_eq!(
                    v.to_bits(),
                    value.to_bits(),
                    "{name}: naga reads {v}, Rust has {value}"
                )
            }
            ref e => panic!("{name} is not an f32 literal: {e:?}"),
        }
    }
}

#[test]
fn earth_structs_match_the_wgsl_layout() {
    let module = validate("earth", &strata::gpu::earth_shader_source());
    check_layout!(
        &module,
        "EarthOctave",
        GpuEarthOctave,
        [freq, amp, seed, cos, sin, ox, oz]
    );
    check_layout!(
        &module,
        "EarthLayer",
        GpuEarthLayer,
        [kind, fine, ridged, amp, octave, floor2]
    );
    check_layout!(
        &module,
        "EarthParams",
        GpuEarthParams,
        [
            gx0,
            gz0,
            w,
            h,
            spacing,
            rounding_key,
            layer_count,
            warp_x_count,
            warp_z_count,
            continent_count,
            belt_count,
            hills_count,
            land_bias,
            origin_land,
            inv_origin_r2,
            belt_width,
            mountain_relief_m,
            hill_relief_m,
            plain_relief_m,
            seafloor_relief_m,
            interior_height_m,
            ocean_depth_m,
            inv_relief_max,
            lattice_step,
            prefix,
            node_i0,
            node_k0,
            nodes_w
        ]
    );
}

#[test]
fn river_carve_structs_match_the_wgsl_layout() {
    let module = validate("rivers", &strata::gpu::rivers_shader_source());
    check_layout!(
        &module,
        "CarveParams",
        GpuCarveParams,
        [
            gx0,
            gz0,
            w,
            h,
            spacing,
            rounding_key,
            x0,
            z0,
            bin_m,
            bins_w,
            bins_h,
            wall_noise,
            wall_seed,
            node_spacing,
            li0,
            lk0,
            lakes_w,
            lakes_h,
            shores,
            shore_seed0,
            shore_seed1,
            shore_seed2,
            shore_seed3,
            shore_warp_m,
            shore_warp_inv_m,
            sills,
            shore_n1,
            shore_n2,
            sink
        ]
    );
    check_layout!(
        &module,
        "Piece",
        Piece,
        [
            ax,
            az,
            bx,
            bz,
            wa,
            wb,
            half_width,
            depth,
            valley,
            wet,
            reach,
            inv_len2,
            floodplain,
            sax,
            saz,
            sbx,
            sbz,
            floodplain_b,
            slope_a,
            slope_b,
            spur_a,
            spur_b
        ]
    );
}
