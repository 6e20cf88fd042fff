//! What a check allows: how long the exercise's tests and its render may
//! run, and the render's size. Here, not in the checker, because `learn
//! hint` tells the learner about them without building the checker.

use std::time::Duration;

/// The check's image size: small enough to render in a blink, large
/// enough that every object, shadow and reflection covers many pixels.
pub const WIDTH: u32 = 160;
pub const HEIGHT: u32 = 120;

/// How long the step's tests may run before the check stops them: far
/// more than they need (milliseconds), so only a step that never ends
/// reaches it.
pub const TEST_TIME_LIMIT: Duration = Duration::from_secs(30);
/// The same for the small render.
pub const RENDER_TIME_LIMIT: Duration = Duration::from_secs(30);

/// How long the tests and the render may run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    pub tests: Duration,
    pub render: Duration,
}

impl Limits {
    pub const DEFAULT: Limits = Limits {
        tests: TEST_TIME_LIMIT,
        render: RENDER_TIME_LIMIT,
    };
}
