//! JSON parse errors in words: the position, the field, and serde's message made readable
//! (no Rust type names, an array that is too long said as such). Scenes and lessons use it.

use super::SceneError;

/// Strips serde_json's " at line L column C" suffix (we print the position in front) and
/// says "a JSON object" where serde names a Rust type ("expected struct Camera").
fn bare_message(e: &serde_json::Error) -> String {
    let s = e.to_string();
    let mut s = match s.rfind(" at line ") {
        Some(i) => s[..i].to_string(),
        None => s,
    };
    for kind in ["struct ", "internally tagged enum ", "enum "] {
        let marker = format!("expected {kind}");
        if let Some(i) = s.find(&marker) {
            let name_start = i + marker.len();
            let name_end = s[name_start..]
                .find(|c: char| !c.is_alphanumeric() && c != '_')
                .map_or(s.len(), |k| name_start + k);
            s.replace_range(i..name_end, "expected a JSON object");
            break;
        }
    }
    for int in ["u8", "u16", "u32", "u64"] {
        s = s.replace(&format!("expected {int}"), "expected a whole number");
    }
    s
}

/// How many values the array at JSON path `field` holds, for "trailing characters" (serde's
/// word for an array that is too long).
fn too_long(field: &str) -> String {
    let last = field.rsplit('.').next().unwrap_or(field);
    let name = last.split('[').next().unwrap_or(last);
    let expected = match name {
        "triangles" => "a triangle has exactly 3 vertex indices",
        "clip" => "`clip` has exactly 4 numbers (x, y, z, w)",
        "uv" => "`uv` has exactly 2 numbers",
        "color" => "`color` has exactly 3 numbers (r, g, b)",
        "background" => "`background` has exactly 4 numbers (r, g, b, a)",
        "position" | "eye" | "target" | "up" => "a point has exactly 3 numbers (x, y, z)",
        "quad" => "`quad` has exactly 4 corners",
        _ => "this array has more values than it may",
    };
    format!("too many values: {expected}")
}

pub(crate) fn parse_error(path: &str, e: serde_json::Error, field: String) -> SceneError {
    let mut message = bare_message(&e);
    if message == "trailing characters" && !field.is_empty() && field != "." {
        message = too_long(&field);
    }
    SceneError::Parse {
        path: path.to_string(),
        line: e.line(),
        column: e.column(),
        field: if field.is_empty() || field == "." {
            String::new()
        } else {
            format!("field `{field}`: ")
        },
        message,
    }
}

pub(crate) fn strict<T: serde::de::DeserializeOwned>(
    text: &str,
    path: &str,
) -> Result<T, SceneError> {
    let de = &mut serde_json::Deserializer::from_str(text);
    let value: T = serde_path_to_error::deserialize(de).map_err(|e| {
        let field = e.path().to_string();
        parse_error(path, e.into_inner(), field)
    })?;
    Ok(value)
}
