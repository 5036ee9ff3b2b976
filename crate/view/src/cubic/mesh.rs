//! Geometry of the cubic renderer: the meshes it instances (cube, sphere, cone), wire boxes and
//! the rotation that points the light's arrow.

use crate::camera::{normalize, V3};
use crate::gl::push_f32s;

/// Floats per mesh vertex: position and normal.
pub(super) const VERTEX: usize = 6;
/// The rotation that leaves a mesh as it is.
pub(super) const IDENTITY: [f32; 9] = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];

/// The centre of cell (x, y, z).
pub(super) fn centre(c: [u32; 3]) -> V3 {
    c.map(|v| f64::from(v) + 0.5)
}

pub(super) fn f32s(v: V3) -> [f32; 3] {
    v.map(|x| x as f32)
}

/// Appends the 12 edges (24 vertices) of a box `grow` from the centre of cell `c` each way.
pub(super) fn box_edges(c: [u32; 3], grow: f64, out: &mut Vec<u8>) {
    let mid = centre(c);
    let lo = mid.map(|v| v - grow);
    let hi = mid.map(|v| v + grow);
    let corner = |bits: [bool; 3]| {
        std::array::from_fn::<f32, 3, _>(|a| (if bits[a] { hi[a] } else { lo[a] }) as f32)
    };
    for a in 0..3 {
        let others: Vec<usize> = (0..3).filter(|&x| x != a).collect();
        for s in 0..4 {
            let mut from = [false; 3];
            from[others[0]] = s & 1 == 1;
            from[others[1]] = (s >> 1) & 1 == 1;
            let mut to = from;
            to[a] = true;
            push_f32s(out, corner(from).into_iter().chain(corner(to)));
        }
    }
}

/// Column-major rotation taking +z to the unit vector `d`.
pub(super) fn rotation_to(d: V3) -> [f32; 9] {
    let c = d[2];
    if c > 0.9999 {
        return IDENTITY;
    }
    if c < -0.9999 {
        return [1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0];
    }
    // Axis z × d, angle acos(c): Rodrigues' formula.
    let [x, y, z] = normalize([-d[1], d[0], 0.0]);
    let s = (1.0 - c * c).sqrt();
    let t = 1.0 - c;
    [
        t * x * x + c,
        t * x * y + s * z,
        t * x * z - s * y,
        t * x * y - s * z,
        t * y * y + c,
        t * y * z + s * x,
        t * x * z + s * y,
        t * y * z - s * x,
        t * z * z + c,
    ]
    .map(|v| v as f32)
}

/// 36 vertices of a unit cube centred on the origin, counter-clockwise outside: position, normal.
pub(super) fn cube_mesh() -> Vec<f32> {
    let faces: [[V3; 3]; 6] = [
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        [[-1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
        [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]],
        [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
        [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
    ];
    let mut out = Vec::with_capacity(36 * VERTEX);
    for [n, u, v] in faces {
        let corner = |su: f64, sv: f64| -> V3 {
            std::array::from_fn(|a| n[a] * 0.5 + u[a] * su * 0.5 + v[a] * sv * 0.5)
        };
        for p in [
            corner(-1.0, -1.0),
            corner(1.0, -1.0),
            corner(1.0, 1.0),
            corner(-1.0, -1.0),
            corner(1.0, 1.0),
            corner(-1.0, 1.0),
        ] {
            out.extend(p.into_iter().chain(n).map(|x| x as f32));
        }
    }
    out
}

/// A sphere of diameter 1: position, normal.
pub(super) fn sphere_mesh(segments: u32, rings: u32) -> Vec<f32> {
    let at = |i: u32, j: u32| {
        let th = f64::from(i) / f64::from(segments) * std::f64::consts::PI * 2.0;
        let ph = f64::from(j) / f64::from(rings) * std::f64::consts::PI;
        let n = [ph.sin() * th.cos(), ph.sin() * th.sin(), ph.cos()];
        [n[0] * 0.5, n[1] * 0.5, n[2] * 0.5, n[0], n[1], n[2]]
    };
    let mut out = Vec::with_capacity((segments * rings * 6) as usize * VERTEX);
    for j in 0..rings {
        for i in 0..segments {
            let (a, b, c, d) = (at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
            for v in [a, b, c, a, c, d] {
                out.extend(v.map(|x| x as f32));
            }
        }
    }
    out
}

/// A cone along +z (base at z = -0.5, apex at +0.5), diameter 1: position, normal.
pub(super) fn cone_mesh(segments: u32) -> Vec<f32> {
    let slope = 0.5;
    let rim = |a: f64| [a.cos() * 0.5, a.sin() * 0.5, -0.5];
    let side = |a: f64| normalize([a.cos(), a.sin(), slope]);
    let down = [0.0, 0.0, -1.0];
    let mut out = Vec::with_capacity(segments as usize * 6 * VERTEX);
    for i in 0..segments {
        let a0 = f64::from(i) / f64::from(segments) * std::f64::consts::PI * 2.0;
        let a1 = f64::from(i + 1) / f64::from(segments) * std::f64::consts::PI * 2.0;
        let am = (a0 + a1) / 2.0;
        for (p, n) in [
            (rim(a0), side(a0)),
            (rim(a1), side(a1)),
            ([0.0, 0.0, 0.5], side(am)),
            (rim(a1), down),
            (rim(a0), down),
            ([0.0, 0.0, -0.5], down),
        ] {
            out.extend(p.into_iter().chain(n).map(|x| x as f32));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::{cross, dot, sub};

    fn vertices(mesh: &[f32]) -> Vec<(V3, V3)> {
        mesh.chunks(VERTEX)
            .map(|v| {
                let v = v.iter().map(|&x| f64::from(x)).collect::<Vec<_>>();
                ([v[0], v[1], v[2]], [v[3], v[4], v[5]])
            })
            .collect()
    }

    #[test]
    fn every_mesh_triangle_winds_counter_clockwise_seen_from_outside() {
        for (name, mesh) in [
            ("cube", cube_mesh()),
            ("sphere", sphere_mesh(14, 10)),
            ("cone", cone_mesh(18)),
        ] {
            let v = vertices(&mesh);
            assert_eq!(v.len() % 3, 0, "{name}");
            for t in v.chunks(3) {
                let face = cross(sub(t[1].0, t[0].0), sub(t[2].0, t[0].0));
                // Degenerate triangles at the sphere's poles have no winding.
                if dot(face, face) < 1e-12 {
                    continue;
                }
                let normal = [0, 1, 2].map(|a| t[0].1[a] + t[1].1[a] + t[2].1[a]);
                assert!(dot(face, normal) > 0.0, "{name}: {t:?}");
            }
        }
        assert_eq!(cube_mesh().len(), 36 * VERTEX);
    }

    #[test]
    fn the_arrow_rotation_takes_z_to_the_direction() {
        for d in [
            normalize([1.0, -2.0, 0.5]),
            [0.0, 0.0, -1.0],
            [0.0, 0.0, 1.0],
            normalize([0.0, 1.0, -3.0]),
        ] {
            let r = rotation_to(d);
            // Column-major: the image of +z is the third column.
            let z = [r[6], r[7], r[8]].map(f64::from);
            assert!(sub(z, d).iter().all(|e| e.abs() < 1e-6), "{d:?} -> {z:?}");
        }
    }

    #[test]
    fn a_box_has_twelve_edges_of_its_full_width() {
        let mut out = Vec::new();
        box_edges([2, 3, 4], 0.5, &mut out);
        let f: Vec<f32> = out
            .chunks(4)
            .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
            .collect();
        assert_eq!(f.len(), 12 * 2 * 3);
        for e in f.chunks(6) {
            let d: Vec<f32> = (0..3).map(|a| (e[a + 3] - e[a]).abs()).collect();
            assert_eq!(d.iter().filter(|&&x| x == 1.0).count(), 1, "{e:?}");
            assert_eq!(d.iter().filter(|&&x| x == 0.0).count(), 2, "{e:?}");
        }
        assert!(f.iter().step_by(3).all(|&x| x == 2.0 || x == 3.0));
    }
}
