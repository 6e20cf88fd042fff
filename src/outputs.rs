//! What a render writes, pixel by pixel: the 8-bit image always, and the
//! linear image and the per-pixel maps when they are asked for.

use image::RgbImage;
use rayon::prelude::*;

use crate::Vec3;
use crate::frame::{Keep, PixelMaps, Rendered, RowTally, Settings};
use crate::linear_image::LinearImage;
use crate::srgb::EncodeTable;

/// A render's outputs, made before the first ray and handed out to the
/// workers a row at a time ([`Outputs::rows`]).
pub struct Outputs {
    width: u32,
    height: u32,
    /// Three bytes a pixel, row by row from the top.
    srgb: Vec<u8>,
    linear: Option<Vec<Vec3>>,
    maps: Option<PixelMaps>,
}

impl Outputs {
    /// Outputs for a `width` × `height` image, keeping what `keep` asks.
    ///
    /// The memory is not written here but by the workers, row by row, so
    /// the kernel hands its pages out on every core at once instead of on
    /// this thread before the first ray. The
    /// byte buffers are allocated zeroed, which the allocator gets from
    /// the kernel as they are without writing them; a vector of `Vec3` is
    /// filled in parallel for the same reason.
    pub fn new(width: u32, height: u32, keep: Keep) -> Outputs {
        let pixels = width as usize * height as usize;
        let linear = keep.linear.then(|| {
            let mut linear = Vec::with_capacity(pixels);
            linear.par_extend(rayon::iter::repeat_n(Vec3::ZERO, pixels));
            linear
        });
        let maps = keep.maps.then(|| PixelMaps {
            deepest: vec![0; pixels],
            rays: vec![0; pixels],
        });
        Outputs {
            width,
            height,
            srgb: vec![0; 3 * pixels],
            linear,
            maps,
        }
    }

    /// One [`RowOutputs`] per image row, from the top, to share out.
    pub fn rows(&mut self) -> impl IndexedParallelIterator<Item = RowOutputs<'_>> {
        let width = self.width.max(1) as usize;
        let height = self.height as usize;
        let table = EncodeTable::get();
        let mut linear = self.linear.as_mut().map(|l| l.chunks_mut(width));
        let mut maps = self
            .maps
            .as_mut()
            .map(|m| m.deepest.chunks_mut(width).zip(m.rays.chunks_mut(width)));
        let rows: Vec<RowOutputs> = self
            .srgb
            .chunks_mut(3 * width)
            .take(height)
            .map(|srgb| RowOutputs {
                srgb,
                linear: linear.as_mut().and_then(Iterator::next),
                maps: maps.as_mut().and_then(Iterator::next),
                table,
            })
            .collect();
        rows.into_par_iter().with_max_len(1)
    }

    /// The finished render, with the rows' tallies summed in `tally`.
    pub fn finish(
        self,
        settings: &Settings,
        tally: RowTally,
        started: std::time::Instant,
    ) -> Rendered {
        let (width, height) = (self.width, self.height);
        Rendered {
            settings: *settings,
            srgb: RgbImage::from_raw(width, height, self.srgb).expect("3 bytes per pixel"),
            linear: self
                .linear
                .map(|pixels| LinearImage::from_pixels(width, height, pixels)),
            maps: self.maps,
            counts: tally.counts,
            elapsed: started.elapsed(),
            non_finite: tally.non_finite,
            over_budget: tally.over_budget,
        }
    }
}

/// One image row's share of the outputs, which one worker fills.
pub struct RowOutputs<'a> {
    srgb: &'a mut [u8],
    linear: Option<&'a mut [Vec3]>,
    maps: Option<(&'a mut [u8], &'a mut [u32])>,
    table: &'static EncodeTable,
}

impl RowOutputs<'_> {
    /// Set pixel `i` of the row to `colour` (its samples' average, in
    /// linear light): kept if asked, and encoded to its three bytes right
    /// away, while the row is in the cache. A NaN or infinite colour is
    /// set to black; the answer is whether the colour was finite.
    #[inline]
    pub fn set_colour(&mut self, i: usize, colour: Vec3) -> bool {
        let finite = colour.is_finite();
        let colour = if finite { colour } else { Vec3::ZERO };
        if let Some(linear) = &mut self.linear {
            linear[i] = colour;
        }
        self.srgb[3 * i..3 * i + 3].copy_from_slice(&self.table.encode_rgb(colour));
        finite
    }

    /// Set pixel `i`'s depth and ray count, if the maps are kept.
    pub fn set_maps(&mut self, i: usize, deepest: u8, rays: u32) {
        if let Some((deepest_row, rays_row)) = &mut self.maps {
            (deepest_row[i], rays_row[i]) = (deepest, rays);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::srgb::encode_channel;

    fn settings() -> Settings {
        Settings {
            width: 2,
            height: 2,
            max_depth: 1,
            epsilon: 1e-4,
            sampling: crate::Sampling::new(1, None, 0).expect("1 spp"),
        }
    }

    #[test]
    fn a_pixel_is_encoded_as_encode_channel_encodes_each_channel() {
        let mut outputs = Outputs::new(2, 2, Keep::LINEAR);
        let colour = Vec3::new(0.5, 0.001, 2.0);
        let finite = outputs.rows().collect::<Vec<_>>()[1].set_colour(1, colour);
        assert!(finite);
        let rendered = outputs.finish(&settings(), RowTally::default(), std::time::Instant::now());
        let expected = colour.to_array().map(encode_channel);
        assert_eq!(expected, [188, 3, 255]);
        assert_eq!(rendered.srgb.get_pixel(1, 1).0, expected);
        assert_eq!(rendered.srgb.get_pixel(0, 1).0, [0, 0, 0]);
        assert_eq!(rendered.linear_image().pixel(1, 1), colour);
    }

    #[test]
    fn a_nan_pixel_is_stored_black_and_reported() {
        let mut outputs = Outputs::new(1, 1, Keep::LINEAR);
        let finite =
            outputs.rows().collect::<Vec<_>>()[0].set_colour(0, Vec3::new(f32::NAN, 1.0, 1.0));
        assert!(!finite);
        let rendered = outputs.finish(&settings(), RowTally::default(), std::time::Instant::now());
        assert_eq!(rendered.srgb.get_pixel(0, 0).0, [0, 0, 0]);
        assert_eq!(rendered.linear_image().pixel(0, 0), Vec3::ZERO);
    }

    #[test]
    fn only_what_is_asked_for_is_kept() {
        for keep in [Keep::IMAGE, Keep::LINEAR, Keep::ALL] {
            let mut outputs = Outputs::new(3, 2, keep);
            assert!(outputs.rows().all(|row| row.maps.is_some() == keep.maps));
            let rendered =
                outputs.finish(&settings(), RowTally::default(), std::time::Instant::now());
            assert_eq!(rendered.linear.is_some(), keep.linear);
            assert_eq!(rendered.maps.is_some(), keep.maps);
            assert_eq!(rendered.srgb.dimensions(), (3, 2));
        }
    }
}
