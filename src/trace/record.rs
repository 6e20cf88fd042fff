//! What the tracer notes down beside the lab model's loop, for the bench:
//! the rays traced by kind, and, when asked for, a probe's log of every ray
//! and the colour every smaller max depth would have given.
//!
//! None of it changes a colour. The loop in [`super`] calls into it at
//! three points: when it counts a ray, when it adds a ray's light to the
//! pixel, and when a step casts a shadow ray.

use crate::Vec3;
use crate::ray::{Ray, RayKind};
use crate::scene::{Hit, Object, SceneQuery};
use crate::stack::{MAX_DEPTH_LIMIT, PendingRay};

use super::{Step, Tracer};

/// One traced ray, as a probe records it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TracedRay {
    /// Why the ray was traced: from the eye, towards the sun, or sent on.
    pub kind: RayKind,
    /// How many rays deep it is (the primary ray is depth 1).
    pub depth: u32,
    /// The share of the pixel's light it carries, the product of the
    /// shares along its branch of the tree.
    pub weight: f32,
    /// Where it starts and where it goes.
    pub ray: Ray,
    /// What it hit and at which distance; `None` for the sky.
    pub hit: Option<(Object, f32)>,
    /// What it added to the pixel's colour (zero for shadow rays, whose
    /// effect is in their parent's local light).
    pub added: Vec3,
    /// Index of the ray it came from in the same log.
    pub parent: Option<usize>,
}

/// Counts of rays traced, by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCounts([u64; RayKind::ALL.len()]);

impl RayCounts {
    /// Count `n` more rays of this kind.
    #[inline]
    pub fn add(&mut self, kind: RayKind, n: u64) {
        self.0[kind.index()] += n;
    }

    /// How many rays of this kind were counted.
    pub fn get(&self, kind: RayKind) -> u64 {
        self.0[kind.index()]
    }

    /// How many rays were counted, of every kind.
    pub fn total(&self) -> u64 {
        self.0.iter().sum()
    }
}

impl std::ops::Add for RayCounts {
    type Output = RayCounts;
    fn add(mut self, other: RayCounts) -> RayCounts {
        for (a, b) in self.0.iter_mut().zip(other.0) {
            *a += b;
        }
        self
    }
}

impl std::ops::Sub for RayCounts {
    type Output = RayCounts;
    fn sub(mut self, other: RayCounts) -> RayCounts {
        for (a, b) in self.0.iter_mut().zip(other.0) {
            *a -= b;
        }
        self
    }
}

/// The most shadow rays a probe records per hit.
const MAX_LOGGED_SHADOWS: usize = 4;

/// The shadow rays a step cast at one hit and whether they were blocked,
/// kept only while a probe's log is.
pub(super) struct ShadowLog(Option<([(Ray, bool); MAX_LOGGED_SHADOWS], usize)>);

impl ShadowLog {
    /// A log that keeps nothing: a render's.
    pub(super) fn off() -> Self {
        ShadowLog(None)
    }

    /// A log that keeps the first few shadow rays of each hit: a probe's.
    pub(super) fn on() -> Self {
        let none = (Ray::new(Vec3::ZERO, Vec3::Z), false);
        ShadowLog(Some(([none; MAX_LOGGED_SHADOWS], 0)))
    }

    /// Forget the last hit's shadow rays.
    #[inline]
    pub(super) fn clear(&mut self) {
        if let Some((_, len)) = &mut self.0 {
            *len = 0;
        }
    }

    /// Note a shadow ray, if the log is on and has room.
    #[inline]
    pub(super) fn note(&mut self, ray: Ray, blocked: bool) {
        if let Some((log, len)) = &mut self.0
            && *len < MAX_LOGGED_SHADOWS
        {
            log[*len] = (ray, blocked);
            *len += 1;
        }
    }

    /// The shadow rays noted since the last [`ShadowLog::clear`], if the log is on.
    fn rays(&self) -> Option<&[(Ray, bool)]> {
        self.0.as_ref().map(|(log, len)| &log[..*len])
    }
}

/// The tracer's bookkeeping: every ray counted, and the probe's log and
/// the per-depth colours when a tracer is made to keep them.
#[derive(Default)]
pub(super) struct Record {
    counts: RayCounts,
    log: Option<Vec<TracedRay>>,
    by_depth: Option<[Vec3; MAX_DEPTH_LIMIT as usize + 1]>,
}

impl Record {
    /// A new pixel: the per-depth colours (if kept) cleared.
    #[inline]
    pub(super) fn start(&mut self) {
        if let Some(by_depth) = &mut self.by_depth {
            by_depth.fill(Vec3::ZERO);
        }
    }

    /// Count `n` more rays of this kind.
    #[inline]
    pub(super) fn count(&mut self, kind: RayKind, n: u64) {
        self.counts.add(kind, n);
    }

    /// Note what a ray added to the pixel: in the colour of every max depth
    /// from its own up, and, with its shadow rays, in the probe's log.
    /// Returns the ray's index in the log, if one is kept.
    #[inline]
    pub(super) fn add(
        &mut self,
        pending: &PendingRay,
        hit: Option<&Hit>,
        added: Vec3,
        max_depth: u32,
        shadows: &ShadowLog,
        objects: &impl SceneQuery,
    ) -> Option<u32> {
        // A render keeps neither: one test, and the loop goes on.
        if self.by_depth.is_none() && self.log.is_none() {
            return None;
        }
        self.keep(pending, hit, added, max_depth, shadows, objects)
    }

    /// [`Record::add`] for a tracer that keeps the per-depth colours or a
    /// probe's log: out of the trace loop's way.
    #[cold]
    #[inline(never)]
    fn keep(
        &mut self,
        pending: &PendingRay,
        hit: Option<&Hit>,
        added: Vec3,
        max_depth: u32,
        shadows: &ShadowLog,
        objects: &impl SceneQuery,
    ) -> Option<u32> {
        if let Some(by_depth) = &mut self.by_depth {
            for colour in &mut by_depth[pending.depth as usize..=max_depth as usize] {
                *colour += added;
            }
        }
        let log = self.log.as_mut()?;
        let me = log.len();
        log.push(TracedRay {
            kind: pending.kind,
            depth: pending.depth,
            weight: pending.weight,
            ray: pending.ray,
            hit: hit.map(|h| (h.object, h.t)),
            added,
            parent: pending.parent.map(|p| p as usize),
        });
        if let (Some(_), Some(shadows)) = (hit, shadows.rays()) {
            for &(ray, _) in shadows {
                let hit = objects.nearest_hit(&ray).map(|h| (h.object, h.t));
                log.push(TracedRay {
                    kind: RayKind::Shadow,
                    depth: pending.depth,
                    weight: pending.weight,
                    ray,
                    hit,
                    added: Vec3::ZERO,
                    parent: Some(me),
                });
            }
        }
        Some(me as u32)
    }
}

impl<'s, S: Step + ?Sized, Q: SceneQuery> Tracer<'s, S, Q> {
    /// Record every ray traced from now on, for a probe.
    pub fn with_log(mut self) -> Self {
        self.record.log = Some(Vec::new());
        self.surface.shadow_log = ShadowLog::on();
        self
    }

    /// Also keep the colour every smaller max depth would have given (see
    /// [`Tracer::colour_at_depth`]).
    pub fn with_depth_colours(mut self) -> Self {
        self.record.by_depth = Some([Vec3::ZERO; MAX_DEPTH_LIMIT as usize + 1]);
        self
    }

    /// The rays traced so far, by kind.
    pub fn counts(&self) -> RayCounts {
        self.record.counts
    }

    /// The rays a probe recorded, in the order they were traced.
    pub fn log(&self) -> &[TracedRay] {
        self.record.log.as_deref().unwrap_or_default()
    }

    /// After [`Tracer::trace`] on a tracer made `with_depth_colours`: the
    /// colour the same ray would have had with `max_depth = depth`.
    ///
    /// A ray's own contribution does not depend on the depth limit, and
    /// removing the deeper rays does not reorder the others, so these are
    /// the same sums, added in the same order, as separate renders.
    pub fn colour_at_depth(&self, depth: u32) -> Option<Vec3> {
        let by_depth = self.record.by_depth.as_ref()?;
        (1..=self.max_depth)
            .contains(&depth)
            .then(|| by_depth[depth as usize])
    }
}
