//! The typeface: Noto Sans Regular from the `ttf-noto-sans` crate, parsed
//! once on first use and shared by every figure afterwards.
//!
//! Two parsers look at the same bytes: `ab_glyph` turns glyph outlines into
//! pixel coverage, and `ttf-parser` (which `ab_glyph` is built on) reads the
//! font's metrics and its GPOS kerning, which `ab_glyph` does not expose.

use std::sync::OnceLock;

use ab_glyph::{Font, FontRef, GlyphId, PxScale};
use ttf_parser::gpos::{PairAdjustment, PositioningSubtable};

/// The parsed font plus the few numbers the text code needs from it.
pub(crate) struct Face {
    /// Outlines and advances, used to rasterise glyphs.
    pub(crate) font: FontRef<'static>,
    /// The same font seen by ttf-parser, used for GPOS kerning lookups.
    tables: ttf_parser::Face<'static>,
    /// Indices of the GPOS lookups that implement the `kern` feature.
    kern_lookups: Vec<u16>,
    /// Font design units in one em (1000 for Noto Sans).
    units_per_em: f32,
    /// Height of capital letters (and digits) above the baseline, in ems.
    pub(crate) cap_height_em: f32,
}

static FACE: OnceLock<Face> = OnceLock::new();

/// The shared font, parsed on first call. Parsing takes about a millisecond;
/// afterwards this is a plain pointer read.
pub(crate) fn face() -> &'static Face {
    FACE.get_or_init(Face::load)
}

impl Face {
    fn load() -> Face {
        let bytes: &'static [u8] = ttf_noto_sans::REGULAR;
        // These cannot fail at run time: the bytes are compiled into the
        // binary, and the tests below parse them on every `cargo test`.
        let font = FontRef::try_from_slice(bytes)
            .expect("the Noto Sans font bundled by ttf-noto-sans is a valid TrueType file");
        let tables = ttf_parser::Face::parse(bytes, 0)
            .expect("the Noto Sans font bundled by ttf-noto-sans is a valid TrueType file");

        let units_per_em = f32::from(tables.units_per_em());
        let cap_height_em = f32::from(capital_height_units(&tables)) / units_per_em;
        let kern_lookups = kern_lookup_indices(&tables);
        Face {
            font,
            tables,
            kern_lookups,
            units_per_em,
            cap_height_em,
        }
    }

    /// The ab_glyph scale at which one em is `size_px` pixels.
    ///
    /// ab_glyph's `PxScale` measures the whole line (ascender to descender),
    /// not the em; converting here lets every caller think of `size_px` the
    /// way CSS thinks of `font-size`.
    pub(crate) fn scale(&self, size_px: f32) -> PxScale {
        PxScale::from(size_px * self.font.height_unscaled() / self.units_per_em)
    }

    /// Pixels per font design unit at `size_px`.
    pub(crate) fn px_per_unit(&self, size_px: f32) -> f32 {
        size_px / self.units_per_em
    }

    /// Horizontal kerning between two neighbouring glyphs, in design units
    /// (negative pulls the pair together, as in "AV" or "To").
    pub(crate) fn kerning_units(&self, left: GlyphId, right: GlyphId) -> f32 {
        let (left, right) = (ttf_parser::GlyphId(left.0), ttf_parser::GlyphId(right.0));
        let Some(gpos) = self.tables.tables().gpos else {
            return 0.0;
        };
        for &index in &self.kern_lookups {
            let Some(lookup) = gpos.lookups.get(index) else {
                continue;
            };
            for subtable in lookup.subtables.into_iter::<PositioningSubtable>() {
                let PositioningSubtable::Pair(pair) = subtable else {
                    continue; // kerning lives in pair-adjustment subtables only
                };
                if let Some(advance) = pair_advance(&pair, left, right) {
                    // The first subtable that knows the pair decides it.
                    return f32::from(advance);
                }
            }
        }
        0.0
    }

    /// Whether the font can draw `c` (rather than an empty "missing" box).
    #[cfg(test)]
    pub(crate) fn has_glyph(&self, c: char) -> bool {
        self.font.glyph_id(c).0 != 0
    }
}

/// Cap height from the OS/2 table, or measured from the letter H if the
/// table does not record it.
fn capital_height_units(tables: &ttf_parser::Face) -> i16 {
    tables
        .capital_height()
        .or_else(|| {
            let h = tables.glyph_index('H')?;
            Some(tables.glyph_bounding_box(h)?.y_max)
        })
        .unwrap_or(700) // a typical Latin cap height in a 1000-unit em
}

/// The GPOS lookups listed under any `kern` feature, without duplicates.
fn kern_lookup_indices(tables: &ttf_parser::Face) -> Vec<u16> {
    let Some(gpos) = tables.tables().gpos else {
        return Vec::new();
    };
    let kern = ttf_parser::Tag::from_bytes(b"kern");
    let mut indices: Vec<u16> = gpos
        .features
        .into_iter()
        .filter(|feature| feature.tag == kern)
        .flat_map(|feature| feature.lookup_indices)
        .collect();
    indices.sort_unstable();
    indices.dedup();
    indices
}

/// The advance adjustment a pair-positioning subtable gives the first glyph
/// of `(left, right)`, if the subtable covers that pair.
fn pair_advance(
    pair: &PairAdjustment,
    left: ttf_parser::GlyphId,
    right: ttf_parser::GlyphId,
) -> Option<i16> {
    match pair {
        // Format 1 lists individual pairs, per first glyph.
        PairAdjustment::Format1 { coverage, sets } => {
            let set = sets.get(coverage.get(left)?)?;
            let (first, _second) = set.get(right)?;
            Some(first.x_advance)
        }
        // Format 2 groups glyphs into classes and stores a class-by-class matrix.
        PairAdjustment::Format2 {
            coverage,
            classes,
            matrix,
        } => {
            coverage.get(left)?;
            let (first, _second) = matrix.get((classes.0.get(left), classes.1.get(right)))?;
            Some(first.x_advance)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn font_parses_with_sensible_metrics() {
        let face = face();
        assert!(face.units_per_em >= 256.0);
        assert!(
            (0.6..0.8).contains(&face.cap_height_em),
            "cap height {} em",
            face.cap_height_em
        );
    }

    #[test]
    fn gpos_kerning_tightens_classic_pairs() {
        let face = face();
        assert!(
            !face.kern_lookups.is_empty(),
            "Noto Sans has a GPOS kern feature"
        );
        let id = |c| face.font.glyph_id(c);
        // "AV" and "To" are kerned in every text face; "oo" never is.
        assert!(face.kerning_units(id('A'), id('V')) < 0.0);
        assert!(face.kerning_units(id('T'), id('o')) < 0.0);
        assert_eq!(face.kerning_units(id('o'), id('o')), 0.0);
    }

    #[test]
    fn font_has_the_characters_the_figures_use() {
        let face = face();
        for c in "0123456789−–×·≤⁰¹²³⁴⁵⁶⁷⁸⁹AZaz()".chars() {
            assert!(face.has_glyph(c), "missing glyph for {c:?}");
        }
    }
}
