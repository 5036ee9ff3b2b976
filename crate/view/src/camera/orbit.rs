//! The orbit camera of the cubic lattice: turned, panned and dollied about a target, with the
//! matrices WebGL needs, projection for Canvas 2D and annotations, and picking by ray.

use super::vector::{cross, dot, multiply, norm, normalize, sub, Mat4, V3};

/// A 3-D pick: the occupied cell hit, and the empty cell in front of the face hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, schemars::JsonSchema)]
pub struct Hit {
    pub cell: u32,
    /// The empty cell in front of the hit face, or -1 when that is off the lattice.
    pub front: i64,
}

/// The orbit camera: it looks at `target` from `distance` away, turned by `yaw` about the
/// vertical (z) axis and raised by `pitch`.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera3D {
    pub target: V3,
    pub yaw: f64,
    pub pitch: f64,
    pub distance: f64,
    pub fov: f64,
    pub width: f64,
    pub height: f64,
}

pub(super) const YAW: f64 = std::f64::consts::FRAC_PI_4;
const PITCH: f64 = 0.6;

impl Default for Camera3D {
    fn default() -> Self {
        Camera3D {
            target: [0.0; 3],
            yaw: YAW,
            pitch: PITCH,
            distance: 20.0,
            fov: std::f64::consts::FRAC_PI_4,
            width: 1.0,
            height: 1.0,
        }
    }
}

/// The eye and the camera's forward, right and up directions.
struct Basis {
    eye: V3,
    f: V3,
    right: V3,
    up: V3,
}

impl Camera3D {
    /// Frames the whole lattice.
    pub fn fit(&mut self, dims: [u32; 3]) {
        let [w, h, d] = dims.map(f64::from);
        self.target = [w / 2.0, h / 2.0, d / 3.0];
        let radius = (w * w + h * h + d * d).sqrt() / 2.0;
        self.distance = radius / (self.fov / 2.0).sin() * 0.9;
    }

    /// Looks at the centre of a world box from the current direction, close enough to fill the
    /// view.
    pub fn fit_box(&mut self, min: V3, max: V3, margin: f64) {
        self.target = std::array::from_fn(|a| (min[a] + max[a]) / 2.0);
        let diag = std::array::from_fn::<f64, 3, _>(|a| max[a] - min[a]);
        let radius = (norm(diag) / 2.0).max(0.75);
        let aspect = self.width / self.height.max(1.0);
        let half = (self.fov / 2.0).min(((self.fov / 2.0).tan() * aspect).atan());
        self.distance = (radius / half.sin() * margin).clamp(1.5, 2000.0);
    }

    /// Back to the default viewing direction.
    pub fn reset_orientation(&mut self) {
        self.yaw = YAW;
        self.pitch = PITCH;
    }

    pub fn eye(&self) -> V3 {
        let cp = self.pitch.cos();
        [
            self.target[0] + self.distance * cp * self.yaw.cos(),
            self.target[1] + self.distance * cp * self.yaw.sin(),
            self.target[2] + self.distance * self.pitch.sin(),
        ]
    }

    pub fn orbit(&mut self, dx: f64, dy: f64) {
        self.yaw -= dx * 0.008;
        self.pitch = (self.pitch + dy * 0.008).clamp(-1.5, 1.5);
    }

    pub fn pan(&mut self, dx: f64, dy: f64) {
        let b = self.basis();
        let k = self.distance * (self.fov / 2.0).tan() * 2.0 / self.height;
        for i in 0..3 {
            self.target[i] += (-dx * b.right[i] + dy * b.up[i]) * k;
        }
    }

    /// Moves toward the target (factor above 1) or away: a dolly, so no screen point is kept.
    pub fn zoom(&mut self, factor: f64) {
        self.distance = (self.distance / factor).clamp(1.5, 2000.0);
    }

    fn basis(&self) -> Basis {
        let eye = self.eye();
        let f = normalize(sub(self.target, eye));
        let right = normalize(cross(f, [0.0, 0.0, 1.0]));
        let up = cross(right, f);
        Basis { eye, f, right, up }
    }

    /// The unit vector from the target toward the eye.
    pub fn toward_eye(&self) -> V3 {
        let f = self.basis().f;
        [-f[0], -f[1], -f[2]]
    }

    /// Screen position (CSS pixels) and eye distance of a world point, or `None` behind the eye.
    pub fn project(&self, p: V3) -> Option<[f64; 3]> {
        let b = self.basis();
        let d = sub(p, b.eye);
        let depth = dot(d, b.f);
        if depth <= 1e-6 {
            return None;
        }
        let t = (self.fov / 2.0).tan();
        let aspect = self.width / self.height.max(1.0);
        let nx = dot(d, b.right) / (depth * t * aspect);
        let ny = dot(d, b.up) / (depth * t);
        Some([
            (nx + 1.0) / 2.0 * self.width,
            (1.0 - ny) / 2.0 * self.height,
            depth,
        ])
    }

    /// The world-to-eye transform.
    pub fn view(&self) -> Mat4 {
        let Basis { eye, f, right, up } = self.basis();
        let mut m = [0f32; 16];
        for a in 0..3 {
            m[4 * a] = right[a] as f32;
            m[4 * a + 1] = up[a] as f32;
            m[4 * a + 2] = -f[a] as f32;
        }
        m[12] = -dot(right, eye) as f32;
        m[13] = -dot(up, eye) as f32;
        m[14] = dot(f, eye) as f32;
        m[15] = 1.0;
        m
    }

    /// The perspective projection; near and far follow the distance.
    pub fn projection(&self) -> Mat4 {
        let near = (self.distance / 200.0).max(0.05);
        let far = self.distance * 20.0 + 100.0;
        let t = 1.0 / (self.fov / 2.0).tan();
        let aspect = self.width / self.height.max(1.0);
        let mut m = [0f32; 16];
        m[0] = (t / aspect) as f32;
        m[5] = t as f32;
        m[10] = ((far + near) / (near - far)) as f32;
        m[11] = -1.0;
        m[14] = (2.0 * far * near / (near - far)) as f32;
        m
    }

    /// Projection times view.
    pub fn view_projection(&self) -> Mat4 {
        multiply(&self.projection(), &self.view())
    }

    /// The ray through a screen point: the eye and a unit direction.
    pub fn ray(&self, sx: f64, sy: f64) -> (V3, V3) {
        let b = self.basis();
        let t = (self.fov / 2.0).tan();
        let aspect = self.width / self.height.max(1.0);
        let nx = (2.0 * sx / self.width - 1.0) * t * aspect;
        let ny = (1.0 - 2.0 * sy / self.height) * t;
        let dir = normalize(std::array::from_fn(|a| {
            b.f[a] + nx * b.right[a] + ny * b.up[a]
        }));
        (b.eye, dir)
    }

    /// Where the ray through a screen point meets the horizontal plane at height z.
    pub fn hit_plane_z(&self, sx: f64, sy: f64, z: f64) -> Option<[f64; 2]> {
        let (o, d) = self.ray(sx, sy);
        if d[2].abs() < 1e-9 {
            return None;
        }
        let t = (z - o[2]) / d[2];
        (t > 0.0).then(|| [o[0] + d[0] * t, o[1] + d[1] * t])
    }

    /// The first occupied cell along the ray through (sx, sy), walking the voxel grid.
    pub fn pick(
        &self,
        dims: [u32; 3],
        occupied: impl Fn(usize) -> bool,
        sx: f64,
        sy: f64,
    ) -> Option<Hit> {
        let (origin, dir) = self.ray(sx, sy);
        let size = dims.map(f64::from);
        let (mut tmin, mut tmax) = (0.0f64, f64::INFINITY);
        for a in 0..3 {
            if dir[a].abs() < 1e-12 {
                if origin[a] < 0.0 || origin[a] > size[a] {
                    return None;
                }
            } else {
                let t0 = (0.0 - origin[a]) / dir[a];
                let t1 = (size[a] - origin[a]) / dir[a];
                tmin = tmin.max(t0.min(t1));
                tmax = tmax.min(t0.max(t1));
            }
        }
        if tmin > tmax {
            return None;
        }
        let p: V3 = std::array::from_fn(|a| origin[a] + dir[a] * (tmin + 1e-6));
        let mut cell: [i64; 3] =
            std::array::from_fn(|a| (p[a].floor() as i64).clamp(0, i64::from(dims[a]) - 1));
        let step: [i64; 3] = std::array::from_fn(|a| if dir[a] > 0.0 { 1 } else { -1 });
        let mut t_max: V3 = std::array::from_fn(|a| {
            let next = if dir[a] > 0.0 { cell[a] + 1 } else { cell[a] } as f64;
            if dir[a].abs() < 1e-12 {
                f64::INFINITY
            } else {
                tmin + (next - p[a]) / dir[a]
            }
        });
        let t_delta: V3 = std::array::from_fn(|a| {
            if dir[a].abs() < 1e-12 {
                f64::INFINITY
            } else {
                (1.0 / dir[a]).abs()
            }
        });
        let [w, h, d] = dims.map(i64::from);
        let mut prev = -1i64;
        for _ in 0..w + h + d + 3 {
            if cell.iter().zip([w, h, d]).any(|(&c, n)| c < 0 || c >= n) {
                break;
            }
            let i = (cell[2] * h + cell[1]) * w + cell[0];
            if occupied(i as usize) {
                return Some(Hit {
                    cell: i as u32,
                    front: prev,
                });
            }
            prev = i;
            let a = if t_max[0] < t_max[1] {
                if t_max[0] < t_max[2] {
                    0
                } else {
                    2
                }
            } else if t_max[1] < t_max[2] {
                1
            } else {
                2
            };
            cell[a] += step[a];
            t_max[a] += t_delta[a];
        }
        None
    }
}
