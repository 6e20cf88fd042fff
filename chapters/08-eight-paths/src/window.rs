//! Finished samples put back in order.
//!
//! The lanes take a row's samples in order, but a short path (one that
//! escapes at once) ends before a long one taken earlier. The scalar
//! tracer sums a pixel's samples in sample order, and float sums depend on
//! the order; so each finished sample waits in a small ring until every
//! sample before it has finished, and then it is summed.

use ch06_path_tracing::Terms;
use ch06_path_tracing::pixel::{RowImages, SampleSums};

/// How many samples may be taken ahead of the oldest unfinished one. A
/// path takes at most `max_depth + 1` bounces, in each of which the other
/// seven lanes end at most one path each: 7 × 65 < 512 for the deepest
/// `--max-depth`, so the lanes hardly ever wait for room.
pub const WINDOW: usize = 512;

/// One finished sample, or an empty slot.
#[derive(Clone, Copy, Default)]
struct Slot {
    terms: Terms,
    rays: u32,
    finished: bool,
}

/// The ring of finished samples, and the pixel being summed.
pub struct Window {
    /// Sample `q` of the row waits in slot `q % WINDOW`: its terms and rays.
    slots: Vec<Slot>,
    /// The row's samples summed so far (all before this one are).
    summed: usize,
    pixel: SampleSums,
}

/// Allocated once per task and reused for every row.
impl Default for Window {
    fn default() -> Window {
        Window {
            slots: vec![Slot::default(); WINDOW],
            summed: 0,
            pixel: SampleSums::default(),
        }
    }
}

impl Window {
    /// Ready for a new row.
    pub fn clear(&mut self) {
        debug_assert!(self.slots.iter().all(|s| !s.finished));
        self.summed = 0;
        self.pixel = SampleSums::default();
    }

    /// How many of the row's samples have been summed, in order.
    pub fn summed(&self) -> usize {
        self.summed
    }

    /// Whether sample `q` may be taken: it must fit in the ring.
    pub fn has_room_for(&self, q: usize) -> bool {
        q < self.summed + WINDOW
    }

    /// Sample `q` has finished with these terms and rays.
    pub fn finish(&mut self, q: usize, terms: Terms, rays: u32) {
        self.slots[q % WINDOW] = Slot {
            terms,
            rays,
            finished: true,
        };
    }

    // ANCHOR: in_order
    /// Sum every finished sample whose predecessors are all summed, in
    /// sample order, writing each pixel (of `spp` samples) into `out` once
    /// its last sample is in.
    pub fn sum_in_order(&mut self, spp: usize, out: &mut RowImages) {
        loop {
            let slot = &mut self.slots[self.summed % WINDOW];
            if !slot.finished {
                break;
            }
            slot.finished = false;
            self.pixel.rays += slot.rays;
            self.pixel.add(&slot.terms);
            self.summed += 1;
            if self.summed.is_multiple_of(spp) {
                let pixel = std::mem::take(&mut self.pixel);
                out.set(self.summed / spp - 1, pixel.finish(spp as u32));
            }
        }
    }
    // ANCHOR_END: in_order
}
