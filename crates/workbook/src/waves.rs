//! Chapter 7's figures: a wave's rays as records and as registers, one
//! row's waves and how the rays sent on are packed, and how busy the
//! lanes are at each depth, all from real renders of the lab scene.

use std::path::{Path, PathBuf};

use ch07_eight_rays::soa::LANES;
use ch07_eight_rays::stats::{WaveStats, wave_stats};
use ch07_eight_rays::{EightRays, Like};
use image::RgbImage;
use raylab::{Camera, RayKind, Sampling, Scene, Settings, Tracer};
use raylab_cli::diagrams::kind_colour;
use raylab_cli::output::save_png;
use raylab_plot::colour::{AXIS, FRAME, TEXT, TEXT_MUTED, WHITE, series_colour};
use raylab_plot::{Anchor, Canvas, Corner, LinePlot, Rgb, Series};

use crate::concepts::{LABEL, SMALL, Sheet};
use crate::{JobError, Size};

/// The files [`make_figures`] writes.
pub const NAMES: [&str; 3] = ["soa.png", "row-waves.png", "busy-lanes.png"];

/// What one record of a wave holds, in order (`soa::Rays`).
pub const FIELDS: [&str; LANES] = ["ox", "oy", "oz", "dx", "dy", "dz", "w", "s"];

/// Write chapter 7's figures into `dir`, from renders of `size`.
pub fn make_figures(dir: &Path, size: Size) -> Result<Vec<PathBuf>, JobError> {
    raylab_cli::prepare_out_dir(dir)?;
    let row = row_waves(
        size.width,
        size.height,
        glass_row(size.width, size.height),
        true,
    );
    // Both panels from one render: chapter 4's lab scene at one ray a
    // pixel, the rays whose waves the right panel sorts (a test checks that
    // the two count the same rays).
    let settings = chapter_settings(size, Like::Refraction);
    let stats = wave_stats(
        &Scene::lab(),
        &Camera::lab(),
        &EightRays {
            like: Like::Refraction,
        },
        &settings,
    );
    let images = [
        soa_figure(),
        row_figure(&row, size),
        busy_figure(
            &stats,
            &settings,
            &optics_lanes(size.width, size.height, true),
            &optics_lanes(size.width, size.height, false),
        ),
    ];
    let mut written = Vec::new();
    for (name, image) in NAMES.iter().zip(&images) {
        let path = dir.join(name);
        save_png(image, &path)?;
        written.push(path);
    }
    Ok(written)
}

/// The settings chapter 7 renders with, as `like` by default, at `size`.
pub fn chapter_settings(size: Size, like: Like) -> Settings {
    let raylab_like::Defaults { max_depth, spp, .. } = like.defaults();
    Settings {
        width: size.width,
        height: size.height,
        max_depth,
        epsilon: 1e-4,
        sampling: Sampling::new(spp, None, 0).expect("the lab's 1 or 5"),
    }
}

// ----- structure of arrays -------------------------------------------------

fn field_colour(field: usize) -> Rgb {
    let base = series_colour(field);
    raylab_plot::colour::mix(base, WHITE, 0.55)
}

fn soa_figure() -> RgbImage {
    let mut sheet = Sheet::new(
        1200.0,
        510.0,
        "Eight rays as eight records, and as eight registers",
    );
    let (cell_w, cell_h) = (48.0, 34.0);
    let top = 120.0;
    let grids = [
        (90.0, "array of structures: one record per ray", false),
        (706.0, "structure of arrays: one register per number", true),
    ];
    for (left, title, registers) in grids {
        sheet.text(
            (left + 4.0 * cell_w, top - 40.0),
            title,
            LABEL,
            TEXT,
            Anchor::BASELINE_CENTRE,
        );
        for (row, row_field) in FIELDS.iter().enumerate() {
            for col in 0..LANES {
                // A record row holds every field of one ray; a register
                // row one field of every ray.
                let (ray, field) = if registers { (col, row) } else { (row, col) };
                let at = (left + col as f32 * cell_w, top + row as f32 * cell_h);
                sheet.fill_rect(at, (cell_w, cell_h), field_colour(field));
                sheet.stroke_rect(at, (cell_w, cell_h), WHITE, 1.5);
                sheet.text(
                    (at.0 + cell_w / 2.0, at.1 + cell_h / 2.0),
                    &format!("{}{ray}", FIELDS[field]),
                    SMALL,
                    TEXT,
                    Anchor::MIDDLE_CENTRE,
                );
            }
            let name = if registers {
                format!("{row_field}: f32x8")
            } else {
                format!("ray {row}")
            };
            let (x, anchor) = if registers {
                (left + LANES as f32 * cell_w + 6.0, Anchor::MIDDLE_LEFT)
            } else {
                (left - 6.0, Anchor::MIDDLE_RIGHT)
            };
            sheet.text(
                (x, top + (row as f32 + 0.5) * cell_h),
                &name,
                SMALL,
                TEXT_MUTED,
                anchor,
            );
        }
        let label = if registers {
            "lane 0 to lane 7: the eight rays side by side"
        } else {
            "origin, direction, weight w, sample s: one f32x8 each"
        };
        sheet.text(
            (left + 4.0 * cell_w, top + LANES as f32 * cell_h + 10.0),
            label,
            SMALL,
            TEXT_MUTED,
            Anchor::TOP_CENTRE,
        );
    }
    let mid = (grids[0].0 + 8.0 * cell_w + grids[1].0) / 2.0;
    sheet.arrow(
        (mid - 70.0, top + 2.5 * cell_h),
        (mid + 70.0, top + 2.5 * cell_h),
        AXIS,
        2.5,
    );
    sheet.text(
        (mid, top + 2.5 * cell_h - 12.0),
        "8 × 8 transpose",
        SMALL,
        TEXT,
        Anchor::BASELINE_CENTRE,
    );
    sheet.text(
        (mid, top + 2.5 * cell_h + 14.0),
        "Rays::group",
        SMALL,
        TEXT_MUTED,
        Anchor::TOP_CENTRE,
    );
    sheet.arrow(
        (mid + 70.0, top + 5.5 * cell_h),
        (mid - 70.0, top + 5.5 * cell_h),
        AXIS,
        2.5,
    );
    sheet.text(
        (mid, top + 5.5 * cell_h - 12.0),
        "and back",
        SMALL,
        TEXT,
        Anchor::BASELINE_CENTRE,
    );
    sheet.text(
        (mid, top + 5.5 * cell_h + 14.0),
        "Rays::push_packed",
        SMALL,
        TEXT_MUTED,
        Anchor::TOP_CENTRE,
    );
    sheet.note(
        1,
        "One instruction on a register works on all eight rays: dx × dx, for every lane at once.",
    );
    sheet.note(
        0,
        "A wave is kept as records (loading a group is 8 loads, packing a ray sent on is 1 store) and shaded as registers.",
    );
    sheet.finish()
}

// ----- one row's waves -----------------------------------------------------

/// One ray of a row's waves: its kind, the position of its parent in the
/// previous wave, and whether it travels inside a sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaveRay {
    pub kind: RayKind,
    pub parent: Option<usize>,
    pub inside: bool,
    /// Which of its parent's rays it is: 0 for transmitted, 1 reflected.
    order: u8,
    /// Its own rays in the scalar tracer's log, to find its children.
    log_index: usize,
    pixel: usize,
}

/// The image row through the glass sphere's centre.
pub fn glass_row(width: u32, height: u32) -> u32 {
    let scene = Scene::lab();
    let glass = scene
        .sphere_named("glass")
        .expect("the lab has a glass sphere");
    let centre = scene.spheres()[glass].shape.centre;
    let (_, y) = Camera::lab()
        .project(centre, width, height)
        .expect("the glass sphere is in view");
    (y as u32).min(height - 1)
}

/// The waves of row `j` of chapter 4's render (one ray per pixel, depth
/// 10), traced ray tree by ray tree by the scalar tracer and sorted into
/// waves as chapter 7 packs them: each wave's groups of eight in order,
/// a group's transmitted rays before its reflected ones, and the rays that
/// travel inside a sphere after all the others (unless not `sorted`).
pub fn row_waves(width: u32, height: u32, j: u32, sorted: bool) -> Vec<Vec<WaveRay>> {
    let (scene, camera) = (Scene::lab(), Camera::lab());
    let step = ch04_refraction::Refraction;
    let mut logs = Vec::new();
    for i in 0..width {
        let mut tracer = Tracer::new(&scene, &step, 10, 1e-4).with_log();
        tracer.trace(camera.ray(i, j, (0.5, 0.5), width, height));
        logs.push(tracer.log().to_vec());
    }
    let first: Vec<WaveRay> = (0..width as usize)
        .map(|pixel| WaveRay {
            kind: RayKind::Primary,
            parent: None,
            inside: false,
            order: 0,
            log_index: 0,
            pixel,
        })
        .collect();
    let mut waves = vec![first];
    while let Some(wave) = waves.last() {
        let (mut outside, mut inside) = (Vec::new(), Vec::new());
        for (g, group) in wave.chunks(LANES).enumerate() {
            let mut children: Vec<WaveRay> = Vec::new();
            for (lane, ray) in group.iter().enumerate() {
                let log = &logs[ray.pixel];
                let traced = &log[ray.log_index];
                let entering = traced
                    .hit
                    .is_some_and(|(object, t)| scene.hit_record(&traced.ray, t, object).entering);
                for (index, child) in log.iter().enumerate() {
                    if child.parent != Some(ray.log_index) || child.kind == RayKind::Shadow {
                        continue;
                    }
                    let transmitted = child.kind != RayKind::Reflection;
                    let total = child.kind == RayKind::TotalInternalReflection;
                    children.push(WaveRay {
                        kind: child.kind,
                        parent: Some(g * LANES + lane),
                        inside: if transmitted {
                            entering || total
                        } else {
                            !entering
                        },
                        order: u8::from(!transmitted),
                        log_index: index,
                        pixel: ray.pixel,
                    });
                }
            }
            // Transmitted rays first, then reflected, each in lane order.
            children.sort_by_key(|c| (c.order, c.parent));
            for child in children {
                if child.inside && sorted {
                    inside.push(child);
                } else {
                    outside.push(child);
                }
            }
        }
        outside.extend(inside);
        if outside.is_empty() {
            break;
        }
        waves.push(outside);
    }
    waves
}

fn row_figure(waves: &[Vec<WaveRay>], size: Size) -> RgbImage {
    let j = glass_row(size.width, size.height);
    let width = size.width as f32;
    let mut sheet = Sheet::new(
        1200.0,
        110.0 + 64.0 * waves.len().max(3) as f32 + 150.0,
        &format!(
            "Row {j} of chapter 4's {}×{} render in waves: the rays sent on, packed",
            size.width, size.height
        ),
    );
    let (left, lane_w) = (230.0, 940.0 / width);
    let strip_h = 26.0;
    let row_y = |k: usize| 100.0 + 64.0 * k as f32 + if k > 0 { 40.0 } else { 0.0 };
    // Where each ray of wave 2 came from in wave 1, drawn first so that
    // the strips and their labels lie on top.
    if let Some(second) = waves.get(1) {
        let above = row_y(0) + strip_h;
        for (n, ray) in second.iter().enumerate() {
            if let Some(parent) = ray.parent {
                let from = (left + (parent as f32 + 0.5) * lane_w, above);
                let to = (left + (n as f32 + 0.5) * lane_w, row_y(1));
                sheet.line(from, to, mix_light(kind_colour(ray.kind)), 0.6);
            }
        }
    }
    for (k, wave) in waves.iter().enumerate() {
        let y = row_y(k);
        sheet.text(
            (left - 12.0, y + strip_h / 2.0 - 10.0),
            &format!("wave {}", k + 1),
            LABEL,
            TEXT,
            Anchor::MIDDLE_RIGHT,
        );
        sheet.text(
            (left - 12.0, y + strip_h / 2.0 + 12.0),
            &format!("{} rays, {} groups", wave.len(), wave.len().div_ceil(LANES)),
            SMALL,
            TEXT_MUTED,
            Anchor::MIDDLE_RIGHT,
        );
        sheet.fill_rect((left, y), (width * lane_w, strip_h), [246, 246, 246]);
        let colours: Vec<Rgb> = wave
            .iter()
            .enumerate()
            .map(|(n, ray)| match (k, ray.kind) {
                (0, _) => {
                    let sends = waves
                        .get(1)
                        .is_some_and(|next| next.iter().any(|c| c.parent == Some(n)));
                    if sends { AXIS } else { FRAME }
                }
                (_, kind) => kind_colour(kind),
            })
            .collect();
        // Each run of one colour as one rectangle: rays about a pixel wide,
        // filled one by one, leave stripes where their soft edges meet.
        let mut start = 0;
        for run in colours.chunk_by(|a, b| a == b) {
            sheet.fill_rect(
                (left + start as f32 * lane_w, y),
                ((run.len() as f32 * lane_w).max(0.6), strip_h),
                run[0],
            );
            start += run.len();
        }
        // Group boundaries, where they can be seen.
        if lane_w * LANES as f32 >= 4.0 {
            for g in 0..=wave.len().div_ceil(LANES) {
                let x = left + (g * LANES) as f32 * lane_w;
                sheet.line((x, y + strip_h), (x, y + strip_h + 4.0), TEXT_MUTED, 0.8);
            }
        }
        if let Some(first_inside) = wave.iter().position(|r| r.inside) {
            let x = left + first_inside as f32 * lane_w;
            sheet.line((x, y - 4.0), (x, y + strip_h + 4.0), TEXT, 1.5);
            sheet.text(
                (x + 3.0, y - 4.0),
                "inside a sphere →",
                SMALL,
                TEXT,
                Anchor::new(raylab_plot::HAlign::Left, raylab_plot::VAlign::Bottom),
            );
        }
    }
    let legend_y = row_y(waves.len().max(3)) - 4.0;
    let entries = [
        (AXIS, "a ray that sends rays on"),
        (FRAME, "one that does not"),
        (kind_colour(RayKind::Reflection), "reflected"),
        (kind_colour(RayKind::Refraction), "refracted"),
        (
            kind_colour(RayKind::TotalInternalReflection),
            "totally reflected",
        ),
    ];
    sheet.legend((60.0, legend_y), &entries[..2]);
    let any_total = waves
        .iter()
        .flatten()
        .any(|r| r.kind == RayKind::TotalInternalReflection);
    sheet.legend(
        (440.0, legend_y),
        &entries[2..if any_total { 5 } else { 4 }],
    );
    sheet.note(
        1,
        "The rays a wave sends on are packed densely into the next, those inside a sphere last: every group but the last is full.",
    );
    sheet.note(
        0,
        "Inside the glass each ray sends one ray on inside and one out, so the waves stop shrinking: it is the weights that fall.",
    );
    sheet.finish()
}

fn mix_light(colour: Rgb) -> Rgb {
    raylab_plot::colour::mix(colour, WHITE, 0.45)
}

// ----- busy lanes ----------------------------------------------------------

/// Per wave (entry `k` is wave `k + 1`): the lanes that send rays on, and
/// the groups of eight with at least one such lane, over every row of
/// chapter 4's render. Those groups run the reflection and refraction for
/// all eight lanes, and keep only the senders' answers.
pub fn optics_lanes(width: u32, height: u32, sorted: bool) -> Vec<(u64, u64)> {
    let mut totals: Vec<(u64, u64)> = Vec::new();
    let rows: Vec<Vec<(u64, u64)>> = {
        use rayon::prelude::*;
        (0..height)
            .into_par_iter()
            .map(|j| {
                let waves = row_waves(width, height, j, sorted);
                waves
                    .windows(2)
                    .map(|pair| {
                        let mut sends = vec![false; pair[0].len()];
                        for child in &pair[1] {
                            if let Some(parent) = child.parent {
                                sends[parent] = true;
                            }
                        }
                        let groups = sends.chunks(LANES).filter(|g| g.contains(&true)).count();
                        let senders = sends.iter().filter(|&&s| s).count();
                        (senders as u64, groups as u64)
                    })
                    .collect()
            })
            .collect()
    };
    for row in rows {
        if totals.len() < row.len() {
            totals.resize(row.len(), (0, 0));
        }
        for (total, (senders, groups)) in totals.iter_mut().zip(row) {
            total.0 += senders;
            total.1 += groups;
        }
    }
    totals
}

fn busy_figure(
    stats: &[WaveStats],
    settings: &Settings,
    sorted: &[(u64, u64)],
    mixed: &[(u64, u64)],
) -> RgbImage {
    let (w, h) = (560, 440);
    let depths = || stats.iter().enumerate().filter(|(_, s)| s.rays > 0);
    // Both panels over the same waves, so that they line up.
    let waves = depths().count().max(2) as f64;
    let rays = LinePlot::new("Rays in each wave")
        .x_label("wave (= depth)")
        .y_label("rays in the whole image")
        .x_range(0.5, waves + 0.5)
        .integer_x_ticks()
        .log_y(1.0)
        .series(Series::new(
            "rays traced by chapter 7",
            series_colour(0),
            depths().map(|(k, s)| ((k + 1) as f64, s.rays as f64)),
        ))
        .legend(Corner::TopRight)
        .render(w, h);
    let share = |lanes: &[(u64, u64)]| -> Vec<(f64, f64)> {
        lanes
            .iter()
            .enumerate()
            .filter(|(_, (_, groups))| *groups > 0)
            .map(|(k, &(senders, groups))| {
                (
                    (k + 1) as f64,
                    100.0 * senders as f64 / (groups * LANES as u64) as f64,
                )
            })
            .collect()
    };
    let busy = LinePlot::new("Busy lanes where the optics runs")
        .x_label("wave (= depth)")
        .y_label("lanes sending rays on (%)")
        .x_range(0.5, waves + 0.5)
        .integer_x_ticks()
        .y_range(0.0, 100.0)
        .series(Series::new(
            "rays inside a sphere packed apart (chapter 7)",
            series_colour(2),
            share(sorted),
        ))
        .series(Series::new(
            "all packed in one order",
            series_colour(3),
            share(mixed),
        ))
        .legend(Corner::BottomRight)
        .render(w, h);
    let mut canvas = Canvas::new(2 * w, h + 64, WHITE);
    canvas.draw_rgb_image(&rays, 0, 0, 1);
    canvas.draw_rgb_image(&busy, w as i32, 0, 1);
    let lines = [
        format!("Both panels: chapter 4's render ({settings}), traced eight at a time as chapter 7 does."),
        "The last wave sends no ray on, so it runs no optics: the right panel stops a wave earlier."
            .to_owned(),
    ];
    for (k, line) in lines.iter().enumerate() {
        canvas.text(
            w as f32,
            h as f32 + 24.0 + 20.0 * k as f32,
            line,
            14.0,
            TEXT,
            Anchor::BASELINE_CENTRE,
        );
    }
    canvas.to_rgb_image()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::concepts::{WIDEST, shown};

    #[test]
    fn the_records_and_row_figures_fit_1200_pixels_and_their_type_reads_12_pixels_tall() {
        let size = Size::DEFAULT;
        let j = glass_row(size.width, size.height);
        let row = row_figure(&row_waves(size.width, size.height, j, true), size);
        for (name, image) in [("soa", soa_figure()), ("row-waves", row)] {
            assert!(image.width() <= WIDEST, "{name}: {}", image.width());
            let small = shown(SMALL, image.width());
            assert!(small >= 12.0, "{name}: small type shown {small} px tall");
        }
    }

    #[test]
    fn the_sorted_waves_of_a_row_hold_as_many_rays_as_chapter_7_traces() {
        // A 64 × 48 render: the waves sorted from the scalar tracer's
        // trees, row by row, against chapter 7's own waves, depth by depth.
        let (width, height) = (64, 48);
        let j = glass_row(width, height);
        let waves = row_waves(width, height, j, true);
        assert_eq!(waves[0].len(), 64);
        let stats = wave_stats(
            &Scene::lab(),
            &Camera::lab(),
            &EightRays {
                like: Like::Refraction,
            },
            &chapter_settings(Size { width, height }, Like::Refraction),
        );
        let mut totals = vec![0u64; stats.len()];
        for row in 0..height {
            for (k, wave) in row_waves(width, height, row, true).iter().enumerate() {
                totals[k] += wave.len() as u64;
            }
        }
        let traced: Vec<u64> = stats.iter().map(|s| s.rays).collect();
        assert_eq!(totals, traced);
        // A row through the glass sends rays on, some inside it.
        assert!(waves.len() >= 3 && waves[1].iter().any(|r| r.inside));
    }
}
