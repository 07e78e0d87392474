//! Vectors, rays, spheres (optionally moving), parallelograms and the sampling maps the path
//! tracer needs (concentric disk, cosine-weighted hemisphere).

use core::ops::{Add, Mul, Neg, Sub};

/// A 3-vector of `f32` (points, directions and RGB alike).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct V3(pub [f32; 3]);

impl V3 {
    /// `(x, y, z)`.
    pub const fn new(x: f32, y: f32, z: f32) -> V3 {
        V3([x, y, z])
    }
    /// Dot product.
    pub fn dot(self, o: V3) -> f32 {
        self.0[0] * o.0[0] + self.0[1] * o.0[1] + self.0[2] * o.0[2]
    }
    /// Cross product.
    pub fn cross(self, o: V3) -> V3 {
        let [a, b, c] = self.0;
        let [x, y, z] = o.0;
        V3([b * z - c * y, c * x - a * z, a * y - b * x])
    }
    /// Euclidean length.
    pub fn length(self) -> f32 {
        self.dot(self).sqrt()
    }
    /// `self / |self|`.
    pub fn normalize(self) -> V3 {
        self * (1.0 / self.length())
    }
    /// Component-wise product.
    pub fn hadamard(self, o: V3) -> V3 {
        V3([self.0[0] * o.0[0], self.0[1] * o.0[1], self.0[2] * o.0[2]])
    }
    /// Largest component.
    pub fn max_component(self) -> f32 {
        self.0[0].max(self.0[1]).max(self.0[2])
    }
}

impl Add for V3 {
    type Output = V3;
    fn add(self, o: V3) -> V3 {
        V3([self.0[0] + o.0[0], self.0[1] + o.0[1], self.0[2] + o.0[2]])
    }
}

impl Sub for V3 {
    type Output = V3;
    fn sub(self, o: V3) -> V3 {
        V3([self.0[0] - o.0[0], self.0[1] - o.0[1], self.0[2] - o.0[2]])
    }
}

impl Mul<f32> for V3 {
    type Output = V3;
    fn mul(self, s: f32) -> V3 {
        V3([self.0[0] * s, self.0[1] * s, self.0[2] * s])
    }
}

impl Neg for V3 {
    type Output = V3;
    fn neg(self) -> V3 {
        self * -1.0
    }
}

/// A ray `origin + t · dir` at shutter time `time` (`dir` has unit length).
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    /// Origin.
    pub origin: V3,
    /// Unit direction.
    pub dir: V3,
}

/// A geometric primitive.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    /// A sphere whose centre moves linearly from `center0` (time 0) to `center1` (time 1).
    Sphere {
        /// Centre at time 0.
        center0: V3,
        /// Centre at time 1.
        center1: V3,
        /// Radius.
        radius: f32,
    },
    /// The parallelogram `corner + a·edge_u + b·edge_v`, `a, b ∈ [0, 1]`; its normal is
    /// `edge_u × edge_v` normalised (the side a one-sided emitter emits to).
    Quad {
        /// One corner.
        corner: V3,
        /// First edge.
        edge_u: V3,
        /// Second edge.
        edge_v: V3,
    },
}

impl Shape {
    /// A parallelogram.
    pub fn quad(corner: V3, edge_u: V3, edge_v: V3) -> Shape {
        Shape::Quad {
            corner,
            edge_u,
            edge_v,
        }
    }

    /// A sphere that does not move.
    pub fn sphere(center: V3, radius: f32) -> Shape {
        Shape::Sphere {
            center0: center,
            center1: center,
            radius,
        }
    }

    /// The nearest hit in `(t_min, t_max)` at `time`: distance and geometric unit normal
    /// (outward for spheres, `edge_u × edge_v` for quads).
    pub fn intersect(&self, ray: &Ray, time: f32, t_min: f32, t_max: f32) -> Option<(f32, V3)> {
        match *self {
            Shape::Sphere {
                center0,
                center1,
                radius,
            } => {
                let c = center0 + (center1 - center0) * time;
                let oc = ray.origin - c;
                let b = oc.dot(ray.dir);
                let q = oc.dot(oc) - radius * radius;
                let disc = b * b - q;
                if disc < 0.0 {
                    return None;
                }
                let s = disc.sqrt();
                let mut t = -b - s;
                if !(t > t_min) {
                    t = -b + s;
                }
                if t > t_min && t < t_max {
                    let p = ray.origin + ray.dir * t;
                    Some((t, (p - c) * (1.0 / radius)))
                } else {
                    None
                }
            }
            Shape::Quad {
                corner,
                edge_u,
                edge_v,
            } => {
                let n = edge_u.cross(edge_v);
                let denom = n.dot(ray.dir);
                if denom.abs() < 1e-12 {
                    return None;
                }
                let t = n.dot(corner - ray.origin) / denom;
                if !(t > t_min && t < t_max) {
                    return None;
                }
                let planar = ray.origin + ray.dir * t - corner;
                let inv = 1.0 / n.dot(n);
                let a = n.dot(planar.cross(edge_v)) * inv;
                let b = n.dot(edge_u.cross(planar)) * inv;
                if (0.0..=1.0).contains(&a) && (0.0..=1.0).contains(&b) {
                    Some((t, n * inv.sqrt()))
                } else {
                    None
                }
            }
        }
    }
}

/// Shirley and Chiu's concentric map from `[0, 1)²` to the unit disk (area-preserving, keeps
/// strata compact).
pub fn concentric_disk(u: [f32; 2]) -> [f32; 2] {
    let a = 2.0 * u[0] - 1.0;
    let b = 2.0 * u[1] - 1.0;
    if a == 0.0 && b == 0.0 {
        return [0.0, 0.0];
    }
    let (r, theta) = if a.abs() > b.abs() {
        (a, core::f32::consts::FRAC_PI_4 * (b / a))
    } else {
        (
            b,
            core::f32::consts::FRAC_PI_2 - core::f32::consts::FRAC_PI_4 * (a / b),
        )
    };
    [r * theta.cos(), r * theta.sin()]
}

/// A direction about the unit normal `n` with density `cos θ / π` (Malley's method over the
/// concentric map).
pub fn cosine_hemisphere(n: V3, u: [f32; 2]) -> V3 {
    let [x, y] = concentric_disk(u);
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    let (t, b) = basis(n);
    (t * x + b * y + n * z).normalize()
}

/// An orthonormal basis `(t, b)` completing the unit vector `n` (Duff et al., 2017).
pub fn basis(n: V3) -> (V3, V3) {
    let [x, y, z] = n.0;
    let sign = 1.0f32.copysign(z);
    let a = -1.0 / (sign + z);
    let b = x * y * a;
    (
        V3([1.0 + sign * x * x * a, sign * b, -sign * x]),
        V3([b, sign + y * y * a, -y]),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn basis_is_orthonormal() {
        for n in [
            V3::new(0.0, 0.0, 1.0),
            V3::new(0.0, 0.0, -1.0),
            V3::new(0.3, -0.4, 0.2).normalize(),
        ] {
            let (t, b) = basis(n);
            for (p, q) in [(t, b), (t, n), (b, n)] {
                assert!(p.dot(q).abs() < 1e-5);
            }
            assert!((t.length() - 1.0).abs() < 1e-5 && (b.length() - 1.0).abs() < 1e-5);
        }
    }

    #[test]
    fn quads_and_spheres_are_hit_where_expected() {
        let ray = Ray {
            origin: V3::new(0.5, 0.5, 2.0),
            dir: V3::new(0.0, 0.0, -1.0),
        };
        let q = Shape::quad(
            V3::default(),
            V3::new(1.0, 0.0, 0.0),
            V3::new(0.0, 1.0, 0.0),
        );
        let (t, n) = q.intersect(&ray, 0.0, 1e-4, f32::INFINITY).unwrap();
        assert!((t - 2.0).abs() < 1e-6 && n == V3::new(0.0, 0.0, 1.0));
        let s = Shape::Sphere {
            center0: V3::new(0.0, 0.5, 0.0),
            center1: V3::new(1.0, 0.5, 0.0),
            radius: 0.25,
        };
        assert!(s.intersect(&ray, 0.0, 1e-4, f32::INFINITY).is_none());
        let (t, _) = s.intersect(&ray, 0.5, 1e-4, f32::INFINITY).unwrap();
        assert!((t - 1.75).abs() < 1e-5);
    }
}
