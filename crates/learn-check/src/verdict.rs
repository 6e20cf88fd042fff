//! Where a check stopped: the one answer every stage of a check gives
//! (the build, the test run, the picture), in a module of its own so that
//! the stages and the checks that run them all use it without using each
//! other.

use crate::compare::Comparison;
use crate::noisy::NoiseAgreement;

/// Where the check stopped.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// It compiles, its tests pass and its render matches: done.
    Passed,
    NoExercise,
    DoesNotCompile,
    TestsFail {
        failed: usize,
        of: usize,
        /// The failing tests, by their function names (`tests::…`): what
        /// the catalogue of mistakes matches.
        failing: Vec<String>,
        /// Their messages, in the same order.
        messages: Vec<String>,
    },
    TestsTimedOut,
    RenderPanicked(String),
    RenderTimedOut,
    NonFinite(usize),
    Differs(Comparison),
    /// Chapter 6: the render is further from the reference than the two
    /// renders' noise allows.
    NoisyDiffers(NoiseAgreement),
    /// The learner's file lost the marker lines the check needs.
    Markers(String),
    /// Something outside the learner's code went wrong (cargo missing …).
    Broken(String),
}

impl Verdict {
    pub fn passed(&self) -> bool {
        *self == Verdict::Passed
    }
}
