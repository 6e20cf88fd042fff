//! The samples' generators eight at a time: the same numbers as the core's
//! [`sample_rng`](raylab::sampling::sample_rng) and its `Pcg32`, lane by lane.
//!
//! Seeding a sample's generator is two rounds of SplitMix64, and each draw
//! one step of a 64-bit LCG: 64-bit multiplications. AVX2 has no 64-bit
//! multiply (`wide`'s `u64x4` does one lane at a time), but it multiplies
//! 32-bit halves into 64-bit products. So a lane's 64-bit number is kept as
//! two 32-bit halves, in two `u32x8`, and the multiplication mod 2⁶⁴ is put
//! together from the halves' products, as on paper:
//!
//! ```text
//! (h·2³² + l) · (H·2³² + L) mod 2⁶⁴ = l·L + (l·H + h·L) · 2³²   (mod 2⁶⁴)
//! ```
//!
//! where `l·L` needs all 64 bits (`*` gives its low half, `mul_keep_high`
//! its high one) and the other two products only their low halves.

use wide::{f32x8, u32x8};

use raylab::sampling::{PixelHash, SPLITMIX_GAMMA, SPLITMIX_MIX, Stream};

use crate::vec3x8::LANES;

/// PCG's LCG multiplier (`rand_pcg`'s `MULTIPLIER`).
const PCG_MULTIPLIER: u64 = 6_364_136_223_846_793_005;

/// Eight 64-bit numbers, one per lane, as their high and low halves.
#[derive(Clone, Copy, Debug)]
pub struct U64x8 {
    hi: u32x8,
    lo: u32x8,
}

impl U64x8 {
    /// `x` in every lane.
    pub fn splat(x: u64) -> U64x8 {
        U64x8 {
            hi: u32x8::splat((x >> 32) as u32),
            lo: u32x8::splat(x as u32),
        }
    }

    /// `x[l]` in lane `l`.
    pub fn new(x: [u64; LANES]) -> U64x8 {
        U64x8 {
            hi: u32x8::new(x.map(|x| (x >> 32) as u32)),
            lo: u32x8::new(x.map(|x| x as u32)),
        }
    }

    /// The eight numbers again, lane `l` at index `l`.
    pub fn to_array(self) -> [u64; LANES] {
        let (hi, lo) = (self.hi.to_array(), self.lo.to_array());
        std::array::from_fn(|l| (u64::from(hi[l]) << 32) | u64::from(lo[l]))
    }

    fn lane(&self, lane: usize) -> u64 {
        (u64::from(self.hi.as_array_ref()[lane]) << 32) | u64::from(self.lo.as_array_ref()[lane])
    }

    fn set_lane(&mut self, lane: usize, x: u64) {
        self.hi.as_array_mut()[lane] = (x >> 32) as u32;
        self.lo.as_array_mut()[lane] = x as u32;
    }

    /// `wrapping_add`, lane by lane.
    #[inline]
    fn add(self, o: U64x8) -> U64x8 {
        let lo = self.lo + o.lo;
        // Mask: the low halves' sum wrapped around, so 1 carries over. A
        // set mask is all ones, −1, and subtracting it adds 1.
        let carry = self.lo.cmp_gt(lo);
        U64x8 {
            hi: self.hi + o.hi - carry,
            lo,
        }
    }

    /// `wrapping_mul` by a constant, lane by lane.
    #[inline]
    fn mul(self, m: u64) -> U64x8 {
        let (m_hi, m_lo) = (u32x8::splat((m >> 32) as u32), u32x8::splat(m as u32));
        U64x8 {
            hi: self.lo.mul_keep_high(m_lo) + self.lo * m_hi + self.hi * m_lo,
            lo: self.lo * m_lo,
        }
    }

    #[inline]
    fn xor(self, o: U64x8) -> U64x8 {
        U64x8 {
            hi: self.hi ^ o.hi,
            lo: self.lo ^ o.lo,
        }
    }

    /// `>> n` for `0 < n < 32`: the high half's lowest bits move down.
    #[inline]
    fn shr(self, n: u32) -> U64x8 {
        debug_assert!(0 < n && n < 32);
        U64x8 {
            hi: self.hi >> n,
            lo: (self.lo >> n) | (self.hi << (32 - n)),
        }
    }

    /// Keep `self` in the lanes of `mask` (all ones or all zeros per lane),
    /// `other` elsewhere.
    #[inline]
    fn select(mask: u32x8, new: U64x8, old: U64x8) -> U64x8 {
        U64x8 {
            hi: mask.blend(new.hi, old.hi),
            lo: mask.blend(new.lo, old.lo),
        }
    }
}

/// [`splitmix64`](raylab::sampling::splitmix64) in every lane.
#[inline]
pub fn splitmix64_x8(x: U64x8) -> U64x8 {
    let z = x.add(U64x8::splat(SPLITMIX_GAMMA));
    let z = z.xor(z.shr(30)).mul(SPLITMIX_MIX[0]);
    let z = z.xor(z.shr(27)).mul(SPLITMIX_MIX[1]);
    z.xor(z.shr(31))
}

// ANCHOR: pcg
/// Eight `Pcg32` generators of one stream, one per lane.
#[derive(Clone, Copy, Debug)]
pub struct Pcg32x8 {
    state: U64x8,
    /// The stream's increment, `2 · stream + 1`, the same in every lane.
    increment: u64,
}

impl Pcg32x8 {
    /// `Pcg32::new(state[l], stream)` in every lane `l`.
    pub fn new(state: U64x8, stream: u64) -> Pcg32x8 {
        let increment = (stream << 1) | 1;
        // As `rand_pcg` moves away from the initial value: add, then step.
        let state = state.add(U64x8::splat(increment));
        let state = state.mul(PCG_MULTIPLIER).add(U64x8::splat(increment));
        Pcg32x8 { state, increment }
    }

    /// Each lane's `next_u32()`, drawn only in the lanes of `mask` (all
    /// ones or all zeros per lane): the other lanes' generators stay where
    /// they are, and their numbers are not to be read.
    #[inline]
    pub fn next_u32(&mut self, mask: u32x8) -> u32x8 {
        let s = self.state;
        let stepped = s.mul(PCG_MULTIPLIER).add(U64x8::splat(self.increment));
        self.state = U64x8::select(mask, stepped, s);
        // PCG's output, XSH RR: the xorshift's bits 27..59, rotated right
        // by the top five bits.
        let rotate = s.hi >> 27u32;
        let x = s.shr(18).xor(s);
        let xorshifted = (x.lo >> 27u32) | (x.hi << 5u32);
        (xorshifted >> rotate) | (xorshifted << ((u32x8::splat(32) - rotate) & u32x8::splat(31)))
    }

    /// [`unit_f32`](raylab::sampling::unit_f32) in the lanes of `mask`.
    #[inline]
    pub fn uniform(&mut self, mask: u32x8) -> f32x8 {
        let top = (self.next_u32(mask) >> 8u32).to_array();
        // Below 2²⁴, so every value is an exact f32.
        f32x8::new(top.map(|t| t as f32)) * f32x8::splat(1.0 / (1u32 << 24) as f32)
    }

    /// [`Pcg32x8::uniform`] in lane `lane` alone, one step of its
    /// generator in scalar arithmetic: for the few lanes that draw again
    /// after the others are done (a rejection loop's retries), where a
    /// step of all eight would wait for one.
    pub fn uniform_in_lane(&mut self, lane: usize) -> f32 {
        let s = self.state.lane(lane);
        let stepped = s.wrapping_mul(PCG_MULTIPLIER).wrapping_add(self.increment);
        self.state.set_lane(lane, stepped);
        // XSH RR, as in `next_u32`.
        let xorshifted = (((s >> 18) ^ s) >> 27) as u32;
        let drawn = xorshifted.rotate_right((s >> 59) as u32);
        // `unit_f32`: the top 24 bits, exact in an f32.
        (drawn >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
    }

    /// Every lane's state, to be started later with [`Pcg32x8::start`].
    pub fn states(&self) -> [u64; LANES] {
        self.state.to_array()
    }

    /// The lanes whose bit is set in `bits` start from their `states`
    /// (each one of [`Pcg32x8::states`]), the others go on: one blend of
    /// all eight, where a lane-by-lane write would leave the next draw
    /// to read a register back from eight pieces of memory.
    pub fn start_lanes(&mut self, bits: u32, states: [u64; LANES]) {
        let mask = lane_mask(bits);
        self.state = U64x8::select(mask, U64x8::new(states), self.state);
    }

    /// Lane `lane` starts from `state` (one of [`Pcg32x8::states`]).
    pub fn start(&mut self, lane: usize, state: u64) {
        self.state.set_lane(lane, state);
    }
}
// ANCHOR_END: pcg

/// The third round of `PixelHash::sample_rng`'s hash for eight samples
/// (lane `l`: sample `samples[l]` of the pixel hashed `hashes[l]`), which
/// all of a sample's streams share.
pub fn sample_hashes(hashes: [PixelHash; LANES], samples: [u32; LANES]) -> U64x8 {
    let h = U64x8::new(std::array::from_fn(|l| {
        hashes[l].bits() ^ u64::from(samples[l])
    }));
    splitmix64_x8(h)
}

/// The generators of eight samples' choices of kind `stream`, from their
/// [`sample_hashes`]: lane `l`'s is `hashes[l].sample_rng(samples[l], stream)`.
pub fn sample_rngs(sample_hashes: U64x8, stream: Stream) -> Pcg32x8 {
    let state = splitmix64_x8(sample_hashes.xor(U64x8::splat(stream as u64)));
    Pcg32x8::new(state, stream as u64)
}

/// The mask of the lanes whose bit is set in `bits` (lane `k` in bit `k`).
pub fn lane_mask(bits: u32) -> u32x8 {
    u32x8::new(std::array::from_fn(|l| {
        if bits >> l & 1 == 1 { u32::MAX } else { 0 }
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand_core::Rng;
    use rand_pcg::Pcg32;
    use raylab::sampling::{splitmix64, unit_f32};

    const ALL: u32 = 0xff;

    #[test]
    fn eight_64_bit_products_and_sums_wrap_as_u64s_do() {
        let xs: [u64; LANES] = [
            0,
            1,
            u64::MAX,
            0xffff_ffff,
            1 << 32,
            0x9e37_79b9_7f4a_7c15,
            0x1234_5678_9abc_def0,
            u64::MAX - 5,
        ];
        let lanes = U64x8::new(xs);
        for m in [PCG_MULTIPLIER, 3, u64::MAX, 0xffff_ffff_0000_0001] {
            let expected = xs.map(|x| x.wrapping_mul(m));
            assert_eq!(lanes.mul(m).to_array(), expected, "times {m:#x}");
            let expected = xs.map(|x| x.wrapping_add(m));
            assert_eq!(
                lanes.add(U64x8::splat(m)).to_array(),
                expected,
                "plus {m:#x}"
            );
        }
        for n in [1, 18, 27, 30, 31] {
            assert_eq!(lanes.shr(n).to_array(), xs.map(|x| x >> n), ">> {n}");
        }
    }

    #[test]
    fn eight_splitmix64s_give_the_reference_outputs() {
        const GAMMA: u64 = 0x9e37_79b9_7f4a_7c15;
        let xs: [u64; LANES] = std::array::from_fn(|l| GAMMA.wrapping_mul(l as u64));
        let out = splitmix64_x8(U64x8::new(xs)).to_array();
        // Vigna's first three outputs, seeded with 0.
        assert_eq!(
            &out[..3],
            &[
                0xe220_a839_7b1d_cdaf,
                0x6e78_9e6a_a1b9_65f4,
                0x06c4_5d18_8009_454f
            ]
        );
        assert_eq!(out, xs.map(splitmix64));
    }

    #[test]
    fn eight_lane_generators_give_each_samples_pcg32_numbers() {
        for (seed, stream) in [
            (0u64, Stream::Offset),
            (7, Stream::Path),
            (u64::MAX, Stream::Rotation),
        ] {
            let pixels: [(u32, u32); LANES] = std::array::from_fn(|l| (l as u32 / 3, 5));
            let hashes = pixels.map(|p| PixelHash::new(seed, p));
            let samples: [u32; LANES] = std::array::from_fn(|l| 11 * l as u32);
            let mut lanes = sample_rngs(sample_hashes(hashes, samples), stream);
            let mut scalar: [Pcg32; LANES] =
                std::array::from_fn(|l| hashes[l].sample_rng(samples[l], stream));
            for _ in 0..100 {
                let drawn = lanes.next_u32(lane_mask(ALL)).to_array();
                assert_eq!(drawn, std::array::from_fn(|l| scalar[l].next_u32()));
            }
            let u = lanes.uniform(lane_mask(ALL)).to_array();
            assert_eq!(u, std::array::from_fn(|l| unit_f32(&mut scalar[l])));
        }
    }

    #[test]
    fn a_lane_left_out_of_a_draw_keeps_its_place_in_its_stream() {
        let hashes = [PixelHash::new(3, (1, 2)); LANES];
        let samples: [u32; LANES] = std::array::from_fn(|l| l as u32);
        let mut lanes = sample_rngs(sample_hashes(hashes, samples), Stream::Path);
        let mut scalar: [Pcg32; LANES] =
            std::array::from_fn(|l| hashes[l].sample_rng(samples[l], Stream::Path));
        // Lanes 0, 3 and 5 draw each time, the others every third time.
        for round in 0..30u32 {
            let bits = if round % 3 == 0 { ALL } else { 0b0010_1001 };
            let drawn = lanes.next_u32(lane_mask(bits)).to_array();
            for lane in crate::vec3x8::lanes_of(bits) {
                assert_eq!(
                    drawn[lane],
                    scalar[lane].next_u32(),
                    "round {round}, lane {lane}"
                );
            }
        }
        // Every lane's state is its scalar generator's, and a lane started
        // from a state goes on as the scalar generator with that state.
        assert_eq!(lanes.states(), scalar.each_ref().map(|rng| rng.state()));
        // A draw in one lane alone goes on as that lane's scalar generator
        // and leaves the other lanes where they were.
        for round in 0..20 {
            let lane = round % LANES;
            let u = lanes.uniform_in_lane(lane);
            assert_eq!(u, unit_f32(&mut scalar[lane]), "round {round}");
            assert_eq!(lanes.states(), scalar.each_ref().map(|rng| rng.state()));
        }
        let mut fresh = hashes[0].sample_rng(100, Stream::Path);
        lanes.start(6, fresh.state());
        assert_eq!(
            lanes.next_u32(lane_mask(ALL)).to_array()[6],
            fresh.next_u32()
        );
        // Lanes 1 and 4 start afresh together, the others go on.
        let mut fresh: [Pcg32; LANES] =
            std::array::from_fn(|l| hashes[0].sample_rng(200 + l as u32, Stream::Path));
        let before = lanes.states();
        lanes.start_lanes(0b1_0010, fresh.each_ref().map(|rng| rng.state()));
        let after = lanes.states();
        for lane in 0..LANES {
            let expected = if lane == 1 || lane == 4 {
                fresh[lane].state()
            } else {
                before[lane]
            };
            assert_eq!(after[lane], expected, "lane {lane}");
        }
        let drawn = lanes.next_u32(lane_mask(ALL)).to_array();
        assert_eq!(drawn[4], fresh[4].next_u32());
    }
}
