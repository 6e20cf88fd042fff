//! `--script`: inputs from the command line instead of a hand, for the
//! smoke test under Xvfb, for the book's screenshots and for timing.
//!
//! Words, separated by spaces, run in order, one frame after each input:
//!
//! | word | what it does |
//! |---|---|
//! | `key:K` | press K: one character, or `up`, `down`, `left`, `right`, `home`, `esc` |
//! | `keys:KKK` | press each character in turn |
//! | `click:X,Y` | click pixel X,Y |
//! | `drag:X0,Y0,X1,Y1` | drag with the left button (orbit) |
//! | `pan:X0,Y0,X1,Y1` | drag with the right button (pan) |
//! | `wheel:N` | turn the wheel N steps (zoom in for N > 0) |
//! | `resize:W,H` | as if the window were resized |
//! | `frames:N` | render N more frames |
//! | `settle` | render until the image is what the knobs ask for |
//! | `shot:FILE` | write the frame shown, overlay and all, as PNG |
//! | `save` | press `w`: write the scene's frame and print its command |

use std::collections::VecDeque;
use std::path::PathBuf;

use crate::error::ExploreError;
use crate::input::{Button, Input, Key};

/// Steps of a drag: enough for the orbit to move in a few frames.
const DRAG_STEPS: u32 = 8;

/// One word of a script: an input, frames to render, waiting for the
/// image to settle, or a screenshot.
#[derive(Clone, Debug, PartialEq)]
pub enum Instruction {
    Input(Input),
    Frames(u32),
    Settle,
    Shot(PathBuf),
}

/// Parse a script; the error names the word that is wrong.
pub fn parse(text: &str) -> Result<VecDeque<Instruction>, ExploreError> {
    let mut steps = VecDeque::new();
    for word in text.split_whitespace() {
        let (verb, arg) = word.split_once(':').unwrap_or((word, ""));
        let bad = |why: &str| ExploreError::Script {
            word: word.to_owned(),
            why: why.to_owned(),
        };
        let numbers = |n: usize| -> Result<Vec<f64>, ExploreError> {
            let values: Vec<f64> = arg
                .split(',')
                .map(|v| v.trim().parse::<f64>())
                .collect::<Result<_, _>>()
                .map_err(|_| bad(&format!("needs {n} numbers separated by commas")))?;
            if values.len() != n || values.iter().any(|v| !v.is_finite()) {
                return Err(bad(&format!("needs {n} numbers separated by commas")));
            }
            Ok(values)
        };
        match verb {
            "key" => steps.push_back(Instruction::Input(Input::Key(key(arg).ok_or_else(
                || bad("a key is one character, or up, down, left, right, home, esc"),
            )?))),
            "keys" if !arg.is_empty() => {
                steps.extend(
                    arg.chars()
                        .map(|c| Instruction::Input(Input::Key(Key::Char(c)))),
                );
            }
            "click" => {
                let v = numbers(2)?;
                let (x, y) = (v[0], v[1]);
                let button = Button::Left;
                steps.push_back(Instruction::Input(Input::Move { x, y }));
                steps.push_back(Instruction::Input(Input::Press { button, x, y }));
                steps.push_back(Instruction::Input(Input::Release { button, x, y }));
            }
            "drag" | "pan" => {
                let v = numbers(4)?;
                let button = if verb == "drag" {
                    Button::Left
                } else {
                    Button::Right
                };
                let (x, y) = (v[0], v[1]);
                steps.push_back(Instruction::Input(Input::Press { button, x, y }));
                for i in 1..=DRAG_STEPS {
                    let t = f64::from(i) / f64::from(DRAG_STEPS);
                    let (x, y) = (v[0] + (v[2] - v[0]) * t, v[1] + (v[3] - v[1]) * t);
                    steps.push_back(Instruction::Input(Input::Move { x, y }));
                }
                let (x, y) = (v[2], v[3]);
                steps.push_back(Instruction::Input(Input::Release { button, x, y }));
            }
            "wheel" => {
                let steps_turned = numbers(1)?[0] as f32;
                steps.push_back(Instruction::Input(Input::Wheel(steps_turned)));
            }
            "resize" => {
                let v = numbers(2)?;
                if v.iter().any(|&n| !(0.0..=16_384.0).contains(&n)) {
                    return Err(bad("a size is 0 to 16384 pixels a side"));
                }
                steps.push_back(Instruction::Input(Input::Resize {
                    width: v[0] as u32,
                    height: v[1] as u32,
                }));
            }
            "frames" => {
                let n = arg
                    .parse::<u32>()
                    .map_err(|_| bad("needs a whole number of frames"))?;
                steps.push_back(Instruction::Frames(n));
            }
            "settle" => steps.push_back(Instruction::Settle),
            "shot" if !arg.is_empty() => steps.push_back(Instruction::Shot(PathBuf::from(arg))),
            "save" => steps.push_back(Instruction::Input(Input::Key(Key::Char('w')))),
            _ => {
                return Err(bad(
                    "unknown word: use key, keys, click, drag, pan, wheel, resize, frames, settle, shot or save",
                ));
            }
        }
    }
    Ok(steps)
}

fn key(name: &str) -> Option<Key> {
    Some(match name {
        "up" => Key::Up,
        "down" => Key::Down,
        "left" => Key::Left,
        "right" => Key::Right,
        "home" => Key::Home,
        "esc" => Key::Escape,
        _ => {
            let mut chars = name.chars();
            let c = chars.next()?;
            if chars.next().is_some() {
                return None;
            }
            Key::Char(c)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_script_reads_keys_clicks_and_drags() {
        let steps =
            parse("key:3 key:up keys:re click:10,20 drag:0,0,80,0 frames:2 settle shot:a.png")
                .unwrap();
        assert_eq!(steps[0], Instruction::Input(Input::Key(Key::Char('3'))));
        assert_eq!(steps[1], Instruction::Input(Input::Key(Key::Up)));
        assert_eq!(steps.len(), 2 + 2 + 3 + (DRAG_STEPS as usize + 2) + 3);
        assert_eq!(
            steps.back(),
            Some(&Instruction::Shot(PathBuf::from("a.png")))
        );
    }

    #[test]
    fn a_bad_script_word_is_one_line_naming_it() {
        let error = parse("key:3 click:10").unwrap_err().to_string();
        assert!(error.contains("'click:10'"), "{error}");
        assert!(
            parse("jump")
                .unwrap_err()
                .to_string()
                .contains("unknown word")
        );
        assert!(parse("key:up2").is_err());
        assert!(parse("frames:-1").is_err());
        assert!(parse("click:nan,1").is_err());
    }
}
