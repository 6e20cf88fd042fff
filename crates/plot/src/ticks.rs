//! Where tick marks go on an axis, and what their labels say.
//!
//! Readers take in round numbers at a glance, so linear axes step by 1, 2
//! or 5 times a power of ten (0, 0.2, 0.4 … or 0, 50, 100 …), never by
//! something like 0.37. Log axes get a tick at each power of ten.

/// Tick positions (in data units) and their printed labels, in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Ticks {
    /// Positions, ascending.
    pub values: Vec<f64>,
    /// One label per position.
    pub labels: Vec<String>,
}

/// The smallest step of the form 1, 2 or 5 × 10ⁿ that covers `span` with at
/// most `max_ticks` ticks (so at most `max_ticks - 1` intervals).
pub fn nice_step(span: f64, max_ticks: usize) -> f64 {
    let intervals = max_ticks.saturating_sub(1).max(1) as f64;
    let smallest = span.abs() / intervals;
    if smallest <= 0.0 || !smallest.is_finite() {
        return 1.0;
    }
    let power = 10f64.powf(smallest.log10().floor());
    // A tiny tolerance so that, e.g., 9 / 9 = 0.999… still picks 1.
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * power)
        .find(|&step| step >= smallest * (1.0 - 1e-9));
    step.unwrap_or(10.0 * power)
}

/// Ticks at nice 1-2-5 steps between `min` and `max` (inclusive), at most
/// `max_ticks` of them.
pub fn linear_ticks(min: f64, max: f64, max_ticks: usize) -> Ticks {
    let step = nice_step(max - min, max_ticks);
    ticks_with_step(min, max, step)
}

/// Like [`linear_ticks`] but never between whole numbers: for counts such
/// as bounce depth, where a tick at 2.5 would make no sense.
pub fn integer_ticks(min: f64, max: f64, max_ticks: usize) -> Ticks {
    let step = nice_step(max - min, max_ticks).max(1.0);
    ticks_with_step(min, max, step)
}

/// Every multiple of `step` within `[min, max]`, labelled with just enough
/// decimals to tell them apart.
fn ticks_with_step(min: f64, max: f64, step: f64) -> Ticks {
    if !(min.is_finite() && max.is_finite() && step > 0.0) || min > max {
        return Ticks {
            values: Vec::new(),
            labels: Vec::new(),
        };
    }
    // Tolerance so that rounding error does not drop a tick at an end.
    let slack = step * 1e-9;
    let first = ((min - slack) / step).ceil() as i64;
    let last = ((max + slack) / step).floor() as i64;
    // Multiplying an integer index by the step (instead of adding the step
    // repeatedly) keeps 0.1 + 0.1 + 0.1 errors from piling up.
    let values: Vec<f64> = (first..=last).map(|i| i as f64 * step).collect();
    let labels = values.iter().map(|&v| format_number(v, step)).collect();
    Ticks { values, labels }
}

/// Ticks for a log axis over `[min, max]` (both must be positive): every
/// power of ten inside the range, or 1-2-5 steps within each decade when
/// the range spans less than one full decade.
pub fn log_ticks(min: f64, max: f64) -> Ticks {
    if !(min > 0.0 && max >= min && max.is_finite()) {
        return Ticks {
            values: Vec::new(),
            labels: Vec::new(),
        };
    }
    let slack = 1e-9;
    let low = (min.log10() - slack).ceil() as i32;
    let high = (max.log10() + slack).floor() as i32;
    if high > low {
        let values = (low..=high).map(|e| 10f64.powi(e)).collect();
        // One style per axis: if any label needs "10ⁿ", write every
        // power from 1 up that way, so "10000" never sits under "10⁵".
        let all_plain = (low..=high).all(|e| (-3..=4).contains(&e));
        let labels = (low..=high)
            .map(|e| match e {
                0.. if !all_plain => format!("10{}", superscript_digits(e.unsigned_abs())),
                _ => format_power_of_ten(e),
            })
            .collect();
        return Ticks { values, labels };
    }
    // Less than a decade: use 1, 2 and 5 of each decade instead.
    log_ticks_at(min, max, &[1.0, 2.0, 5.0])
}

/// Ticks for a log axis over `[min, max]` (both positive) at the given
/// `multiples` of every power of ten, e.g. `[1, 2, 3, 4, 5]` gives 1, 2, 3,
/// 4, 5, 10, 20, 30, 40, 50, 100 …: for a scale whose small values must be
/// read off one by one, where the decades alone say only "about".
pub fn log_ticks_at(min: f64, max: f64, multiples: &[f64]) -> Ticks {
    if !(min > 0.0 && max >= min && max.is_finite()) {
        return Ticks {
            values: Vec::new(),
            labels: Vec::new(),
        };
    }
    let slack = 1e-9;
    let mut values = Vec::new();
    for exponent in (min.log10().floor() as i32)..=(max.log10().ceil() as i32) {
        for multiple in multiples {
            let value = multiple * 10f64.powi(exponent);
            if value >= min * (1.0 - slack) && value <= max * (1.0 + slack) {
                values.push(value);
            }
        }
    }
    let labels = values
        .iter()
        .map(|&v| format_number(v, 10f64.powf(v.log10().floor())))
        .collect();
    Ticks { values, labels }
}

/// Keeps every n-th tick when there are more than `max_ticks`, e.g. when a
/// log axis spans more decades than there is room to label.
pub fn thin(ticks: Ticks, max_ticks: usize) -> Ticks {
    let every = ticks.values.len().div_ceil(max_ticks.max(1)).max(1);
    Ticks {
        values: ticks.values.into_iter().step_by(every).collect(),
        labels: ticks.labels.into_iter().step_by(every).collect(),
    }
}

/// `value` printed with as many decimals as `step` needs (none for a step
/// of 1 or more, one for 0.1 or 0.5, …), with a true minus sign.
pub fn format_number(value: f64, step: f64) -> String {
    let decimals = if step >= 1.0 || step <= 0.0 {
        0
    } else {
        (-step.log10() - 1e-9).ceil().max(0.0) as usize
    };
    let text = format!("{value:.decimals$}");
    // "-0" and "-0.0" come from values a hair below zero: print plain zero.
    if text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        return text.trim_start_matches('-').to_string();
    }
    // U+2212 MINUS SIGN is as wide as a digit and sits at the right height,
    // unlike the short hyphen that `format!` produces.
    text.replace('-', "\u{2212}")
}

/// 10ⁿ as a label: plain digits from 0.001 to 10000, where they are still
/// easy to read; "10" with a superscript exponent above that; and "1e−4"
/// style below, because this version of Noto Sans has superscript digits
/// but no superscript minus sign.
pub fn format_power_of_ten(exponent: i32) -> String {
    match exponent {
        0..=4 => format!("{:.0}", 10f64.powi(exponent)),
        -3..=-1 => format!(
            "{:.*}",
            exponent.unsigned_abs() as usize,
            10f64.powi(exponent)
        ),
        5.. => format!("10{}", superscript_digits(exponent.unsigned_abs())),
        _ => format!("1e\u{2212}{}", exponent.unsigned_abs()),
    }
}

/// A whole number written in superscript digits, e.g. 12 → "¹²".
fn superscript_digits(n: u32) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    n.to_string()
        .chars()
        .filter_map(|c| c.to_digit(10))
        .map(|d| DIGITS[d as usize])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_steps_are_one_two_or_five_times_a_power_of_ten() {
        assert_eq!(nice_step(10.0, 11), 1.0);
        assert_eq!(nice_step(10.0, 6), 2.0);
        assert_eq!(nice_step(10.0, 5), 5.0);
        assert_eq!(nice_step(1.0, 6), 0.2);
        assert_eq!(nice_step(700.0, 8), 100.0);
        assert_eq!(nice_step(0.0, 5), 1.0, "degenerate span");
    }

    #[test]
    fn linear_ticks_cover_the_range_in_round_steps() {
        let ticks = linear_ticks(0.0, 1.0, 6);
        assert_eq!(ticks.values.len(), 6);
        assert_eq!(ticks.labels, ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]);
        let ticks = linear_ticks(-3.0, 7.5, 8);
        assert_eq!(ticks.labels.first().map(String::as_str), Some("\u{2212}2"));
        assert_eq!(ticks.labels.last().map(String::as_str), Some("6"));
    }

    #[test]
    fn integer_ticks_for_one_to_ten_are_every_integer() {
        let ticks = integer_ticks(1.0, 10.0, 12);
        assert_eq!(ticks.values, (1..=10).map(f64::from).collect::<Vec<_>>());
        assert_eq!(ticks.labels[0], "1");
        // When space is short the step grows but stays whole.
        let ticks = integer_ticks(0.0, 10.0, 4);
        assert_eq!(ticks.labels, ["0", "5", "10"]);
        let ticks = integer_ticks(0.0, 3.0, 20);
        assert_eq!(ticks.labels, ["0", "1", "2", "3"], "never 0.5 steps");
    }

    #[test]
    fn log_ticks_are_powers_of_ten() {
        let ticks = log_ticks(1.0, 1000.0);
        assert_eq!(ticks.values, [1.0, 10.0, 100.0, 1000.0]);
        assert_eq!(ticks.labels, ["1", "10", "100", "1000"]);
        let ticks = log_ticks(0.01, 1e6);
        assert_eq!(
            ticks.labels,
            [
                "0.01", "0.1", "10⁰", "10¹", "10²", "10³", "10⁴", "10⁵", "10⁶"
            ]
        );
        // Less than a decade: 1-2-5 within it.
        assert_eq!(log_ticks(2.0, 9.0).labels, ["2", "5"]);
    }

    #[test]
    fn log_ticks_at_two_three_four_five_label_each_small_count() {
        let ticks = log_ticks_at(1.0, 120.0, &[1.0, 2.0, 3.0, 4.0, 5.0]);
        assert_eq!(
            ticks.labels,
            ["1", "2", "3", "4", "5", "10", "20", "30", "40", "50", "100"]
        );
        assert_eq!(ticks.values[3], 4.0);
        assert_eq!(log_ticks_at(0.0, 10.0, &[1.0]).values, Vec::<f64>::new());
    }

    #[test]
    fn numbers_print_tidily() {
        assert_eq!(format_number(-1e-17, 0.1), "0.0");
        assert_eq!(format_number(0.30000000000000004, 0.1), "0.3");
        assert_eq!(format_number(2500.0, 500.0), "2500");
        assert_eq!(format_number(-0.25, 0.05), "\u{2212}0.25");
        assert_eq!(format_power_of_ten(-2), "0.01");
        assert_eq!(format_power_of_ten(-7), "1e\u{2212}7");
        assert_eq!(format_power_of_ten(12), "10¹²");
    }
}
