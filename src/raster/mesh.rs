//! The input of the rasterizer: triangles over clip-space vertices ([`ClipMesh`]), and their
//! subdivision for dense-mesh benchmarks ([`ClipMesh::subdivided`]).

use glam::{DVec4, Vec2, Vec3};

/// One vertex of a mesh, already in clip space.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct MeshVertex {
    /// Clip-space position `(x, y, z, w)`.
    pub clip: DVec4,
    /// Texture coordinate (v = 0 is the texture's bottom row).
    pub uv: Vec2,
    /// Vertex colour, RGB in [0, 1].
    pub color: Vec3,
    /// Unit normal in view space (x right, y up, z towards the viewer), for normal and
    /// Lambert shading; zero when the scene has none (clip-space scenes), read as facing
    /// the viewer.
    pub normal: Vec3,
}

/// Triangles over clip-space vertices: what the rasterizer draws.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ClipMesh {
    /// The vertices, shared by the triangles that index them.
    pub vertices: Vec<MeshVertex>,
    /// The source triangles: index triples into `vertices`, drawn in this order (with the
    /// less-than depth test, the earlier of two equal depths stays).
    pub triangles: Vec<[u32; 3]>,
}

impl ClipMesh {
    /// Every triangle split into `n x n` triangles on its barycentric grid: the grid point
    /// `(i, j, k)`, `i + j + k = n`, is `(i A + j B + k C) / n` in clip space, with its uv and
    /// colour interpolated the same way. Clip-space interpolation is what perspective-correct
    /// interpolation reproduces, so the subdivided mesh draws the same surface with the same
    /// values (up to rounding). Points on an edge two triangles share are computed bit for bit
    /// alike (the third weight is 0), so no crack opens. `n <= 1` returns a copy.
    ///
    /// ```
    /// use barylab::raster::render::{ClipMesh, MeshVertex};
    /// use glam::{DVec4, Vec2, Vec3};
    /// let v = |x: f64, y: f64| MeshVertex { clip: DVec4::new(x, y, 0.0, 1.0), uv: Vec2::ZERO, color: Vec3::ONE, ..Default::default() };
    /// let m = ClipMesh { vertices: vec![v(0.0, 0.0), v(1.0, 0.0), v(0.0, 1.0)], triangles: vec![[0, 1, 2]] };
    /// let s = m.subdivided(3);
    /// assert_eq!(s.triangles.len(), 9);
    /// assert_eq!(s.vertices.len(), 10); // (n + 1)(n + 2) / 2
    /// ```
    pub fn subdivided(&self, n: u32) -> ClipMesh {
        if n <= 1 {
            return self.clone();
        }
        let per_tri = ((n + 1) * (n + 2) / 2) as usize;
        let mut out = ClipMesh {
            vertices: Vec::with_capacity(self.triangles.len() * per_tri),
            triangles: Vec::with_capacity(self.triangles.len() * (n * n) as usize),
        };
        let nf = f64::from(n);
        for tri in &self.triangles {
            let Some(v) = tri
                .iter()
                .map(|&i| self.vertices.get(i as usize).copied())
                .collect::<Option<Vec<_>>>()
            else {
                // Kept as triangles with out-of-range indices (drawn as `BadIndex`), so the
                // triangle numbers of the rest stay `source * n² + local`.
                out.triangles
                    .extend(std::iter::repeat_n([u32::MAX; 3], (n * n) as usize));
                continue;
            };
            let base = out.vertices.len() as u32;
            for i in 0..=n {
                for j in 0..=(n - i) {
                    let w = [
                        f64::from(n - i - j) / nf,
                        f64::from(i) / nf,
                        f64::from(j) / nf,
                    ];
                    let mix3 = |f: &dyn Fn(&MeshVertex) -> DVec4| {
                        f(&v[0]) * w[0] + f(&v[1]) * w[1] + f(&v[2]) * w[2]
                    };
                    let clip = mix3(&|m| m.clip);
                    let uv = mix3(&|m| m.uv.as_dvec2().extend(0.0).extend(0.0));
                    let color = mix3(&|m| m.color.as_dvec3().extend(0.0));
                    let normal = mix3(&|m| m.normal.as_dvec3().extend(0.0));
                    out.vertices.push(MeshVertex {
                        clip,
                        uv: uv.truncate().truncate().as_vec2(),
                        color: color.truncate().as_vec3(),
                        normal: normal.truncate().as_vec3(),
                    });
                }
            }
            out.triangles
                .extend((0..n * n).map(|local| subdivided_triangle(n, base, local)));
        }
        out
    }
}

/// Triangle `local` (0..n²) of one source triangle split by [`ClipMesh::subdivided`], whose
/// grid vertices start at index `base`: the grid's row `i` (B's weight `i/n`) has
/// `2 (n - i) - 1` triangles, alternately `(i, j), (i + 1, j), (i, j + 1)` and
/// `(i + 1, j), (i + 1, j + 1), (i, j + 1)`, where grid point `(i, j)` (C's weight `j/n`) is
/// vertex `base + i (n + 1) - i (i - 1) / 2 + j`.
///
/// ```
/// use barylab::raster::render::subdivided_triangle;
/// // n = 2: row 0 holds three triangles, row 1 one; grid points 0 1 2 / 3 4 / 5.
/// assert_eq!(subdivided_triangle(2, 0, 0), [0, 3, 1]);
/// assert_eq!(subdivided_triangle(2, 0, 1), [3, 4, 1]);
/// assert_eq!(subdivided_triangle(2, 0, 2), [1, 4, 2]);
/// assert_eq!(subdivided_triangle(2, 0, 3), [3, 5, 4]);
/// ```
pub fn subdivided_triangle(n: u32, base: u32, local: u32) -> [u32; 3] {
    let index = |i: u32, j: u32| base + i * (n + 1) - i * i.saturating_sub(1) / 2 + j;
    let (mut i, mut rest) = (0, local);
    while i + 1 < n && rest >= 2 * (n - i) - 1 {
        rest -= 2 * (n - i) - 1;
        i += 1;
    }
    let j = rest / 2;
    if rest % 2 == 0 {
        [index(i, j), index(i + 1, j), index(i, j + 1)]
    } else {
        [index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)]
    }
}
