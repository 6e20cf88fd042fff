//! Acne at scale: how many pixels of a render a too-small offset has
//! speckled, against a render without acne (the test of the page's "ε at
//! scale" and the workbook's figure of it count the same way).

/// A change this large is a lit point turned to shadow (a tenth of the
/// sunlight) or a reflection that found its own sphere, not the shift of a
/// grazing ray onto another checker square: acne.
pub const SPECKLE: u8 = 24;

/// Per pixel (row by row), whether the 8-bit RGB pixels of `image` differ
/// from `reference`'s by more than [`SPECKLE`] levels in some channel.
pub fn speckled(image: &[u8], reference: &[u8]) -> Vec<bool> {
    image
        .chunks_exact(3)
        .zip(reference.chunks_exact(3))
        .map(|(a, b)| a.iter().zip(b).any(|(x, y)| x.abs_diff(*y) > SPECKLE))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_a_change_of_more_than_24_levels_is_a_speckle() {
        let a = [100, 100, 100, 100, 100, 100];
        let b = [100, 124, 100, 100, 100, 125];
        assert_eq!(speckled(&a, &b), [false, true]);
    }
}
