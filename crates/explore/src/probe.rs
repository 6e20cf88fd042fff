//! A clicked pixel's ray trees: what the explorer keeps of a click, for
//! the tree in 3D ([`crate::tree3d`]) and its text in the overlay.

use raylab::Camera;
use raylab::probe::SampleTree;

/// A clicked pixel's ray trees, kept in the scene's space so that they
/// stay put while the camera moves.
#[derive(Clone, Debug)]
pub struct Probe {
    pub pixel: (u32, u32),
    /// The camera the pixel was clicked through.
    pub camera: Camera,
    pub trees: Vec<SampleTree>,
    /// `raylab_cli::probe_text`'s text of the trees.
    pub text: String,
}
