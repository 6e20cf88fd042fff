//! Two noisy renders of one picture, compared the way renderers' test
//! suites compare them (Mitsuba's per-pixel z-test): each pixel's
//! difference in units of its standard error, from both renders' own
//! `variance.exr`. Two correct path tracers agree within their noise
//! whatever random numbers they drew; a biased one stands out where its
//! bias exceeds the noise.

use raylab::linear_image::LinearImage;

/// How far a pixel's `|z|` must be to count as "far": four standard
/// errors, which one normal value in 16,000 exceeds by chance.
pub const FAR: f64 = 4.0;

/// The pixel channel whose `|z|` is largest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorstZ {
    pub x: u32,
    pub y: u32,
    /// 0, 1, 2: red, green, blue.
    pub channel: usize,
    /// `(a − b) / √(var_a + var_b)`; infinite where both are noiseless and differ.
    pub z: f64,
    pub a: f32,
    pub b: f32,
    /// `√(var_a + var_b)`.
    pub standard_error: f64,
}

/// What the per-pixel z-test found, over every channel of every pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct ZTest {
    /// Each pixel's z, per channel, row by row.
    pub z: Vec<[f64; 3]>,
    /// The pixel channels compared.
    pub values: usize,
    /// How many have `|z| > FAR`.
    pub far: usize,
    /// The mean z of the finite ones: near 0 when neither is brighter.
    pub mean_z: f64,
    pub worst: Option<WorstZ>,
}

impl ZTest {
    /// The share of pixel channels with `|z| > FAR`.
    pub fn far_share(&self) -> f64 {
        self.far as f64 / self.values.max(1) as f64
    }
}

/// Compare renders `a` and `b` of the same size, each with its variance
/// of the mean. Where both variances are zero (no random choice reached
/// the pixel: the sky) the two must agree to 1e-6, or `z` is infinite.
///
/// # Panics
/// If the four images are not all the same size.
pub fn z_test(
    (a, var_a): (&LinearImage, &LinearImage),
    (b, var_b): (&LinearImage, &LinearImage),
) -> ZTest {
    let size = (a.width(), a.height());
    for image in [var_a, b, var_b] {
        assert_eq!(
            (image.width(), image.height()),
            size,
            "one size for all four"
        );
    }
    let mut z = Vec::with_capacity(a.pixels().len());
    let (mut far, mut finite, mut sum) = (0, 0, 0.0);
    let mut worst: Option<WorstZ> = None;
    let pixels = a.pixels().iter().zip(var_a.pixels());
    let others = b.pixels().iter().zip(var_b.pixels());
    for (p, ((ma, va), (mb, vb))) in pixels.zip(others).enumerate() {
        let mut zs = [0.0; 3];
        for c in 0..3 {
            let standard_error = f64::from(va[c] + vb[c]).sqrt();
            let difference = f64::from(ma[c]) - f64::from(mb[c]);
            let zc = if standard_error > 0.0 {
                difference / standard_error
            } else if difference.abs() < 1e-6 {
                0.0
            } else {
                f64::INFINITY.copysign(difference)
            };
            zs[c] = zc;
            if zc.abs() > FAR {
                far += 1;
            }
            if zc.is_finite() {
                finite += 1;
                sum += zc;
            }
            if worst.is_none_or(|w| zc.abs() > w.z.abs()) {
                worst = Some(WorstZ {
                    x: p as u32 % size.0,
                    y: p as u32 / size.0,
                    channel: c,
                    z: zc,
                    a: ma[c],
                    b: mb[c],
                    standard_error,
                });
            }
        }
        z.push(zs);
    }
    ZTest {
        values: 3 * z.len(),
        z,
        far,
        mean_z: sum / f64::from(finite.max(1)),
        worst,
    }
}

/// The per-test threshold for `tests` z-tests that together fail with
/// probability `alpha` (Šidák): `|z|` beyond it has chance `1 − (1 − α)^(1/m)`.
pub fn sidak_threshold(alpha: f64, tests: usize) -> f64 {
    let per_test = 1.0 - (1.0 - alpha).powf(1.0 / tests as f64);
    // Invert the normal tail by bisection: P(|Z| > z) = erfc(z/√2).
    let (mut lo, mut hi) = (0.0f64, 10.0f64);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if erfc(mid / std::f64::consts::SQRT_2) > per_test {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// The complementary error function (Numerical Recipes' erfcc, |error| < 1.2e-7).
pub fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let r = t
        * (-z * z - 1.26551223
            + t * (1.00002368
                + t * (0.37409196
                    + t * (0.09678418
                        + t * (-0.18628806
                            + t * (0.27886807
                                + t * (-1.13520398
                                    + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277)))))))))
            .exp();
    if x >= 0.0 { r } else { 2.0 - r }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Vec3;

    fn image(pixels: &[f32]) -> LinearImage {
        let pixels = pixels.iter().map(|&v| Vec3::splat(v)).collect();
        LinearImage::from_pixels(2, 1, pixels)
    }

    /// the Šidák threshold for one test at 5 % is 1.96
    #[test]
    fn the_sidak_threshold_for_one_test_at_5_percent_is_1_96() {
        assert!((sidak_threshold(0.05, 1) - 1.959_964).abs() < 1e-4);
        // One in a million per test for 10,000 tests: |z| > 4.89.
        assert!((sidak_threshold(0.01, 10_000) - 4.89).abs() < 0.01);
    }

    #[test]
    fn a_pixel_two_standard_errors_brighter_has_z_2() {
        // Variances 0.01 and 0.03: a standard error of √0.04 = 0.2.
        let (a, va) = (image(&[1.4, 0.5]), image(&[0.01, 0.0]));
        let (b, vb) = (image(&[1.0, 0.5]), image(&[0.03, 0.0]));
        let agreement = z_test((&a, &va), (&b, &vb));
        assert!((agreement.z[0][1] - 2.0).abs() < 1e-5);
        assert_eq!(agreement.z[1], [0.0; 3], "noiseless and equal");
        assert_eq!((agreement.values, agreement.far), (6, 0));
        let worst = agreement.worst.unwrap();
        assert_eq!((worst.x, worst.y), (0, 0));
        assert!((agreement.mean_z - 1.0).abs() < 1e-5, "three 2s, three 0s");
    }

    #[test]
    fn noiseless_pixels_that_differ_are_infinitely_far() {
        let zero = image(&[0.0, 0.0]);
        let agreement = z_test((&image(&[0.5, 0.5]), &zero), (&image(&[0.5, 0.6]), &zero));
        assert_eq!(agreement.far, 3);
        let worst = agreement.worst.unwrap();
        assert_eq!((worst.x, worst.z), (1, f64::NEG_INFINITY));
    }
}
