//! The scene: a ground plane, spheres, a sky and a sun, and the two
//! questions a tracer asks of it — what does this ray hit first, and does
//! it hit anything at all?

use crate::Vec3;
use crate::light::{Sky, Sun};
use crate::material::{Material, MaterialError};
use crate::plane::{Checker, Plane};
use crate::ray::Ray;
use crate::sphere::Sphere;

/// The checkered ground. It neither reflects nor transmits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ground {
    /// Where the ground lies.
    pub plane: Plane,
    /// Its two colours.
    pub checker: Checker,
}

/// A sphere in the scene, with its name and its material.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneSphere {
    /// The name scene files, probes and error messages call it by.
    pub name: String,
    /// Where it is and how big.
    pub shape: Sphere,
    /// What it does with the light that reaches it.
    pub material: Material,
}

/// Which object a ray hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Object {
    /// The checkered ground plane.
    Ground,
    /// The sphere at this index of [`Scene::spheres`].
    Sphere(usize),
}

/// What a ray meets: where, on what, and which way the surface faces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance along the ray.
    pub t: f32,
    /// Where the ray meets the surface: `o + t · d`.
    pub point: Vec3,
    /// Unit normal pointing out of the object (`n`).
    pub normal: Vec3,
    /// Unit normal on the side the ray comes from (`nf`).
    pub facing_normal: Vec3,
    /// Whether the ray arrives from outside (`dot(d, n) < 0`).
    pub entering: bool,
    /// The object hit, for the probe's log and the ground's checker.
    pub object: Object,
    /// The material, with the ground's checker colour filled in.
    pub material: Material,
}

/// A scene rejected while it was being built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SceneError {
    /// A sphere whose radius is not a finite number above 0.
    #[error("sphere '{name}': radius is {radius}, but it must be a finite number above 0")]
    BadRadius {
        /// The sphere's name.
        name: String,
        /// The radius given.
        radius: f32,
    },
    /// A sphere whose centre is NaN or infinite.
    #[error("sphere '{name}': its centre {centre} must be finite")]
    BadCentre {
        /// The sphere's name.
        name: String,
        /// The centre given.
        centre: Vec3,
    },
    /// An object whose material breaks a rule.
    #[error("{object}: {source}")]
    Material {
        /// The object's name (`ground` or a sphere's).
        object: String,
        /// The rule broken.
        source: MaterialError,
    },
}

/// Everything a ray can meet, and the light that falls on it.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The checkered plane under everything.
    pub ground: Ground,
    spheres: Vec<SceneSphere>,
    /// What a ray that meets nothing sees.
    pub sky: Sky,
    /// The one light that casts shadows.
    pub sun: Sun,
}

impl Scene {
    /// A scene with the ground, sky and sun and no spheres yet.
    pub fn new(ground: Ground, sky: Sky, sun: Sun) -> Result<Self, SceneError> {
        for colour in [ground.checker.even, ground.checker.odd] {
            Material::diffuse(colour).map_err(|source| SceneError::Material {
                object: "ground".into(),
                source,
            })?;
        }
        Ok(Scene {
            ground,
            spheres: Vec::new(),
            sky,
            sun,
        })
    }

    /// Add a sphere after checking that it is a real one.
    pub fn add_sphere(
        &mut self,
        name: &str,
        shape: Sphere,
        material: Material,
    ) -> Result<(), SceneError> {
        let name = name.to_owned();
        if !(shape.radius.is_finite() && shape.radius > 0.0) {
            return Err(SceneError::BadRadius {
                name,
                radius: shape.radius,
            });
        }
        if !shape.centre.is_finite() {
            return Err(SceneError::BadCentre {
                name,
                centre: shape.centre,
            });
        }
        self.spheres.push(SceneSphere {
            name,
            shape,
            material,
        });
        Ok(())
    }

    /// The lab scene of the lab model: a checkered ground, five spheres, sky and sun.
    pub fn lab() -> Self {
        let mut scene = Scene::new(
            Ground {
                plane: Plane {
                    point: Vec3::ZERO,
                    normal: Vec3::Y,
                },
                checker: Checker {
                    even: Vec3::splat(0.75),
                    odd: Vec3::splat(0.25),
                },
            },
            Sky {
                horizon: Vec3::new(0.85, 0.90, 1.00),
                zenith: Vec3::new(0.25, 0.45, 0.85),
            },
            Sun {
                direction: Vec3::new(-1.0, 1.2, 0.8).normalize(),
                brightness: 25.0,
            },
        )
        .expect("the lab ground is valid");
        #[rustfmt::skip]
        let spheres = [
            // name      centre              radius  albedo             refl  trans  ior
            ("mirror", (-1.25, 0.5,  0.5),  0.5,  (0.5,  0.2, 0.6 ),  0.6,  0.0,  1.0),
            ("glass",  ( 1.0,  0.6,  0.8),  0.6,  (0.2,  0.7, 0.3 ),  0.1,  0.7,  1.5),
            ("red",    ( 0.0,  1.0, -1.5),  1.0,  (0.8,  0.2, 0.15),  0.0,  0.0,  1.0),
            ("blue",   ( 0.1,  0.25, 1.2),  0.25, (0.15, 0.3, 0.85),  0.0,  0.0,  1.0),
            ("yellow", (-2.0,  0.75,-1.2),  0.75, (0.9,  0.75, 0.2),  0.0,  0.0,  1.0),
        ];
        for (name, centre, radius, albedo, reflection, transmission, ior) in spheres {
            let material = Material::new(albedo.into(), reflection, transmission, ior)
                .expect("the lab materials are valid");
            let shape = Sphere {
                centre: centre.into(),
                radius,
            };
            scene
                .add_sphere(name, shape, material)
                .expect("the lab spheres are valid");
        }
        scene
    }

    /// The spheres, in the order they were added (the order that breaks ties).
    pub fn spheres(&self) -> &[SceneSphere] {
        &self.spheres
    }

    /// The index of the sphere with this name.
    pub fn sphere_named(&self, name: &str) -> Option<usize> {
        self.spheres.iter().position(|s| s.name == name)
    }

    /// A human name for an object, for probes and diagrams.
    pub fn object_name(&self, object: Object) -> &str {
        match object {
            Object::Ground => "ground",
            Object::Sphere(i) => &self.spheres[i].name,
        }
    }

    // ANCHOR: nearest_hit
    /// The first surface the ray meets, or `None` if it escapes to the sky.
    ///
    /// Objects are tested in order (the ground, then the spheres) and only a
    /// strictly nearer hit replaces the best so far, so ties go to the
    /// earlier object.
    #[inline]
    pub fn nearest_hit(&self, ray: &Ray) -> Option<Hit> {
        let mut nearest = f32::INFINITY;
        let mut object = None;
        if let Some(t) = self.ground.plane.intersect(ray) {
            (nearest, object) = (t, Some(Object::Ground));
        }
        for (i, sphere) in self.spheres.iter().enumerate() {
            if let Some(t) = sphere.shape.intersect(ray)
                && t < nearest
            {
                (nearest, object) = (t, Some(Object::Sphere(i)));
            }
        }
        object.map(|object| self.hit_record(ray, nearest, object))
    }
    // ANCHOR_END: nearest_hit

    /// Whether the ray meets any surface at all: the shadow-ray query,
    /// which may stop at the first hit it finds.
    #[inline]
    pub fn any_hit(&self, ray: &Ray) -> bool {
        self.ground.plane.intersect(ray).is_some()
            || self
                .spheres
                .iter()
                .any(|s| s.shape.intersect(ray).is_some())
    }

    /// Everything about a hit that the shading needs, computed once for
    /// the nearest hit rather than for every candidate. Public for the
    /// queries that find `t` their own way ([`SceneQuery`]).
    #[inline]
    pub fn hit_record(&self, ray: &Ray, t: f32, object: Object) -> Hit {
        let point = ray.at(t);
        let (normal, material) = match object {
            Object::Ground => {
                let albedo = self.ground.checker.albedo_at(point);
                (self.ground.plane.normal, Material::matte(albedo))
            }
            Object::Sphere(i) => {
                let sphere = &self.spheres[i];
                (sphere.shape.normal_at(point), sphere.material)
            }
        };
        let entering = ray.direction.dot(normal) < 0.0;
        Hit {
            t,
            point,
            normal,
            facing_normal: if entering { normal } else { -normal },
            entering,
            object,
            material,
        }
    }
}

/// The two questions a tracer asks of a scene's objects: which one a ray
/// meets first, and whether it meets any. [`Scene`] answers them by
/// testing every object in turn; a faster way to find the same answers
/// (a tree of boxes around the objects, say) answers them through this
/// trait, to the bit, so that a tracer may be handed either.
pub trait SceneQuery: Sync {
    /// The first surface the ray meets ([`Scene::nearest_hit`]).
    fn nearest_hit(&self, ray: &Ray) -> Option<Hit>;
    /// Whether the ray meets any surface at all ([`Scene::any_hit`]).
    fn any_hit(&self, ray: &Ray) -> bool;
}

/// A reference answers as what it points to: a tracer can be handed a
/// `&dyn SceneQuery` chosen at run time.
impl<T: SceneQuery + ?Sized> SceneQuery for &T {
    fn nearest_hit(&self, ray: &Ray) -> Option<Hit> {
        (**self).nearest_hit(ray)
    }

    fn any_hit(&self, ray: &Ray) -> bool {
        (**self).any_hit(ray)
    }
}

impl SceneQuery for Scene {
    #[inline]
    fn nearest_hit(&self, ray: &Ray) -> Option<Hit> {
        Scene::nearest_hit(self, ray)
    }

    #[inline]
    fn any_hit(&self, ray: &Ray) -> bool {
        Scene::any_hit(self, ray)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lab_scene_has_the_five_spheres_of_lab_md() {
        let scene = Scene::lab();
        let names: Vec<_> = scene.spheres().iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["mirror", "glass", "red", "blue", "yellow"]);
        let glass = &scene.spheres()[1];
        assert_eq!(glass.shape.centre, Vec3::new(1.0, 0.6, 0.8));
        assert_eq!(glass.material.ior(), 1.5);
    }

    #[test]
    fn a_ray_straight_down_onto_the_ground_hits_it_from_above() {
        let scene = Scene::lab();
        let ray = Ray::new(Vec3::new(3.0, 2.0, 3.0), Vec3::NEG_Y);
        let hit = scene.nearest_hit(&ray).unwrap();
        assert_eq!(hit.object, Object::Ground);
        assert_eq!(hit.t, 2.0);
        assert!(hit.entering);
        // floor(3) + floor(3) = 6 is even: the light square.
        assert_eq!(hit.material.albedo(), Vec3::splat(0.75));
    }

    #[test]
    fn the_nearer_of_two_objects_wins() {
        // Down through the red sphere's top: the sphere (t = 2) before the ground (t = 4).
        let scene = Scene::lab();
        let ray = Ray::new(Vec3::new(0.0, 4.0, -1.5), Vec3::NEG_Y);
        let hit = scene.nearest_hit(&ray).unwrap();
        assert_eq!(scene.object_name(hit.object), "red");
        assert_eq!(hit.t, 2.0);
        assert_eq!(hit.normal, Vec3::Y);
    }

    #[test]
    fn a_ray_leaving_a_sphere_faces_the_inside() {
        let scene = Scene::lab();
        let centre = Vec3::new(1.0, 0.6, 0.8);
        let hit = scene.nearest_hit(&Ray::new(centre, Vec3::X)).unwrap();
        assert!(!hit.entering);
        assert!(hit.normal.abs_diff_eq(Vec3::X, 1e-6));
        assert!(hit.facing_normal.abs_diff_eq(Vec3::NEG_X, 1e-6));
    }

    #[test]
    fn a_ray_into_the_sky_hits_nothing() {
        let scene = Scene::lab();
        let ray = Ray::new(Vec3::new(0.0, 1.0, 4.0), Vec3::Y);
        assert_eq!(scene.nearest_hit(&ray), None);
        assert!(!scene.any_hit(&ray));
    }

    #[test]
    fn spheres_with_a_zero_or_nan_radius_are_rejected_by_name() {
        let mut scene = Scene::lab();
        let material = Material::diffuse(Vec3::ONE).unwrap();
        for radius in [0.0, -1.0, f32::NAN] {
            let shape = Sphere {
                centre: Vec3::ZERO,
                radius,
            };
            let err = scene.add_sphere("ball", shape, material).unwrap_err();
            assert!(
                err.to_string().starts_with("sphere 'ball': radius"),
                "{err}"
            );
        }
    }
}
