//! Linear images as 32-bit float OpenEXR, the format renderers compare in.

use std::io;
use std::path::Path;

use exr::prelude::{Encoding, Image, SpecificChannels, Vec2, WritableImage};
use raylab::linear_image::LinearImage;
use raylab_cli::output::{WriteError, write_atomically};

/// How an EXR file's pixels are packed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Packing {
    /// As they are. For a Monte Carlo estimate and its variance: every
    /// pixel is noise in its last bits, which no lossless coder shrinks
    /// (run-length coding an 800 × 600 render saved 4 KB of its 5.8 MB,
    /// and took longer than writing it).
    Raw,
    /// Runs of equal values coded once (`exr`'s fast lossless default):
    /// for the terms, black wherever a kind of light does not reach.
    RunLength,
}

/// Save a linear image as an RGB 32-bit float EXR, atomically.
pub fn save_exr(image: &LinearImage, path: &Path, packing: Packing) -> Result<(), WriteError> {
    let width = image.width() as usize;
    let pixels = image.pixels();
    let channels = SpecificChannels::rgb(|at: Vec2<usize>| {
        let p = pixels[at.y() * width + at.x()];
        (p.x, p.y, p.z)
    });
    let encoding = match packing {
        Packing::Raw => Encoding::UNCOMPRESSED,
        Packing::RunLength => Encoding::FAST_LOSSLESS,
    };
    let size = (width, image.height() as usize);
    write_atomically(path, |w| {
        Image::from_encoded_channels(size, encoding, channels)
            .write()
            .to_buffered(w)
            .map_err(io::Error::other)
    })
}

/// Read an EXR back into a linear image (for tests and figures).
pub fn load_exr(path: &Path) -> Result<LinearImage, image::ImageError> {
    let rgb = image::open(path)?.into_rgb32f();
    let (w, h) = rgb.dimensions();
    let pixels = rgb
        .pixels()
        .map(|p| raylab::Vec3::new(p.0[0], p.0[1], p.0[2]))
        .collect();
    Ok(LinearImage::from_pixels(w, h, pixels))
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Vec3;

    #[test]
    fn an_exr_packed_either_way_reads_back_as_the_same_floats() {
        let (w, h) = (67, 5);
        let pixels = (0..w * h)
            .map(|k| {
                let x = k as f32;
                Vec3::new(
                    x * 1e-7,
                    1.0 / (x + 1.0),
                    if k % 3 == 0 { 0.0 } else { x * 37.5 },
                )
            })
            .collect();
        let image = LinearImage::from_pixels(w, h, pixels);
        let dir = tempfile::tempdir().unwrap();
        for packing in [Packing::Raw, Packing::RunLength] {
            let path = dir.path().join(format!("{packing:?}.exr"));
            save_exr(&image, &path, packing).unwrap();
            assert_eq!(load_exr(&path).unwrap(), image, "{packing:?}");
        }
    }
}
