//! A framebuffer the OpenGL refuses, in words: `glCheckFramebufferStatus`'s code named and
//! explained, with the sizes the OpenGL allows and what to do (instead of "status 0x8cd6").

/// Why a `width` x `height` framebuffer with a colour buffer of `format` (`"RGBA8"`,
/// `"RGBA32F"`, `bytes_per_pixel` bytes a pixel) and a 32-bit depth buffer is incomplete,
/// for `status` (the GL code); `max_size` is the OpenGL's `GL_MAX_RENDERBUFFER_SIZE` (0
/// when unknown) and `gl_error` the first `glGetError` after the buffers were made (0: none).
///
/// ```
/// # use barylab::gpu::status::incomplete;
/// let m = incomplete(0x8cd6, 20000, 100, "RGBA8", 4, 16384, 0);
/// assert!(m.starts_with("the OpenGL cannot make a 20000x100 buffer: its largest is 16384"));
/// ```
pub fn incomplete(
    status: u32,
    width: u32,
    height: u32,
    format: &str,
    bytes_per_pixel: u64,
    max_size: u32,
    gl_error: u32,
) -> String {
    let name = status_name(status);
    if max_size > 0 && width.max(height) > max_size {
        return format!(
            "the OpenGL cannot make a {width}x{height} buffer: its largest is {max_size} pixels \
             a side (GL_MAX_RENDERBUFFER_SIZE; {name}); use --size up to {max_size}x{max_size}"
        );
    }
    let need = crate::files::bytes(u64::from(width) * u64::from(height) * bytes_per_pixel);
    let half = format!("{}x{}", (width / 2).max(1), (height / 2).max(1));
    match status {
        // GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT, GL_FRAMEBUFFER_UNDEFINED, or 0 (the check
        // itself failed): a buffer could not be made.
        0x8cd6 | 0x8219 | 0 => {
            let why = if gl_error == 0x0505 {
                "the GPU is out of memory (GL_OUT_OF_MEMORY)".to_string()
            } else {
                format!(
                    "the GPU cannot make a buffer that large, although {} pixels a side is \
                     within its limit",
                    max_size.max(width.max(height))
                )
            };
            format!(
                "the OpenGL could not make the {width}x{height} {format} buffer ({need}; {name}): \
                 {why}; use a smaller size, e.g. --size {half}"
            )
        }
        // GL_FRAMEBUFFER_UNSUPPORTED
        0x8cdd => format!(
            "this OpenGL cannot draw into a {format} colour buffer with a 32-bit float depth \
             buffer ({name}); it cannot be compared with barylab"
        ),
        _ => format!(
            "the OpenGL could not make the {width}x{height} {format} framebuffer ({name}); \
             use a smaller size, e.g. --size {half}"
        ),
    }
}

/// The GL name of a framebuffer status code, or its number when unknown.
pub fn status_name(status: u32) -> String {
    let name = match status {
        0x8cd5 => "GL_FRAMEBUFFER_COMPLETE",
        0x8219 => "GL_FRAMEBUFFER_UNDEFINED",
        0x8cd6 => "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT",
        0x8cd7 => "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT",
        0x8cdb => "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER",
        0x8cdc => "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER",
        0x8cdd => "GL_FRAMEBUFFER_UNSUPPORTED",
        0x8d56 => "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE",
        0x8da8 => "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS",
        0 => "the status check itself failed",
        _ => return format!("framebuffer status {status:#x}"),
    };
    name.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statuses_are_words_with_what_to_do() {
        assert_eq!(
            incomplete(0x8cd6, 16384, 16384, "RGBA32F", 16, 16384, 0x0505),
            "the OpenGL could not make the 16384x16384 RGBA32F buffer (4.0 GiB; \
             GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT): the GPU is out of memory \
             (GL_OUT_OF_MEMORY); use a smaller size, e.g. --size 8192x8192"
        );
        assert_eq!(
            incomplete(0x8cd6, 16384, 100, "RGBA8", 4, 8192, 0),
            "the OpenGL cannot make a 16384x100 buffer: its largest is 8192 pixels a side \
             (GL_MAX_RENDERBUFFER_SIZE; GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT); use --size up \
             to 8192x8192"
        );
        let m = incomplete(0x8cd6, 16384, 16384, "RGBA32F", 16, 16384, 0);
        assert!(m.contains("the GPU cannot make a buffer that large"), "{m}");
        assert!(!m.contains("0x"), "{m}");
        assert!(
            incomplete(0x8cdd, 8, 8, "RGBA32F", 16, 0, 0).contains("GL_FRAMEBUFFER_UNSUPPORTED")
        );
        assert_eq!(status_name(0x1234), "framebuffer status 0x1234");
    }
}
