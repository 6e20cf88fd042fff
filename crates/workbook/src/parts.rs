//! Where the main job's time goes: each part of the job timed on the wall
//! clock and in processor time, and one line per part at the end, so that
//! a slow figure is found by reading the job's output rather than by
//! guessing. Processor time over wall time is how many cores a part kept
//! busy; on a loaded machine the wall time grows and the processor time
//! does not.

use std::time::{Duration, Instant};

/// The parts of the job done so far, in order, with their wall-clock time
/// and the processor time the whole process spent meanwhile.
#[derive(Debug, Default)]
pub struct Parts {
    done: Vec<(&'static str, Duration, Option<Duration>)>,
}

/// The processor time this process has used so far, all threads, user and
/// system, where the system tells it (Linux's `/proc/self/stat`).
fn processor_time() -> Option<Duration> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The command's name (field 2) is in parentheses and may hold spaces:
    // fields 14 and 15, utime and stime, are the 12th and 13th after it.
    let after_name = stat.get(stat.rfind(')')? + 1..)?;
    let mut fields = after_name.split_whitespace().skip(11);
    let user: u64 = fields.next()?.parse().ok()?;
    let system: u64 = fields.next()?.parse().ok()?;
    // Linux reports them in USER_HZ, 100 per second on every architecture
    // it supports.
    Some(Duration::from_millis((user + system) * 10))
}

impl Parts {
    /// Run `work` as the part `name` and keep its time (a part named twice
    /// adds up, so a family of figures made in two places is one line).
    pub fn time<T>(&mut self, name: &'static str, work: impl FnOnce() -> T) -> T {
        let (started, cpu_before) = (Instant::now(), processor_time());
        let result = work();
        let took = started.elapsed();
        let cpu = cpu_before
            .zip(processor_time())
            .map(|(a, b)| b.saturating_sub(a));
        match self.done.iter_mut().find(|(done, ..)| *done == name) {
            Some((_, total, total_cpu)) => {
                *total += took;
                *total_cpu = total_cpu.zip(cpu).map(|(a, b)| a + b);
            }
            None => self.done.push((name, took, cpu)),
        }
        result
    }

    /// The time of part `name`, if it ran.
    pub fn get(&self, name: &str) -> Option<Duration> {
        self.done
            .iter()
            .find(|(done, ..)| *done == name)
            .map(|(_, took, _)| *took)
    }

    /// All the parts' time together.
    pub fn total(&self) -> Duration {
        self.done.iter().map(|(_, took, _)| *took).sum()
    }

    /// All the parts' processor time together, where the system tells it.
    pub fn total_processor_time(&self) -> Option<Duration> {
        self.done.iter().map(|(.., cpu)| *cpu).sum()
    }

    /// One line per part, the slowest first, each with its share of the
    /// whole and its processor time, then the total.
    pub fn summary(&self) -> String {
        let total = self.total().as_secs_f64();
        let mut parts = self.done.clone();
        parts.sort_by_key(|part| std::cmp::Reverse(part.1));
        let width = parts.iter().map(|(name, ..)| name.len()).max().unwrap_or(0);
        let cpu = |cpu: Option<Duration>| match cpu {
            Some(cpu) => format!("  {:6.1} s of processor time", cpu.as_secs_f64()),
            None => String::new(),
        };
        let mut text = String::from("where the job's time went (wall clock):\n");
        for (name, took, used) in parts {
            let seconds = took.as_secs_f64();
            let share = if total > 0.0 { seconds / total } else { 0.0 };
            text.push_str(&format!(
                "  {name:<width$}  {seconds:6.1} s  {:3.0} %{}\n",
                100.0 * share,
                cpu(used)
            ));
        }
        text.push_str(&format!(
            "  {:<width$}  {total:6.1} s       {}\n",
            "all",
            cpu(self.total_processor_time())
        ));
        text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_part_named_twice_is_one_line_with_both_times() {
        let mut parts = Parts::default();
        parts.time("figures", || std::thread::sleep(Duration::from_millis(20)));
        parts.time("book", || ());
        parts.time("figures", || std::thread::sleep(Duration::from_millis(20)));
        let figures = parts.get("figures").expect("timed");
        assert!(figures >= Duration::from_millis(40), "{figures:?}");
        assert_eq!(parts.summary().matches("figures").count(), 1);
    }

    #[test]
    fn the_summary_lists_the_slowest_part_first_and_the_total_last() {
        let mut parts = Parts::default();
        parts.time("quick", || ());
        parts.time("slow", || std::thread::sleep(Duration::from_millis(30)));
        let summary = parts.summary();
        let lines: Vec<&str> = summary.lines().collect();
        assert!(lines[1].trim_start().starts_with("slow"), "{summary}");
        assert!(lines[2].trim_start().starts_with("quick"), "{summary}");
        assert!(lines[3].trim_start().starts_with("all"), "{summary}");
    }

    #[test]
    fn processor_time_grows_while_a_part_computes() {
        let Some(before) = processor_time() else {
            return; // not Linux: the summary shows wall time only
        };
        // Spin until the system has counted 50 ms of this process's time,
        // however loaded the machine is; a clock that never moves fails
        // after ten seconds of wall time.
        let mut parts = Parts::default();
        let counted = parts.time("spin", || {
            let started = Instant::now();
            let mut x = 0u64;
            while started.elapsed() < Duration::from_secs(10) {
                for _ in 0..100_000 {
                    x = std::hint::black_box(x.wrapping_mul(6364136223846793005).wrapping_add(1));
                }
                if processor_time().is_some_and(|now| now >= before + Duration::from_millis(50)) {
                    return true;
                }
            }
            false
        });
        assert!(
            counted,
            "the processor time stayed at {before:?} for 10 s of spinning"
        );
        let spin = parts.done[0].2.expect("measured on Linux");
        assert!(spin >= Duration::from_millis(40), "{spin:?}");
        assert!(parts.summary().contains("of processor time"));
    }

    #[test]
    fn a_value_returned_by_a_part_comes_back_unchanged() {
        let mut parts = Parts::default();
        assert_eq!(parts.time("answer", || 42), 42);
    }
}
