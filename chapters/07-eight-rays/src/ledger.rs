//! The row's ledger: what each ray added to its sample, and which ray of
//! the same sample the scalar ray stack pops after it.
//!
//! The waves trace a row's rays depth by depth, but chapter 5 sums a
//! sample's light in the order its ray stack pops the rays. Each traced
//! ray leaves an entry here, and [`crate::render`] sums a sample by walking
//! the links from its primary ray, so the sums round exactly as chapter
//! 5's do.

use raylab::Vec3;
use wide::f32x8;

use crate::link::settle;
use crate::soa::{LANES, Vec3x8};

// ANCHOR: ledger
/// One entry per ray traced in a row, numbered in the order the waves
/// trace them (wave 1's rays first, so a primary ray's number is its
/// sample's): the light the ray added to its sample, `w · (1 − r − t) ·
/// local` or `w · sky`, and the number of the ray that the scalar ray stack
/// pops next for the same sample ([`END`](crate::link::END) after its last).
///
/// A ray that sends rays on links to its first child (the transmitted one,
/// which the stack pops first); the child links to its sibling, and the
/// last child to whatever its parent linked to before. The links are made
/// when the children are packed, so summing a sample is a walk along them.
///
/// Each entry is one record of 16 bytes, the light and the link side by
/// side: the walk reads one cache line per ray, not one from each of four
/// arrays.
#[derive(Clone, Debug, Default)]
pub struct Ledger {
    entries: Vec<Entry>,
    /// The entries whose link is provisional (see [`crate::link::LATER`])
    /// until the wave is done.
    unsettled: Vec<u32>,
}

/// One ray's entry: the light it added, and the ray popped after it.
#[derive(Clone, Copy, Debug, Default)]
#[repr(C, align(16))]
struct Entry {
    light: [f32; 3],
    next: u32,
}
// ANCHOR_END: ledger

impl Ledger {
    pub fn clear(&mut self) {
        self.entries.clear();
        self.unsettled.clear();
    }

    /// How many rays are in the ledger: the number the next one gets.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// What ray `ray` added to its sample.
    pub fn light(&self, ray: usize) -> Vec3 {
        Vec3::from_array(self.entries[ray].light)
    }

    /// The ray its sample's stack pops after ray `ray`, or [`END`](crate::link::END).
    pub fn next(&self, ray: usize) -> u32 {
        self.entries[ray].next
    }

    /// Append a group's first `lanes` rays: the four numbers of each lane
    /// transposed into its record (a link travels as an `f32`'s bits).
    pub(crate) fn push_group(&mut self, light: Vec3x8, next: [u32; LANES], lanes: usize) {
        let next = f32x8::from(next.map(f32::from_bits));
        let zero = f32x8::ZERO;
        let rows = f32x8::transpose([light.x, light.y, light.z, next, zero, zero, zero, zero]);
        self.entries.extend(rows[..lanes].iter().map(|row| {
            let [x, y, z, next, ..] = row.to_array();
            Entry {
                light: [x, y, z],
                next: next.to_bits(),
            }
        }));
    }

    pub(crate) fn reserve(&mut self, more: usize) {
        self.entries.reserve(more + LANES);
    }

    /// Note that the links of the lanes of `unsettled` (lane `k` in bit
    /// `k`) of the group whose first entry is `first` are provisional.
    pub(crate) fn unsettled(&mut self, first: usize, unsettled: i32) {
        let lanes = raylab_lanes::lanes_of(unsettled as u32);
        self.unsettled
            .extend(lanes.map(|lane| (first + lane) as u32));
    }

    /// Make the provisional links final.
    pub(crate) fn settle(&mut self, base: u32) {
        for entry in self.unsettled.drain(..) {
            settle(&mut self.entries[entry as usize].next, base);
        }
    }
}
