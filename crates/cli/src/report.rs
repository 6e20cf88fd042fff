//! What a chapter run made ([`Report`]), and the text that tells the
//! learner: the summary line, the probe's tree, the sweep's conclusion and
//! where the files are.

use std::io::Write;
use std::path::PathBuf;

use crate::diagrams::sweep::{self, DepthSweep};
use crate::flags::Options;
use crate::program::Chapter;
use raylab::frame::Rendered;
use raylab::trace::Step;

/// What a chapter run made.
#[derive(Debug)]
pub struct Report {
    pub rendered: Rendered,
    pub out_dir: PathBuf,
    pub render_png: PathBuf,
    /// Every file written, `render.png` first.
    pub written: Vec<PathBuf>,
    /// The probed pixel and its ray tree as text, when diagrams are drawn
    /// or `--probe` asks for it.
    pub probe: Option<((u32, u32), String)>,
    /// The depth sweep's numbers and its time, when one was made.
    pub sweep: Option<(DepthSweep, std::time::Duration)>,
    /// Whether the chapter's own depth sweep was left out because the
    /// render has more than [`SWEEP_SPP`](crate::SWEEP_SPP) rays per pixel.
    pub sweep_skipped: bool,
}

/// Print what a run did: the summary line, the probe when asked for, the
/// sweep's conclusion, and where the files are. With `--quiet`, only the
/// probe's tree when `--probe` asked for one.
///
/// A reader that stops reading (`… | head -1`) is not an error: the files
/// are written by then, so a closed standard output is left at that.
pub fn print_report<S: Step>(chapter: &Chapter<S>, options: &Options, report: &Report) {
    let text = report_text(chapter, options, report);
    if let Err(error) = std::io::stdout().lock().write_all(text.as_bytes())
        && error.kind() != std::io::ErrorKind::BrokenPipe
    {
        eprintln!("{}: could not print the summary: {error}", chapter.binary);
    }
}

/// The text [`print_report`] prints.
fn report_text<S: Step>(chapter: &Chapter<S>, options: &Options, report: &Report) -> String {
    let asked_tree = match (options.ray_tree.probe, &report.probe) {
        (Some(_), Some((_, tree))) => tree.as_str(),
        _ => "",
    };
    if options.common.quiet {
        return asked_tree.to_owned();
    }
    let mut text = format!("{}: {}\n", chapter.binary, report.rendered);
    text.push_str(asked_tree);
    if let Some((sweep, elapsed)) = &report.sweep {
        text.push_str(&format!(
            "  depth sweep 1 to {} in {:.0} ms: no pixel changes by more than {} level after depth {}\n",
            sweep.images.len(),
            elapsed.as_secs_f64() * 1e3,
            sweep::SETTLED,
            sweep.settles_at()
        ));
    }
    if report.sweep_skipped {
        text.push_str(&format!(
            "  no depth sweep at {} rays per pixel (it would trace every sample again): \
             ask for one with --sweep {}\n",
            report.rendered.settings.sampling.spp(),
            report.rendered.settings.max_depth
        ));
    }
    let names: Vec<String> = report
        .written
        .iter()
        .filter(|p| p.parent() == Some(report.out_dir.as_path()))
        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
        .chain(report.sweep.as_ref().map(|_| "depth-sweep/".to_owned()))
        .collect();
    text.push_str(&format!(
        "  wrote {} in {}\n",
        names.join(", "),
        report.out_dir.display()
    ));
    text
}
