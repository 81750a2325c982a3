//! The GLSL of barylab's GL draws: one vertex shader passing uv and colour on (`QUALIFIER`
//! becomes `smooth` or `noperspective`, the interpolation mode compared), and one fragment
//! shader whose `OUTPUT` picks what it writes: the texture's colour, the vertex colour, the
//! primitive's id + 1 (which triangle owns a pixel), or the interpolated uv with
//! `gl_FragCoord`'s z and w (the values compared as floats).

pub(super) const VERTEX_SHADER: &str = "#version 330 core
layout(location = 0) in vec4 clip_position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec3 color;
QUALIFIER out vec2 v_uv;
QUALIFIER out vec3 v_color;
void main() {
    v_uv = uv;
    v_color = color;
    gl_Position = clip_position;
}
";

pub(super) const FRAGMENT_SHADER: &str = "#version 330 core
QUALIFIER in vec2 v_uv;
QUALIFIER in vec3 v_color;
uniform sampler2D tex;
out vec4 out_color;
void main() {
#if OUTPUT == 0
    out_color = texture(tex, v_uv);
#elif OUTPUT == 1
    out_color = vec4(v_color, 1.0);
#elif OUTPUT == 2
    uint id = uint(gl_PrimitiveID + 1);
    out_color = vec4(float(id & 255u), float((id >> 8) & 255u), float((id >> 16) & 255u),
                     float((id >> 24) & 255u)) / 255.0;
#else
    out_color = vec4(v_uv, gl_FragCoord.z, gl_FragCoord.w);
#endif
}
";
