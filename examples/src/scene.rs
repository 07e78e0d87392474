//! The analytic scenes: a Cornell-box-like room of quads lit by a square area light, with two
//! spheres (`cornell`), and the same room seen through a thin lens with a sphere moving during
//! the shutter (`dof`).

use crate::geometry::{Ray, Shape, V3, concentric_disk};

/// The scene names [`Scene::by_name`] accepts.
pub const SCENE_NAMES: [&str; 2] = ["cornell", "dof"];

/// A surface: a shape with a diffuse albedo, and an emitter flag.
#[derive(Clone, Copy, Debug)]
pub struct Object {
    /// Geometry.
    pub shape: Shape,
    /// Lambertian albedo (RGB, each in `[0, 1)`).
    pub albedo: V3,
    /// Whether this is the scene's light (it reflects nothing).
    pub emitter: bool,
}

/// The square area light: one-sided, emitting `radiance` towards `edge_u × edge_v`.
#[derive(Clone, Copy, Debug)]
pub struct AreaLight {
    /// One corner.
    pub corner: V3,
    /// First edge.
    pub edge_u: V3,
    /// Second edge.
    pub edge_v: V3,
    /// Emitted radiance (RGB), constant over the light and its hemisphere.
    pub radiance: V3,
}

impl AreaLight {
    /// Unit normal, the side it emits to.
    pub fn normal(&self) -> V3 {
        self.edge_u.cross(self.edge_v).normalize()
    }
    /// Area.
    pub fn area(&self) -> f32 {
        self.edge_u.cross(self.edge_v).length()
    }
    /// The point of the light at `u ∈ [0, 1)²` (uniform by area).
    pub fn point(&self, u: [f32; 2]) -> V3 {
        self.corner + self.edge_u * u[0] + self.edge_v * u[1]
    }
}

/// A perspective camera with a thin lens (`lens_radius = 0` is a pinhole).
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// Centre of the lens.
    pub position: V3,
    /// Unit right, up and backward vectors.
    pub basis: [V3; 3],
    /// `tan(vertical field of view / 2)`.
    pub tan_half_fov: f32,
    /// Lens radius (scene units).
    pub lens_radius: f32,
    /// Distance of the plane in focus along the view axis.
    pub focus_distance: f32,
}

impl Camera {
    /// A camera at `position` looking at `target` with `+y` up.
    pub fn look_at(
        position: V3,
        target: V3,
        vfov_degrees: f32,
        lens_radius: f32,
        focus_distance: f32,
    ) -> Camera {
        let w = (position - target).normalize();
        let u = V3::new(0.0, 1.0, 0.0).cross(w).normalize();
        let v = w.cross(u);
        Camera {
            position,
            basis: [u, v, w],
            tan_half_fov: (vfov_degrees.to_radians() * 0.5).tan(),
            lens_radius,
            focus_distance,
        }
    }

    /// The ray through film position `p_film` (pixels, `[0, w) × [0, h)`, y down) and lens
    /// sample `lens ∈ [0, 1)²` (mapped to the disk by [`concentric_disk`]).
    pub fn ray(&self, p_film: [f32; 2], lens: [f32; 2], resolution: [u32; 2]) -> Ray {
        let [w, h] = [resolution[0] as f32, resolution[1] as f32];
        let aspect = w / h;
        let x = (2.0 * p_film[0] / w - 1.0) * self.tan_half_fov * aspect;
        let y = (1.0 - 2.0 * p_film[1] / h) * self.tan_half_fov;
        let [bu, bv, bw] = self.basis;
        let through = bu * x + bv * y - bw;
        if self.lens_radius <= 0.0 {
            return Ray {
                origin: self.position,
                dir: through.normalize(),
            };
        }
        let focus = self.position + through * self.focus_distance;
        let [lx, ly] = concentric_disk(lens);
        let origin = self.position + (bu * lx + bv * ly) * self.lens_radius;
        Ray {
            origin,
            dir: (focus - origin).normalize(),
        }
    }
}

/// A scene: objects (the light among them), the light, the camera.
#[derive(Clone, Debug)]
pub struct Scene {
    /// Everything a ray can hit.
    pub objects: Vec<Object>,
    /// The one light.
    pub light: AreaLight,
    /// The camera.
    pub camera: Camera,
}

/// Ray-offset distance (scene units) against self-intersection.
pub const EPSILON: f32 = 1e-4;

impl Scene {
    /// The scene called `name` (one of [`SCENE_NAMES`]).
    pub fn by_name(name: &str) -> Option<Scene> {
        match name {
            "cornell" => Some(Scene::cornell()),
            "dof" => Some(Scene::depth_of_field()),
            _ => None,
        }
    }

    /// The unit room `[0, 1]³` open towards `+z`: white floor, ceiling and back wall, red left
    /// and green right wall; a 0.25 × 0.25 square light just under the ceiling's centre facing
    /// down; two white spheres. Pinhole camera at `(0.5, 0.5, 2.2)` with a 38° field of view.
    pub fn cornell() -> Scene {
        let (camera, objects, light) = room();
        let mut objects = objects;
        objects.push(diffuse(
            Shape::sphere(V3::new(0.32, 0.2, 0.35), 0.2),
            [0.75, 0.75, 0.75],
        ));
        objects.push(diffuse(
            Shape::sphere(V3::new(0.72, 0.14, 0.68), 0.14),
            [0.75, 0.75, 0.75],
        ));
        Scene {
            objects,
            light,
            camera: Camera { ..camera },
        }
    }

    /// The room of [`Scene::cornell`] with three spheres at different depths, seen through a
    /// thin lens (radius 0.05) focused on the middle one (distance 1.9), and a fourth sphere that
    /// moves from x = 0.25 to x = 0.55 during the shutter (time `[0, 1)`).
    pub fn depth_of_field() -> Scene {
        let (camera, mut objects, light) = room();
        for (c, r, a) in [
            (V3::new(0.22, 0.12, 0.85), 0.12, [0.8, 0.6, 0.3]),
            (V3::new(0.5, 0.15, 0.5), 0.15, [0.75, 0.75, 0.75]),
            (V3::new(0.78, 0.18, 0.15), 0.18, [0.3, 0.5, 0.8]),
        ] {
            objects.push(diffuse(Shape::sphere(c, r), a));
        }
        objects.push(diffuse(
            Shape::Sphere {
                center0: V3::new(0.25, 0.62, 0.4),
                center1: V3::new(0.55, 0.62, 0.4),
                radius: 0.08,
            },
            [0.8, 0.3, 0.3],
        ));
        let camera = Camera {
            lens_radius: 0.05,
            focus_distance: 1.9,
            ..camera
        };
        Scene {
            objects,
            light,
            camera,
        }
    }

    /// The nearest object hit by `ray` at `time` within `(EPSILON, t_max)`: index, distance and
    /// geometric normal.
    pub fn intersect(&self, ray: &Ray, time: f32, t_max: f32) -> Option<(usize, f32, V3)> {
        let mut best = None;
        let mut t_best = t_max;
        for (i, o) in self.objects.iter().enumerate() {
            if let Some((t, n)) = o.shape.intersect(ray, time, EPSILON, t_best) {
                t_best = t;
                best = Some((i, t, n));
            }
        }
        best
    }

    /// Whether anything but the light blocks the segment from `p` to the light point `q`.
    pub fn occluded(&self, p: V3, q: V3, time: f32) -> bool {
        let d = q - p;
        let dist = d.length();
        let ray = Ray {
            origin: p,
            dir: d * (1.0 / dist),
        };
        let t_max = dist * (1.0 - 1e-3);
        self.objects
            .iter()
            .any(|o| !o.emitter && o.shape.intersect(&ray, time, EPSILON, t_max).is_some())
    }
}

fn diffuse(shape: Shape, albedo: [f32; 3]) -> Object {
    Object {
        shape,
        albedo: V3(albedo),
        emitter: false,
    }
}

/// The room's camera, walls and light.
fn room() -> (Camera, Vec<Object>, AreaLight) {
    let o = V3::new(0.0, 0.0, 0.0);
    let x = V3::new(1.0, 0.0, 0.0);
    let y = V3::new(0.0, 1.0, 0.0);
    let z = V3::new(0.0, 0.0, 1.0);
    let white = [0.73, 0.73, 0.73];
    let objects = vec![
        diffuse(Shape::quad(o, z, x), white), // floor, normal +y
        diffuse(Shape::quad(y, x, z), white), // ceiling, normal −y
        diffuse(Shape::quad(o, x, y), white), // back wall, normal +z
        diffuse(Shape::quad(o, y, z), [0.63, 0.065, 0.05]), // left wall, normal +x
        diffuse(Shape::quad(x, z, y), [0.14, 0.45, 0.091]), // right wall, normal −x
    ];
    let side = 0.25;
    let light = AreaLight {
        corner: V3::new(0.5 - side / 2.0, 0.999, 0.5 - side / 2.0),
        edge_u: x * side,
        edge_v: z * side,
        radiance: V3::new(17.0, 12.0, 4.0) * 0.7,
    };
    let mut objects = objects;
    objects.push(Object {
        shape: Shape::quad(light.corner, light.edge_u, light.edge_v),
        albedo: V3::default(),
        emitter: true,
    });
    let camera = Camera::look_at(
        V3::new(0.5, 0.5, 2.2),
        V3::new(0.5, 0.5, 0.0),
        38.0,
        0.0,
        1.0,
    );
    (camera, objects, light)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_light_faces_down_into_the_room() {
        let s = Scene::cornell();
        assert!((s.light.normal().0[1] + 1.0).abs() < 1e-6);
        assert!((s.light.area() - 0.0625).abs() < 1e-6);
    }

    #[test]
    fn the_centre_ray_hits_the_back_wall_or_a_sphere() {
        let s = Scene::cornell();
        let ray = s.camera.ray([32.0, 32.0], [0.5, 0.5], [64, 64]);
        let (_, t, _) = s.intersect(&ray, 0.0, f32::INFINITY).unwrap();
        assert!(t > 1.0 && t <= 2.2 + 1e-4, "{t}");
    }
}
