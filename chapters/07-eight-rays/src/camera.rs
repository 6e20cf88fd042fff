//! The camera's rays for a whole row, eight at a time.

use raylab::{Camera, RayKind, Settings};
use wide::f32x8;

use raylab_lanes::{CameraX8, Vec3x8};

use crate::link::END;
use crate::soa::{Group, LANES};

// ANCHOR: primary
/// Every sample's primary ray of row `j`, eight at a time, in the order
/// pixel by pixel and within a pixel in the pattern's order: sample
/// `i · spp + k` is pixel `i`'s `k`-th ray. The rays are made in registers
/// when wave 1 traces them, never stored. The arithmetic is `Camera::ray`'s,
/// operation for operation, so the directions are the same to the bit.
pub struct PrimaryRays<'a> {
    settings: &'a Settings,
    primary: &'a Primary,
    j: u32,
    spp: usize,
    /// When every pixel has the same points: per group of the period, the
    /// lanes' rows' part of their directions ([`CameraX8::down`]).
    down: [f32x8; MAX_PERIOD],
}

/// What every row's primary rays share, made once per image: the camera
/// in lanes and, for points that are the same in every pixel, what the
/// rows share of their directions.
pub struct Primary {
    camera: CameraX8,
    repeating: Option<Repeating>,
}

impl Primary {
    pub fn new(camera: &Camera, settings: &Settings) -> Self {
        let camera = CameraX8::new(camera, settings.width, settings.height);
        let repeating = Repeating::new(&settings.sampling, &camera, settings.width);
        Primary { camera, repeating }
    }
}

/// The most groups in a [`Repeating`] period (32 covers every `spp` up to
/// 32 and the squares up to 256; others use the general loop).
const MAX_PERIOD: usize = 32;

/// What the rows share when every pixel has the same points (the pixel
/// centre, the lab's five, the grid). Sample `s` is pixel `s / spp`'s
/// point `s % spp`, so the lanes' points repeat every `lcm(spp, 8)`
/// samples: `period` groups, `pixels` pixels further on. And each row has
/// the same columns: a direction's part that depends on the column alone
/// (`forward + right · x`, with its division) is worked out once per
/// image for every group of a row, and each row adds its own part to it.
struct Repeating {
    period: usize,
    /// Per group of the period: each lane's point's offset down the pixel.
    sy: [f32x8; MAX_PERIOD],
    /// Per whole group of a row: the lanes' directions' column part.
    across: Vec<Vec3x8>,
}

impl Repeating {
    fn new(sampling: &raylab::Sampling, camera: &CameraX8, width: u32) -> Option<Repeating> {
        if sampling.is_random() {
            return None;
        }
        let spp = sampling.spp() as usize;
        let samples = spp * LANES / gcd(spp, LANES);
        let (period, pixels) = (samples / LANES, samples / spp);
        if period > MAX_PERIOD {
            return None;
        }
        // Any pixel's points are every pixel's: the first stands in.
        let points = sampling.pixel((0, 0));
        let mut sy = [f32x8::ZERO; MAX_PERIOD];
        // Per group of the period: each lane's pixel counted from the
        // period's first (a whole number), and its point's offset across.
        let mut pixel = [f32x8::ZERO; MAX_PERIOD];
        let mut sx = [f32x8::ZERO; MAX_PERIOD];
        for group in 0..period {
            let (mut p, mut x, mut y) = ([0.0; LANES], [0.0; LANES], [0.0; LANES]);
            for lane in 0..LANES {
                let sample = group * LANES + lane;
                p[lane] = (sample / spp) as f32;
                (x[lane], y[lane]) = points.offset((sample % spp) as u32);
            }
            (pixel[group], sx[group], sy[group]) = (p.into(), x.into(), y.into());
        }
        let groups = width as usize * spp / LANES;
        let across = (0..groups)
            .map(|group| {
                let (first, phase) = (group / period * pixels, group % period);
                // `i as f32 + sx` as the scalar camera adds it: the pixel's
                // number is a whole number, exact in an f32, and so is the
                // sum of its two parts.
                let column = (f32x8::splat(first as f32) + pixel[phase]) + sx[phase];
                camera.across(column)
            })
            .collect();
        Some(Repeating { period, sy, across })
    }
}

fn gcd(a: usize, b: usize) -> usize {
    if b == 0 { a } else { gcd(b, a % b) }
}

impl<'a> PrimaryRays<'a> {
    /// Row `j`'s primary rays, from what the image's rows share.
    pub fn new(primary: &'a Primary, settings: &'a Settings, j: u32) -> Self {
        let mut down = [f32x8::ZERO; MAX_PERIOD];
        if let Some(repeating) = &primary.repeating {
            for (down, sy) in down.iter_mut().zip(&repeating.sy[..repeating.period]) {
                *down = primary.camera.down(f32x8::splat(j as f32) + *sy);
            }
        }
        PrimaryRays {
            settings,
            primary,
            j,
            spp: settings.sampling.spp() as usize,
            down,
        }
    }

    /// How many samples (primary rays) the row has.
    pub fn len(&self) -> usize {
        self.settings.width as usize * self.spp
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Samples `8 · group ..`, the last group's padding lanes aimed at the
    /// row's first pixel (traced, and thrown away).
    pub fn group(&self, group: usize) -> Group {
        let first = group * LANES;
        let count = (self.len() - first).min(LANES);
        let camera = &self.primary.camera;
        let direction = match &self.primary.repeating {
            Some(repeating) if count == LANES => {
                let down = self.down[group % repeating.period];
                camera.through(repeating.across[group], down)
            }
            _ => {
                let (column, row) = self.places(first, count);
                camera.directions(column, row)
            }
        };
        // Padding lanes are sample 0's: traced, and never read.
        let sample = std::array::from_fn(|lane| {
            if lane < count {
                (first + lane) as u32
            } else {
                0
            }
        });
        Group {
            origin: camera.eye,
            direction,
            weight: f32x8::ONE,
            sample,
            kind: [RayKind::Primary; LANES],
            // A primary ray's sample is done once its tree is.
            after: [END; LANES],
        }
    }

    /// Where in the image the samples `first ..` (`count` of them, the
    /// rest padding at the row's first pixel) lie, in pixels, found one
    /// lane at a time: for points that differ from pixel to pixel.
    fn places(&self, first: usize, count: usize) -> (f32x8, f32x8) {
        let mut column = [0.0f32; LANES];
        let mut row = [0.0f32; LANES];
        let (mut i, mut k) = (first / self.spp, first % self.spp);
        // What a pixel's samples share (a random pattern's hash of the
        // pixel), worked out once per pixel rather than once per sample.
        let sampling = &self.settings.sampling;
        let mut pixel = sampling.pixel((i as u32, self.j));
        for lane in 0..count {
            let (sx, sy) = pixel.offset(k as u32);
            column[lane] = i as f32 + sx;
            row[lane] = self.j as f32 + sy;
            k += 1;
            if k == self.spp && lane + 1 < count {
                (i, k) = (i + 1, 0);
                pixel = sampling.pixel((i as u32, self.j));
            }
        }
        (f32x8::from(column), f32x8::from(row))
    }
}
// ANCHOR_END: primary

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Sampling;

    #[test]
    fn eight_camera_rays_at_a_time_are_camera_ray_to_the_bit() {
        let camera = Camera::lab();
        let settings = Settings {
            width: 13,
            height: 7,
            max_depth: 1,
            epsilon: 1e-4,
            sampling: Sampling::LAB_FIVE,
        };
        let primary = Primary::new(&camera, &settings);
        for j in 0..7 {
            let rays = PrimaryRays::new(&primary, &settings, j);
            assert_eq!(rays.len(), 13 * 5);
            for s in 0..rays.len() {
                let i = s / 5;
                let offset = settings.sampling.offset((i as u32, j), (s % 5) as u32);
                let expected = camera.ray(i as u32, j, offset, 13, 7);
                let group = rays.group(s / LANES);
                let lane = s % LANES;
                assert_eq!(group.direction.lane(lane), expected.direction);
                assert_eq!(group.origin.lane(lane), expected.origin);
                assert_eq!(group.sample[lane], s as u32);
            }
        }
    }
}
