//! # raylab-explore: the lab live in a window
//!
//! The lab this workbook comes from ran in real time, a fragment shader on
//! a GPU. The explorer brings that back on the CPU: it renders the lab
//! scene (or any scene file) again whenever something changes, with the
//! fast floor on every core (chapter 7's waves for chapters 1–5, chapter
//! 8's eight paths for path tracing), with the knobs on keys, an orbit
//! camera on the mouse, a clicked pixel's ray tree drawn into the scene,
//! and the scene file read again on every save. `g` puts the same view
//! from chapter 10's shader beside it, to compare the two.
//!
//! Read first:
//!
//! - [`state`]: the explorer without its window, inputs to frame;
//! - [`knobs`] and [`orbit`]: what the keys and the mouse change;
//! - [`tree3d`] and [`overlay`]: what is drawn over the scene;
//! - [`render`] and [`worker`]: a frame asked for as a job, rendered on a
//!   thread of its own;
//! - [`gpu`]: `g`, the GPU's render beside the CPU's;
//! - [`live`] and [`window`]: the window's event loop, and the window itself.
//!
//! **Why winit and softbuffer.** The frame is made on the CPU, a row per
//! task, as 8-bit sRGB: all a window has to do is show those pixels and
//! hand back keys and mouse. winit is Rust's common window and event
//! library; softbuffer copies a CPU buffer into a winit window with no GPU,
//! no OpenGL and no shader, so the explorer runs where the workbook runs,
//! virtual machines and Xvfb included. A GPU presenting layer (wgpu,
//! pixels) would put a driver between every frame and the screen, for
//! pixels made on the CPU. The one time pixels come from a GPU is `g`
//! ([`gpu`]): chapter 10's shader renders the same view through wgpu, and
//! its image is read back and shown through softbuffer like the CPU's.
//! So wgpu is in the build (chapter 10 brings it), but the explorer looks
//! for a GPU only when `g` is first pressed, and a machine without one
//! gets one line in the overlay. Only winit's X11 backend is built
//! (XWayland covers Wayland desktops), and it loads the X libraries when
//! the window opens, so building needs no system headers.
//!
//! **Why the state is apart from the window.** Everything the learner
//! does arrives as an [`input::Input`], and everything shown is
//! [`state::Explorer::compose`]'s image: the tests, the `--script` runs
//! and the book's screenshots drive the same state the window does,
//! without a screen.
//!
//! **Why a render worker.** A path-traced pass at a large size takes a good
//! part of a second and a GPU frame on a CPU's Vulkan driver seconds; an
//! event loop that rendered would leave every key waiting for them. So the
//! window's loop sends jobs to a thread that owns the renderers and takes
//! the newest finished frame, the way interactive renderers do; a frame for
//! a view that has changed since is dropped ([`state::Explorer::take`]).

pub mod compose;
pub mod driver;
pub mod error;
pub mod figures;
pub mod gpu;
pub mod input;
pub mod knobs;
pub mod live;
pub mod measure;
pub mod orbit;
pub mod overlay;
pub mod probe;
pub mod render;
pub mod save;
pub mod script;
pub mod source;
pub mod state;
pub mod tree3d;
pub mod watch;
pub mod window;
pub mod worker;

pub use error::ExploreError;
pub use input::{Button, Input, Key};
pub use source::Loaded;
pub use state::Explorer;
