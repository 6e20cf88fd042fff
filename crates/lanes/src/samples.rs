//! Where a pixel's samples go, eight samples at a time: the points of the
//! patterns that draw theirs (`jittered`, `random`), from the same
//! generators and with the same arithmetic as `PixelSamples::offset`.

use raylab::sampling::{Layout, ONE_BELOW, Pattern, Sampling, Stream};
use wide::f32x8;

use crate::rng::{U64x8, lane_mask, sample_rngs};

/// Whether [`offsets_x8`] finds `sampling`'s points eight at a time.
pub fn offsets_in_lanes(sampling: &Sampling) -> bool {
    matches!(
        sampling.layout(),
        Layout::Pattern(Pattern::Jittered | Pattern::Random)
    )
}

/// `PixelSamples::offset` of eight samples at once, for the patterns that
/// draw their points (`jittered`, `random`): lane `l` is sample
/// `samples[l]`, whose [`sample_hashes`](crate::rng::sample_hashes) are
/// `hashes`. The same numbers from the same generators, and the same
/// arithmetic, lane by lane. `None` for the other layouts, whose points
/// cost little one at a time.
pub fn offsets_x8(sampling: &Sampling, hashes: U64x8, samples: [u32; 8]) -> Option<(f32x8, f32x8)> {
    if !offsets_in_lanes(sampling) {
        return None;
    }
    let mut rng = sample_rngs(hashes, Stream::Offset);
    let every = lane_mask(0xff);
    let (u, v) = (rng.uniform(every), rng.uniform(every));
    if sampling.layout() == Layout::Pattern(Pattern::Random) {
        return Some((u, v));
    }
    let side = sampling.side();
    let m = f32x8::splat(side as f32);
    let column = f32x8::new(samples.map(|k| (k % side) as f32));
    let row = f32x8::new(samples.map(|k| (k / side) as f32));
    let below = f32x8::splat(ONE_BELOW);
    Some((((column + u) / m).min(below), ((row + v) / m).min(below)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::sample_hashes;
    use raylab::sampling::PixelHash;

    fn sampling(spp: u32, pattern: Pattern, seed: u64) -> Sampling {
        Sampling::new(spp, Some(pattern), seed).unwrap()
    }

    #[test]
    fn eight_jittered_or_random_points_at_once_are_offset_s_points_to_the_bit() {
        // Lanes across two pixels (sample numbers wrap at spp), with the
        // last cells of a large grid, where the clamp below 1 matters.
        for (spp, pattern, seed) in [
            (16, Pattern::Jittered, 0),
            (4096, Pattern::Jittered, 9),
            (7, Pattern::Random, 3),
            (16, Pattern::Random, 0),
        ] {
            let s = sampling(spp, pattern, seed);
            assert!(offsets_in_lanes(&s));
            for first in [0, spp - 3, spp * 2 - 8] {
                let samples: [u32; 8] = std::array::from_fn(|l| first + l as u32);
                let pixel = |k: u32| (5 + k / spp, 2);
                let hashes: [PixelHash; 8] = samples.map(|k| PixelHash::new(seed, pixel(k)));
                let within = samples.map(|k| k % spp);
                let (x, y) =
                    offsets_x8(&s, sample_hashes(hashes, within), within).expect("drawn in lanes");
                for (l, &k) in samples.iter().enumerate() {
                    let expected = s.offset(pixel(k), k % spp);
                    assert_eq!(
                        (x.as_array_ref()[l], y.as_array_ref()[l]),
                        expected,
                        "{s}, sample {k}"
                    );
                }
            }
        }
        // The fixed points and halton are found one at a time.
        assert!(!offsets_in_lanes(&Sampling::LAB_FIVE));
        assert!(!offsets_in_lanes(&sampling(16, Pattern::Halton, 1)));
        assert!(!offsets_in_lanes(&sampling(16, Pattern::Grid, 1)));
    }
}
