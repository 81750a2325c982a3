//! The colour-and-depth fast path (`render_into` with `Buffers::ColorDepth`, the lane code in
//! `raster::lanes`) against the per-pixel renderer with every buffer (`render`):
//! - edge functions: colour and depth bit for bit, with the AVX2 intrinsics and with the
//!   portable SIMD lanes and the scalar lanes, for every filter, wrap, mode and shading;
//! - scanline: identical coverage, colours equal up to rounding, every shading; every vector
//!   build of the scanline lanes bit for bit as the scalar one.

mod common;

use barylab::raster::lanes::VectorLevel;
use barylab::raster::render::{ClipMesh, Rasterizer, RenderSettings, render, render_into_at};
use barylab::raster::setup::TieRule;
use barylab::raster::texture::texel_difference;
use barylab::raster::{
    Buffers, BuiltinTexture, Filter, Framebuffer, Interpolation, Shading, Texture, Wrap,
};
use barylab::scene::Scene;
use common::at_window;
use proptest::prelude::*;

/// The fast path's colour and depth, its lanes at `vector` (the level is a parameter of the
/// render, so tests running in parallel each draw at their own).
fn fast(
    mesh: &ClipMesh,
    tex: &Texture,
    s: &RenderSettings,
    frame: &mut Framebuffer,
    vector: VectorLevel,
) {
    render_into_at(frame, mesh, tex, s, Buffers::ColorDepth, vector).expect("render");
}

/// A texture whose size is not a power of two (the general wrap path), not opaque (the
/// other two are: bilinear lanes skip the alpha sum of an opaque texture).
fn odd_texture() -> Texture {
    let (w, h) = (37u32, 23u32);
    let texels = (0..w * h)
        .map(|k| {
            let (i, j) = (k % w, k / w);
            let alpha = 255 - ((i * 5 + j * 3) % 200) as u8;
            [(i * 7) as u8, (j * 11) as u8, ((i * j) % 256) as u8, alpha]
        })
        .collect();
    let t = Texture::from_texels(w, h, texels).expect("texture");
    assert!(!t.is_opaque());
    t
}

fn textures() -> Vec<(&'static str, Texture)> {
    assert!(Texture::builtin(BuiltinTexture::Noise).is_opaque());
    vec![
        ("noise", Texture::builtin(BuiltinTexture::Noise)),
        ("uv-grid", Texture::builtin(BuiltinTexture::UvGrid)),
        ("37x23", odd_texture()),
    ]
}

/// Colour and depth of the fast path equal the full render's, bit for bit (edge functions),
/// with the vector path on and off; and a reused frame gives the same as a fresh one.
fn assert_edge_identical(mesh: &ClipMesh, tex: &Texture, s: &RenderSettings, what: &str) {
    let reference = render(mesh, tex, s).expect("render").frame;
    // A reused framebuffer of another size and content: fully reset by render_into.
    let mut frame = Framebuffer::new(3, 5, [1, 2, 3, 4]).expect("small frame");
    for vector in VectorLevel::ALL {
        fast(mesh, tex, s, &mut frame, vector);
        assert_eq!(
            (frame.width, frame.height),
            (reference.width, reference.height)
        );
        assert!(frame.triangle.is_empty() && frame.uv_perspective.is_empty());
        let bad = (0..reference.color.len())
            .find(|&i| {
                frame.color[i] != reference.color[i]
                    || frame.depth[i].to_bits() != reference.depth[i].to_bits()
            })
            .map(|i| {
                (
                    i % reference.width as usize,
                    i / reference.width as usize,
                    frame.color[i],
                    reference.color[i],
                )
            });
        assert_eq!(
            bad, None,
            "{what}, vector level {vector:?}: (x, y, fast, reference)"
        );
        // The heatmap's buffers (colour, depth, triangle, uv both ways), bit for bit too.
        render_into_at(&mut frame, mesh, tex, s, Buffers::ColorDepthUv, vector).expect("render");
        assert!(frame.weights_screen.is_empty() && frame.inv_w.is_empty());
        let bits = |uv: [f32; 2]| uv.map(f32::to_bits);
        let bad = (0..reference.color.len()).find(|&i| {
            frame.color[i] != reference.color[i]
                || frame.depth[i].to_bits() != reference.depth[i].to_bits()
                || frame.triangle[i] != reference.triangle[i]
                || bits(frame.uv_affine[i]) != bits(reference.uv_affine[i])
                || bits(frame.uv_perspective[i]) != bits(reference.uv_perspective[i])
        });
        assert_eq!(
            bad.map(|i| (i % reference.width as usize, i / reference.width as usize)),
            None,
            "{what}, vector level {vector:?}: uv buffers differ at (x, y)"
        );
        // The difference view's buffers: depth and the texel difference, which is the full
        // render's two uvs through `texel_difference` (NaN where nothing is drawn); nothing is
        // shaded, so the colour is the background everywhere.
        render_into_at(&mut frame, mesh, tex, s, Buffers::DepthDifference, vector).expect("render");
        assert!(frame.triangle.is_empty() && frame.uv_affine.is_empty());
        let size = (tex.width(), tex.height());
        let bad = (0..reference.color.len()).find(|&i| {
            let expected = if reference.triangle[i] == barylab::raster::NO_TRIANGLE {
                f32::NAN
            } else {
                texel_difference(reference.uv_affine[i], reference.uv_perspective[i], size)
            };
            frame.color[i] != s.background
                || frame.depth[i].to_bits() != reference.depth[i].to_bits()
                || frame.texel_difference[i].to_bits() != expected.to_bits()
        });
        assert_eq!(
            bad.map(|i| (i % reference.width as usize, i / reference.width as usize)),
            None,
            "{what}, vector level {vector:?}: texel differences differ at (x, y)"
        );
    }
}

/// Covered exactly where the reference is covered; colours equal but for rounding.
fn assert_scanline_close(mesh: &ClipMesh, tex: &Texture, s: &RenderSettings, what: &str) {
    let reference = render(mesh, tex, s).expect("render").frame;
    let mut frame = Framebuffer::empty();
    let scan = RenderSettings {
        rasterizer: Rasterizer::Scanline,
        ..*s
    };
    // Every build of the scanline lanes does the same arithmetic: the scalar code's image
    // is the vector code's, bit for bit (short spans gathered into chunks included).
    let mut scalar = Framebuffer::empty();
    fast(mesh, tex, &scan, &mut scalar, VectorLevel::Scalar);
    for vector in VectorLevel::ALL {
        fast(mesh, tex, &scan, &mut frame, vector);
        assert!(
            frame.color == scalar.color && frame.depth == scalar.depth,
            "{what}, vector level {vector:?}: the scanline lanes differ from the scalar build"
        );
        let mut differing = 0;
        for i in 0..reference.color.len() {
            let (x, y) = (i as u32 % frame.width, i as u32 / frame.width);
            assert_eq!(
                frame.covered(x, y),
                reference.covered(x, y),
                "{what}: coverage at ({x}, {y})"
            );
            let (a, b) = (frame.depth[i], reference.depth[i]);
            assert!((a - b).abs() <= 1e-5, "{what}: depth at ({x}, {y})");
            differing += usize::from(frame.color[i] != reference.color[i]);
        }
        assert!(
            differing * 200 <= reference.color.len(),
            "{what}, vector level {vector:?}: {differing} colours differ"
        );
    }
}

#[test]
fn edge_fast_path_is_bit_identical_on_every_sample_scene() {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"));
    let mut n = 0;
    for entry in std::fs::read_dir(dir).expect("scenes") {
        let path = entry.expect("entry").path();
        if path.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        let mut scene = Scene::load(&path).expect("scene");
        let (w, h) = scene.size();
        if w * h > 640 * 480 {
            scene.set_size(w / 4, h / 4);
        }
        let tex = scene.load_texture(dir).expect("texture");
        let mesh = scene.to_mesh();
        for mode in [Interpolation::Affine, Interpolation::Perspective] {
            for filter in [Filter::Nearest, Filter::Bilinear, Filter::Trilinear] {
                for shading in Shading::ALL {
                    for wireframe in [false, true] {
                        let s = RenderSettings {
                            mode,
                            filter,
                            shading,
                            wireframe,
                            ..scene.settings()
                        };
                        let what = format!("{} {mode:?} {filter:?} {shading:?}", path.display());
                        assert_edge_identical(&mesh, &tex, &s, &what);
                    }
                }
                // The scanline lanes draw every shading but the wireframe.
                for shading in Shading::ALL {
                    let s = RenderSettings {
                        mode,
                        filter,
                        shading,
                        ..scene.settings()
                    };
                    let what = format!("{} {mode:?} {filter:?} {shading:?}", path.display());
                    assert_scanline_close(&mesh, &tex, &s, &what);
                }
            }
        }
        n += 1;
    }
    assert!(n >= 8);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random triangles (overlapping, both windings, some partly off screen, w from 0.3 to
    /// 12) with every texture, wrap and filter the lanes handle.
    #[test]
    fn fast_paths_agree_on_random_meshes(
        pts in proptest::collection::vec((-30.0f64..110.0, -30.0f64..80.0, 0.3f64..12.0), 6),
        uv_scale in 0.5f32..6.0,
        persp in any::<bool>(),
        bilinear in any::<bool>(),
        wrap in 0usize..3,
        which in 0usize..3,
        wireframe in any::<bool>(),
        shading in 0usize..6,
        top_left in any::<bool>(),
    ) {
        let (w, h) = (83, 61);
        let mesh = common::four_triangles(&pts, uv_scale, w, h);
        let (name, tex) = textures().swap_remove(which);
        let s = RenderSettings {
            width: w,
            height: h,
            mode: if persp { Interpolation::Perspective } else { Interpolation::Affine },
            filter: if bilinear { Filter::Bilinear } else { Filter::Nearest },
            wrap: [Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat][wrap],
            wireframe,
            shading: Shading::ALL[shading],
            tie_rule: if top_left { TieRule::TopLeft } else { TieRule::Llvmpipe },
            ..RenderSettings::default()
        };
        assert_edge_identical(&mesh, &tex, &s, name);
        assert_scanline_close(&mesh, &tex, &s, name);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// What the fast path keeps of a triangle before drawing it (its bounds, or nothing)
    /// is what the full set-up gives, slivers and off-screen triangles included.
    #[test]
    fn setup_bounds_agree_with_the_full_setup(
        pts in proptest::collection::vec((-20.0f64..100.0, -20.0f64..80.0), 3),
        sliver in any::<bool>(),
    ) {
        use barylab::raster::clip::ClipVertex;
        use barylab::raster::project::{Viewport, project_vertex};
        use barylab::raster::setup::{setup_bounds, setup_triangle};
        use barylab::raster::varying::Varyings;
        let vp = Viewport { width: 64, height: 48 };
        let mut p = pts.clone();
        if sliver {
            // The third point a hair off the line through the first two.
            p[2] = (p[0].0 * 0.5 + p[1].0 * 0.5 + 1e-4, p[0].1 * 0.5 + p[1].1 * 0.5);
        }
        let v = [0, 1, 2].map(|k| {
            let clip = glam::DVec4::new(p[k].0 / 32.0 - 1.0, 1.0 - p[k].1 / 24.0, 0.0, 1.0);
            project_vertex(&ClipVertex::new(clip, Varyings::default()), vp)
        });
        let full = setup_triangle(v, vp).map(|s| s.bounds);
        prop_assert_eq!(setup_bounds(v.map(|v| v.fixed), vp), full);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Many small, overlapping triangles at different depths (most under four pixels wide,
    /// the lanes' narrow path, which draws two rows at once), across band boundaries, with
    /// every shading: bit for bit as the full render, the heatmap's buffers too; the scanline
    /// lanes with the same coverage.
    #[test]
    fn small_triangles_agree(
        tris in proptest::collection::vec(
            (0.0f64..60.0, 0.0f64..45.0, 0.2f64..5.5, 0.2f64..6.0, 0.0f64..1.0, -0.9f64..0.9, 0.5f64..4.0),
            40,
        ),
        persp in any::<bool>(),
        bilinear in any::<bool>(),
        wireframe in any::<bool>(),
        shading in 0usize..6,
    ) {
        let (w, h) = (61, 47);
        let mut mesh = ClipMesh { vertices: Vec::new(), triangles: Vec::new() };
        for (k, &(x, y, dx, dy, skew, z, cw)) in tris.iter().enumerate() {
            let corners = [(x, y), (x + dx, y + skew * dy), (x + skew * dx, y + dy)];
            let first = mesh.vertices.len() as u32;
            for (j, &(px, py)) in corners.iter().enumerate() {
                let mut v = at_window(px, py, cw, w, h);
                v.clip.z = (z + 0.03 * j as f64) * cw;
                v.color = glam::Vec3::new(k as f32 / 40.0, j as f32 * 0.4, 0.7);
                v.normal = glam::Vec3::new(0.3 * j as f32, 0.2, 0.9).normalize();
                mesh.vertices.push(v);
            }
            // Both windings.
            mesh.triangles.push(if k % 2 == 0 {
                [first, first + 1, first + 2]
            } else {
                [first, first + 2, first + 1]
            });
        }
        let (name, tex) = textures().swap_remove(0);
        let s = RenderSettings {
            width: w,
            height: h,
            mode: if persp { Interpolation::Perspective } else { Interpolation::Affine },
            filter: if bilinear { Filter::Bilinear } else { Filter::Nearest },
            wireframe,
            shading: Shading::ALL[shading],
            ..RenderSettings::default()
        };
        assert_edge_identical(&mesh, &tex, &s, name);
        // The scanline lanes find a narrow triangle's spans from its edge values.
        if !wireframe {
            assert_scanline_close(&mesh, &tex, &s, name);
        }
    }
}

/// A texture with alpha below 255 and a power-of-two size (the vector lanes' own wrap), so
/// the bilinear lanes sum alpha as the full render does (an opaque texture skips that sum).
#[test]
fn bilinear_lanes_blend_alpha_of_a_translucent_texture() {
    let (w, h) = (64u32, 32u32);
    let texels = (0..w * h)
        .map(|k| {
            let (i, j) = (k % w, k / w);
            [(i * 4) as u8, (j * 8) as u8, 128, (i * 3 + j * 5) as u8]
        })
        .collect();
    let tex = Texture::from_texels(w, h, texels).expect("texture");
    assert!(!tex.is_opaque());
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"));
    let scene = Scene::load(&dir.join("default.json")).expect("scene");
    let mesh = scene.to_mesh();
    for mode in [Interpolation::Affine, Interpolation::Perspective] {
        for wrap in [Wrap::Repeat, Wrap::ClampToEdge] {
            let s = RenderSettings {
                mode,
                filter: Filter::Bilinear,
                wrap,
                ..scene.settings()
            };
            let what = format!("translucent {mode:?} {wrap:?}");
            assert_edge_identical(&mesh, &tex, &s, &what);
            assert_scanline_close(&mesh, &tex, &s, &what);
        }
    }
}
