//! A row's samples made ready eight at a time: where each one's camera ray
//! goes, and the state of its path's generator.
//!
//! A lane takes a new sample whenever its path ends, and only a few lanes
//! end at once. Seeding a generator, drawing a sample's point in the pixel
//! and making its camera ray are the same work for every sample, so they
//! are done ahead, for a block of the row's next samples, eight lanes at a
//! time with every lane busy; a lane that starts a sample then only reads
//! its numbers.

use raylab::Vec3;
use raylab::sampling::{PixelHash, PixelSamples, Sampling, Stream};
use raylab_lanes::{CameraX8, LANES, offsets_in_lanes, offsets_x8, sample_hashes, sample_rngs};
use wide::f32x8;

/// How many samples are made ready at a time.
const BLOCK: usize = 8 * LANES;

/// The next samples of a row, `first ..`: their camera rays' directions
/// and their generators' states.
pub(super) struct Starts {
    first: usize,
    len: usize,
    direction: [Vec3; BLOCK],
    state: [u64; BLOCK],
    /// The pixel whose samples were made last, with what they share: its
    /// hash, and its `PixelSamples` when its points are found one at a time.
    pixel: Option<(usize, Option<PixelSamples>, PixelHash)>,
}

impl Default for Starts {
    fn default() -> Starts {
        Starts {
            first: 0,
            len: 0,
            direction: [Vec3::ZERO; BLOCK],
            state: [0; BLOCK],
            pixel: None,
        }
    }
}

/// Sample `q` of row `j`: its camera ray's direction (from the eye) and
/// its path generator's state.
pub(super) struct Start {
    pub direction: Vec3,
    pub state: u64,
}

impl Starts {
    /// Start row `j` afresh.
    pub fn clear(&mut self) {
        (self.first, self.len, self.pixel) = (0, 0, None);
    }

    /// Sample `q` of row `j`'s `total` (pixel `q / spp`'s sample
    /// `q % spp`), made in a block with those after it when it is not made
    /// yet. Samples are asked for in order.
    pub fn get(
        &mut self,
        sampling: &Sampling,
        camera: &CameraX8,
        j: u32,
        q: usize,
        total: usize,
    ) -> Start {
        if q >= self.first + self.len {
            self.make(sampling, camera, j, q, total);
        }
        let k = q - self.first;
        Start {
            direction: self.direction[k],
            state: self.state[k],
        }
    }

    /// Samples `q ..` (up to [`BLOCK`] of them, and none past the row's
    /// `total`), eight at a time, exactly as the scalar tracer makes each
    /// one: its point from `PixelSamples::offset`, its ray from
    /// `Camera::ray` and its generator from `PixelHash::sample_rng(sample,
    /// Stream::Path)`.
    fn make(&mut self, sampling: &Sampling, camera: &CameraX8, j: u32, q: usize, total: usize) {
        let spp = sampling.spp() as usize;
        (self.first, self.len) = (q, BLOCK.min(total - q));
        // The points of the patterns that draw them are found in lanes;
        // the others one at a time, from what their pixel shares.
        let in_lanes = offsets_in_lanes(sampling);
        // Sample `q`'s pixel and its number there, counted on from `q`
        // (a division per sample costs more than the rest of its count).
        let (mut pixel, mut sample) = (q / spp, q % spp);
        let last = total - 1;
        for group in 0..self.len.div_ceil(LANES) {
            // (Every lane is set below.)
            let mut hashes = [self.pixel_hash(sampling, j, pixel, in_lanes); LANES];
            let (mut samples, mut pixels) = ([0u32; LANES], [0f32; LANES]);
            let (mut sx, mut sy) = ([0f32; LANES], [0f32; LANES]);
            for lane in 0..LANES {
                hashes[lane] = self.pixel_hash(sampling, j, pixel, in_lanes);
                if let Some((_, Some(samples_of), _)) = &self.pixel {
                    (sx[lane], sy[lane]) = samples_of.offset(sample as u32);
                }
                (samples[lane], pixels[lane]) = (sample as u32, pixel as f32);
                // On to the next sample; lanes past the row's end repeat
                // its last one, unread.
                if q + group * LANES + lane < last {
                    sample += 1;
                    if sample == spp {
                        (pixel, sample) = (pixel + 1, 0);
                    }
                }
            }
            let hashed = sample_hashes(hashes, samples);
            let (sx, sy) =
                offsets_x8(sampling, hashed, samples).unwrap_or((f32x8::new(sx), f32x8::new(sy)));
            // `pixel as f32 + sx`, as the scalar camera adds it.
            let column = f32x8::new(pixels) + sx;
            let row = f32x8::splat(j as f32) + sy;
            let at = group * LANES..(group + 1) * LANES;
            let directions = camera.directions(column, row).to_lanes();
            self.direction[at.clone()].copy_from_slice(&directions);
            let states = sample_rngs(hashed, Stream::Path).states();
            self.state[at].copy_from_slice(&states);
        }
    }

    /// Pixel `pixel`'s hash (of row `j`), worked out once per pixel, with
    /// its `PixelSamples` where the points are found one at a time.
    fn pixel_hash(
        &mut self,
        sampling: &Sampling,
        j: u32,
        pixel: usize,
        in_lanes: bool,
    ) -> PixelHash {
        match self.pixel {
            Some((p, _, hash)) if p == pixel => hash,
            _ => {
                let at = (pixel as u32, j);
                let samples = (!in_lanes).then(|| sampling.pixel(at));
                let hash = PixelHash::new(sampling.seed(), at);
                self.pixel = Some((pixel, samples, hash));
                hash
            }
        }
    }
}
