//! A rectangle a label covers, for keeping labels from landing on top of
//! each other (a plot's marker labels, a ray tree's depth badges).

/// A rectangle on the canvas: its top-left corner, width and height.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LabelBox {
    pub x: f32,
    pub y: f32,
    pub w: f32,
    pub h: f32,
}

impl LabelBox {
    /// The box `w` × `h` centred on `(x, y)`.
    pub fn around((x, y): (f32, f32), w: f32, h: f32) -> LabelBox {
        LabelBox {
            x: x - w / 2.0,
            y: y - h / 2.0,
            w,
            h,
        }
    }

    /// Whether the two boxes share any area (touching edges do not).
    pub fn overlaps(&self, other: &LabelBox) -> bool {
        self.x < other.x + other.w
            && other.x < self.x + self.w
            && self.y < other.y + other.h
            && other.y < self.y + self.h
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boxes_that_share_area_overlap_and_boxes_that_only_touch_do_not() {
        let a = LabelBox::around((10.0, 10.0), 4.0, 4.0);
        assert_eq!((a.x, a.y), (8.0, 8.0));
        assert!(a.overlaps(&LabelBox::around((13.0, 10.0), 4.0, 4.0)));
        assert!(!a.overlaps(&LabelBox::around((14.0, 10.0), 4.0, 4.0)));
    }
}
