//! How busy the eight lanes are: for each step of a bounce, how many
//! lanes it runs for, on average, when it runs at all.
//!
//! A step runs when any lane needs it, and costs the same for one lane as
//! for eight; the lanes that do not need it wait. The camera rays and the
//! nearest hit run for every path in flight, but a wave of paths diverges
//! at its first surface: some escape to the sky, some scatter off matte
//! surfaces, some off the mirror or the glass. This is where chapter 8
//! loses what chapter 7 keeps (the book's figure of it).

use wide::f32x8;

use raylab_lanes::LANES;

/// The steps of [`crate::paths::Paths::bounce`] that run only for some lanes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// The nearest hit of every path in flight.
    Trace,
    /// The sky and the sun's disc, for the paths that left the scene.
    Escape,
    /// The hit record and the choice of lobe, for the paths that hit.
    Surface,
    /// The sun by next-event estimation and a new cosine direction.
    Diffuse,
    /// The shadow ray towards the sun, where a diffuse surface faces it.
    ShadowRay,
    /// The mirror direction, or the refracted one.
    Specular,
    /// The caustic lookup on the ground (`--caustics`).
    Caustics,
}

impl Stage {
    pub const ALL: [Stage; 7] = [
        Stage::Trace,
        Stage::Escape,
        Stage::Surface,
        Stage::Diffuse,
        Stage::ShadowRay,
        Stage::Specular,
        Stage::Caustics,
    ];

    /// What the step does, for a figure's label.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Trace => "nearest hit",
            Stage::Escape => "sky (escaped)",
            Stage::Surface => "hit record, lobe",
            Stage::Diffuse => "matte: sun, new direction",
            Stage::ShadowRay => "shadow ray",
            Stage::Specular => "mirror or glass",
            Stage::Caustics => "caustic lookup",
        }
    }
}

/// Per stage: how often it ran, and for how many lanes in all.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LaneUse {
    runs: [u64; Stage::ALL.len()],
    lanes: [u64; Stage::ALL.len()],
}

impl LaneUse {
    /// `stage` is about to run for the lanes of `mask` (if any).
    #[inline]
    pub fn note(&mut self, stage: Stage, mask: f32x8) {
        let busy = u64::from((mask.move_mask() as u32 & 0xff).count_ones());
        if busy > 0 {
            self.runs[stage as usize] += 1;
            self.lanes[stage as usize] += busy;
        }
    }

    /// How many times `stage` ran.
    pub fn runs(&self, stage: Stage) -> u64 {
        self.runs[stage as usize]
    }

    /// The share of the eight lanes busy when `stage` ran (0 if it never did).
    pub fn share(&self, stage: Stage) -> f64 {
        let runs = self.runs(stage);
        if runs == 0 {
            return 0.0;
        }
        self.lanes[stage as usize] as f64 / (runs * LANES as u64) as f64
    }

    /// Both tallies together.
    pub fn add(&mut self, other: &LaneUse) {
        for i in 0..Stage::ALL.len() {
            self.runs[i] += other.runs[i];
            self.lanes[i] += other.lanes[i];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab_lanes::mask_from_bits;

    #[test]
    fn a_step_run_for_three_lanes_then_for_eight_is_eleven_sixteenths_busy() {
        let mut used = LaneUse::default();
        used.note(Stage::Specular, mask_from_bits(0b0010_0101));
        used.note(Stage::Specular, mask_from_bits(0xff));
        // A mask of no lanes: the step does not run.
        used.note(Stage::Specular, mask_from_bits(0));
        assert_eq!(used.runs(Stage::Specular), 2);
        assert_eq!(used.share(Stage::Specular), 11.0 / 16.0);
        assert_eq!(used.share(Stage::Escape), 0.0);
    }
}
