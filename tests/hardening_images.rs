//! Hardening, round 2 (issue 30): images. Decoding a texture is counted in the memory budget
//! from the file's header, bench's two-image views count two renders, and a bad image file is
//! described in plain words, the same for `render` and `compare`.

mod bad_input;

use std::path::Path;

use bad_input::{bin, fails, s, scene, stderr, succeeds};

/// The default scene with `texture` (a file beside it), written to `dir/s.json`.
fn scene_with_texture(dir: &Path, texture: &str) -> String {
    let text = std::fs::read_to_string(scene("default.json")).expect("default scene");
    let path = dir.join("s.json");
    std::fs::write(
        &path,
        text.replace("\"uv-grid\"", &format!("\"{texture}\"")),
    )
    .expect("write scene");
    s(&path).to_string()
}

#[test]
fn decoding_a_texture_is_counted_before_it_is_decoded() {
    let dir = tempfile::tempdir().expect("tempdir");
    image::RgbImage::new(2000, 2000)
        .save(dir.path().join("big.png"))
        .expect("save");
    let sc = scene_with_texture(dir.path(), "big.png");
    let out = dir.path().join("o.png");
    // 2000 x 2000 x 16 bytes = 61.0 MiB; the 800x600 render itself needs 27.9 MiB.
    let e = fails(&["render", &sc, "-o", s(&out), "--memory-limit", "40M"]);
    assert_eq!(
        e,
        format!(
            "error: decoding texture {} (2000x2000) needs about 61.0 MiB of memory, more than \
             the limit of 40.0 MiB (--memory-limit); see --memory-limit\n",
            s(&dir.path().join("big.png"))
        )
    );
    succeeds(&["render", &sc, "-o", s(&out), "--memory-limit", "70M"]);
}

#[test]
fn bench_side_and_wipe_count_both_images() {
    let args = |view: &'static str| {
        [
            "bench",
            scene("default.json").leak(),
            "--size",
            "2000x2000",
            "--view",
            view,
            "--frames",
            "1",
            "--threads",
            "1",
            "--rasterizer",
            "edge",
            "--mode",
            "affine",
            "--filter",
            "nearest",
            "--memory-limit",
            "75M",
        ]
    };
    // One render of 2000x2000 with colour and depth needs about 45.8 MiB: one fits, two not.
    succeeds(&args("single"));
    for view in ["side", "wipe"] {
        let e = fails(&args(view));
        assert_eq!(
            e,
            format!(
                "error: the {view} view at 2000x2000 (2 renders of 2 triangles) needs about \
                 91.6 MiB of memory, more than the limit of 75.0 MiB (--memory-limit); see \
                 --memory-limit\n"
            )
        );
    }
}

#[test]
fn bad_image_files_are_described_in_plain_words() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    let out = d("o.png");
    // A text file named .png: not an image (it was "truncated (no IEND chunk)").
    std::fs::write(d("notes.png"), "these are my notes\n").expect("write");
    let e = fails(&[
        "render",
        &scene_with_texture(dir.path(), "notes.png"),
        "-o",
        s(&out),
    ]);
    assert!(
        e.ends_with(
            "notes.png: it is not an image: its content is text, not PNG, JPEG, BMP, TGA or \
             WebP data\n"
        ),
        "{e}"
    );
    // A PNG whose data chunk fails its checksum: no decoder record in the message.
    let mut png = Vec::new();
    image::RgbImage::from_pixel(4, 4, image::Rgb([200, 10, 10]))
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .expect("encode");
    let idat = png
        .windows(4)
        .position(|w| w == b"IDAT")
        .expect("an IDAT chunk");
    let len = u32::from_be_bytes(png[idat - 4..idat].try_into().expect("4 bytes")) as usize;
    // The chunk's CRC follows its type and data.
    png[idat + 4 + len] ^= 0xFF;
    std::fs::write(d("crc.png"), &png).expect("write");
    let e = fails(&[
        "render",
        &scene_with_texture(dir.path(), "crc.png"),
        "-o",
        s(&out),
    ]);
    assert!(
        e.ends_with(
            "crc.png: the PNG file is damaged: a chunk's checksum (CRC) does not match its data\n"
        ),
        "{e}"
    );
}

#[test]
fn compare_reads_images_as_render_does() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    let sc = scene("default.json");
    succeeds(&["render", &sc, "-o", s(&d("r.png"))]);
    let rendered = image::open(d("r.png")).expect("open").to_rgb8();
    // A TGA (no signature: read by its extension), as `render` reads one.
    rendered.save(d("r.tga")).expect("tga");
    let o = bin()
        .args(["compare", &sc, s(&d("r.tga"))])
        .output()
        .expect("run");
    assert!(o.status.success(), "{}", stderr(&o));
    // A JPEG cut short is reported, not compared as grey.
    rendered.save(d("r.jpg")).expect("jpeg");
    let jpeg = std::fs::read(d("r.jpg")).expect("read");
    std::fs::write(d("cut.jpg"), &jpeg[..jpeg.len() / 2]).expect("write");
    let e = fails(&["compare", &sc, s(&d("cut.jpg"))]);
    assert!(
        e.ends_with(
            "cut.jpg: the JPEG file is truncated (no end-of-image marker after its data)\n"
        ),
        "{e}"
    );
}
