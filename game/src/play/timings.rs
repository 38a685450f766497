//! Per-frame costs of the loop, split where the engine ends: rendering (the
//! engine's `render_frame`) and upload + present (copying the framebuffer
//! into pixels' buffer, the texture upload, the scaling pass and the present,
//! which waits for the display when vsync is on).

use std::time::Duration;

#[derive(Default)]
pub struct Timings {
    render: Vec<Duration>,
    present: Vec<Duration>,
}

impl Timings {
    pub fn push(&mut self, render: Duration, present: Duration) {
        self.render.push(render);
        self.present.push(present);
    }

    pub fn frames(&self) -> usize {
        self.render.len()
    }

    /// `render ms` and `upload+present ms` medians, one line.
    pub fn summary(&self) -> String {
        format!(
            "frames {}: median render {:.3} ms, median upload+present {:.3} ms",
            self.frames(),
            median_ms(&self.render),
            median_ms(&self.present)
        )
    }
}

fn median_ms(samples: &[Duration]) -> f64 {
    if samples.is_empty() {
        return f64::NAN;
    }
    let mut sorted = samples.to_vec();
    sorted.sort_unstable();
    let mid = sorted.len() / 2;
    let m = if sorted.len().is_multiple_of(2) { (sorted[mid - 1] + sorted[mid]) / 2 } else { sorted[mid] };
    m.as_secs_f64() * 1000.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn medians() {
        let ms = Duration::from_millis;
        assert_eq!(median_ms(&[ms(3), ms(1), ms(2)]), 2.0);
        assert_eq!(median_ms(&[ms(4), ms(1), ms(2), ms(3)]), 2.5);
        assert!(median_ms(&[]).is_nan());
    }
}
