//! Where inside a pixel its rays go (the lab model, "Anti-aliasing" and "More rays
//! per pixel").
//!
//! A pixel's colour is the plain average of its samples' colours. The
//! lab's defaults are fixed points: the pixel centre for one sample, the
//! lab's five for five. Any other count uses a [`Pattern`]; the random
//! ones draw from a generator seeded by (seed, pixel, sample) alone
//! ([`sample_rng`]), so a render is the same bytes on any number of threads.

mod halton;
mod rng;

use std::fmt;

pub use halton::{ONE_BELOW, halton_2_3, radical_inverse};
pub use rng::{PixelHash, SPLITMIX_GAMMA, SPLITMIX_MIX, Stream, sample_rng, splitmix64, unit_f32};

/// The most samples per pixel accepted (a 64 × 64 grid).
pub const MAX_SPP: u32 = 4096;

// ANCHOR: lab_five
/// The lab's anti-aliasing: the centre ray and four more, one in the
/// middle of each quarter of the pixel. Summed in this order.
pub const LAB_FIVE: [(f32, f32); 5] = [
    (0.5, 0.5),
    (0.25, 0.25),
    (0.75, 0.25),
    (0.25, 0.75),
    (0.75, 0.75),
];
// ANCHOR_END: lab_five

/// `--pattern`: where a pixel's N samples go.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Pattern {
    /// The centres of an m × m grid of cells (N = m²).
    Grid,
    /// Stratified: one uniformly random point in each cell of an m × m grid.
    Jittered,
    /// N independent uniform points.
    Random,
    /// The first N Halton points in bases 2 and 3, shifted by a random
    /// offset per pixel (Cranley–Patterson rotation).
    Halton,
}

impl Pattern {
    /// Every pattern, in the order `--help` lists them.
    pub const ALL: [Pattern; 4] = [
        Pattern::Grid,
        Pattern::Jittered,
        Pattern::Random,
        Pattern::Halton,
    ];

    /// The name `--pattern` takes.
    pub fn name(self) -> &'static str {
        match self {
            Pattern::Grid => "grid",
            Pattern::Jittered => "jittered",
            Pattern::Random => "random",
            Pattern::Halton => "halton",
        }
    }

    /// The pattern called `name`, if there is one.
    pub fn from_name(name: &str) -> Option<Pattern> {
        Pattern::ALL.into_iter().find(|p| p.name() == name)
    }

    /// Whether the pattern is made of m × m cells, and so needs N = m².
    pub fn needs_square(self) -> bool {
        matches!(self, Pattern::Grid | Pattern::Jittered)
    }

    /// Whether its points depend on the seed.
    pub fn is_random(self) -> bool {
        self != Pattern::Grid
    }

    /// The pattern used for `spp` samples when none is asked for (and
    /// `spp` is neither 1 nor 5): jittered where `spp` is a square, which
    /// has the least error of the four (chapter 5 measures it), else halton.
    pub fn default_for(spp: u32) -> Pattern {
        if square_root(spp).is_some() {
            Pattern::Jittered
        } else {
            Pattern::Halton
        }
    }
}

impl fmt::Display for Pattern {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Where a render's sample points come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// One ray through the centre of the pixel (the lab model, `--spp 1`).
    PixelCentre,
    /// [`LAB_FIVE`] (the lab model, `--spp 5`).
    LabFive,
    /// Any count, any pattern ("More rays per pixel").
    Pattern(Pattern),
}

/// Why a sampling cannot be made; each is one line for the learner.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SamplingError {
    /// Rays per pixel outside 1 to [`MAX_SPP`].
    #[error("rays per pixel must be a whole number from 1 to {MAX_SPP}, not {0}")]
    Count(u32),
    /// A grid pattern asked for a number of rays that is not a square.
    #[error(
        "--pattern {pattern} needs a square number of rays per pixel (m × m), and {spp} is not \
         one: try --spp {below} or --spp {above}"
    )]
    NotSquare {
        /// The pattern asked for (`grid` or `jittered`).
        pattern: Pattern,
        /// The rays per pixel asked for.
        spp: u32,
        /// The nearest square below it.
        below: u32,
        /// The nearest square above it.
        above: u32,
    },
}

/// A render's samples: how many per pixel, where, and the seed of every
/// random choice. `--spp 1` is the pixel centre and `--spp 5` the lab's
/// five, exactly as the lab has them, unless a pattern is asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sampling {
    spp: u32,
    layout: Layout,
    seed: u64,
    /// m, the side of the m × m grid of cells (1 for the other layouts).
    side: u32,
    /// The points of [`Layout::LabFive`]: [`LAB_FIVE`], or the five the
    /// chapter's step gives ([`Sampling::with_lab_five`]).
    five: [(f32, f32); 5],
}

impl Sampling {
    /// One ray through each pixel's centre, as the lab model's chapters 1-4.
    pub const PIXEL_CENTRE: Sampling = Sampling {
        spp: 1,
        layout: Layout::PixelCentre,
        seed: 0,
        side: 1,
        five: LAB_FIVE,
    };

    /// The lab's five rays, as the lab model's chapter 5.
    pub const LAB_FIVE: Sampling = Sampling {
        spp: 5,
        layout: Layout::LabFive,
        seed: 0,
        side: 1,
        five: LAB_FIVE,
    };

    /// `spp` samples per pixel in `pattern` (or, without one, the lab's
    /// points for 1 and 5 and [`Pattern::default_for`] otherwise), with
    /// `seed` for the random patterns.
    pub fn new(spp: u32, pattern: Option<Pattern>, seed: u64) -> Result<Sampling, SamplingError> {
        if !(1..=MAX_SPP).contains(&spp) {
            return Err(SamplingError::Count(spp));
        }
        let layout = match (pattern, spp) {
            (None, 1) => Layout::PixelCentre,
            (None, 5) => Layout::LabFive,
            (None, _) => Layout::Pattern(Pattern::default_for(spp)),
            (Some(p), _) => Layout::Pattern(p),
        };
        let side = match layout {
            Layout::Pattern(p) if p.needs_square() => {
                square_root(spp).ok_or_else(|| nearest_squares(p, spp))?
            }
            _ => 1,
        };
        Ok(Sampling {
            spp,
            layout,
            seed,
            side,
            five: LAB_FIVE,
        })
    }

    /// The same sampling with `five` as the lab's five points: how a
    /// chapter's own [`Step::lab_five`](crate::Step::lab_five) reaches every
    /// render, probe and sweep of `--spp 5`. The other layouts ignore it.
    pub fn with_lab_five(self, five: [(f32, f32); 5]) -> Sampling {
        Sampling { five, ..self }
    }

    /// Samples per pixel.
    pub fn spp(&self) -> u32 {
        self.spp
    }

    /// The seed of every random choice of a render.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// How a pixel's samples are laid out (what `--spp` and `--pattern` chose).
    pub fn layout(&self) -> Layout {
        self.layout
    }

    /// m, the side of the m × m grid of cells of `grid` and `jittered`
    /// (1 for the other layouts).
    pub fn side(&self) -> u32 {
        self.side
    }

    /// The pattern, or `None` for the lab's fixed points.
    pub fn pattern(&self) -> Option<Pattern> {
        match self.layout {
            Layout::Pattern(p) => Some(p),
            Layout::PixelCentre | Layout::LabFive => None,
        }
    }

    /// Whether the seed changes the image.
    pub fn is_random(&self) -> bool {
        self.pattern().is_some_and(Pattern::is_random)
    }

    /// What pixel `pixel`'s samples share, worked out once for all of them.
    #[inline]
    pub fn pixel(&self, pixel: (u32, u32)) -> PixelSamples {
        // Fixed points need no hash: the pixel centre, the lab's five and
        // the grid cost nothing per pixel.
        let hash = self.is_random().then(|| PixelHash::new(self.seed, pixel));
        let shift = match (self.layout, hash) {
            // One shift for the whole pixel, drawn as its sample 0.
            (Layout::Pattern(Pattern::Halton), Some(hash)) => {
                let mut shift = hash.sample_rng(0, Stream::Rotation);
                (unit_f32(&mut shift), unit_f32(&mut shift))
            }
            _ => (0.0, 0.0),
        };
        PixelSamples {
            sampling: *self,
            hash,
            shift,
        }
    }

    /// The offset (sx, sy) in [0,1)² of sample `sample` (from 0, below
    /// [`Sampling::spp`]) of pixel `pixel` (column, row). Pure: it depends
    /// on (seed, pixel, sample) only, never on what was drawn before.
    pub fn offset(&self, pixel: (u32, u32), sample: u32) -> (f32, f32) {
        self.pixel(pixel).offset(sample)
    }

    /// Every sample's offset in pixel `pixel`, in the order they are summed.
    pub fn offsets(&self, pixel: (u32, u32)) -> impl Iterator<Item = (f32, f32)> + use<> {
        let samples = self.pixel(pixel);
        (0..self.spp).map(move |k| samples.offset(k))
    }
}

/// One pixel's samples ([`Sampling::pixel`]): the pixel's part of every
/// sample's hash, and halton's shift, computed once rather than per sample.
#[derive(Clone, Copy, Debug)]
pub struct PixelSamples {
    sampling: Sampling,
    /// `None` for the patterns that draw no random numbers.
    hash: Option<PixelHash>,
    /// Halton's per-pixel shift (Cranley–Patterson rotation).
    shift: (f32, f32),
}

impl PixelSamples {
    // ANCHOR: offset
    /// The offset (sx, sy) in [0,1)² of sample `sample` of this pixel.
    /// Pure: it depends on (seed, pixel, sample) only, never on what was
    /// drawn before, so any order of samples gives the same points.
    #[inline]
    pub fn offset(&self, sample: u32) -> (f32, f32) {
        let s = &self.sampling;
        debug_assert!(sample < s.spp, "sample {sample} of {}", s.spp);
        let pattern = match s.layout {
            Layout::PixelCentre => return (0.5, 0.5),
            Layout::LabFive => return s.five[sample as usize],
            Layout::Pattern(p) => p,
        };
        let m = s.side as f32;
        // Cells are numbered row by row, left to right.
        let cell = ((sample % s.side) as f32, (sample / s.side) as f32);
        let rng = || {
            let hash = self.hash.expect("a random pattern hashes its pixel");
            hash.sample_rng(sample, Stream::Offset)
        };
        match pattern {
            Pattern::Grid => ((cell.0 + 0.5) / m, (cell.1 + 0.5) / m),
            Pattern::Jittered => {
                let mut rng = rng();
                let (u, v) = (unit_f32(&mut rng), unit_f32(&mut rng));
                // (m - 1 + u) / m can round up to 1 for large m: keep it below.
                let x = ((cell.0 + u) / m).min(ONE_BELOW);
                let y = ((cell.1 + v) / m).min(ONE_BELOW);
                (x, y)
            }
            Pattern::Random => {
                let mut rng = rng();
                (unit_f32(&mut rng), unit_f32(&mut rng))
            }
            Pattern::Halton => {
                let (hx, hy) = halton_2_3(sample);
                (wrap(hx + self.shift.0), wrap(hy + self.shift.1))
            }
        }
    }
    // ANCHOR_END: offset
}

/// `x` modulo 1, for `x` in [0, 2): the subtraction is exact (Sterbenz).
fn wrap(x: f32) -> f32 {
    if x >= 1.0 { x - 1.0 } else { x }
}

/// `m` where `n = m²`.
fn square_root(n: u32) -> Option<u32> {
    let m = n.isqrt();
    (m * m == n).then_some(m)
}

fn nearest_squares(pattern: Pattern, spp: u32) -> SamplingError {
    let m = spp.isqrt();
    SamplingError::NotSquare {
        pattern,
        spp,
        below: m * m,
        above: (m + 1) * (m + 1),
    }
}

/// "5 spp", or "64 spp jittered, seed 0": what the summary line says.
impl fmt::Display for Sampling {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} spp", self.spp)?;
        match self.pattern() {
            None => Ok(()),
            Some(p) if p.is_random() => write!(f, " {p}, seed {}", self.seed),
            Some(p) => write!(f, " {p}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sampling(spp: u32, pattern: Pattern, seed: u64) -> Sampling {
        Sampling::new(spp, Some(pattern), seed).unwrap()
    }

    #[test]
    fn one_sample_per_pixel_goes_through_the_centre() {
        let one = Sampling::new(1, None, 0).unwrap();
        assert_eq!(one, Sampling::PIXEL_CENTRE);
        assert_eq!(one.offsets((3, 7)).collect::<Vec<_>>(), [(0.5, 0.5)]);
    }

    #[test]
    fn five_samples_are_the_lab_five_whatever_the_seed() {
        let five = Sampling::new(5, None, 99).unwrap();
        assert_eq!(five.layout(), Layout::LabFive);
        assert_eq!(five.offsets((3, 7)).collect::<Vec<_>>(), LAB_FIVE);
    }

    #[test]
    fn the_lab_pattern_starts_at_the_centre_and_covers_the_four_quarters() {
        assert_eq!(LAB_FIVE[0], (0.5, 0.5));
        let mean_x: f32 = LAB_FIVE.iter().map(|o| o.0).sum::<f32>() / 5.0;
        let mean_y: f32 = LAB_FIVE.iter().map(|o| o.1).sum::<f32>() / 5.0;
        assert_eq!((mean_x, mean_y), (0.5, 0.5));
    }

    #[test]
    fn a_grid_of_16_samples_is_the_centres_of_4_by_4_cells() {
        let grid: Vec<_> = sampling(16, Pattern::Grid, 0).offsets((0, 0)).collect();
        let centres = [0.125, 0.375, 0.625, 0.875];
        let expected: Vec<_> = centres
            .iter()
            .flat_map(|&y| centres.iter().map(move |&x| (x, y)))
            .collect();
        assert_eq!(grid, expected);
    }

    #[test]
    fn jittered_points_stay_inside_their_own_cells() {
        for spp in [4, 16, 64, 4096] {
            let jittered = sampling(spp, Pattern::Jittered, 3);
            let m = spp.isqrt();
            for pixel in [(0, 0), (799, 599), (123, 45)] {
                for (k, (x, y)) in jittered.offsets(pixel).enumerate() {
                    let (cx, cy) = ((k as u32 % m) as f32, (k as u32 / m) as f32);
                    let m = m as f32;
                    assert!(
                        cx / m <= x && x <= (cx + 1.0) / m,
                        "{spp}: x {x} in cell {cx}"
                    );
                    assert!(
                        cy / m <= y && y <= (cy + 1.0) / m,
                        "{spp}: y {y} in cell {cy}"
                    );
                }
            }
        }
    }

    #[test]
    fn halton_points_are_the_sequence_shifted_by_one_offset_per_pixel() {
        let halton = sampling(8, Pattern::Halton, 5);
        let points: Vec<_> = halton.offsets((10, 20)).collect();
        // Undo the shift with the first point, whose unshifted value is (1/2, 1/3).
        let shift = (points[0].0 - 0.5, points[0].1 - 1.0 / 3.0);
        for (k, &(x, y)) in points.iter().enumerate() {
            let (hx, hy) = halton_2_3(k as u32);
            let unshifted = ((x - shift.0).rem_euclid(1.0), (y - shift.1).rem_euclid(1.0));
            assert!((unshifted.0 - hx).abs() < 1e-6, "{k}: {unshifted:?}");
            assert!((unshifted.1 - hy).abs() < 1e-6, "{k}: {unshifted:?}");
        }
        let other_pixel: Vec<_> = halton.offsets((11, 20)).collect();
        assert_ne!(points, other_pixel, "each pixel has its own shift");
    }

    #[test]
    fn every_offset_of_every_pattern_lies_in_the_unit_square() {
        for pattern in Pattern::ALL {
            for spp in [1, 4, 9, 256, 4096] {
                let s = sampling(spp, pattern, 11);
                for pixel in [(0, 0), (1, 0), (16_383, 16_383)] {
                    for (x, y) in s.offsets(pixel) {
                        assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
                    }
                }
            }
        }
    }

    #[test]
    fn the_same_seed_gives_the_same_offsets_and_another_seed_others() {
        for pattern in [Pattern::Jittered, Pattern::Random, Pattern::Halton] {
            let a: Vec<_> = sampling(16, pattern, 1).offsets((4, 2)).collect();
            let again: Vec<_> = sampling(16, pattern, 1).offsets((4, 2)).collect();
            let b: Vec<_> = sampling(16, pattern, 2).offsets((4, 2)).collect();
            assert_eq!(a, again, "{pattern}");
            assert_ne!(a, b, "{pattern}");
        }
        let grid = |seed| {
            sampling(16, Pattern::Grid, seed)
                .offsets((4, 2))
                .collect::<Vec<_>>()
        };
        assert_eq!(grid(1), grid(2), "the grid has no random choice");
    }

    #[test]
    fn random_points_have_the_mean_of_a_uniform_square() {
        // 4096 points: each coordinate's mean is 1/2 with a standard error
        // of sqrt(1/12 / 4096) = 0.0045; allow 5 of them.
        let points: Vec<_> = sampling(4096, Pattern::Random, 8).offsets((1, 1)).collect();
        let mean = |f: fn(&(f32, f32)) -> f32| points.iter().map(f).sum::<f32>() / 4096.0;
        assert!((mean(|p| p.0) - 0.5).abs() < 5.0 * 0.0045);
        assert!((mean(|p| p.1) - 0.5).abs() < 5.0 * 0.0045);
    }

    #[test]
    fn other_counts_default_to_jittered_for_squares_and_halton_otherwise() {
        assert_eq!(
            Sampling::new(16, None, 0).unwrap().pattern(),
            Some(Pattern::Jittered)
        );
        assert_eq!(
            Sampling::new(10, None, 0).unwrap().pattern(),
            Some(Pattern::Halton)
        );
        assert_eq!(
            Sampling::new(2, None, 0).unwrap().pattern(),
            Some(Pattern::Halton)
        );
    }

    #[test]
    fn a_grid_of_10_is_refused_with_the_nearest_squares() {
        let error = Sampling::new(10, Some(Pattern::Grid), 0).unwrap_err();
        assert_eq!(
            error.to_string(),
            "--pattern grid needs a square number of rays per pixel (m × m), and 10 is not one: \
             try --spp 9 or --spp 16"
        );
        assert!(Sampling::new(5, Some(Pattern::Jittered), 0).is_err());
        assert!(Sampling::new(5, Some(Pattern::Random), 0).is_ok());
    }

    #[test]
    fn counts_outside_1_to_4096_are_refused() {
        assert_eq!(Sampling::new(0, None, 0), Err(SamplingError::Count(0)));
        assert_eq!(
            Sampling::new(4097, None, 0),
            Err(SamplingError::Count(4097))
        );
        assert!(Sampling::new(4096, Some(Pattern::Grid), 0).is_ok());
    }

    #[test]
    fn the_summary_names_the_pattern_and_seed_only_where_they_matter() {
        assert_eq!(Sampling::LAB_FIVE.to_string(), "5 spp");
        assert_eq!(sampling(16, Pattern::Grid, 3).to_string(), "16 spp grid");
        assert_eq!(
            sampling(64, Pattern::Jittered, 3).to_string(),
            "64 spp jittered, seed 3"
        );
    }
}
