//! The ray stack: the rays still to be traced for one pixel.
//!
//! A fragment shader cannot recurse, so the lab kept its own stack; so does
//! this tracer, for another reason: a fixed-size array on the thread's own
//! stack costs no heap allocation per ray or per pixel.

use crate::Vec3;
use crate::ray::{Ray, RayKind};

/// The deepest `--max-depth` a render accepts.
pub const MAX_DEPTH_LIMIT: u32 = 64;

/// The most rays a single hit may send on (a chapter uses at most two:
/// the reflected and the transmitted one).
pub const MAX_SECONDARIES: usize = 4;

// ANCHOR: capacity
/// Depth-first, each pop makes room for the children it pushes; the stack
/// never holds more than one ray plus the waiting siblings of every level.
pub const STACK_CAPACITY: usize = MAX_DEPTH_LIMIT as usize * (MAX_SECONDARIES - 1) + 1;

/// A ray waiting on the stack, with what the ray stack of the lab model carries.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PendingRay {
    /// The ray to trace.
    pub ray: Ray,
    /// Why it is traced: from the eye, or sent on by a surface.
    pub kind: RayKind,
    /// The share of this ray's light that reaches the pixel.
    pub weight: f32,
    /// 1 for the primary ray, one more for every bounce.
    pub depth: u32,
    /// Where the ray's parent stands in a probe's ray log, if one is kept.
    pub parent: Option<u32>,
}

/// A last-in, first-out stack of fixed capacity.
pub struct RayStack {
    rays: [PendingRay; STACK_CAPACITY],
    len: usize,
}
// ANCHOR_END: capacity

impl Default for RayStack {
    fn default() -> Self {
        let empty = PendingRay {
            ray: Ray {
                origin: Vec3::ZERO,
                direction: Vec3::Z,
            },
            kind: RayKind::Primary,
            weight: 0.0,
            depth: 0,
            parent: None,
        };
        RayStack {
            rays: [empty; STACK_CAPACITY],
            len: 0,
        }
    }
}

impl RayStack {
    // ANCHOR: push_pop
    /// Put a ray on top of the stack.
    ///
    /// # Panics
    /// When the stack is full, which the depth limit makes impossible for
    /// a step that sends at most [`MAX_SECONDARIES`] rays on per hit.
    pub fn push(&mut self, ray: PendingRay) {
        // ANCHOR: todo_stack_push "Put the ray in the first free slot and count it (assert first that there is room: the ray stack overflowed)."
        assert!(self.len < STACK_CAPACITY, "the ray stack overflowed");
        self.rays[self.len] = ray;
        self.len += 1;
        // ANCHOR_END: todo_stack_push
    }

    /// Take the ray on top of the stack.
    pub fn pop(&mut self) -> Option<PendingRay> {
        // ANCHOR: todo_stack_pop "Take the ray on top (the last one pushed) and uncount it; None when the stack is empty."
        self.len = self.len.checked_sub(1)?;
        Some(self.rays[self.len])
        // ANCHOR_END: todo_stack_pop
    }
    // ANCHOR_END: push_pop

    /// How many rays wait on the stack.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether no ray waits: the pixel's tree is finished.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

// ANCHOR: tests
#[cfg(test)]
mod tests {
    use super::*;
    use crate::Vec3;

    fn pending(depth: u32) -> PendingRay {
        PendingRay {
            ray: Ray::new(Vec3::ZERO, Vec3::X),
            kind: RayKind::Reflection,
            weight: 1.0,
            depth,
            parent: None,
        }
    }

    #[test]
    fn the_last_ray_pushed_is_the_first_popped() {
        let mut stack = RayStack::default();
        stack.push(pending(1));
        stack.push(pending(2));
        assert_eq!(stack.len(), 2);
        assert_eq!(stack.pop().unwrap().depth, 2);
        assert_eq!(stack.pop().unwrap().depth, 1);
        assert!(stack.pop().is_none());
        assert!(stack.is_empty());
    }

    #[test]
    fn popping_an_empty_stack_gives_nothing_and_leaves_it_empty() {
        let mut stack = RayStack::default();
        assert!(stack.pop().is_none());
        assert_eq!(stack.len(), 0);
        stack.push(pending(7));
        assert_eq!(stack.pop().unwrap().depth, 7);
        assert!(stack.pop().is_none());
    }

    #[test]
    fn a_ray_pushed_keeps_everything_it_carries() {
        let mut stack = RayStack::default();
        let ray = PendingRay {
            ray: Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::Y),
            kind: RayKind::Refraction,
            weight: 0.49,
            depth: 3,
            parent: Some(5),
        };
        stack.push(ray);
        assert_eq!(stack.pop(), Some(ray));
    }

    #[test]
    #[should_panic(expected = "the ray stack overflowed")]
    fn a_full_stack_refuses_one_more_ray() {
        let mut stack = RayStack::default();
        for _ in 0..=STACK_CAPACITY {
            stack.push(pending(1));
        }
    }
}
// ANCHOR_END: tests
