//! Materials: how much light a surface keeps, mirrors and lets through.

use crate::Vec3;

/// What a surface does with light.
///
/// `reflection` and `transmission` are the shares of the light that leave
/// along the mirror and the refracted direction; the rest, `1 − r − t`, is
/// shaded locally with `albedo`. Build one with [`Material::new`], which
/// checks the rules of the lab model, so that a `Material` in hand is always valid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    albedo: Vec3,
    reflection: f32,
    transmission: f32,
    ior: f32,
}

/// Why a material was rejected: the field and the rule it breaks.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MaterialError {
    /// A number is NaN or infinite.
    #[error("{field} is {value}, but every number of a material must be finite")]
    NotFinite {
        /// The field's name, as a scene file spells it.
        field: &'static str,
        /// The number given.
        value: f32,
    },
    /// An albedo channel below 0 or above 1.
    #[error("albedo {value} must be between 0 and 1 in every channel")]
    AlbedoOutOfRange {
        /// The channel's value.
        value: f32,
    },
    /// A mirror or glass share below 0.
    #[error("{field} is {value}, but it must be at least 0")]
    Negative {
        /// The field's name, as a scene file spells it.
        field: &'static str,
        /// The number given.
        value: f32,
    },
    /// `r + t > 1`: the surface would send on more light than it receives.
    #[error(
        "reflection + transmission is {reflection} + {transmission} = {sum}, \
         but a surface cannot send on more light than it receives: keep the sum at most 1"
    )]
    MoreThanAllTheLight {
        /// The mirror share `r`.
        reflection: f32,
        /// The glass share `t`.
        transmission: f32,
        /// `r + t`, as added in `f32`.
        sum: f32,
    },
    /// A transmitting material with an index of refraction below 1.
    #[error(
        "ior is {ior}, but a material that transmits light needs an index of refraction of at least 1"
    )]
    IorBelowOne {
        /// The index given.
        ior: f32,
    },
    /// An index of refraction above [`MAX_IOR`].
    #[error("ior is {ior}, but it must be at most {MAX_IOR} (diamond is 2.42)")]
    IorTooHigh {
        /// The index given.
        ior: f32,
    },
}

/// The largest index of refraction accepted. No real material comes near
/// (germanium, at about 4, is among the highest); far larger ones overflow
/// `eta²` in the refract formula to infinity.
pub const MAX_IOR: f32 = 100.0;

impl Material {
    /// A validated material; see [`MaterialError`] for the rules.
    pub fn new(
        albedo: Vec3,
        reflection: f32,
        transmission: f32,
        ior: f32,
    ) -> Result<Self, MaterialError> {
        for (field, value) in [
            ("albedo", albedo.x),
            ("albedo", albedo.y),
            ("albedo", albedo.z),
            ("reflection", reflection),
            ("transmission", transmission),
            ("ior", ior),
        ] {
            if !value.is_finite() {
                return Err(MaterialError::NotFinite { field, value });
            }
        }
        if let Some(&value) = albedo.to_array().iter().find(|c| !(0.0..=1.0).contains(*c)) {
            return Err(MaterialError::AlbedoOutOfRange { value });
        }
        for (field, value) in [("reflection", reflection), ("transmission", transmission)] {
            if value < 0.0 {
                return Err(MaterialError::Negative { field, value });
            }
        }
        let sum = reflection + transmission;
        if sum > 1.0 {
            return Err(MaterialError::MoreThanAllTheLight {
                reflection,
                transmission,
                sum,
            });
        }
        if transmission > 0.0 && ior < 1.0 {
            return Err(MaterialError::IorBelowOne { ior });
        }
        if ior > MAX_IOR {
            return Err(MaterialError::IorTooHigh { ior });
        }
        Ok(Material {
            albedo,
            reflection,
            transmission,
            ior,
        })
    }

    /// A matte surface: all light is shaded locally.
    pub fn diffuse(albedo: Vec3) -> Result<Self, MaterialError> {
        Material::new(albedo, 0.0, 0.0, 1.0)
    }

    /// A matte material from a colour that was validated before, such as
    /// one of the ground's checker colours (checked by `Scene::new`): no
    /// checks on the hot path.
    pub(crate) fn matte(albedo: Vec3) -> Self {
        Material {
            albedo,
            reflection: 0.0,
            transmission: 0.0,
            ior: 1.0,
        }
    }

    /// The colour of the locally shaded share (linear RGB, 0 to 1).
    pub fn albedo(&self) -> Vec3 {
        self.albedo
    }

    /// The share of light that leaves along the mirror direction.
    pub fn reflection(&self) -> f32 {
        self.reflection
    }

    /// The share of light that passes through the surface.
    pub fn transmission(&self) -> f32 {
        self.transmission
    }

    /// The index of refraction, relative to the air around it.
    pub fn ior(&self) -> f32 {
        self.ior
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const GREY: Vec3 = Vec3::splat(0.5);

    #[test]
    fn the_lab_glass_is_a_valid_material() {
        let glass = Material::new(Vec3::new(0.2, 0.7, 0.3), 0.1, 0.7, 1.5).unwrap();
        assert_eq!(glass.reflection() + glass.transmission(), 0.8);
    }

    #[test]
    fn reflection_plus_transmission_above_one_is_rejected() {
        let err = Material::new(GREY, 0.6, 0.5, 1.5).unwrap_err();
        assert!(matches!(err, MaterialError::MoreThanAllTheLight { .. }));
        assert!(err.to_string().contains("keep the sum at most 1"), "{err}");
    }

    #[test]
    fn negative_shares_are_rejected_by_name() {
        let err = Material::new(GREY, -0.1, 0.0, 1.0).unwrap_err();
        assert_eq!(
            err,
            MaterialError::Negative {
                field: "reflection",
                value: -0.1
            }
        );
    }

    #[test]
    fn a_transmitting_material_needs_ior_at_least_one() {
        assert!(matches!(
            Material::new(GREY, 0.0, 0.5, 0.9),
            Err(MaterialError::IorBelowOne { .. })
        ));
        // An opaque material may carry any ior: it is never used.
        assert!(Material::new(GREY, 0.5, 0.0, 0.5).is_ok());
    }

    #[test]
    fn an_ior_too_large_to_compute_with_is_rejected() {
        // Found by the property tests: with ior 1e29, eta² overflows and a
        // ray leaving the sphere head-on became NaN.
        assert!(matches!(
            Material::new(GREY, 0.0, 0.5, 1e29),
            Err(MaterialError::IorTooHigh { .. })
        ));
        assert!(Material::new(GREY, 0.0, 0.5, 2.42).is_ok());
    }

    #[test]
    fn nan_and_infinite_numbers_are_rejected() {
        assert!(matches!(
            Material::new(GREY, f32::NAN, 0.0, 1.0),
            Err(MaterialError::NotFinite {
                field: "reflection",
                ..
            })
        ));
        assert!(matches!(
            Material::new(Vec3::new(0.1, f32::INFINITY, 0.1), 0.0, 0.0, 1.0),
            Err(MaterialError::NotFinite {
                field: "albedo",
                ..
            })
        ));
    }

    #[test]
    fn albedo_outside_zero_to_one_is_rejected() {
        assert!(matches!(
            Material::diffuse(Vec3::new(0.5, 1.5, 0.5)),
            Err(MaterialError::AlbedoOutOfRange { .. })
        ));
    }
}
