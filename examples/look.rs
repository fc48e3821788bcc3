//! Dev tool: hillshade of an area. `look LOD X_M Z_M TILES OUT.png [classic]`
use strata::terrain::{synthesize, TileKey, WorldParams, WorldPlan};
use rayon::prelude::*;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let lod: u32 = a[1].parse().unwrap();
    let cx: f64 = a[2].parse().unwrap();
    let cz: f64 = a[3].parse().unwrap();
    let n: i64 = a[4].parse().unwrap();
    let out = &a[5];
    let params = if a.get(6).map(|s| s == "classic").unwrap_or(false) { WorldParams::classic() } else { WorldParams::default() };
    let mut params = params;
    if let (Some(e), Ok(v)) = (params.earth.as_mut(), std::env::var("EROSION")) { e.erosion = v.parse().unwrap(); }
    if let (Some(e), Ok(v)) = (params.earth.as_mut(), std::env::var("GULLIES")) { e.gully_octaves = v.parse().unwrap(); }
    if let (Some(e), Ok(v)) = (params.earth.as_mut(), std::env::var("OCTAVES")) { e.octaves = v.parse().unwrap(); }
    let plan = WorldPlan::new(42, params).unwrap();
    let d = plan.lods[lod as usize].spacing_m as f64;
    let span = 64.0 * d;
    let tx0 = (cx / span).floor() as i64 - n / 2;
    let tz0 = (cz / span).floor() as i64 - n / 2;
    let side = (n * 64) as usize;
    let keys: Vec<(i64,i64)> = (0..n*n).map(|i| (tx0 + i % n, tz0 + i / n)).collect();
    let t0 = std::time::Instant::now();
    let tiles: Vec<_> = keys.par_iter().map(|&(x,z)| synthesize(&plan, TileKey{lod, x, z})).collect();
    let el = t0.elapsed().as_secs_f64();
    let mut h = vec![0f32; side*side];
    let mut bw = vec![0u8; side*side];
    for (t, &(x,z)) in tiles.iter().zip(&keys) {
        let k = t.biome_count;
        for j in 0..64 { for i in 0..64 {
            let gi = ((x - tx0) * 64 + i) as usize; let gj = ((z - tz0) * 64 + j) as usize;
            let v = j as usize * 65 + i as usize;
            h[gj*side+gi] = t.heights[v];
            let wv = &t.weights[v*k..(v+1)*k];
            let mut best=0; for b in 0..k { if wv[b] > wv[best] { best=b; } }
            bw[gj*side+gi] = best as u8;
        }}
    }
    let mut slopes = Vec::new();
    let mut img = vec![0u8; side*side*3];
    let (mut lo, mut hi) = (f32::MAX, f32::MIN);
    let mut land = 0usize;
    for j in 0..side { for i in 0..side {
        let g = |i: usize, j: usize| h[j.min(side-1)*side + i.min(side-1)];
        let v = g(i,j); lo = lo.min(v); hi = hi.max(v); if v > 0.0 { land += 1; }
        let dx = (g(i+1,j) - g(i.saturating_sub(1),j)) as f64 / (2.0*d);
        let dz = (g(i,j+1) - g(i,j.saturating_sub(1))) as f64 / (2.0*d);
        if i>0 && j>0 && i<side-1 && j<side-1 && v > 0.0 { slopes.push((dx*dx+dz*dz).sqrt().atan().to_degrees()); }
        // light from NW (azimuth 315), altitude 45
        let (nx, ny, nz) = (-dx, 1.0, -dz); let l = (nx*nx+ny*ny+nz*nz).sqrt();
        let (lx, ly, lz) = (-0.5f64, 0.7071, -0.5);
        let shade = ((nx*lx + ny*ly + nz*lz)/l).max(0.0);
        let (r,gc,b) = if v <= 0.0 { let t = (1.0 + (v as f64)/4000.0).clamp(0.0,1.0); (20.0+40.0*t, 60.0+80.0*t, 120.0+100.0*t) }
            else { let t = (v as f64 / 3000.0).clamp(0.0,1.0); (90.0+165.0*t, 140.0+100.0*t, 80.0+170.0*t) };
        let s = 0.35 + 0.9*shade;
        let p = (j*side+i)*3; img[p]=(r*s).min(255.0) as u8; img[p+1]=(gc*s).min(255.0) as u8; img[p+2]=(b*s).min(255.0) as u8;
        if a.get(7).is_some() { let c = [[255,0,0],[0,255,0],[0,0,255],[255,255,0],[0,255,255],[255,0,255]][bw[j*side+i] as usize % 6]; for q in 0..3 { img[p+q] = ((img[p+q] as u16 + c[q] as u16)/2) as u8; } }
    }}
    slopes.sort_by(f64::total_cmp);
    let pct = |q: f64| if slopes.is_empty() { f64::NAN } else { slopes[((slopes.len()-1) as f64 * q) as usize] };
    println!("lod {lod} spacing {d} m, {side}x{side}, {:.1} km; h {lo:.0}..{hi:.0} m; land {:.0}%; slope median {:.1}° p95 {:.1}°; {:.2} ms/tile (par)", side as f64*d/1000.0, 100.0*land as f64/(side*side) as f64, pct(0.5), pct(0.95), el*1000.0/(n*n) as f64);
    let f = std::fs::File::create(out).unwrap();
    let mut e = png::Encoder::new(std::io::BufWriter::new(f), side as u32, side as u32);
    e.set_color(png::ColorType::Rgb); e.set_depth(png::BitDepth::Eight);
    e.write_header().unwrap().write_image_data(&img).unwrap();
}
