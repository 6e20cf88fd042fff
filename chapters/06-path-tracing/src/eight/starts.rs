//! A row's samples made ready eight at a time: where each one's camera ray
//! goes, and the state of its path's generator.
//!
//! A lane takes a new sample whenever its path ends, and only a few lanes
//! end at once. Seeding a generator and drawing a sample's point in the
//! pixel are the same work for every sample, so they are done ahead, for
//! a block of the row's next samples, eight lanes at a time with every
//! lane busy; a lane that starts a sample then only reads its numbers.

use raylab::lanes::LANES;
use raylab::sampling::lanes::{sample_hashes, sample_rngs};
use raylab::sampling::{PixelHash, PixelSamples, Sampling, Stream};
use wide::f32x8;

/// How many samples are made ready at a time.
const BLOCK: usize = 8 * LANES;

/// The next samples of a row, `first ..`: their places in the image and
/// their generators' states.
pub(super) struct Starts {
    first: usize,
    len: usize,
    column: [f32; BLOCK],
    row: [f32; BLOCK],
    state: [u64; BLOCK],
    /// The pixel whose samples were made last, with what they share.
    pixel: Option<(usize, PixelSamples, PixelHash)>,
}

impl Default for Starts {
    fn default() -> Starts {
        Starts {
            first: 0,
            len: 0,
            column: [0.0; BLOCK],
            row: [0.0; BLOCK],
            state: [0; BLOCK],
            pixel: None,
        }
    }
}

/// Sample `q` of row `j`: where its camera ray goes through the image
/// (`column`, `row`, in pixels) and its path generator's state.
pub(super) struct Start {
    pub column: f32,
    pub row: f32,
    pub state: u64,
}

impl Starts {
    /// Start row `j` afresh.
    pub fn clear(&mut self) {
        (self.first, self.len, self.pixel) = (0, 0, None);
    }

    /// Sample `q` of row `j` (pixel `q / spp`'s sample `q % spp`), made in
    /// a block with those after it when it is not made yet. Samples are
    /// asked for in order.
    pub fn get(&mut self, sampling: &Sampling, j: u32, q: usize) -> Start {
        if q >= self.first + self.len {
            self.make(sampling, j, q);
        }
        let k = q - self.first;
        Start {
            column: self.column[k],
            row: self.row[k],
            state: self.state[k],
        }
    }

    /// Samples `q .. q + BLOCK`, eight at a time, exactly as the scalar
    /// tracer makes each one: its point from `PixelSamples::offset` and
    /// its generator from `PixelHash::sample_rng(sample, Stream::Path)`.
    fn make(&mut self, sampling: &Sampling, j: u32, q: usize) {
        let spp = sampling.spp() as usize;
        (self.first, self.len) = (q, BLOCK);
        let any_hash = PixelHash::new(0, (0, 0));
        for group in 0..BLOCK / LANES {
            let mut hashes = [any_hash; LANES];
            let (mut samples, mut pixels) = ([0u32; LANES], [0f32; LANES]);
            let (mut sx, mut sy) = ([0f32; LANES], [0f32; LANES]);
            for lane in 0..LANES {
                let q = q + group * LANES + lane;
                let (pixel, sample) = (q / spp, (q % spp) as u32);
                let (_, samples_of, hash) = match self.pixel {
                    Some(ref p) if p.0 == pixel => p,
                    _ => self.pixel.insert((
                        pixel,
                        sampling.pixel((pixel as u32, j)),
                        PixelHash::new(sampling.seed(), (pixel as u32, j)),
                    )),
                };
                if !sampling.offsets_in_lanes() {
                    (sx[lane], sy[lane]) = samples_of.offset(sample);
                }
                (hashes[lane], samples[lane], pixels[lane]) = (*hash, sample, pixel as f32);
            }
            let hashed = sample_hashes(hashes, samples);
            let (sx, sy) = sampling
                .offsets_x8(hashed, samples)
                .unwrap_or((f32x8::new(sx), f32x8::new(sy)));
            // `pixel as f32 + sx`, as the scalar camera adds it.
            let column = f32x8::new(pixels) + sx;
            let row = f32x8::splat(j as f32) + sy;
            let at = group * LANES..(group + 1) * LANES;
            self.column[at.clone()].copy_from_slice(column.as_array_ref());
            self.row[at.clone()].copy_from_slice(row.as_array_ref());
            let states = sample_rngs(hashed, Stream::Path).states();
            self.state[at].copy_from_slice(&states);
        }
    }
}
