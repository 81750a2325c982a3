//! The streaming OBJ reader (`ModelMesh::from_obj`, `ModelMesh::load`) against the
//! `tobj`-based loader it replaced (`barylab::model::from_obj_tobj`, the independent
//! reference): random valid OBJ texts give exactly the same mesh, and every kind of bad file
//! gives the reference's message, with the line where it is known.

use std::fmt::Write as _;
use std::path::Path;

use barylab::model::{ModelError, ModelMesh, from_obj_tobj};
use proptest::prelude::*;
use proptest::strategy::ValueTree;

/// A material library for the generated files: `red` (a colour), `tex` (a colour and a
/// texture), and `gray` defined in the second library.
const MTL: &str = "newmtl red\nKd 1 0 0\n\nnewmtl tex\nKd 0.5 0.25 1\nmap_Kd checker.png\n";
const MTL2: &str = "newmtl gray\nKd 0.5 0.5 0.5\nnewmtl red\nKd 0 1 0\n";

/// One line of a generated OBJ.
#[derive(Clone, Debug)]
enum Line {
    V([i8; 3], Option<i8>),
    Vt([i8; 2]),
    Vn([i8; 3]),
    /// Corners: (form: v, v/vt, v//vn, v/vt/vn; three index choices; relative).
    F(Vec<(u8, [u32; 3], bool)>),
    /// A point or a line (dropped).
    Short(u8),
    O(u8),
    G(u8),
    Usemtl(u8),
    Mtllib(u8),
    Comment,
    Blank,
}

fn line() -> impl Strategy<Value = Line> {
    let corner = (0u8..4, any::<[u32; 3]>(), any::<bool>());
    prop_oneof![
        6 => (any::<[i8; 3]>(), prop::option::weighted(0.05, 1i8..4)).prop_map(|(p, w)| Line::V(p, w)),
        3 => any::<[i8; 2]>().prop_map(Line::Vt),
        3 => any::<[i8; 3]>().prop_map(Line::Vn),
        8 => prop::collection::vec(corner, 3..=6).prop_map(Line::F),
        1 => (1u8..3).prop_map(Line::Short),
        1 => any::<u8>().prop_map(Line::O),
        1 => any::<u8>().prop_map(Line::G),
        1 => any::<u8>().prop_map(Line::Usemtl),
        1 => any::<u8>().prop_map(Line::Mtllib),
        1 => Just(Line::Comment),
        1 => Just(Line::Blank),
    ]
}

/// An index for a face: one of the `count` defined so far (1-based or relative), or in a
/// `wild` file now and then one defined later or never.
fn index(choice: u32, count: usize, relative: bool, wild: bool) -> String {
    let count = count as u32;
    if count == 0 || (wild && choice.is_multiple_of(13)) {
        return (count + 1 + choice % 3).to_string();
    }
    let i = choice % count;
    if relative {
        format!("-{}", count - i)
    } else {
        (i + 1).to_string()
    }
}

/// The OBJ text of `lines` after three positions, two texture coordinates and a normal, with
/// `\n` or `\r\n` line ends as `crlf` says; `wild` files have indices out of range now and
/// then. `style` picks the faces' forms: 0 each corner its own, 1 every corner `v/vt/vn`, 2
/// every corner `v/vt`, 3 each face one form (its first corner's).
fn text(lines: &[Line], crlf: &[bool], wild: bool, style: u8) -> String {
    let (mut v, mut vt, mut vn) = (3, 2, 1);
    let mut out = String::from("v 0 0 0\nv 1 0.5 0\nv 0 1 0.25\nvt 0 0\nvt 1 1\nvn 0 0 1\n");
    for (k, l) in lines.iter().enumerate() {
        match l {
            Line::V(p, w) => {
                v += 1;
                let [x, y, z] = p.map(|c| f32::from(c) / 16.0);
                let _ = write!(out, "v {x} {y} {z}");
                if let Some(w) = w {
                    let _ = write!(out, " {}", f32::from(*w) / 2.0);
                }
            }
            Line::Vt([a, b]) => {
                vt += 1;
                let _ = write!(
                    out,
                    "vt {} {}",
                    f32::from(*a) / 128.0,
                    f32::from(*b) / 100.0
                );
            }
            Line::Vn(n) => {
                vn += 1;
                let [x, y, z] = n.map(|c| f32::from(c) / 7.0);
                let _ = write!(out, "vn {x} {y} {z}");
            }
            Line::F(corners) => {
                out.push('f');
                let first = corners.first().map_or(0, |c| c.0);
                for (form, [a, b, c], rel) in corners {
                    let form = match style {
                        1 => 3,
                        2 => 1,
                        3 => first,
                        _ => *form,
                    };
                    let p = index(*a, v, *rel, wild);
                    let t = index(*b, vt, *rel, wild);
                    let n = index(*c, vn, !rel, wild);
                    let _ = match form {
                        0 => write!(out, " {p}"),
                        1 => write!(out, " {p}/{t}"),
                        2 => write!(out, " {p}//{n}"),
                        _ => write!(out, " {p}/{t}/{n}"),
                    };
                }
            }
            Line::Short(n) => {
                let _ = if *n == 1 {
                    write!(out, "f {}", v.max(1))
                } else {
                    write!(out, "l 1 {}", v.max(1))
                };
            }
            Line::O(n) => {
                let _ = write!(out, "o part{}", n % 4);
            }
            Line::G(n) => {
                let _ = write!(out, "g  group {}", n % 3);
            }
            Line::Usemtl(n) => {
                let name = ["red", "tex", "gray", "none"][usize::from(n % 4)];
                let _ = write!(out, "usemtl {name}");
            }
            Line::Mtllib(n) => {
                let name = ["m.mtl", "m2.mtl", "missing.mtl"][usize::from(n % 3)];
                let _ = write!(out, "mtllib {name}");
            }
            Line::Comment => out.push_str("# a comment f 1 2 3"),
            Line::Blank => out.push_str("   "),
        }
        out.push_str(if crlf.get(k).copied().unwrap_or(false) {
            "\r\n"
        } else {
            "\n"
        });
    }
    out
}

/// A folder with the material libraries the generated files name.
fn mtl_dir() -> tempfile::TempDir {
    let dir = tempfile::tempdir().expect("tempdir");
    std::fs::write(dir.path().join("m.mtl"), MTL).expect("write");
    std::fs::write(dir.path().join("m2.mtl"), MTL2).expect("write");
    dir
}

/// The reason of a parse error (the message without the file).
fn reason(e: &ModelError) -> String {
    match e {
        ModelError::Parse { reason, .. } => reason.clone(),
        other => other.to_string(),
    }
}

/// Both readers on `obj`: the same mesh, or errors where the streaming reader's message holds
/// the reference's. Returns the mesh when it loaded.
fn same_as_reference(obj: &str, dir: &Path) -> Result<Option<ModelMesh>, TestCaseError> {
    let ours = ModelMesh::from_obj(obj.as_bytes(), "g.obj", dir);
    let reference = from_obj_tobj(obj.as_bytes(), "g.obj", dir);
    match (ours, reference) {
        (Ok(a), Ok(b)) => {
            prop_assert_eq!(&a, &b, "{}", obj);
            Ok(Some(a))
        }
        (Err(a), Err(b)) => {
            let (a, b) = (reason(&a), reason(&b));
            prop_assert!(a.contains(&b), "ours: {a}\nreference: {b}\n{obj}");
            Ok(None)
        }
        (a, b) => Err(TestCaseError::fail(format!(
            "ours: {:?}\nreference: {:?}\n{obj}",
            a.map(|m| m.triangles.len()),
            b.map(|m| m.triangles.len())
        ))),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1024, ..ProptestConfig::default() })]

    #[test]
    fn random_obj_files_give_the_reference_mesh(
        lines in prop::collection::vec(line(), 1..60),
        crlf in prop::collection::vec(any::<bool>(), 60),
        wild in prop::bool::weighted(0.2),
        style in 0u8..4,
    ) {
        let dir = mtl_dir();
        same_as_reference(&text(&lines, &crlf, wild, style), dir.path())?;
    }
}

#[test]
fn most_generated_files_load() {
    // The property above is about meshes, not errors: most of its files must load, many with
    // uvs.
    let dir = mtl_dir();
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let strategy = (
        prop::collection::vec(line(), 1..60),
        prop::collection::vec(any::<bool>(), 60),
        prop::bool::weighted(0.2),
        0u8..4,
    );
    let (mut loaded, mut textured, mut total) = (0, 0, 0);
    for _ in 0..300 {
        let (lines, crlf, wild, style) = strategy.new_tree(&mut runner).expect("case").current();
        total += 1;
        if let Some(m) =
            same_as_reference(&text(&lines, &crlf, wild, style), dir.path()).expect("same")
        {
            loaded += 1;
            textured += usize::from(m.has_uv);
        }
    }
    assert!(loaded * 2 > total, "{loaded} of {total} loaded");
    // With uvs on every face (and so the uv and normal paths taken) in a good share.
    assert!(textured * 5 > total, "{textured} of {total} with uvs");
}

/// The streaming reader's message for `obj`.
fn error(obj: &str) -> String {
    ModelMesh::from_obj(obj.as_bytes(), "bad.obj", Path::new("/nonexistent"))
        .expect_err(obj)
        .to_string()
}

#[test]
fn each_error_names_the_file_the_line_and_the_problem() {
    const TRI: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (obj, needle) in [
        (
            "v 0 0\n",
            "line 1: a `v` (position) line has a missing or bad number",
        ),
        (
            "# c\nv 0 0 zero\n",
            "line 2: a `v` (position) line has a missing or bad number",
        ),
        ("v 0 0 0 x\n", "line 1: a `v` (position) line"),
        ("v 0 0 0 0\n", "line 1: a `v` line has a w of 0"),
        (
            "v 0 0 0 1 1\n",
            "line 1: a `v` line has too many or too few numbers",
        ),
        ("v 0 0 0 1 1 1 1\n", "line 1: a `v` line has too many"),
        (
            "vt 0.5\n",
            "line 1: a `vt` (texture coordinate) line has a bad number",
        ),
        (
            "\n\nvn 0 0 q\n",
            "line 3: a `vn` (normal) line has a bad number",
        ),
        (
            &format!("{TRI}f 1 2 x\n"),
            "line 4: an `f` (face) line is malformed",
        ),
        (
            &format!("{TRI}f 1/1/1/1 2 3\n"),
            "line 4: an `f` (face) line is malformed",
        ),
        (
            &format!("{TRI}f 1 2 99999999999999999999\n"),
            "line 4: an `f` (face) line is malformed",
        ),
        (
            &format!("{TRI}f\n"),
            "line 4: an `f` (face) line has no vertices",
        ),
        (
            &format!("{TRI}f 1 2 3\nf 1 2 9\nf 1 2 3\n"),
            "line 5: a face uses a vertex index beyond the vertices defined (3 defined)",
        ),
        (
            &format!("{TRI}f 1 2 -4\n"),
            "line 4: a face uses a vertex index beyond",
        ),
        (
            &format!("{TRI}f 1 2 0\n"),
            "line 4: a face uses a vertex index beyond",
        ),
        (
            &format!("{TRI}vt 0 0\nf 1/1 2/1 3/2\n"),
            "line 5: a face uses a texture coordinate index beyond those defined (1 defined)",
        ),
        (
            &format!("{TRI}vn 0 0 1\nf 1//1 2//1 3//2\n"),
            "line 5: a face uses a normal index beyond those defined (1 defined)",
        ),
        (
            "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
            "line 4: a face uses a vertex beyond the vertices given a colour",
        ),
        ("usemtl\n", "line 1: a `usemtl` line names no material"),
    ] {
        let e = error(obj);
        assert!(e.contains("bad.obj") && e.contains(needle), "{obj:?}: {e}");
    }
    // Invalid UTF-8 on line 2.
    let e = ModelMesh::from_obj(b"v 0 0 0\nv \xff 0 0\n", "bad.obj", Path::new("/"))
        .expect_err("utf-8")
        .to_string();
    assert!(
        e.contains("not a readable text OBJ file") && e.contains("at line 2"),
        "{e}"
    );
    // No faces, or only points and lines.
    for obj in ["", "v 0 0 0\n", "v 0 0 0\nv 1 0 0\nf 1\nl 1 2\n"] {
        assert!(error(obj).contains("contains no triangles"), "{obj:?}");
    }
}

#[test]
fn errors_found_when_a_model_ends_come_in_the_reference_order() {
    // A face before its vertices is fine while the model lasts (tobj checks indices when it
    // ends); an index still out of range then is named with its face's line.
    let obj = "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    let m = ModelMesh::from_obj(obj.as_bytes(), "f.obj", Path::new("/")).expect("forward");
    assert_eq!(m.triangles, vec![[0, 1, 2]]);
    let obj = "f 1 2 3\nv 0 0 0\nv 1 0 0\no next\nv 0 1 0\n";
    assert!(error(obj).contains("line 1: a face uses a vertex index beyond"));
    // A bad line after the bad index, in the same model: the line's error comes first.
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\nvt x\n";
    assert!(error(obj).contains("line 5: a `vt`"), "{}", error(obj));
    // In the next model: the index's.
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\ng next\nvt x\n";
    assert!(error(obj).contains("line 4: a face uses a vertex index"));
}

#[test]
fn coordinates_are_checked_on_the_vertices_faces_use() {
    // Vertex 1 is never used: its NaN does not matter; vertex 4's does, named by its `v`
    // line's number (the reference names the output vertex instead).
    let obj = "v nan 0 0\nv 0 0 0\nv 1 0 0\nv 0 inf 0\nf 2 3 4\n";
    let e = error(obj);
    assert!(
        e.contains("vertex 4 has a coordinate that is not a finite"),
        "{e}"
    );
    let obj = "v 0 0 0\nv 1 0 0\nv 0 2e6 0\nf 1 2 3\n";
    assert!(error(obj).contains("vertex 3 has a coordinate that is larger than 1e6"));
    let obj = "v nan 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n";
    let m = ModelMesh::from_obj(obj.as_bytes(), "n.obj", Path::new("/")).expect("unused nan");
    assert_eq!(m.positions.len(), 3);
}

#[test]
fn indices_forms_and_line_ends_follow_tobj() {
    let dir = mtl_dir();
    for obj in [
        // Relative indices, quads and pentagons, uvs and normals.
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n\
         f -4/-4/-1 -3/-3/-1 -2/-2/-1 -1/-1/-1\nf 1/1/1 3/3/1 4/4/1 2/2/1 1/2/1\n",
        // CRLF, a BOM, tabs, a trailing `\r` on the last line, an empty fourth field.
        "\u{feff}v 0 0 0\r\nv 1 0 0\r\nv\t0 1 0\r\nf 1// 2/ 3/1/\r",
        // `vt` and `vn` indices in a file without `vt` or `vn` lines mean nothing.
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/7/9 2/7/9 3/7/9\n",
        // Index 0 of a texture coordinate is missing (tobj), so this part has no uvs.
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/0 2/1 3/1\n",
        // w divides, colours are read and unused.
        "v 0 0 0 2\nv 1 0 0 0.5\nv 0 1 0 -1\nf 1 2 3\no x\nv 1 1 1 0.5 0.5 0.5\n",
        // Materials: per model, from libraries loaded before `usemtl`.
        "usemtl red\nmtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nusemtl red\nf 3 2 1\n\
         usemtl tex\nf 1 2 3\nmtllib m2.mtl\nusemtl red\nf 1 3 2\nusemtl gray\nf 2 1 3\n",
        // A failed library beside a good one: no note.
        "mtllib missing.mtl\nmtllib m.mtl\nusemtl tex\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    ] {
        let ours = ModelMesh::from_obj(obj.as_bytes(), "i.obj", dir.path()).expect(obj);
        let reference = from_obj_tobj(obj.as_bytes(), "i.obj", dir.path()).expect(obj);
        assert_eq!(ours, reference, "{obj:?}");
    }
    // Dedup per model: the same corner in two models is two vertices.
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 1\no b\nf 1 2 3\n";
    let m = ModelMesh::from_obj(obj.as_bytes(), "d.obj", dir.path()).expect("dedup");
    assert_eq!(m.triangles, vec![[0, 1, 2], [2, 1, 0], [3, 4, 5]]);
    // Vertices in the order faces first use them, not the `v` lines' order.
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 3 1 2\n";
    let m = ModelMesh::from_obj(obj.as_bytes(), "o.obj", dir.path()).expect("order");
    assert_eq!(m.positions[0], glam::DVec3::Y);
}

#[test]
fn a_model_without_vertices_does_not_take_the_uvs_away() {
    // Deliberately unlike the tobj path before: an `o` line after the last face (or a part of
    // only lines) made an empty model, and with it the whole file lost its uvs and normals.
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\nl 1 2\no end\n";
    let m = ModelMesh::from_obj(obj.as_bytes(), "e.obj", Path::new("/")).expect("loads");
    assert!(m.has_uv && m.notes.is_empty(), "{:?}", m.notes);
    assert_eq!(m.normals, vec![glam::DVec3::Z; 3]);
    let reference = from_obj_tobj(obj.as_bytes(), "e.obj", Path::new("/")).expect("loads");
    assert_eq!(m, reference);
}

#[test]
fn load_reads_files_and_names_them() {
    let dir = mtl_dir();
    let path = dir.path().join("m.obj");
    let obj = "mtllib m.mtl\nusemtl tex\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n";
    std::fs::write(&path, obj).expect("write");
    let m = ModelMesh::load(&path).expect("load");
    assert_eq!(
        m,
        from_obj_tobj(obj.as_bytes(), &path.display().to_string(), dir.path()).expect("ref")
    );
    assert_eq!(m.diffuse_texture, Some(dir.path().join("checker.png")));
    std::fs::write(&path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n").expect("write");
    let e = ModelMesh::load(&path).expect_err("range").to_string();
    assert!(e.contains("m.obj") && e.contains("line 4:"), "{e}");
    std::fs::write(&path, "").expect("write");
    let e = ModelMesh::load(&path).expect_err("empty").to_string();
    assert!(e.contains("m.obj is empty (0 bytes)"), "{e}");
    let e = ModelMesh::load(dir.path()).expect_err("folder").to_string();
    assert!(
        e.contains("cannot read model") && e.contains("a folder"),
        "{e}"
    );
}

/// Vertex normals as the loader computed them before its compact position table: a hash map
/// from each position's bits to the sum of the face normals around it, in triangle order.
fn normals_by_hash_map(positions: &[glam::DVec3], triangles: &[[u32; 3]]) -> Vec<glam::DVec3> {
    use std::collections::HashMap;
    let key = |p: &glam::DVec3| p.to_array().map(f64::to_bits);
    let mut sums: HashMap<[u64; 3], glam::DVec3> = HashMap::new();
    for t in triangles {
        let [a, b, c] = t.map(|i| positions[i as usize]);
        let face = (b - a).cross(c - a);
        if face.is_finite() {
            for &i in t {
                *sums.entry(key(&positions[i as usize])).or_default() += face;
            }
        }
    }
    positions
        .iter()
        .map(|p| {
            sums.get(&key(p))
                .copied()
                .unwrap_or_default()
                .normalize_or_zero()
        })
        .collect()
}

proptest! {
    #[test]
    fn vertex_normals_share_sums_at_equal_positions(
        picks in prop::collection::vec(0usize..12, 3..40),
        triangles in prop::collection::vec(any::<[u16; 3]>(), 1..40),
    ) {
        // Few distinct positions (-0 beside 0 is a different one), so many vertices share one.
        let corners: Vec<glam::DVec3> = (0..12)
            .map(|k| {
                let k = k as f64;
                glam::DVec3::new(k.sin(), (k * 0.7).cos(), if k == 3.0 { -0.0 } else { k * 0.1 })
            })
            .collect();
        let positions: Vec<glam::DVec3> = picks.iter().map(|&k| corners[k]).collect();
        let n = positions.len();
        let triangles: Vec<[u32; 3]> = triangles
            .iter()
            .map(|t| t.map(|i| (usize::from(i) % n) as u32))
            .collect();
        let ours = barylab::model::vertex_normals(&positions, &triangles);
        prop_assert_eq!(ours, normals_by_hash_map(&positions, &triangles));
    }
}
