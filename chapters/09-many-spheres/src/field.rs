//! A field of many spheres: the scenes this chapter is for, made from a
//! seed so that the same command always writes the same file.

use rand_core::{Rng, SeedableRng};
use rand_pcg::Pcg32;

use std::fmt::Write;

/// The most spheres a field may have: the scene files' own limit.
pub const MAX_FIELD: usize = raylab_cli::scene_file::MAX_OBJECTS;

/// The side of each sphere's square of ground, in scene units.
const CELL: f32 = 1.2;

/// A number from 0 to 1 (exclusive) from the generator.
fn unit(rng: &mut Pcg32) -> f32 {
    (rng.next_u32() >> 8) as f32 / (1u32 << 24) as f32
}

// ANCHOR: field
/// A scene file (TOML) with `n` spheres resting on the lab's checkered
/// ground, under the lab's sky and sun, seen from above one edge.
///
/// The ground is cut into a square grid of `⌈√n⌉²` cells of side 1.2 and
/// `n` of them, chosen by the seed, hold one sphere each: radius 0.15 to
/// 0.45, moved about inside its cell without leaving it, so no two spheres
/// touch. One in six is a mirror, one in six glass, the rest matte in a
/// random colour. The same `n` and `seed` give the same text.
pub fn field(n: usize, seed: u64) -> String {
    let mut rng = Pcg32::seed_from_u64(seed);
    let side = (n as f64).sqrt().ceil() as usize;
    // Choose n of the side² cells: a partial Fisher–Yates shuffle.
    let mut cells: Vec<usize> = (0..side * side).collect();
    for k in 0..n {
        let pick = k + (rng.next_u32() as usize) % (cells.len() - k);
        cells.swap(k, pick);
    }
    let half = side as f32 * CELL / 2.0;
    let (eye_y, eye_z) = (0.35 * half + 1.2, half + 2.5);
    let epsilon = epsilon_for(half.hypot(eye_y).hypot(eye_z + half));
    let mut text = format!(
        "# A field of {n} random spheres (seed {seed}), written by\n\
         # `cargo run -p ch09-many-spheres -- generate-field {n} --seed {seed}`.\n\n\
         # How far shadow and secondary rays start from their surface: the lab's\n\
         # 1e-4 is below the rounding error of a hit this far from the eye.\n\
         epsilon = {epsilon:.1e}\n\n\
         [camera]\neye = [0.0, {eye_y:.3}, {eye_z:.3}]\ntarget = [0.0, 0.0, {:.3}]\n\
         up = [0.0, 1.0, 0.0]\nfov = 45.0\n\n\
         [sun]\ndirection = [-1.0, 1.2, 0.8]\nbrightness = 25.0\n\n\
         [sky]\nhorizon = [0.85, 0.90, 1.00]\nzenith = [0.25, 0.45, 0.85]\n\n\
         [ground]\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 1.0, 0.0]\n\
         even = [0.75, 0.75, 0.75]\nodd = [0.25, 0.25, 0.25]\n",
        -0.25 * half
    );
    for &cell in &cells[..n] {
        let radius = 0.15 + 0.3 * unit(&mut rng);
        let room = CELL / 2.0 - radius;
        let (col, row) = ((cell % side) as f32, (cell / side) as f32);
        let x = -half + (col + 0.5) * CELL + room * (2.0 * unit(&mut rng) - 1.0);
        let z = -half + (row + 0.5) * CELL + room * (2.0 * unit(&mut rng) - 1.0);
        let kind = rng.next_u32() % 6;
        let albedo = [unit(&mut rng), unit(&mut rng), unit(&mut rng)].map(|c| 0.1 + 0.8 * c);
        let _ = write!(
            text,
            "\n[[sphere]]\ncentre = [{x:.3}, {radius:.3}, {z:.3}]\nradius = {radius:.3}\n\
             albedo = [{:.2}, {:.2}, {:.2}]\n",
            albedo[0], albedo[1], albedo[2]
        );
        let _ = match kind {
            0 => writeln!(text, "reflection = 0.8"),
            1 => writeln!(text, "reflection = 0.1\ntransmission = 0.8\nior = 1.5"),
            _ => Ok(()),
        };
    }
    text
}
// ANCHOR_END: field

/// A field of `n` spheres (seed 1), as a scene and its camera: the scenes
/// the tests, the figures and the bench try the tree on.
pub fn field_scene(n: usize) -> (raylab::Scene, raylab::Camera) {
    let text = field(n, 1);
    raylab_cli::scene_file::parse(&text, std::path::Path::new("field.toml"))
        .expect("a generated field is a valid scene")
}

/// The smallest radius of a field's spheres.
const SMALLEST_RADIUS: f32 = 0.15;

// ANCHOR: epsilon
/// The offset a field's rays need when its farthest point is `far` units
/// from the eye. The sphere test subtracts two numbers near `far²`, so it
/// rounds by about `far² · 2⁻²³`; divided by the radius, that is how far a
/// hit point may lie inside its sphere, and a grazing hit lies several
/// times farther. Eight times that, never less than the lab's 1e-4, nor
/// more than the 0.1 a scene file allows.
pub fn epsilon_for(far: f32) -> f32 {
    let rounding = far * far * f32::EPSILON;
    (8.0 * rounding / SMALLEST_RADIUS).clamp(1e-4, raylab_cli::MAX_EPSILON)
}
// ANCHOR_END: epsilon

#[cfg(test)]
mod tests {
    use super::*;

    fn load(text: &str) -> raylab::Scene {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("field.toml");
        std::fs::write(&path, text).unwrap();
        raylab_cli::scene_file::load(&path).unwrap().0
    }

    #[test]
    fn a_field_of_n_is_a_valid_scene_of_n_spheres() {
        for n in [0, 1, 7, 500] {
            assert_eq!(load(&field(n, 3)).spheres().len(), n);
        }
    }

    #[test]
    fn a_field_asks_for_an_epsilon_that_grows_with_the_square_of_its_size() {
        // 30 units away: 900 · 2⁻²³ / 0.15 · 8 = 5.72e-3.
        assert!((epsilon_for(30.0) - 5.722e-3).abs() < 1e-6);
        assert_eq!(epsilon_for(3.0), 1e-4);
        assert_eq!(epsilon_for(1e4), 0.1);
        let file = |n| {
            let dir = tempfile::tempdir().unwrap();
            let path = dir.path().join("field.toml");
            std::fs::write(&path, field(n, 1)).unwrap();
            raylab_cli::scene_file::load_file(&path).unwrap().epsilon
        };
        assert_eq!(file(500), Some(7.2e-3));
    }

    #[test]
    fn the_same_seed_writes_the_same_field_and_another_seed_another() {
        assert_eq!(field(50, 1), field(50, 1));
        assert_ne!(field(50, 1), field(50, 2));
    }

    #[test]
    fn the_largest_field_fits_in_a_scene_file() {
        let text = field(MAX_FIELD, 0);
        assert!(text.len() as u64 <= raylab_cli::scene_file::MAX_FILE_BYTES);
        assert_eq!(load(&text).spheres().len(), MAX_FIELD);
    }

    #[test]
    fn no_two_spheres_of_a_field_overlap() {
        let scene = load(&field(400, 9));
        let s = scene.spheres();
        for (i, a) in s.iter().enumerate() {
            for b in &s[i + 1..] {
                let gap = (a.shape.centre - b.shape.centre).length();
                assert!(gap >= a.shape.radius + b.shape.radius - 2e-3);
            }
        }
    }
}
