//! The image as the renderer makes it: linear light, one `Vec3` a pixel.

use image::RgbImage;

use crate::Vec3;
use rayon::prelude::*;

use crate::srgb::EncodeTable;

/// A `width` × `height` grid of linear RGB colours, row 0 at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct LinearImage {
    width: u32,
    height: u32,
    pixels: Vec<Vec3>,
}

impl LinearImage {
    /// A black image.
    pub fn new(width: u32, height: u32) -> Self {
        LinearImage {
            width,
            height,
            pixels: vec![Vec3::ZERO; width as usize * height as usize],
        }
    }

    /// An image from its pixels, row by row from the top.
    ///
    /// # Panics
    /// If there are not `width · height` pixels.
    pub fn from_pixels(width: u32, height: u32, pixels: Vec<Vec3>) -> Self {
        assert_eq!(pixels.len(), width as usize * height as usize);
        LinearImage {
            width,
            height,
            pixels,
        }
    }

    /// Columns of pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Rows of pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Every pixel, row by row from the top, each row left to right.
    pub fn pixels(&self) -> &[Vec3] {
        &self.pixels
    }

    /// The pixel in column `x` of row `y` (row 0 at the top).
    ///
    /// # Panics
    /// If `(x, y)` is outside the image.
    pub fn pixel(&self, x: u32, y: u32) -> Vec3 {
        self.pixels[(y * self.width + x) as usize]
    }

    /// Whether every channel of every pixel is a finite number.
    pub fn is_finite(&self) -> bool {
        self.pixels.iter().all(|p| p.is_finite())
    }

    /// Encode for display: clamp, sRGB, round to 8 bits (the lab model), with
    /// [`EncodeTable`] (the same bytes as `encode_channel`, without a
    /// `powf` per channel), rows shared out over every core.
    pub fn to_srgb8(&self) -> RgbImage {
        let table = EncodeTable::get();
        let mut bytes = vec![0u8; self.pixels.len() * 3];
        let row = self.width.max(1) as usize;
        bytes
            .par_chunks_mut(row * 3)
            .zip(self.pixels.par_chunks(row))
            .for_each(|(out, pixels)| {
                for (rgb, p) in out.chunks_exact_mut(3).zip(pixels) {
                    rgb.copy_from_slice(&table.encode_rgb(*p));
                }
            });
        RgbImage::from_raw(self.width, self.height, bytes).expect("3 bytes per pixel")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn encoding_keeps_rows_and_channels_in_place() {
        let image = LinearImage::from_pixels(2, 1, vec![Vec3::new(1.0, 0.0, 0.5), Vec3::ONE]);
        let rgb = image.to_srgb8();
        assert_eq!(rgb.get_pixel(0, 0).0, [255, 0, 188]);
        assert_eq!(rgb.get_pixel(1, 0).0, [255, 255, 255]);
    }

    #[test]
    fn the_encoded_image_is_encode_channel_of_every_channel() {
        use crate::srgb::encode_channel;
        let pixels: Vec<Vec3> = (0..300)
            .map(|i| Vec3::new(i as f32 / 299.0, (i as f32 * 0.37).sin(), 1e-3 * i as f32))
            .collect();
        let image = LinearImage::from_pixels(20, 15, pixels.clone());
        let bytes: Vec<u8> = pixels
            .iter()
            .flat_map(|p| p.to_array().map(encode_channel))
            .collect();
        assert_eq!(image.to_srgb8().into_raw(), bytes);
    }
}
