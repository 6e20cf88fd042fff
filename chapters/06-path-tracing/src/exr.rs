//! Linear images as 32-bit float OpenEXR, the format renderers compare in.

use std::io;
use std::path::Path;

use image::{DynamicImage, Rgb32FImage};
use raylab::linear_image::LinearImage;
use raylab_cli::output::{WriteError, write_atomically};

/// Save a linear image as an RGB 32-bit float EXR, atomically.
pub fn save_exr(image: &LinearImage, path: &Path) -> Result<(), WriteError> {
    let floats = image.pixels().iter().flat_map(|p| p.to_array()).collect();
    let rgb =
        Rgb32FImage::from_raw(image.width(), image.height(), floats).expect("3 floats per pixel");
    write_atomically(path, |w| {
        DynamicImage::ImageRgb32F(rgb)
            .write_to(w, image::ImageFormat::OpenExr)
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
