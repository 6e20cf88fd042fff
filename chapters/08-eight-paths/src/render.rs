//! Chapter 8's render: chapter 6's frame (the tracer, the caustic map,
//! the output images) around rows traced eight paths at a time.

use ch06_path_tracing::pixel::RowImages;
use ch06_path_tracing::{PathRender, PathSettings, PathTracer, path_frame};
use raylab::SceneQuery;
use raylab::Vec3;
use raylab::render::Progress;
use raylab::{Camera, Scene};
use raylab_lanes::{
    CameraX8, LANES, SceneQueryX8, SceneX8, SpheresX8, Vec3x8, lanes_of, mask_from_bits,
};
use rayon::prelude::*;

use crate::lane_use::{LaneUse, Stage};
use crate::paths::Paths;
use crate::starts::Starts;
use crate::window::Window;

/// Render on every core, eight paths at a time: chapter 6's image,
/// variance and terms to the bit. The photons of `--caustics` are traced
/// one at a time by chapter 6's code, each ray against eight spheres at
/// once ([`SpheresX8`]).
pub fn render_eight(
    scene: &Scene,
    camera: &Camera,
    settings: &PathSettings,
    progress: &dyn Progress,
) -> PathRender {
    let spheres = SpheresX8::new(scene);
    let lanes = SceneX8::new(scene);
    path_frame(scene, &spheres, settings, |tracer, rows| {
        render_rows(tracer, &lanes, camera, settings, progress, rows)
    })
}

/// [`render_eight`], with every hit found by `query` (chapter 9's tree),
/// the paths' eight at a time and the photons' one at a time, rather than
/// by testing every sphere: the same bytes.
pub fn render_eight_with_query<Q: SceneQueryX8>(
    scene: &Scene,
    query: &Q,
    camera: &Camera,
    settings: &PathSettings,
    progress: &dyn Progress,
) -> PathRender {
    let lanes = SceneX8::new(scene).with_query(query);
    path_frame(scene, query, settings, |tracer, rows| {
        render_rows(tracer, &lanes, camera, settings, progress, rows)
    })
}

/// How busy the lanes were in [`render_eight`]'s render of the same image,
/// step by step (for the book's figure). It renders the rows one after
/// the other on one core, with one set of eight paths, as one of
/// `render_eight`'s tasks does: the same paths, counted.
pub fn lane_use(scene: &Scene, camera: &Camera, settings: &PathSettings) -> LaneUse {
    let spheres = SpheresX8::new(scene);
    let lanes = SceneX8::new(scene);
    let mut used = LaneUse::default();
    path_frame(scene, &spheres, settings, |tracer, rows| {
        let camera = CameraX8::new(camera, settings.width, settings.height);
        let (mut paths, mut window, mut starts) = Default::default();
        let mut totals = (0, 0);
        for (j, mut row) in rows.into_iter().enumerate() {
            Rows {
                tracer,
                scene: &lanes,
                camera: &camera,
                settings,
                paths: &mut paths,
                window: &mut window,
                starts: &mut starts,
            }
            .render_row(j as u32, &mut row);
            totals = (totals.0 + row.rays, totals.1 + row.non_finite);
        }
        used = paths.lane_use;
        totals
    });
    used
}

/// Every row of `rows` (row `j`'s images) on every core, telling
/// `progress` of each row; returns the rays traced and the non-finite samples.
fn render_rows<Q: SceneQuery>(
    tracer: &PathTracer<'_, Q>,
    scene: &SceneX8,
    camera: &Camera,
    settings: &PathSettings,
    progress: &dyn Progress,
    rows: Vec<RowImages<'_>>,
) -> (u64, u64) {
    let camera = CameraX8::new(camera, settings.width, settings.height);
    rows.into_par_iter()
        .enumerate()
        .map_init(
            || (Paths::default(), Window::default(), Starts::default()),
            |(paths, window, starts), (j, mut row)| {
                let mut rows = Rows {
                    tracer,
                    scene,
                    camera: &camera,
                    settings,
                    paths,
                    window,
                    starts,
                };
                rows.render_row(j as u32, &mut row);
                progress.row_done();
                (row.rays, row.non_finite)
            },
        )
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1))
}

/// What one task needs to trace rows: the scene and camera in lanes, and
/// its eight paths and window of finished samples, made once per task.
struct Rows<'a, 's, Q: SceneQuery> {
    tracer: &'a PathTracer<'s, Q>,
    scene: &'a SceneX8<'s>,
    camera: &'a CameraX8,
    settings: &'a PathSettings,
    paths: &'a mut Paths,
    window: &'a mut Window,
    /// The row's next samples, made ready eight at a time.
    starts: &'a mut Starts,
}

impl<Q: SceneQuery> Rows<'_, '_, Q> {
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
            let mut directions = [Vec3::ZERO; LANES];
            let mut states = [0u64; LANES];
            let mut started = 0;
            for lane in lanes_of(idle) {
                if next == total || !self.window.has_room_for(next) {
                    break;
                }
                let start = self.starts.get(sampling, self.camera, j, next, total);
                (directions[lane], states[lane]) = (start.direction, start.state);
                job[lane] = next;
                started |= 1 << lane;
                next += 1;
            }
            if started != 0 {
                self.paths.random.start_lanes(started, states);
                let directions = Vec3x8::from_lanes(directions);
                let mask = mask_from_bits(started);
                self.paths.start(mask, self.camera.eye, directions);
            }
            // One bounce of every path in flight; the ones that ended hand
            // their light to the window, which sums what is complete.
            self.paths.lane_use.note(Stage::Trace, self.paths.active);
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
