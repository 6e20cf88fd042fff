//! Where inside a pixel its rays go.

/// Offsets `(sx, sy)` ∈ [0,1]² inside a pixel, one per ray; the pixel's
/// colour is the plain average of its rays' colours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SamplePattern {
    name: &'static str,
    offsets: &'static [(f32, f32)],
}

impl SamplePattern {
    /// One ray through the centre of the pixel.
    pub const PIXEL_CENTRE: SamplePattern = SamplePattern {
        name: "the pixel centre",
        offsets: &[(0.5, 0.5)],
    };

    // ANCHOR: lab_five
    /// The lab's anti-aliasing: the centre ray and four more, one in the
    /// middle of each quarter of the pixel. Summed in this order.
    pub const LAB_FIVE: SamplePattern = SamplePattern {
        name: "the lab's five rays",
        offsets: &[
            (0.5, 0.5),
            (0.25, 0.25),
            (0.75, 0.25),
            (0.25, 0.75),
            (0.75, 0.75),
        ],
    };
    // ANCHOR_END: lab_five

    /// Every pattern there is, for `--spp`.
    pub const ALL: [SamplePattern; 2] = [SamplePattern::PIXEL_CENTRE, SamplePattern::LAB_FIVE];

    /// The pattern with `spp` samples per pixel, if there is one.
    pub fn with_samples(spp: u32) -> Option<SamplePattern> {
        SamplePattern::ALL
            .into_iter()
            .find(|p| p.offsets.len() == spp as usize)
    }

    pub fn name(&self) -> &'static str {
        self.name
    }

    pub fn offsets(&self) -> &'static [(f32, f32)] {
        self.offsets
    }

    /// Samples per pixel.
    pub fn len(&self) -> usize {
        self.offsets.len()
    }

    pub fn is_empty(&self) -> bool {
        self.offsets.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_sample_per_pixel_goes_through_the_centre() {
        assert_eq!(
            SamplePattern::with_samples(1).unwrap().offsets(),
            &[(0.5, 0.5)]
        );
    }

    #[test]
    fn the_lab_pattern_starts_at_the_centre_and_covers_the_four_quarters() {
        let five = SamplePattern::with_samples(5).unwrap();
        assert_eq!(five.offsets()[0], (0.5, 0.5));
        let mean_x: f32 = five.offsets().iter().map(|o| o.0).sum::<f32>() / 5.0;
        let mean_y: f32 = five.offsets().iter().map(|o| o.1).sum::<f32>() / 5.0;
        assert_eq!((mean_x, mean_y), (0.5, 0.5));
    }

    #[test]
    fn there_is_no_pattern_with_three_samples() {
        assert_eq!(SamplePattern::with_samples(3), None);
    }
}
