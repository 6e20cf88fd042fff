//! Eight paths' light by term ([`Terms`]), one lane per path.

use wide::{CmpEq, f32x8};

use ch06_path_tracing::Terms;
use raylab_lanes::Vec3x8;

/// [`Terms`] in lanes: lane `l` of each is path `l`'s.
#[derive(Clone, Copy, Debug)]
pub struct TermsX8 {
    pub seen: Vec3x8,
    pub sun_direct: Vec3x8,
    pub sky_direct: Vec3x8,
    pub indirect: Vec3x8,
    pub caustics: Vec3x8,
}

/// `term + light` in the lanes of `mask`, `term` elsewhere: each lane adds
/// only the light its own path found, as the scalar `+=` does. The other
/// lanes add +0: a term starts at +0 and only grows by sums, so it is
/// never −0, and adding +0 leaves it as it is, to the bit.
#[inline]
fn add(term: &mut Vec3x8, mask: f32x8, light: Vec3x8) {
    *term = *term + Vec3x8::select(mask, light, Vec3x8::ZERO);
}

impl TermsX8 {
    pub const ZERO: TermsX8 = TermsX8 {
        seen: Vec3x8::ZERO,
        sun_direct: Vec3x8::ZERO,
        sky_direct: Vec3x8::ZERO,
        indirect: Vec3x8::ZERO,
        caustics: Vec3x8::ZERO,
    };

    /// [`Terms::add_sky`] in the lanes of `mask`: light from the sky (or
    /// the sun's disc seen along a path) after `k` diffuse scatterings.
    #[inline]
    pub fn add_sky(&mut self, mask: f32x8, k: f32x8, light: Vec3x8) {
        let (zero, one) = (k.cmp_eq(f32x8::ZERO), k.cmp_eq(f32x8::ONE));
        add(&mut self.seen, mask & zero, light);
        add(&mut self.sky_direct, mask & one, light);
        add(&mut self.indirect, mask & !(zero | one), light);
    }

    /// [`Terms::add_sun`] in the lanes of `mask`.
    #[inline]
    pub fn add_sun(&mut self, mask: f32x8, k: f32x8, light: Vec3x8) {
        let (zero, one) = (k.cmp_eq(f32x8::ZERO), k.cmp_eq(f32x8::ONE));
        add(&mut self.seen, mask & zero, light);
        add(&mut self.sun_direct, mask & one, light);
        add(&mut self.indirect, mask & !(zero | one), light);
    }

    /// The caustic light, in the lanes of `mask`.
    #[inline]
    pub fn add_caustics(&mut self, mask: f32x8, light: Vec3x8) {
        add(&mut self.caustics, mask, light);
    }

    /// Every lane set in `mask` back to no light (a new path starts there).
    #[inline]
    pub fn clear(&mut self, mask: f32x8) {
        for term in [
            &mut self.seen,
            &mut self.sun_direct,
            &mut self.sky_direct,
            &mut self.indirect,
            &mut self.caustics,
        ] {
            *term = Vec3x8::blend_back(mask, Vec3x8::ZERO, *term);
        }
    }

    /// Path `l`'s terms as scalar [`Terms`].
    #[inline]
    pub fn lane(&self, l: usize) -> Terms {
        Terms {
            seen: self.seen.lane(l),
            sun_direct: self.sun_direct.lane(l),
            sky_direct: self.sky_direct.lane(l),
            indirect: self.indirect.lane(l),
            caustics: self.caustics.lane(l),
        }
    }
}
