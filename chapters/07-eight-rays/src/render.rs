//! The whole image: one row per task on every core, each row traced in
//! waves, then each sample's rays summed in the scalar tracer's order.

use std::cell::RefCell;
use std::time::Instant;

use raylab::frame::RowTally;
use raylab::outputs::{Outputs, RowOutputs};
use raylab::render::Progress;
use raylab::trace::RayCounts;
use raylab::{Camera, Keep, RayKind, Rendered, Scene, Settings, Tracer, Vec3};
use raylab_lanes::{SceneQueryX8, SceneX8};
use rayon::prelude::*;

use crate::EightRays;
use crate::camera::{Primary, PrimaryRays};
use crate::ledger::Ledger;
use crate::link::END;
use crate::shade::Light;
use crate::wave::{Setup, Waves};

// ANCHOR: sum
/// A sample's colour: the light of its rays added up in the order the
/// scalar ray stack pops them, by following the ledger's links from its
/// primary ray (whose number is the sample's). Most samples' primary ray
/// sent nothing on, and the walk ends after one step.
fn sum_sample(ledger: &Ledger, sample: usize) -> Vec3 {
    let mut colour = Vec3::ZERO;
    let mut ray = sample as u32;
    while ray != END {
        colour += ledger.light(ray as usize);
        ray = ledger.next(ray as usize);
    }
    colour
}
// ANCHOR_END: sum

/// The rays of a sample by kind, to take its wave-traced part back out of
/// the counts when the scalar tracer traces that sample again.
fn count_sample(waves: &Waves, sample: usize, counts: &mut RayCounts) {
    let mut ray = sample as u32;
    while ray != END {
        let (kind, cast_shadow) = waves.kinds[ray as usize];
        counts.add(kind, 1);
        counts.add(RayKind::Shadow, u64::from(cast_shadow));
        ray = waves.ledger.next(ray as usize);
    }
}

/// Sample `k` of pixel (`i`, `j`), whose tree reached the ray budget,
/// traced again by a scalar tracer made for it, its wave-traced rays taken
/// back out of the row's counts. Rare, and kept out of the pixel loop.
#[cold]
fn trace_again(
    worker: &Worker<'_, '_>,
    setup: &Setup,
    camera: &Camera,
    settings: &Settings,
    (i, j, k): (usize, u32, usize),
    tally: &mut RowTally,
) -> raylab::trace::Traced {
    let sample = i * settings.sampling.spp() as usize + k;
    let mut waved = RayCounts::default();
    count_sample(worker.waves, sample, &mut waved);
    tally.counts = tally.counts - waved;
    let one_ray = setup.scene.one_ray();
    let mut scalar = Tracer::with_query(
        worker.scene,
        &one_ray,
        worker.step,
        settings.max_depth,
        settings.epsilon,
    );
    let offset = settings.sampling.offset((i as u32, j), k as u32);
    let ray = camera.ray(i as u32, j, offset, settings.width, settings.height);
    let traced = scalar.trace(ray);
    tally.counts = tally.counts + scalar.counts();
    tally.over_budget += u64::from(traced.over_budget);
    traced
}

/// One worker's tools: its waves, and what a scalar tracer needs for the
/// rare sample whose tree reaches the ray budget.
struct Worker<'w, 's> {
    waves: &'w mut Waves,
    scene: &'s Scene,
    step: &'s EightRays,
}

thread_local! {
    /// Each thread's waves, kept from row to row and from render to
    /// render. Rayon hands a render's rows out one at a time, and waves
    /// made afresh for each would grow their arrays again from nothing:
    /// new memory, whose pages the kernel must clear as they are first
    /// written.
    static WAVES: RefCell<Waves> = RefCell::new(Waves::default());
}

/// Render `scene` as `step`'s chapter would, eight rays at a time; the
/// images, the ray counts and (as `keep` asks) the per-pixel maps equal
/// `raylab::render`'s.
pub fn render_waves(
    scene: &Scene,
    camera: &Camera,
    step: &EightRays,
    settings: &Settings,
    keep: Keep,
    progress: &dyn Progress,
) -> Rendered {
    render_waves_or_query(scene, None, camera, step, settings, keep, progress)
}

/// [`render_waves`], with every hit found by `query` (chapter 9's tree)
/// rather than by testing every sphere: the same bytes. Named and typed
/// by the core's rule ([`raylab::render::render_with_query`]).
pub fn render_waves_with_query<Q: SceneQueryX8>(
    scene: &Scene,
    query: &Q,
    camera: &Camera,
    step: &EightRays,
    settings: &Settings,
    keep: Keep,
    progress: &dyn Progress,
) -> Rendered {
    render_waves_or_query(scene, Some(query), camera, step, settings, keep, progress)
}

fn render_waves_or_query(
    scene: &Scene,
    query: Option<&dyn SceneQueryX8>,
    camera: &Camera,
    step: &EightRays,
    settings: &Settings,
    keep: Keep,
    progress: &dyn Progress,
) -> Rendered {
    let start = Instant::now();
    let features = step.like.features();
    let mut lanes = SceneX8::new(scene).with_optics(features.reflection, features.transmission);
    if let Some(query) = query {
        lanes = lanes.with_query(query);
    }
    let setup = Setup {
        primary: Primary::new(camera, settings),
        scene: lanes,
        light: Light::new(scene),
        features,
        max_depth: settings.max_depth,
        epsilon: settings.epsilon,
        maps: keep.maps,
    };
    let mut outputs = Outputs::new(settings.width, settings.height, keep);
    let tally = outputs
        .rows()
        .enumerate()
        .map(|(j, out)| {
            let row = Row { j: j as u32, out };
            let tally = WAVES.with_borrow_mut(|waves| {
                let mut worker = Worker { waves, scene, step };
                render_row(&mut worker, &setup, camera, settings, row)
            });
            progress.row_done();
            tally
        })
        .reduce(RowTally::default, |a, b| a + b);
    outputs.finish(settings, tally, start)
}

/// One image row: its number, and its share of the outputs.
struct Row<'a> {
    j: u32,
    out: RowOutputs<'a>,
}

// ANCHOR: row
/// One image row: its primary rays as wave 1, every wave traced, then
/// each pixel's samples summed in the pattern's order.
fn render_row(
    worker: &mut Worker<'_, '_>,
    setup: &Setup,
    camera: &Camera,
    settings: &Settings,
    mut row: Row,
) -> RowTally {
    let spp = settings.sampling.spp() as usize;
    let j = row.j;
    worker.waves.start(settings.width as usize * spp, setup);
    (worker.waves).trace(setup, &PrimaryRays::new(&setup.primary, settings, j));
    let (worker, waves) = (&*worker, &*worker.waves);

    let mut tally = RowTally {
        counts: waves.counts,
        ..RowTally::default()
    };
    for i in 0..settings.width as usize {
        let mut sum = Vec3::ZERO;
        let (mut deepest, mut rays) = (0, 0);
        for k in 0..spp {
            let sample = i * spp + k;
            let traced = if waves.over_budget(sample) {
                let scalar = trace_again(worker, setup, camera, settings, (i, j, k), &mut tally);
                deepest = deepest.max(scalar.deepest as u8);
                rays += scalar.rays;
                scalar.colour
            } else {
                if setup.maps {
                    deepest = deepest.max(waves.sample_deepest[sample]);
                    rays += waves.sample_rays[sample];
                }
                sum_sample(&waves.ledger, sample)
            };
            sum += traced;
        }
        if !row.out.set_colour(i, sum / spp as f32) {
            tally.non_finite += 1;
        }
        row.out.set_maps(i, deepest, rays);
    }
    tally
}
// ANCHOR_END: row
