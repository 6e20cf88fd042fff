//! Chapter 6's figures, 5: the glass ball's caustic, without and with
//! photons.

use std::path::{Path, PathBuf};

use raylab::Scene;
use raylab_plot::montage;

use super::{CAUSTIC_SPP, magnified_crop, path_render, save_all, size_flags, with};
use crate::measure::luminance;
use crate::{JobError, Size};

/// The scene file that looks at the glass ball's caustic.
pub const CAUSTIC_VIEW: &str = "caustic-view.toml";

pub(super) fn caustic_figure(
    dir: &Path,
    scenes: &Path,
    size: Size,
    quiet: bool,
) -> Result<Vec<PathBuf>, JobError> {
    // Small and few paths: with --caustics every path that reaches the
    // ground reads the photon map, which makes this view's run slow.
    let (w, h) = ((size.width / 4).max(8), (size.height / 4).max(6));
    let scene_flag = format!("--scene={}", scenes.join(CAUSTIC_VIEW).display());
    let flags = with(size_flags(w, h, CAUSTIC_SPP), &[&scene_flag]);
    let eye_only = path_render(&flags, quiet)?;
    let traced = path_render(&with(flags, &["--caustics"]), quiet)?;
    let caustic = &traced.terms()[4];
    // Crop around the brightest caustic pixel.
    let (k, _) = caustic
        .pixels()
        .iter()
        .enumerate()
        .fold((0, f32::MIN), |best, (k, &c)| {
            if luminance(c) > best.1 {
                (k, luminance(c))
            } else {
                best
            }
        });
    let at = ((k as u32 % w) as f32, (k as u32 / w) as f32);
    let crop = ((w / 4).max(4), (h / 4).max(3));
    let scale = (240 / crop.0).max(1);
    let images = [
        eye_only.image.to_srgb8(),
        traced.image.to_srgb8(),
        caustic.to_srgb8(),
    ];
    let crops = [&images[0], &images[1]].map(|i| magnified_crop(i, at, crop, scale));
    let peak = luminance(caustic.pixels()[k]);
    let figure = montage(
        &format!(
            "The glass ball's caustic, seen from the side: {w}×{h}, {CAUSTIC_SPP} paths per pixel"
        ),
        &[
            ("from the eye only: no caustic", &images[0]),
            ("with --caustics: traced from the sun", &images[1]),
            ("the caustics term alone", &images[2]),
            (
                &format!("from the eye only, {}×{} pixels, ×{scale}", crop.0, crop.1),
                &crops[0],
            ),
            (&format!("with --caustics, ×{scale}"), &crops[1]),
        ],
        3,
    );
    let mean_lit_ground = 2.5 * Scene::lab().sun.direction.y / std::f32::consts::PI;
    let text = format!(
        "The caustic's brightest pixel adds a luminance of {peak:.3} (linear), where the sun \
         alone gives open ground {mean_lit_ground:.3} per unit albedo (albedo/π · 2.5 · cos): \
         {} photons were traced from the sun, {} of them landed on the ground.\n",
        traced.caustics.map_or(0, |c| c.sent),
        traced.caustics.map_or(0, |c| c.landed)
    );
    save_all(dir, &[("caustic.png", &figure)], &[("caustic.md", &text)])
}
