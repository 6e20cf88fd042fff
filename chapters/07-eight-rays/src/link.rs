//! How a ray links to the next one of its sample: the order in which the
//! scalar ray stack would pop them, kept as numbers in the row's ledger
//! ([`crate::ledger::Ledger`]) so that summing a sample is a walk.

/// The link of a sample's last ray: after it, the sample is finished.
pub const END: u32 = u32::MAX;

/// The mark of a provisional ray number: the ray's place among the next
/// wave's rays inside spheres. Those go after the rays outside, whose count
/// is known only once the whole wave is traced; then [`settle`] makes the
/// number final.
pub const LATER: u32 = 1 << 31;

/// Make a ray number final: a provisional one is counted on from `base`
/// (the first number after the rays outside spheres), any other is left
/// as it is (and not written: most are final already).
pub fn settle(number: &mut u32, base: u32) {
    if *number != END && *number & LATER != 0 {
        *number = base + (*number & !LATER);
    }
}
