//! TEMPORARY: the part of `raylab::sampling` (SAMPLING-API.md, being built
//! on branch `sampling`) that this chapter uses, so that it can be written
//! against that API now. Deleted when that branch is merged.

use rand_pcg::Pcg32;

/// `--pattern`: where a pixel's samples go.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Pattern {
    Jittered,
    Random,
}

/// Which random choices a generator is for, so that they never share numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stream {
    Offset,
    Path,
}

/// A render's samples: how many per pixel, where, and the seed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sampling {
    spp: u32,
    pattern: Pattern,
    seed: u64,
}

impl Sampling {
    pub fn new(spp: u32, pattern: Option<Pattern>, seed: u64) -> Result<Sampling, String> {
        let pattern = pattern.unwrap_or(Pattern::Random);
        let side = (spp as f64).sqrt().round() as u32;
        if pattern == Pattern::Jittered && side * side != spp {
            return Err(format!(
                "--pattern jittered needs a square number of rays per pixel (4, 16, 256, …), not {spp}"
            ));
        }
        Ok(Sampling { spp, pattern, seed })
    }

    pub fn spp(&self) -> u32 {
        self.spp
    }

    pub fn seed(&self) -> u64 {
        self.seed
    }

    pub fn pattern(&self) -> Pattern {
        self.pattern
    }

    /// The offset in [0,1)² of sample `sample` of pixel `pixel`.
    pub fn offset(&self, pixel: (u32, u32), sample: u32) -> (f32, f32) {
        let mut rng = sample_rng(self.seed, pixel, sample, Stream::Offset);
        let (u, v) = (unit(&mut rng), unit(&mut rng));
        match self.pattern {
            Pattern::Random => (u, v),
            Pattern::Jittered => {
                let side = (self.spp as f64).sqrt().round() as u32;
                let (cx, cy) = (sample % side, sample / side);
                ((cx as f32 + u) / side as f32, (cy as f32 + v) / side as f32)
            }
        }
    }
}

/// The generator for one sample's random choices: PCG32 seeded by a hash
/// of (seed, pixel, sample), with `stream` as its PCG stream.
pub fn sample_rng(seed: u64, pixel: (u32, u32), sample: u32, stream: Stream) -> Pcg32 {
    let key = mix(seed
        ^ mix((u64::from(pixel.0) << 32) | u64::from(pixel.1))
        ^ mix(u64::from(sample) + 0x9e37_79b9));
    Pcg32::new(key, stream as u64)
}

/// SplitMix64's finaliser: every input bit moves every output bit.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

fn unit(rng: &mut Pcg32) -> f32 {
    use rand_core::Rng;
    (rng.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0)
}
