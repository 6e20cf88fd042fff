//! A row's next eight samples, made ready eight at a time.
//!
//! A lane whose path ends takes the next sample at once, so a bounce
//! starts only a few new paths (three on average in the lab scene). Their
//! camera rays are made eight at a time all the same, for the next eight
//! samples of the row in one pass of [`CameraX8::directions`], and handed
//! out one by one as lanes come free.

use raylab::Vec3;
use raylab::sampling::{PixelHash, PixelSamples, Sampling, Stream};

use super::camera::CameraX8;
use super::vec3x8::LANES;
use crate::random::Random;

/// The samples `first .. first + len` of row `j`: their camera rays'
/// directions and what seeds their generators.
pub struct Upcoming {
    first: usize,
    len: usize,
    directions: [Vec3; LANES],
    hash: [PixelHash; LANES],
    sample: [u32; LANES],
    /// The pixel whose offsets were made last, with what its samples share.
    pixel: Option<(usize, PixelSamples, PixelHash)>,
}

impl Default for Upcoming {
    fn default() -> Upcoming {
        Upcoming {
            first: 0,
            len: 0,
            directions: [Vec3::ZERO; LANES],
            hash: [PixelHash::new(0, (0, 0)); LANES],
            sample: [0; LANES],
            pixel: None,
        }
    }
}

impl Upcoming {
    /// Ready for row `j`'s samples (none made yet).
    pub fn clear(&mut self) {
        (self.first, self.len, self.pixel) = (0, 0, None);
    }

    /// Sample `q` of row `j` (of `total`): its camera ray's direction and
    /// its generator. `q` must be the row's next sample after the last one
    /// taken.
    pub fn take(
        &mut self,
        q: usize,
        (j, total): (u32, usize),
        sampling: &Sampling,
        camera: &CameraX8,
    ) -> (Vec3, Random) {
        if q >= self.first + self.len {
            self.make(q, (j, total), sampling, camera);
        }
        let k = q - self.first;
        let random = Random(self.hash[k].sample_rng(self.sample[k], Stream::Path));
        (self.directions[k], random)
    }

    /// Make samples `q ..` (eight, or what is left of the row).
    fn make(&mut self, q: usize, (j, total): (u32, usize), sampling: &Sampling, camera: &CameraX8) {
        let spp = sampling.spp() as usize;
        let (mut column, mut row) = ([0f32; LANES], [0f32; LANES]);
        self.first = q;
        self.len = (total - q).min(LANES);
        for k in 0..self.len {
            let (pixel, sample) = ((q + k) / spp, ((q + k) % spp) as u32);
            let (_, samples, hash) = match self.pixel {
                Some(ref p) if p.0 == pixel => p,
                _ => self.pixel.insert((
                    pixel,
                    sampling.pixel((pixel as u32, j)),
                    PixelHash::new(sampling.seed(), (pixel as u32, j)),
                )),
            };
            let (sx, sy) = samples.offset(sample);
            (column[k], row[k]) = (pixel as f32 + sx, j as f32 + sy);
            (self.hash[k], self.sample[k]) = (*hash, sample);
        }
        self.directions = camera.directions(column, row).to_lanes();
    }
}
