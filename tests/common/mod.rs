//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod app;
pub mod browser;
#[cfg(feature = "gpu")]
pub mod gl;
pub mod xvfb;

use barylab::raster::render::{ClipMesh, MeshVertex, Render, RenderSettings, render};
use barylab::raster::{Filter, Interpolation, Shading, Texture, Wrap};
use glam::{DVec4, Vec2, Vec3};

/// A clip-space vertex whose window position (image coordinates, y down) is (x, y) in a
/// `width` x `height` viewport, at clip w = `w`.
pub fn at_window(x: f64, y: f64, w: f64, width: u32, height: u32) -> MeshVertex {
    let ndc_x = 2.0 * x / f64::from(width) - 1.0;
    let ndc_y = 1.0 - 2.0 * y / f64::from(height);
    MeshVertex {
        clip: DVec4::new(ndc_x * w, ndc_y * w, 0.0, w),
        uv: Vec2::new(
            (x / f64::from(width)) as f32,
            (y / f64::from(height)) as f32,
        ),
        color: Vec3::ONE,
        normal: Vec3::ZERO,
    }
}

pub fn settings(width: u32, height: u32) -> RenderSettings {
    RenderSettings {
        width,
        height,
        mode: Interpolation::Perspective,
        filter: Filter::Nearest,
        wrap: Wrap::Repeat,
        shading: Shading::Barycentric,
        wireframe: false,
        background: [0, 0, 0, 0],
        rasterizer: Default::default(),
        tie_rule: Default::default(),
        samples: Default::default(),
        max_anisotropy: Default::default(),
    }
}

/// The full render (edge functions) of `mesh`, after checking that every other way of
/// drawing it covers exactly the same pixels: the scanline rasterizer (same triangle in every
/// pixel) and the colour-and-depth fast path of both rasterizers. So every conformance test
/// written against this holds for all of them.
pub fn draw(mesh: &ClipMesh, width: u32, height: u32) -> Render {
    use barylab::raster::render::{Rasterizer, render_into};
    use barylab::raster::{Buffers, Framebuffer};
    let tex = Texture::from_texels(1, 1, vec![[255; 4]]).expect("1x1 texture");
    let base = settings(width, height);
    let reference = render(mesh, &tex, &base).expect("render");
    for rasterizer in [Rasterizer::EdgeFunction, Rasterizer::Scanline] {
        let s = RenderSettings { rasterizer, ..base };
        let full = render(mesh, &tex, &s).expect("render");
        assert!(
            full.frame.triangle == reference.frame.triangle,
            "{rasterizer:?}: coverage or owning triangle differs"
        );
        let mut fast = Framebuffer::empty();
        render_into(&mut fast, mesh, &tex, &s, Buffers::ColorDepth).expect("render");
        for y in 0..height {
            for x in 0..width {
                assert_eq!(
                    fast.covered(x, y),
                    reference.frame.covered(x, y),
                    "{rasterizer:?} fast path: coverage differs at ({x}, {y})"
                );
            }
        }
    }
    reference
}

/// Coverage as rows of '#' (covered) and '.' (not).
pub fn coverage_art(r: &Render) -> String {
    let f = &r.frame;
    let mut s = String::new();
    for y in 0..f.height {
        for x in 0..f.width {
            s.push(if f.covered(x, y) { '#' } else { '.' });
        }
        s.push('\n');
    }
    s
}

/// How many of the mesh's triangles cover each pixel, each triangle drawn on its own.
pub fn coverage_counts(mesh: &ClipMesh, width: u32, height: u32) -> Vec<u32> {
    let mut counts = vec![0u32; (width * height) as usize];
    for tri in &mesh.triangles {
        let single = ClipMesh {
            vertices: mesh.vertices.clone(),
            triangles: vec![*tri],
        };
        let r = draw(&single, width, height);
        for (c, t) in counts.iter_mut().zip(&r.frame.triangle) {
            if *t != barylab::raster::NO_TRIANGLE {
                *c += 1;
            }
        }
    }
    counts
}

/// Parses art like `coverage_art` produces (leading/trailing whitespace per line ignored).
pub fn art(s: &str) -> String {
    let mut out = String::new();
    for line in s.lines().map(str::trim).filter(|l| !l.is_empty()) {
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// The tie lattice (`gpu::check::tie_lattice`: many pixel centres exactly on shared edges) as a
/// clip-space scene file, with `extra` fields.
#[cfg(feature = "gpu")]
pub fn lattice_scene(extra: &str) -> String {
    use barylab::gpu::check::tie_lattice;
    let (mesh, settings) = tie_lattice();
    let vertices: Vec<String> = mesh
        .vertices
        .iter()
        .map(|v| {
            format!(
                "{{\"clip\": [{}, {}, {}, {}], \"color\": [{}, {}, {}]}}",
                v.clip.x, v.clip.y, v.clip.z, v.clip.w, v.color.x, v.color.y, v.color.z
            )
        })
        .collect();
    let triangles: Vec<String> = mesh
        .triangles
        .iter()
        .map(|t| format!("[{}, {}, {}]", t[0], t[1], t[2]))
        .collect();
    format!(
        "{{\"width\": {}, \"height\": {}, \"vertices\": [{}], \"triangles\": [{}], \
         \"shading\": \"vertex_color\", \"filter\": \"nearest\"{extra}}}",
        settings.width,
        settings.height,
        vertices.join(", "),
        triangles.join(", ")
    )
}

/// Sample scenes (`assets/scenes/NAME`), made at most `max` pixels in size, each in both
/// interpolation modes with both rasterizers: `(what, mesh, texture, settings)`.
pub fn scene_variants(
    names: &[&str],
    max: (u32, u32),
) -> Vec<(String, ClipMesh, Texture, RenderSettings)> {
    use barylab::raster::render::Rasterizer;
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"));
    let mut out = Vec::new();
    for name in names {
        let mut sc = barylab::scene::Scene::load(&dir.join(name)).expect("scene");
        let (w, h) = sc.size();
        sc.set_size(w.min(max.0), h.min(max.1));
        let mesh = sc.to_mesh();
        let tex = sc.load_texture(dir).expect("texture");
        for mode in [Interpolation::Affine, Interpolation::Perspective] {
            for rasterizer in [Rasterizer::EdgeFunction, Rasterizer::Scanline] {
                let s = RenderSettings {
                    mode,
                    rasterizer,
                    ..sc.settings()
                };
                let what = format!("{name} {mode:?} {rasterizer:?}");
                out.push((what, mesh.clone(), tex.clone(), s));
            }
        }
    }
    out
}

/// Four overlapping triangles over six window points `(x, y, w)` of a `width` x `height`
/// viewport (the random scenes of the fast-path tests): uv scaled by `uv_scale` and moved by
/// -0.3, colours beyond [0, 1] too (the clamp to 8 bits), unit normals in several directions,
/// one facing away and one zero.
pub fn four_triangles(pts: &[(f64, f64, f64)], uv_scale: f32, width: u32, height: u32) -> ClipMesh {
    let mut mesh = ClipMesh {
        vertices: pts
            .iter()
            .map(|&(x, y, z)| at_window(x, y, z, width, height))
            .collect(),
        triangles: vec![[0, 1, 2], [3, 4, 5], [0, 2, 4], [5, 3, 1]],
    };
    for (k, v) in mesh.vertices.iter_mut().enumerate() {
        v.uv = v.uv * uv_scale - 0.3;
        v.color = Vec3::new(k as f32 * 0.3 - 0.2, 1.0 - k as f32 * 0.25, 0.5);
        let a = k as f32 * 1.3;
        v.normal = match k {
            4 => Vec3::ZERO,
            _ => Vec3::new(a.cos() * 0.8, a.sin() * 0.6, 0.5 - k as f32 * 0.2).normalize(),
        };
    }
    mesh
}

/// The project's sample scenes (`assets/scenes/*.json`), each with its path and the folder
/// its textures are found from.
pub fn sample_scenes() -> Vec<(std::path::PathBuf, barylab::scene::Scene)> {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"));
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).expect("scenes") {
        let path = entry.expect("entry").path();
        if path.extension().and_then(|e| e.to_str()) == Some("json") {
            let scene = barylab::scene::Scene::load(&path).expect("scene");
            out.push((path, scene));
        }
    }
    out
}

/// The level-of-detail derivation of a probed pixel (trilinear or anisotropic filtering).
pub fn lod_of(t: &barylab::probe::PixelTrace) -> &barylab::probe::LodTrace {
    t.detail
        .as_ref()
        .and_then(|d| d.attribute.as_ref())
        .and_then(|a| a.lod.as_ref())
        .expect("a level-of-detail derivation")
}

/// Makes `c`'s child run under an address-space limit (`ulimit -v`) of `bytes`.
pub fn limit_address_space(c: &mut std::process::Command, bytes: u64) {
    use std::os::unix::process::CommandExt;
    let limit = libc::rlimit {
        rlim_cur: bytes,
        rlim_max: bytes,
    };
    // SAFETY: setrlimit is async-signal-safe and `limit` is a valid record copied into the
    // closure; it runs in the child between fork and exec.
    unsafe {
        c.pre_exec(move || {
            if libc::setrlimit(libc::RLIMIT_AS, &limit) == 0 {
                Ok(())
            } else {
                Err(std::io::Error::last_os_error())
            }
        });
    }
}
