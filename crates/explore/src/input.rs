//! What the explorer is told, whatever tells it: the window's keys and
//! mouse, a `--script`, or a test. Positions are in image pixels.

/// A key the explorer knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Key {
    Char(char),
    Up,
    Down,
    Left,
    Right,
    Home,
    Escape,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Button {
    /// Click to probe, drag to orbit.
    Left,
    /// Drag to pan.
    Right,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Input {
    Key(Key),
    Press {
        button: Button,
        x: f64,
        y: f64,
    },
    Release {
        button: Button,
        x: f64,
        y: f64,
    },
    Move {
        x: f64,
        y: f64,
    },
    /// Wheel steps, positive away from the learner (zoom in).
    Wheel(f32),
    Resize {
        width: u32,
        height: u32,
    },
}

/// The keys, as the help panel lists them.
pub const HELP: &[(&str, &str)] = &[
    ("1 … 5", "chapter 1–5: which Whitted features are on"),
    ("6", "chapter 6: path tracing"),
    ("↑ ↓", "max depth up, down"),
    ("r  R", "rays (paths) per pixel: 1, 5, 16, 64, 256, 1024"),
    ("e", "epsilon 1e-4 ↔ 0 (shadow acne)"),
    ("[  ]", "the sun's size (path tracing)"),
    ("m", "lab ↔ Fresnel materials (path tracing)"),
    ("drag", "orbit;  right-drag: pan;  wheel, + −: zoom"),
    ("← →", "orbit by 5°"),
    ("click", "the pixel's ray tree;  Esc clears it"),
    ("c", "back to the scene's camera"),
    ("g", "the GPU's render (chapter 10) beside the CPU's"),
    ("w", "write the frame as PNG, print its command"),
    ("?  h", "this help;  q: quit"),
];
