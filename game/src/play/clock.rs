//! The fixed-timestep clock between wall time and simulation ticks: each
//! frame hands it the elapsed time and gets back how many ticks to run and
//! how far the frame lies between the last two ticks (the interpolation
//! alpha for `Game::view`).

use std::time::Duration;

/// Longest stretch of wall time one frame may turn into ticks. After a stall
/// (a window drag, a breakpoint, a slow software frame) the game skips ahead
/// rather than running seconds of ticks at once and stalling again: Glenn
/// Fiedler's "Fix Your Timestep" spiral of death. A quarter second is 8-9
/// ticks at 35 Hz, so ordinary frame-rate dips are never clipped.
const MAX_FRAME: Duration = Duration::from_millis(250);

pub struct TickClock {
    tick: Duration,
    /// Wall time not yet turned into ticks; always less than one tick after
    /// `advance` returns.
    pending: Duration,
}

impl TickClock {
    pub fn new(ticrate: u32) -> TickClock {
        TickClock { tick: Duration::from_secs(1) / ticrate.max(1), pending: Duration::ZERO }
    }

    /// Adds `elapsed` wall time; returns the whole ticks now due and alpha in
    /// [0, 1): the fraction of the next tick already elapsed.
    pub fn advance(&mut self, elapsed: Duration) -> (u32, f64) {
        self.pending += elapsed.min(MAX_FRAME);
        let mut ticks = 0;
        while self.pending >= self.tick {
            self.pending -= self.tick;
            ticks += 1;
        }
        (ticks, self.pending.as_secs_f64() / self.tick.as_secs_f64())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_follow_wall_time_not_frames() {
        // 35 Hz: a tick is 28.571... ms. 100 frames of 10 ms are one second.
        let mut clock = TickClock::new(35);
        let mut total = 0;
        for _ in 0..100 {
            let (ticks, alpha) = clock.advance(Duration::from_millis(10));
            assert!((0.0..1.0).contains(&alpha));
            total += ticks;
        }
        assert_eq!(total, 35);
        // The same second in 8 frames gives the same ticks.
        let mut clock = TickClock::new(35);
        let total: u32 = (0..8).map(|_| clock.advance(Duration::from_millis(125)).0).sum();
        assert_eq!(total, 35);
        // A stall is clipped to a quarter second.
        assert_eq!(TickClock::new(35).advance(Duration::from_secs(10)).0, 8);
    }
}
