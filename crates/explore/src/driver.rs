//! Running a script on the explorer, a frame at a time: the window's loop
//! and the headless run share it, so a script does the same in both.

use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::time::Duration;

use raylab_cli::output::save_png;

use crate::error::ExploreError;
use crate::script::Instruction;
use crate::state::{Action, Explorer};

/// The most frames `settle` renders: path tracing at 1024 paths per pixel.
pub const SETTLE_LIMIT: u32 = 1024;

/// Whether the script has more to do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tick {
    Busy,
    /// The script waits until the image is what the knobs ask for (at
    /// most [`SETTLE_LIMIT`] frames): the runner renders until then.
    Settle,
    Done,
    Quit,
}

pub struct Driver {
    steps: VecDeque<Instruction>,
    wait: u32,
    /// Where `w` writes.
    pub out_dir: PathBuf,
}

impl Driver {
    pub fn new(steps: VecDeque<Instruction>, out_dir: PathBuf) -> Driver {
        Driver {
            steps,
            wait: 0,
            out_dir,
        }
    }

    pub fn is_done(&self) -> bool {
        self.steps.is_empty() && self.wait == 0
    }

    /// Run the script up to its next input (one input per frame) or its
    /// next `settle`.
    pub fn tick(&mut self, explorer: &mut Explorer) -> Result<Tick, ExploreError> {
        if self.wait > 0 {
            self.wait -= 1;
            return Ok(Tick::Busy);
        }
        while let Some(step) = self.steps.pop_front() {
            match step {
                Instruction::Input(input) => {
                    let action = explorer.handle(input);
                    if act(explorer, action, &self.out_dir) {
                        return Ok(Tick::Quit);
                    }
                    return Ok(Tick::Busy);
                }
                Instruction::Frames(0) => {}
                Instruction::Frames(n) => {
                    self.wait = n - 1;
                    return Ok(Tick::Busy);
                }
                Instruction::Settle => return Ok(Tick::Settle),
                Instruction::Shot(path) => write_shot(explorer, &path)?,
            }
        }
        Ok(Tick::Done)
    }
}

/// Write the frame shown, overlay and all.
pub fn write_shot(explorer: &Explorer, path: &Path) -> Result<(), ExploreError> {
    if let Some(folder) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(folder).map_err(|source| ExploreError::Write {
            path: path.to_owned(),
            source,
        })?;
    }
    Ok(save_png(&explorer.compose(), path)?)
}

/// Do what an input asked of the runner; whether to quit.
pub fn act(explorer: &mut Explorer, action: Action, out_dir: &Path) -> bool {
    match action {
        Action::None => false,
        Action::Quit => true,
        Action::Save => {
            match crate::save::save(explorer, out_dir) {
                Ok(saved) => {
                    explorer.set_status(format!("wrote {}", saved.png.display()));
                    let mut text = format!("wrote {}", saved.png.display());
                    if let Some(scene) = &saved.scene {
                        text.push_str(&format!(" and {}", scene.display()));
                    }
                    text.push_str(&format!(
                        "\nthe same frame from the chapter:\n  {}",
                        saved.command
                    ));
                    explorer.say(text);
                }
                Err(error) => explorer.set_status(error.to_string()),
            }
            false
        }
    }
}

/// Print the explorer's lines for the terminal.
pub fn print_messages(explorer: &mut Explorer) {
    for line in explorer.take_messages() {
        println!("{line}");
    }
}

/// Frame times in order, as one line: how many, the median, the fastest.
pub fn frame_summary(times: &[Duration]) -> String {
    if times.is_empty() {
        return "no frame rendered".into();
    }
    let mut sorted = times.to_vec();
    sorted.sort();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    format!(
        "{} frame{} rendered, median {:.1} ms, fastest {:.1} ms, slowest {:.1} ms",
        times.len(),
        if times.len() == 1 { "" } else { "s" },
        ms(sorted[sorted.len() / 2]),
        ms(sorted[0]),
        ms(sorted[sorted.len() - 1])
    )
}

/// What a run without a window does with the explorer's lines (a probe's
/// ray tree, a saved frame's command): print them, as the program does, or
/// drop them, as the book's figures do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Messages {
    Print,
    Drop,
}

/// The whole run without a window: the script, then `frames` more frames,
/// then the screenshot. Returns the summary of the frame times.
pub fn run_headless(
    explorer: &mut Explorer,
    driver: &mut Driver,
    frames: u32,
    screenshot: Option<&Path>,
    messages: Messages,
) -> Result<String, ExploreError> {
    let mut times = Vec::new();
    loop {
        let tick = driver.tick(explorer)?;
        if tick == Tick::Settle {
            explorer.settle(SETTLE_LIMIT);
            continue;
        }
        if explorer.frame() {
            times.push(explorer.stats().frame);
        }
        match messages {
            Messages::Print => print_messages(explorer),
            Messages::Drop => drop(explorer.take_messages()),
        }
        if tick != Tick::Busy {
            break;
        }
    }
    for _ in 0..frames {
        if explorer.frame() {
            times.push(explorer.stats().frame);
        }
    }
    if let Some(path) = screenshot {
        write_shot(explorer, path)?;
    }
    Ok(frame_summary(&times))
}
