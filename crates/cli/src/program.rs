//! What a program is to the bench: a chapter's name, defaults, step and
//! renderer ([`Chapter`]), or only its name and defaults ([`Program`]) for
//! a program that does not render through the Whitted step.

use raylab::camera::Camera;
use raylab::frame::{Keep, Rendered, Settings};
use raylab::probe::ProbeTarget;
use raylab::render::Progress;
use raylab::scene::Scene;
use raylab::trace::Step;

/// How a program renders its whole image with its step: the core's
/// [`raylab::render()`], one ray at a time, unless the chapter brings a
/// faster renderer of its own that makes the same bytes (chapter 7's
/// waves). The probe and the depth sweep always trace one ray at a time.
pub type Renderer<S> = fn(&Scene, &Camera, &S, &Settings, Keep, &dyn Progress) -> Rendered;

/// One step of the workbook: its program's name, its defaults, its step.
pub struct Chapter<S: Step> {
    /// The binary's name, e.g. `ch01-ray-cast`; also the default output folder.
    pub binary: &'static str,
    /// One line for `--help`.
    pub about: &'static str,
    /// The default `--max-depth` (the lab model's chapter table).
    pub max_depth: u32,
    /// The default `--spp`.
    pub spp: u32,
    /// The pixel whose ray tree is drawn when `--probe` is not given.
    pub probe: ProbeTarget,
    pub step: S,
    /// How the program renders its image.
    pub render: Renderer<S>,
}

/// What the shared command line needs to know of a program: its name, its
/// line of help and its defaults. Every [`Chapter`] has one; a program
/// that does not render through the Whitted [`Step`] (chapters 6 and 8,
/// path tracers) names its own, adds its own flags to [`CommonFlags::command`](crate::CommonFlags::command)
/// and runs on [`main_of`](crate::main_of), so that its command line and its errors are
/// the same as every other chapter's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Program {
    pub binary: &'static str,
    pub about: &'static str,
    pub max_depth: u32,
    pub spp: u32,
}

impl<S: Step> Chapter<S> {
    /// This chapter's name and defaults on the command line.
    pub fn program(&self) -> Program {
        Program {
            binary: self.binary,
            about: self.about,
            max_depth: self.max_depth,
            spp: self.spp,
        }
    }
}
