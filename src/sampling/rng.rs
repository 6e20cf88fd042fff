//! The random numbers behind every random choice: one small generator per
//! sample, made from (seed, pixel, sample) alone.
//!
//! A render never shares a generator between pixels or threads. Each
//! sample makes its own, in a few multiplications, from nothing but the
//! render's seed, the pixel and the sample's number, so the numbers a
//! sample sees cannot depend on which thread renders it or in which order
//! the rows are done: the image is the same bytes on 1 or 64 cores.

use rand_core::Rng;
use rand_pcg::Pcg32;

/// Which random choices a generator is for. Each kind gets its own PCG
/// stream (and its own state), so that, say, where a sample lands in its
/// pixel never shares numbers with the path it then follows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stream {
    /// Where in the pixel a sample goes (`jittered`, `random`).
    Offset = 1,
    /// The per-pixel shift of the Halton points (drawn with sample 0).
    Rotation = 2,
    /// Chapter 6's random path: its bounce directions and choices.
    Path = 3,
}

// ANCHOR: hash
/// One round of SplitMix64 (Steele, Lea and Flood, 2014): add the golden
/// ratio constant, then scramble. Any change to one input bit flips about
/// half of the output bits, which is what seeding needs.
#[inline]
pub fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(SPLITMIX_GAMMA);
    z = (z ^ (z >> 30)).wrapping_mul(SPLITMIX_MIX[0]);
    z = (z ^ (z >> 27)).wrapping_mul(SPLITMIX_MIX[1]);
    z ^ (z >> 31)
}

/// SplitMix64's golden ratio increment (an eight-lane SplitMix64 must use
/// the same).
pub const SPLITMIX_GAMMA: u64 = 0x9e37_79b9_7f4a_7c15;
/// SplitMix64's two mixing multipliers, in the order [`splitmix64`] uses them.
pub const SPLITMIX_MIX: [u64; 2] = [0xbf58_476d_1ce4_e5b9, 0x94d0_49bb_1331_11eb];

/// The generator for one sample's random choices of one kind.
///
/// The 64-bit PCG state is a hash of the four inputs, folded in one at a
/// time, each through a round of SplitMix64:
///
/// ```text
/// h = splitmix64(seed)
/// h = splitmix64(h ^ (column << 32 | row))    (PixelHash: once per pixel)
/// h = splitmix64(h ^ sample)
/// h = splitmix64(h ^ stream)
/// generator = Pcg32::new(state = h, stream = stream)
/// ```
///
/// Neighbouring pixels and samples (inputs one bit apart) thus start from
/// unrelated states; the stream number also picks the PCG increment, so
/// two kinds of choice for the same sample are different sequences.
#[inline]
pub fn sample_rng(seed: u64, pixel: (u32, u32), sample: u32, stream: Stream) -> Pcg32 {
    PixelHash::new(seed, pixel).sample_rng(sample, stream)
}

/// The first two rounds of [`sample_rng`]'s hash, which depend on the
/// seed and the pixel only: a pixel's N samples share them, so a renderer
/// hashes them once per pixel rather than N times. The generators are the
/// same either way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelHash(u64);

impl PixelHash {
    /// The hash itself, for a generator that finishes it another way
    /// (eight samples at once).
    #[inline]
    pub fn bits(self) -> u64 {
        self.0
    }

    /// The hash of `seed` and the pixel in `column` and `row`.
    #[inline]
    pub fn new(seed: u64, (column, row): (u32, u32)) -> PixelHash {
        let pixel = (u64::from(column) << 32) | u64::from(row);
        PixelHash(splitmix64(splitmix64(seed) ^ pixel))
    }

    /// The generator for sample `sample`'s choices of kind `stream`.
    #[inline]
    pub fn sample_rng(self, sample: u32, stream: Stream) -> Pcg32 {
        let h = splitmix64(self.0 ^ u64::from(sample));
        let h = splitmix64(h ^ stream as u64);
        Pcg32::new(h, stream as u64)
    }
}
// ANCHOR_END: hash

/// A uniform number in [0, 1) from the top 24 bits of one draw: every
/// value is an exact `f32`, the largest is `1 - 2⁻²⁴`, and 1 never comes.
#[inline]
pub fn unit_f32(rng: &mut Pcg32) -> f32 {
    (rng.next_u32() >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_matches_its_reference_outputs() {
        // The first outputs of the reference SplitMix64 generator seeded
        // with 0 (Vigna's splitmix64.c): each is one round on 0, γ, 2γ.
        const GAMMA: u64 = 0x9e37_79b9_7f4a_7c15;
        assert_eq!(splitmix64(0), 0xe220_a839_7b1d_cdaf);
        assert_eq!(splitmix64(GAMMA), 0x6e78_9e6a_a1b9_65f4);
        assert_eq!(splitmix64(GAMMA.wrapping_mul(2)), 0x06c4_5d18_8009_454f);
    }

    #[test]
    fn a_pixel_hash_made_once_gives_the_generators_of_the_four_round_chain() {
        // The documented chain, written out round by round.
        let (seed, (column, row), sample) = (7u64, (3u32, 4u32), 5u32);
        let mut h = splitmix64(seed);
        h = splitmix64(h ^ ((u64::from(column) << 32) | u64::from(row)));
        h = splitmix64(h ^ u64::from(sample));
        h = splitmix64(h ^ Stream::Offset as u64);
        let mut chain = Pcg32::new(h, Stream::Offset as u64);
        let mut hashed = PixelHash::new(seed, (column, row)).sample_rng(sample, Stream::Offset);
        for _ in 0..4 {
            assert_eq!(chain.next_u32(), hashed.next_u32());
        }
    }

    #[test]
    fn the_same_seed_pixel_and_sample_give_the_same_numbers() {
        let mut a = sample_rng(7, (3, 4), 5, Stream::Offset);
        let mut b = sample_rng(7, (3, 4), 5, Stream::Offset);
        for _ in 0..8 {
            assert_eq!(a.next_u32(), b.next_u32());
        }
    }

    #[test]
    fn changing_any_input_changes_the_numbers() {
        let first =
            |seed, pixel, sample, stream| sample_rng(seed, pixel, sample, stream).next_u64();
        let base = first(7, (3, 4), 5, Stream::Offset);
        assert_ne!(base, first(8, (3, 4), 5, Stream::Offset));
        assert_ne!(base, first(7, (4, 3), 5, Stream::Offset));
        assert_ne!(base, first(7, (3, 5), 5, Stream::Offset));
        assert_ne!(base, first(7, (3, 4), 6, Stream::Offset));
        assert_ne!(base, first(7, (3, 4), 5, Stream::Path));
    }

    #[test]
    fn unit_numbers_are_uniform_in_zero_to_one() {
        // 10,000 draws: the mean of U(0,1) is 1/2 with a standard error of
        // sqrt(1/12 / 10,000) = 0.0029; allow 5 of them.
        let mut rng = sample_rng(1, (0, 0), 0, Stream::Offset);
        let draws: Vec<f32> = (0..10_000).map(|_| unit_f32(&mut rng)).collect();
        assert!(draws.iter().all(|u| (0.0..1.0).contains(u)));
        let mean = draws.iter().map(|&u| f64::from(u)).sum::<f64>() / 10_000.0;
        assert!((mean - 0.5).abs() < 5.0 * 0.0029, "{mean}");
    }
}
