//! Chapter 6's path tracer eight paths at a time, to the same bytes.
//!
//! [`PathTracer::trace`] follows one path; here eight paths are in flight,
//! one per lane of an `f32x8`, and every bounce is made for all eight at
//! once: the camera rays, the hits against the ground and the spheres, the
//! hit records, the sky, the sun's shadow rays, the new directions, the
//! throughputs and the terms. Only what is rare, or the learner's, is done
//! lane by lane: the choice of lobe where a material has one (the
//! learner's `choose_lobe`), the disc sun's sample (`--sun-size`) and the
//! caustic lookup (`--caustics`).
//!
//! The bytes are the scalar tracer's because each lane does the scalar
//! code's operations in its order (the workspace builds without FMA), and
//! draws from its sample's own generator exactly where the scalar code
//! draws. When a path ends, its lane takes the row's next sample at once
//! (path regeneration), and [`window`] puts the finished samples back in
//! sample order before they are summed.

mod paths;
mod scene;
mod starts;
mod terms;
mod window;

use raylab::Camera;
use raylab::indicatif::ProgressBar;
use rayon::prelude::*;
use wide::f32x8;

use crate::integrator::PathTracer;
use crate::render::{PathSettings, RowImages};
use paths::Paths;
use raylab::lanes::{CameraX8, LANES, lanes_of, mask_from_bits};
use scene::SceneX8;
use starts::Starts;
use window::Window;

/// Every row of `rows` (row `j`'s images) on every core, ticking
/// `progress` per row; returns the rays traced and the non-finite samples.
pub(crate) fn render_rows<'i>(
    tracer: &PathTracer,
    camera: &Camera,
    settings: &PathSettings,
    progress: &ProgressBar,
    rows: impl IndexedParallelIterator<Item = (usize, RowImages<'i>)>,
) -> (u64, u64) {
    let scene = SceneX8::new(tracer.scene);
    let camera = CameraX8::new(camera, settings.width, settings.height);
    rows.map_init(
        || (Paths::default(), Window::default(), Starts::default()),
        |(paths, window, starts), (j, mut row)| {
            let mut rows = Rows {
                tracer,
                scene: &scene,
                camera: &camera,
                settings,
                paths,
                window,
                starts,
            };
            rows.render_row(j as u32, &mut row);
            progress.inc(1);
            (row.rays, row.non_finite)
        },
    )
    .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1))
}

/// What one task needs to trace rows: the scene and camera in lanes, and
/// its eight paths and window of finished samples, made once per task.
struct Rows<'a, 's> {
    tracer: &'a PathTracer<'s>,
    scene: &'a SceneX8<'s>,
    camera: &'a CameraX8,
    settings: &'a PathSettings,
    paths: &'a mut Paths,
    window: &'a mut Window,
    /// The row's next samples, made ready eight at a time.
    starts: &'a mut Starts,
}

impl Rows<'_, '_> {
    // ANCHOR: row
    /// Row `j`'s pixels into `out`: sample `q` of the row is pixel
    /// `q / spp`'s sample `q % spp`; the lanes take them in that order, a
    /// lane taking the next one as soon as its path ends.
    fn render_row(&mut self, j: u32, out: &mut RowImages) {
        let sampling = &self.settings.sampling;
        let spp = sampling.spp() as usize;
        let total = self.settings.width as usize * spp;
        let mut job = [0usize; LANES];
        let mut next = 0;
        self.starts.clear();
        self.window.clear();
        while self.window.summed() < total {
            // Every idle lane starts the next sample, while there is one
            // and it fits in the window.
            let idle = !self.paths.active.move_mask() as u32 & 0xff;
            let (mut column, mut row) = ([0f32; LANES], [0f32; LANES]);
            let mut started = 0;
            for lane in lanes_of(idle) {
                if next == total || !self.window.has_room_for(next) {
                    break;
                }
                let start = self.starts.get(sampling, j, next, total);
                (column[lane], row[lane]) = (start.column, start.row);
                self.paths.random.start(lane, start.state);
                job[lane] = next;
                started |= 1 << lane;
                next += 1;
            }
            if started != 0 {
                let directions = self.camera.directions(f32x8::new(column), f32x8::new(row));
                let mask = mask_from_bits(started);
                self.paths.start(mask, self.camera.eye, directions);
            }
            // One bounce of every path in flight; the ones that ended hand
            // their light to the window, which sums what is complete.
            let ended = self.paths.bounce(self.tracer, self.scene).move_mask() as u32;
            if ended != 0 {
                let rays = self.paths.rays.as_array_ref();
                for lane in lanes_of(ended) {
                    let terms = self.paths.terms.lane(lane);
                    self.window.finish(job[lane], terms, rays[lane] as u32);
                }
                self.window.sum_in_order(spp, out);
            }
        }
    }
    // ANCHOR_END: row
}
