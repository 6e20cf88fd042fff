//! What a pixel's paths add up to, and the images a render fills in: each
//! pixel's mean, the variance of that mean and its five terms, written row
//! by row by the workers.

use raylab::Vec3;

use crate::integrator::Terms;

/// One pixel's sums over its samples.
#[derive(Clone, Copy, Default)]
pub struct PixelSums {
    mean: Vec3,
    variance: Vec3,
    terms: Terms,
    rays: u64,
    non_finite: u64,
}

/// A pixel's running sums as its samples come in, in sample order (float
/// sums depend on the order).
#[derive(Clone, Copy, Default)]
pub struct SampleSums {
    sum: [f64; 3],
    sum_sq: [f64; 3],
    terms: Terms,
    /// Every ray of the pixel's paths.
    pub rays: u32,
    non_finite: u64,
}

impl SampleSums {
    /// One more sample's light; a NaN or infinite one is counted, not summed.
    pub fn add(&mut self, terms: &Terms) {
        let radiance = terms.total();
        if !radiance.is_finite() {
            self.non_finite += 1;
            return;
        }
        self.terms += *terms;
        for (c, x) in radiance.to_array().into_iter().enumerate() {
            let x = f64::from(x);
            self.sum[c] += x;
            self.sum_sq[c] += x * x;
        }
    }

    /// The mean of `n` samples, and the variance of that mean from the
    /// same samples: `(Σx² − N·x̄²) / (N − 1) / N`, summed in f64 because a
    /// sun disc seen in the mirror is 37,000 times brighter than the sky
    /// and its squares would swamp an f32 sum.
    pub fn finish(self, n: u32) -> PixelSums {
        let n = f64::from(n);
        let mean = self.sum.map(|s| s / n);
        let variance = std::array::from_fn(|c| {
            if n < 2.0 {
                return 0.0;
            }
            ((self.sum_sq[c] - n * mean[c] * mean[c]) / (n - 1.0)).max(0.0) / n
        });
        let to_vec = |a: [f64; 3]| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32);
        let terms = self.terms.as_array().map(|t| t / n as f32);
        PixelSums {
            mean: to_vec(mean),
            variance: to_vec(variance),
            terms: Terms {
                seen: terms[0],
                sun_direct: terms[1],
                sky_direct: terms[2],
                indirect: terms[3],
                caustics: terms[4],
            },
            rays: u64::from(self.rays),
            non_finite: self.non_finite,
        }
    }
}
/// The images a render fills in: each pixel's mean, the variance of that
/// mean and, when kept, its five terms.
pub struct Images {
    pub mean: Vec<Vec3>,
    pub variance: Vec<Vec3>,
    pub terms: Option<[Vec<Vec3>; 5]>,
}

impl Images {
    /// `pixels` black pixels in each image, cleared by this thread before
    /// the render (clearing them on every core measured no faster).
    pub fn new(pixels: usize, keep_terms: bool) -> Images {
        let black = || vec![Vec3::ZERO; pixels];
        Images {
            mean: black(),
            variance: black(),
            terms: keep_terms.then(|| std::array::from_fn(|_| black())),
        }
    }

    /// Each row's share of every image, `width` pixels each.
    pub fn rows(&mut self, width: usize) -> Vec<RowImages<'_>> {
        let mut term_rows =
            (self.terms.as_mut()).map(|terms| terms.each_mut().map(|term| term.chunks_mut(width)));
        let mut next_term_rows = move || {
            let rows = term_rows.as_mut()?;
            Some(
                rows.each_mut()
                    .map(|r| r.next().expect("every image has the rows")),
            )
        };
        (self.mean.chunks_mut(width))
            .zip(self.variance.chunks_mut(width))
            .map(|(mean, variance)| RowImages {
                mean,
                variance,
                terms: next_term_rows(),
                rays: 0,
                non_finite: 0,
            })
            .collect()
    }
}

/// One image row's pixels in each output image, filled in by one task,
/// and the rays and non-finite samples of its pixels.
pub struct RowImages<'a> {
    mean: &'a mut [Vec3],
    variance: &'a mut [Vec3],
    terms: Option<[&'a mut [Vec3]; 5]>,
    pub rays: u64,
    pub non_finite: u64,
}

impl RowImages<'_> {
    /// Pixel `i` of the row, from its sums.
    pub fn set(&mut self, i: usize, pixel: PixelSums) {
        self.mean[i] = pixel.mean;
        self.variance[i] = pixel.variance;
        if let Some(terms) = &mut self.terms {
            for (image, term) in terms.iter_mut().zip(pixel.terms.as_array()) {
                image[i] = term;
            }
        }
        self.rays += pixel.rays;
        self.non_finite += pixel.non_finite;
    }
}
