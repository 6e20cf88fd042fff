//! What can go wrong in the explorer, each as the one line the learner
//! reads after `raylab-explore: error:` (or in the overlay's status line).

use std::io;
use std::path::PathBuf;

use raylab_cli::output::WriteError;
use raylab_cli::scene_file::SceneFileError;

/// The explorer's errors.
#[derive(Debug, thiserror::Error)]
pub enum ExploreError {
    #[error(
        "no display: DISPLAY is not set (run it on a desktop, under xvfb-run, or with --headless)"
    )]
    NoDisplay,
    #[error("cannot open the display '{display}': {reason}")]
    Display { display: String, reason: String },
    #[error("the window's event loop failed: {0}")]
    EventLoop(winit::error::EventLoopError),
    #[error("cannot open a window: {0}")]
    Window(winit::error::OsError),
    #[error("cannot draw into the window: {0}")]
    Draw(softbuffer::SoftBufferError),
    #[error("cannot start the render thread: {0}")]
    Thread(io::Error),
    /// A word of `--script` the explorer cannot play.
    #[error("--script: '{word}': {why}")]
    Script { word: String, why: String },
    #[error("cannot read scene file '{}': {source}", path.display())]
    ReadScene { path: PathBuf, source: io::Error },
    #[error(transparent)]
    SceneFile(#[from] SceneFileError),
    #[error("cannot watch the scene file: {0}")]
    Watch(String),
    #[error("cannot rewrite the scene: {0}")]
    Rewrite(String),
    #[error("cannot use folder '{}': {source}", path.display())]
    Folder { path: PathBuf, source: io::Error },
    #[error("cannot write '{}': {source}", path.display())]
    Write { path: PathBuf, source: io::Error },
    #[error(transparent)]
    Output(#[from] WriteError),
    #[error("there are 9999 saved frames already: choose another folder with --out")]
    SavesFull,
}
