//! A short fuzz run of the scene-JSON and OBJ parsers: arbitrary bytes, and valid files with
//! bytes changed, give a scene or an error, never a panic. The case count is bounded so the
//! run takes seconds.

use std::path::Path;

use barylab::model::ModelMesh;
use barylab::scene::Scene;
use proptest::prelude::*;

/// Cases per property: enough to reach the parsers' error paths, quick in CI.
const CASES: u32 = 256;

const CLIP_SCENE: &str = r#"{"width":8,"height":8,"vertices":[{"clip":[0,0,0,1],"uv":[0,0]},{"clip":[1,0,0.5,2]},{"clip":[0,1,0,1],"color":[1,0,0]}],"triangles":[[0,1,2]],"mode":"affine","wrap":"clamp_to_edge"}"#;

const OBJ: &str = "mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 2/2 4/1 3/3\nf 1 2 3 4\n";

/// `text` with `edits` applied: each replaces the byte at a position (modulo the length).
fn mutate(text: &str, edits: &[(usize, u8)]) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    for &(at, b) in edits {
        let i = at % bytes.len();
        bytes[i] = b;
    }
    bytes
}

fn parse_scene(bytes: &[u8]) {
    let text = String::from_utf8_lossy(bytes);
    if let Ok(scene) = Scene::from_json(&text, "fuzz.json") {
        // A scene that parses also makes a mesh, settings and JSON again.
        let _ = scene.to_mesh();
        let _ = scene.settings();
        let _ = scene.to_json();
    }
}

fn parse_obj(bytes: &[u8]) {
    let _ = ModelMesh::from_obj(bytes, "fuzz.obj", Path::new("/nonexistent"));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: CASES, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes_never_panic_the_scene_parser(bytes in proptest::collection::vec(any::<u8>(), 0..512)) {
        parse_scene(&bytes);
    }

    #[test]
    fn a_scene_with_bytes_changed_never_panics_the_parser(
        edits in proptest::collection::vec((any::<usize>(), any::<u8>()), 1..6)
    ) {
        parse_scene(&mutate(CLIP_SCENE, &edits));
    }

    #[test]
    fn arbitrary_bytes_never_panic_the_obj_parser(bytes in proptest::collection::vec(any::<u8>(), 0..512)) {
        parse_obj(&bytes);
    }

    #[test]
    fn an_obj_with_bytes_changed_never_panics_the_parser(
        edits in proptest::collection::vec((any::<usize>(), any::<u8>()), 1..6)
    ) {
        parse_obj(&mutate(OBJ, &edits));
    }
}

#[test]
fn the_starting_files_of_the_fuzz_run_are_valid() {
    assert!(Scene::from_json(CLIP_SCENE, "clip.json").is_ok());
    let m =
        ModelMesh::from_obj(OBJ.as_bytes(), "quad.obj", Path::new("/nonexistent")).expect("obj");
    assert_eq!(m.triangles.len(), 4);
}
