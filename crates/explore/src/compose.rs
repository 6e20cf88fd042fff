//! The frame the window shows, composed from the explorer's state: the
//! scene (split with the GPU's with `g` on), the clicked pixel's ray tree
//! in 3D, and the overlay. Apart from [`crate::state`], so that the state
//! knows nothing of what is drawn over it.

use image::RgbImage;

use crate::state::Explorer;

impl Explorer {
    /// The scene as the window shows it, without the overlay: the image,
    /// or with `g` on, its left half beside the GPU's right half.
    pub fn scene_frame(&self) -> RgbImage {
        match self.gpu().frame(self.image().dimensions()) {
            Some(gpu) => crate::gpu::split(self.image(), &gpu.image),
            None => self.image().clone(),
        }
    }

    /// The frame the window shows: the scene, the clicked pixel's ray
    /// tree in 3D, and the overlay.
    pub fn compose(&self) -> RgbImage {
        let mut frame = self.scene_frame();
        crate::overlay::draw_seam(&mut frame, self);
        let Some(probe) = self.probe() else {
            crate::overlay::draw_on(&mut frame, self);
            return frame;
        };
        // The tree may cross the whole frame: draw everything on a canvas.
        let (width, height) = self.size();
        let mut canvas = raylab_plot::Canvas::new(width, height, [0, 0, 0]);
        canvas.draw_rgb_image(&frame, 0, 0, 1);
        crate::tree3d::draw(&mut canvas, &self.camera(), probe);
        crate::overlay::draw(&mut canvas, self);
        canvas.to_rgb_image()
    }
}
