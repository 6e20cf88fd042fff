//! Caustics: the light the photons traced from the sun ([`crate::photons`])
//! left on the ground, and the irradiance at a ground point estimated from
//! the photons near it (a density estimate).

use rayon::prelude::*;

use raylab::{Scene, Vec3};

/// The density estimate's kernel radius on the ground, in scene units
/// (the checker squares are 1 across).
pub const KERNEL_RADIUS: f32 = 0.025;
/// Photons sent towards each mirror or glass sphere.
pub const PHOTONS_PER_SPHERE: u32 = 2_000_000;
/// Photons are kept where they land within this distance of the ground's
/// point, along either axis: the part of the ground the lab camera sees
/// in any detail.
const EXTENT: f32 = 16.0;
/// Photons that land in the same small square of the ground, a
/// `BINS_PER_CELL`-th of the kernel radius across, with the same number of
/// bounces, are merged into one at their centre of power.
const BINS_PER_CELL: f32 = 8.0;

/// One photon on the ground.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Photon {
    /// Position in the ground's own two axes.
    pub u: f32,
    pub v: f32,
    /// Its power (irradiance × area), the same in every colour channel.
    pub power: f32,
    /// Mirror and glass bounces it took from the sun.
    pub bounces: u32,
}

/// Photons as four columns of equal length, padded with powerless photons
/// so that a lookup can read its last run eight at a time.
#[derive(Clone, Debug, Default)]
pub struct PhotonColumns {
    /// Where each photon landed, in the ground's own two axes.
    pub u: Vec<f32>,
    pub v: Vec<f32>,
    /// The power every channel carries: mirrors and the lab's glass do not
    /// tint the sunlight, so one number per photon.
    pub power: Vec<f32>,
    /// Its mirror and glass bounces (a whole number).
    pub bounces: Vec<f32>,
}

/// What a lookup at a ground point reads ([`CausticMap::near`]).
pub struct Near<'m> {
    /// The point in the ground's own axes.
    pub u: f32,
    pub v: f32,
    /// The photons of each row of the 3 × 3 cells around it, as indices
    /// into the columns (a run's last group of eight may reach past it).
    pub runs: [std::ops::Range<usize>; 3],
    pub photons: &'m PhotonColumns,
}

/// The photons on the ground, bucketed in a grid of cells one kernel
/// radius across, so that a lookup reads only the 3 × 3 cells around it.
pub struct CausticMap {
    origin: Vec3,
    axis_u: Vec3,
    axis_v: Vec3,
    cells: usize,
    /// Where each cell's photons start in the columns (one more entry at
    /// the end). Cells are numbered row by row, so the three cells of a row
    /// of the 3 × 3 block a lookup reads are one run of photons.
    cell_start: Vec<u32>,
    /// The photons sorted by cell, as columns (structure of arrays), so
    /// that a lookup reads each quantity of consecutive photons from one
    /// run of memory.
    photons: PhotonColumns,
    /// How many of the columns' photons are real (the rest is padding).
    kept: usize,
    /// Light rays sent, and rays traced for them.
    pub sent: u64,
    pub rays: u64,
}

impl CausticMap {
    pub(crate) fn from_photons(
        scene: &Scene,
        photons: Vec<Photon>,
        sent: u64,
        rays: u64,
    ) -> CausticMap {
        let photons = merged(photons);
        let plane = scene.ground.plane;
        let (axis_u, axis_v) = plane.normal.any_orthonormal_pair();
        let cells = (2.0 * EXTENT / KERNEL_RADIUS).ceil() as usize;
        let cell_of = |p: &Photon| -> Option<usize> {
            let x = ((p.u + EXTENT) / KERNEL_RADIUS).floor();
            let y = ((p.v + EXTENT) / KERNEL_RADIUS).floor();
            let inside = (0.0..cells as f32).contains(&x) && (0.0..cells as f32).contains(&y);
            inside.then(|| y as usize * cells + x as usize)
        };
        // A counting sort by cell.
        let mut cell_start = vec![0u32; cells * cells + 1];
        for p in &photons {
            if let Some(c) = cell_of(p) {
                cell_start[c + 1] += 1;
            }
        }
        for c in 0..cells * cells {
            cell_start[c + 1] += cell_start[c];
        }
        let mut next = cell_start.clone();
        let kept = cell_start[cells * cells] as usize;
        // Room for the last run of a lookup to be read eight at a time.
        let padded = kept.next_multiple_of(8) + 8;
        let mut sorted = PhotonColumns {
            u: vec![0.0; padded],
            v: vec![0.0; padded],
            power: vec![0.0; padded],
            bounces: vec![0.0; padded],
        };
        for p in &photons {
            if let Some(c) = cell_of(p) {
                let i = next[c] as usize;
                sorted.u[i] = p.u;
                sorted.v[i] = p.v;
                sorted.power[i] = p.power;
                sorted.bounces[i] = p.bounces as f32;
                next[c] += 1;
            }
        }
        CausticMap {
            origin: plane.point,
            axis_u,
            axis_v,
            cells,
            cell_start,
            photons: sorted,
            kept,
            sent,
            rays,
        }
    }

    /// How many photons landed on the kept part of the ground.
    pub fn len(&self) -> usize {
        self.kept
    }

    pub fn is_empty(&self) -> bool {
        self.kept == 0
    }

    // ANCHOR: density
    /// The caustic irradiance at ground point `p` from photons that took
    /// at most `max_bounces` mirror and glass bounces: their power, spread
    /// by the Epanechnikov kernel `K(d) = 2/(πh²) · (1 − d²/h²)` of radius
    /// `h` ([`KERNEL_RADIUS`]), which integrates to 1 over the plane.
    pub fn irradiance(&self, p: Vec3, max_bounces: u32) -> Vec3 {
        if max_bounces == 0 {
            return Vec3::ZERO;
        }
        let Some(near) = self.near(p) else {
            return Vec3::ZERO; // beside the grid: no photon is that far out
        };
        let (u, v, h) = (near.u, near.v, KERNEL_RADIUS);
        // A bright caustic holds thousands of photons in a few cells, and
        // every path that lands near it reads them all. They are added as
        // eight partial sums (the k-th photon of each group of eight adds
        // to sum k) and the eight are added pairwise at the end.
        // Floating-point addition is not associative: this order is the
        // one the caustic images were made with, so it is part of them.
        let most = max_bounces as f32;
        let mut sums = [0.0f32; 8];
        let photons = &self.photons;
        for run in near.runs {
            for i in run.clone().step_by(8) {
                let (pu, pv) = (&photons.u[i..i + 8], &photons.v[i..i + 8]);
                let (bounces, power) = (&photons.bounces[i..i + 8], &photons.power[i..i + 8]);
                for (k, sum) in sums.iter_mut().enumerate() {
                    let (du, dv) = (pu[k] - u, pv[k] - v);
                    let d2 = du * du + dv * dv;
                    // Past the run's end are the next cells' photons: not these.
                    let counts = d2 < h * h && bounces[k] <= most && i + k < run.end;
                    let kernel = 1.0 - d2 / (h * h);
                    *sum += if counts { power[k] * kernel } else { 0.0 };
                }
            }
        }
        let [s0, s1, s2, s3, s4, s5, s6, s7] = sums;
        let sum = ((s0 + s4) + (s2 + s6)) + ((s1 + s5) + (s3 + s7));
        Vec3::splat(sum * (2.0 / (std::f32::consts::PI * h * h)))
    }
    // ANCHOR_END: density

    /// Where a lookup at ground point `p` reads: `p` in the ground's own
    /// axes, and the photons of the 3 × 3 cells around it, one run of the
    /// columns per row of cells. `None` beside the grid.
    pub fn near(&self, p: Vec3) -> Option<Near<'_>> {
        let local = p - self.origin;
        let (u, v) = (local.dot(self.axis_u), local.dot(self.axis_v));
        let h = KERNEL_RADIUS;
        let cx = ((u + EXTENT) / h).floor() as i64;
        let cy = ((v + EXTENT) / h).floor() as i64;
        let last = self.cells as i64 - 1;
        let (x0, x1) = ((cx - 1).max(0), (cx + 1).min(last));
        if x0 > x1 {
            return None;
        }
        // Rows of cells outside the grid read nothing (an empty run).
        let runs = [cy - 1, cy, cy + 1].map(|y| {
            if !(0..=last).contains(&y) {
                return 0..0;
            }
            let row = (y * self.cells as i64) as usize;
            let start = self.cell_start[row + x0 as usize] as usize;
            start..self.cell_start[row + x1 as usize + 1] as usize
        });
        Some(Near {
            u,
            v,
            runs,
            photons: &self.photons,
        })
    }
}

/// Merge the photons of each bin (see [`BINS_PER_CELL`]) into one, with
/// their summed power, at their centre of power.
///
/// The glass focuses a million photons into a spot a few kernels across,
/// and every path that lands there would read a hundred thousand of them.
/// Merged, the spot is a few thousand. The estimate hardly moves: the
/// kernel is a parabola, so moving photons to their centre changes the sum
/// only by their spread in the bin, at most (r/8)², squared against r²:
/// well under 1 %, except within a bin of the kernel's rim.
fn merged(photons: Vec<Photon>) -> Vec<Photon> {
    let bin = KERNEL_RADIUS / BINS_PER_CELL;
    let key = |p: &Photon| {
        let row = ((p.v + EXTENT) / bin).floor() as i64;
        let column = ((p.u + EXTENT) / bin).floor() as i64;
        (row, column, p.bounces)
    };
    let mut keyed: Vec<_> = photons.into_iter().map(|p| (key(&p), p)).collect();
    // Stable, so that a bin's sums are added in the photons' own order and
    // the map is the same on any number of threads.
    keyed.par_sort_by_key(|(k, _)| *k);
    keyed
        .chunk_by(|a, b| a.0 == b.0)
        .filter_map(|run| {
            let (mut power, mut u, mut v) = (0f64, 0f64, 0f64);
            for (_, p) in run {
                let w = f64::from(p.power);
                (power, u, v) = (power + w, u + w * f64::from(p.u), v + w * f64::from(p.v));
            }
            (power > 0.0).then(|| Photon {
                u: (u / power) as f32,
                v: (v / power) as f32,
                power: power as f32,
                bounces: run[0].1.bounces,
            })
        })
        .collect()
}

pub(crate) fn ground_axes(scene: &Scene) -> (Vec3, Vec3) {
    scene.ground.plane.normal.any_orthonormal_pair()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ground point at (u, v) in the ground's own axes.
    fn ground_point(scene: &Scene, u: f32, v: f32) -> Vec3 {
        let (a, b) = ground_axes(scene);
        scene.ground.plane.point + u * a + v * b
    }

    fn photon_at(u: f32, v: f32, power: f32, bounces: u32) -> Photon {
        Photon {
            u,
            v,
            power,
            bounces,
        }
    }

    #[test]
    fn one_photon_spreads_its_power_by_the_epanechnikov_kernel() {
        let scene = Scene::lab();
        let map = CausticMap::from_photons(&scene, vec![photon_at(0.3, -0.2, 2.0, 1)], 1, 1);
        let h = KERNEL_RADIUS;
        let peak = 2.0 * 2.0 / (std::f32::consts::PI * h * h);
        let at = |du: f32| map.irradiance(ground_point(&scene, 0.3 + du, -0.2), 10).x;
        // On the photon: the kernel's peak 2/(πh²), times its power 2.
        assert!((at(0.0) / peak - 1.0).abs() < 1e-5, "{}", at(0.0));
        // Half a radius away: 1 − (1/2)² = 3/4 of the peak.
        assert!((at(h / 2.0) / peak - 0.75).abs() < 1e-4, "{}", at(h / 2.0));
        // Beyond the radius: nothing.
        assert_eq!(at(1.01 * h), 0.0);
    }

    #[test]
    fn photons_with_more_bounces_than_the_path_allows_do_not_count() {
        let scene = Scene::lab();
        let map = CausticMap::from_photons(&scene, vec![photon_at(0.0, 0.0, 1.0, 3)], 1, 1);
        let p = ground_point(&scene, 0.0, 0.0);
        assert_eq!(map.irradiance(p, 2), Vec3::ZERO);
        assert!(map.irradiance(p, 3).x > 0.0);
    }

    #[test]
    fn photons_merged_in_one_bin_keep_their_power_at_their_centre() {
        let scene = Scene::lab();
        let h = KERNEL_RADIUS;
        // Two photons a tenth of a bin apart: one photon of twice the power.
        let (a, b) = (0.3001, 0.3001 + 0.1 * h / BINS_PER_CELL);
        let map = CausticMap::from_photons(
            &scene,
            vec![photon_at(a, 0.0, 1.0, 1), photon_at(b, 0.0, 1.0, 1)],
            2,
            2,
        );
        assert_eq!(map.len(), 1);
        let exact = |q: f32| {
            [a, b]
                .iter()
                .map(|&p| 1.0 - (p - q).powi(2) / (h * h))
                .sum::<f32>()
                * (2.0 / (std::f32::consts::PI * h * h))
        };
        for q in [a, a + 0.5 * h] {
            let merged = map.irradiance(ground_point(&scene, q, 0.0), 1).x;
            assert!(
                (merged / exact(q) - 1.0).abs() < 1e-3,
                "{merged} against {}",
                exact(q)
            );
        }
        // Different bounces are never merged: the bounce limit still tells them apart.
        let two = CausticMap::from_photons(
            &scene,
            vec![photon_at(a, 0.0, 1.0, 1), photon_at(a, 0.0, 1.0, 2)],
            2,
            2,
        );
        assert_eq!(two.len(), 2);
    }

    #[test]
    fn the_density_estimate_adds_its_photons_in_eight_partial_sums_paired_as_the_lanes_are() {
        // Nine photons on the query point (kernel 1), kept apart by their
        // bounces (1 to 9), which also orders them in their run. The first
        // carries 2²⁴, the others 1: a 1 added to 2²⁴ alone is rounded away
        // (2²⁴ + 1 is halfway, and ties go to the even 2²⁴).
        let scene = Scene::lab();
        let photons = (1..=9)
            .map(|b| photon_at(0.0, 0.0, if b == 1 { 16_777_216.0 } else { 1.0 }, b))
            .collect();
        let map = CausticMap::from_photons(&scene, photons, 9, 9);
        assert_eq!(map.len(), 9);
        // Sum 0 holds photons 1 and 9: 2²⁴ + 1 = 2²⁴. Sums 1 to 7 hold 1
        // each. Paired ((s0 + s4) + (s2 + s6)) + ((s1 + s5) + (s3 + s7)):
        // (2²⁴ + 2) + 4 = 2²⁴ + 6, where a photon-by-photon sum gives 2²⁴
        // and two sums of four (s0 + … + s3) + (s4 + … + s7) give 2²⁴ + 4.
        let h = KERNEL_RADIUS;
        let expected = 16_777_222.0 * (2.0 / (std::f32::consts::PI * h * h));
        assert_eq!(map.irradiance(scene.ground.plane.point, 10).x, expected);
    }

    #[test]
    fn the_density_estimate_counts_exactly_the_photons_within_the_kernel_and_the_bounces() {
        // Many photons over a few cells, some beyond the kernel, some with
        // too many bounces, runs that end inside a group of eight: the
        // eight partial sums must count exactly the right ones.
        let scene = Scene::lab();
        // Each photon in a bin of its own (the centre of bin (i, j)), so
        // that merging leaves them as they are.
        let bin = KERNEL_RADIUS / BINS_PER_CELL;
        let photons: Vec<Photon> = (0..203u32)
            .map(|k| {
                let (i, j) = ((k % 23) as f32, (k / 23) as f32 * 2.0 + (k % 2) as f32);
                let centre = |n: f32| ((EXTENT / bin).floor() - 12.0 + n + 0.5) * bin - EXTENT;
                photon_at(centre(i), centre(j), 1.0 + (k % 5) as f32, 1 + k % 4)
            })
            .collect();
        let map = CausticMap::from_photons(&scene, photons.clone(), 203, 203);
        let h = KERNEL_RADIUS;
        for (qu, qv) in [(0.0, 0.0), (0.011, -0.007), (-0.02, 0.024)] {
            let one_by_one: f32 = photons
                .iter()
                .filter(|p| p.bounces <= 2)
                .map(|p| {
                    let d2 = (p.u - qu).powi(2) + (p.v - qv).powi(2);
                    if d2 < h * h {
                        p.power * (1.0 - d2 / (h * h))
                    } else {
                        0.0
                    }
                })
                .sum::<f32>()
                * (2.0 / (std::f32::consts::PI * h * h));
            let estimate = map.irradiance(ground_point(&scene, qu, qv), 2).x;
            assert!(
                (estimate - one_by_one).abs() <= 1e-4 * one_by_one.max(1.0),
                "{estimate} against {one_by_one}"
            );
        }
    }
}
