//! Pacing of the slide show: how many strips are due, when to wake, when to
//! start the next mountain. Pure: the caller passes the time in.

use std::time::{Duration, Instant};

/// Time between two drawing frames: ~30 fps is plenty for a strip-by-strip reveal.
pub const FRAME_INTERVAL: Duration = Duration::from_millis(33);

/// The timing a slide show follows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pacing {
    /// Time over which one mountain is drawn (zero: all at once).
    pub draw: Duration,
    /// Time a finished mountain is held.
    pub pause: Duration,
    /// Start the next mountain after the hold (false: hold until asked).
    pub auto_advance: bool,
    /// Least time between two drawing frames (xscreensaver's `-delay`).
    pub frame: Duration,
}

impl Pacing {
    /// Pacing from the settings' seconds; negative or non-finite values count as zero.
    pub fn from_seconds(draw: f32, pause: f32, auto_advance: bool) -> Self {
        Pacing {
            draw: seconds(draw),
            pause: seconds(pause),
            auto_advance,
            frame: FRAME_INTERVAL,
        }
    }

    /// The same pacing with `delay` between drawing frames (`-delay`, in
    /// xscreensaver's sense), kept between a millisecond and a second.
    pub fn with_frame_interval(self, delay: Duration) -> Self {
        let frame = delay.clamp(Duration::from_millis(1), Duration::from_secs(1));
        Pacing { frame, ..self }
    }
}

fn seconds(s: f32) -> Duration {
    // A day is far more than any sensible value and keeps Duration in range.
    Duration::try_from_secs_f32(s.clamp(0.0, 86_400.0)).unwrap_or(Duration::ZERO)
}

/// What the caller should do now.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Due {
    /// Draw this many more strips (at least one).
    Draw(usize),
    /// Nothing to do; sleep until `Slideshow::wake_at`.
    Wait,
    /// The hold is over: start the next mountain.
    Advance,
}

/// The state of one window's slide show: drawing, holding, or paused.
#[derive(Debug, Clone)]
pub struct Slideshow {
    pacing: Pacing,
    total: usize,
    done: usize,
    draw_start: Instant,
    hold_start: Option<Instant>,
    paused_at: Option<Instant>,
    /// Economy (on battery, power saver): how the hold changes.
    economy: Economy,
}

/// What the slide show does while the system saves power (the `on_battery`
/// key, when on battery or in power-saver mode).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Economy {
    /// As usual: mains power, or `on_battery = "same"`.
    #[default]
    None,
    /// The hold lasts until the power returns: no wake-up at all.
    Hold,
    /// Holds last [`SLOW_PAUSE_FACTOR`] times as long.
    Slow,
}

/// How much longer a hold lasts under [`Economy::Slow`].
pub const SLOW_PAUSE_FACTOR: u32 = 5;

impl Slideshow {
    /// A slide show whose first mountain of `total` strips starts drawing at `now`.
    pub fn new(pacing: Pacing, total: usize, now: Instant) -> Self {
        let mut show = Slideshow {
            pacing,
            total,
            done: 0,
            draw_start: now,
            hold_start: None,
            paused_at: None,
            economy: Economy::None,
        };
        show.restart(total, now);
        show
    }

    /// Starts drawing a new mountain of `total` strips at `now` (keeps a pause).
    pub fn restart(&mut self, total: usize, now: Instant) {
        self.total = total;
        self.done = 0;
        self.draw_start = now;
        self.hold_start = (total == 0).then_some(now);
        if self.paused_at.is_some() {
            self.paused_at = Some(now);
        }
    }

    /// Marks the current mountain as completely drawn at `now` (e.g. after a
    /// resize redrew it at once); the hold starts now.
    pub fn finish_now(&mut self, now: Instant) {
        self.done = self.total;
        self.hold_start = Some(now);
        if self.paused_at.is_some() {
            self.paused_at = Some(now);
        }
    }

    /// The strips drawn so far.
    pub fn strips_done(&self) -> usize {
        self.done
    }

    /// True once the mountain is complete and being held.
    pub fn is_holding(&self) -> bool {
        self.hold_start.is_some()
    }

    /// True while paused (Space).
    pub fn is_paused(&self) -> bool {
        self.paused_at.is_some()
    }

    /// Sets how the hold behaves from now on; the slide being drawn is
    /// finished either way.
    pub fn set_economy(&mut self, economy: Economy) {
        self.economy = economy;
    }

    /// True while a hold lasts until the power returns.
    pub fn is_held_for_power(&self) -> bool {
        self.economy == Economy::Hold
    }

    /// The hold's length, or `None` when it lasts until something changes.
    fn pause(&self) -> Option<Duration> {
        match self.economy {
            _ if !self.pacing.auto_advance => None,
            Economy::Hold => None,
            Economy::Slow => Some(self.pacing.pause * SLOW_PAUSE_FACTOR),
            Economy::None => Some(self.pacing.pause),
        }
    }

    /// What is due at `now`.
    pub fn due(&self, now: Instant) -> Due {
        if self.paused_at.is_some() {
            return Due::Wait;
        }
        if let Some(hold) = self.hold_start {
            let over = self
                .pause()
                .is_some_and(|pause| now.saturating_duration_since(hold) >= pause);
            return if over { Due::Advance } else { Due::Wait };
        }
        match self.target(now).saturating_sub(self.done) {
            0 => Due::Wait,
            n => Due::Draw(n),
        }
    }

    /// Records that `strips` more were drawn at `now`; the hold starts when the last one is.
    pub fn drew(&mut self, strips: usize, now: Instant) {
        self.done = (self.done + strips).min(self.total);
        if self.done >= self.total && self.hold_start.is_none() {
            self.hold_start = Some(now);
        }
    }

    /// When the caller should next look at `due`; `None` means not until an
    /// event arrives (paused, or holding without auto advance).
    pub fn wake_at(&self, now: Instant) -> Option<Instant> {
        if self.paused_at.is_some() {
            return None;
        }
        match self.hold_start {
            Some(hold) => self.pause().map(|pause| hold + pause),
            None => Some((now + self.pacing.frame).max(self.strip_time(self.done))),
        }
    }

    /// Pauses or resumes at `now`; on resume the clock continues where it stopped.
    pub fn toggle_pause(&mut self, now: Instant) {
        match self.paused_at.take() {
            None => self.paused_at = Some(now),
            Some(at) => {
                let gap = now.saturating_duration_since(at);
                self.draw_start += gap;
                if let Some(hold) = self.hold_start.as_mut() {
                    *hold += gap;
                }
            }
        }
    }

    /// Strips that should be drawn by `now`: the first at once, the last at `draw`.
    fn target(&self, now: Instant) -> usize {
        if self.pacing.draw.is_zero() {
            return self.total;
        }
        let fraction = now.saturating_duration_since(self.draw_start).as_secs_f64()
            / self.pacing.draw.as_secs_f64();
        let strips = (fraction * self.total as f64).floor() as usize + 1;
        strips.min(self.total)
    }

    /// The moment strip `index` (0-based) falls due.
    fn strip_time(&self, index: usize) -> Instant {
        if self.total == 0 {
            return self.draw_start;
        }
        let fraction = index as f64 / self.total as f64;
        self.draw_start + self.pacing.draw.mul_f64(fraction)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pacing(draw_ms: u64, pause_ms: u64, auto: bool) -> Pacing {
        Pacing {
            draw: Duration::from_millis(draw_ms),
            pause: Duration::from_millis(pause_ms),
            auto_advance: auto,
            frame: FRAME_INTERVAL,
        }
    }

    /// `-delay`: drawing frames come that far apart, within sane bounds.
    #[test]
    fn a_delay_spaces_the_drawing_frames() {
        let t0 = Instant::now();
        let slow = pacing(10_000, 1000, true).with_frame_interval(Duration::from_millis(200));
        let show = Slideshow::new(slow, 1000, t0);
        assert_eq!(show.wake_at(t0), Some(t0 + Duration::from_millis(200)));
        let zero = pacing(10_000, 1000, true).with_frame_interval(Duration::ZERO);
        assert_eq!(zero.frame, Duration::from_millis(1));
        let huge = pacing(10_000, 1000, true).with_frame_interval(Duration::from_secs(60));
        assert_eq!(huge.frame, Duration::from_secs(1));
    }

    #[test]
    fn draws_in_proportion_to_elapsed_time() {
        let t0 = Instant::now();
        let mut show = Slideshow::new(pacing(1000, 500, true), 100, t0);
        assert_eq!(show.due(t0), Due::Draw(1));
        show.drew(1, t0);
        assert_eq!(show.due(t0 + Duration::from_millis(250)), Due::Draw(25));
        show.drew(25, t0 + Duration::from_millis(250));
        assert_eq!(show.due(t0 + Duration::from_millis(250)), Due::Wait);
        assert_eq!(show.due(t0 + Duration::from_secs(5)), Due::Draw(74));
    }

    #[test]
    fn zero_draw_time_draws_everything_at_once() {
        let t0 = Instant::now();
        let show = Slideshow::new(pacing(0, 500, true), 257, t0);
        assert_eq!(show.due(t0), Due::Draw(257));
    }

    #[test]
    fn holds_for_the_pause_then_advances() {
        let t0 = Instant::now();
        let mut show = Slideshow::new(pacing(0, 500, true), 10, t0);
        show.drew(10, t0);
        assert!(show.is_holding());
        assert_eq!(show.due(t0 + Duration::from_millis(499)), Due::Wait);
        assert_eq!(show.wake_at(t0), Some(t0 + Duration::from_millis(500)));
        assert_eq!(show.due(t0 + Duration::from_millis(500)), Due::Advance);
    }

    #[test]
    fn without_auto_advance_it_holds_and_sleeps_forever() {
        let t0 = Instant::now();
        let mut show = Slideshow::new(pacing(0, 10, false), 10, t0);
        show.drew(10, t0);
        assert_eq!(show.due(t0 + Duration::from_secs(3600)), Due::Wait);
        assert_eq!(show.wake_at(t0), None);
    }

    #[test]
    fn wakes_at_frame_rate_while_drawing_fast() {
        let t0 = Instant::now();
        let show = Slideshow::new(pacing(1000, 0, true), 1000, t0);
        assert_eq!(show.wake_at(t0), Some(t0 + FRAME_INTERVAL));
    }

    #[test]
    fn sleeps_until_the_next_strip_when_drawing_slowly() {
        let t0 = Instant::now();
        let mut show = Slideshow::new(pacing(10_000, 0, true), 10, t0);
        show.drew(1, t0);
        assert_eq!(show.wake_at(t0), Some(t0 + Duration::from_secs(1)));
    }

    #[test]
    fn pause_freezes_drawing_and_resume_continues_where_it_stopped() {
        let t0 = Instant::now();
        let mut show = Slideshow::new(pacing(1000, 0, true), 100, t0);
        show.drew(50, t0 + Duration::from_millis(500));
        show.toggle_pause(t0 + Duration::from_millis(500));
        assert_eq!(show.due(t0 + Duration::from_secs(10)), Due::Wait);
        assert_eq!(show.wake_at(t0 + Duration::from_secs(10)), None);
        show.toggle_pause(t0 + Duration::from_millis(10_500));
        // 750 ms of drawing: 75 strips due plus the one drawn at once.
        assert_eq!(show.due(t0 + Duration::from_millis(10_750)), Due::Draw(26));
    }

    #[test]
    fn pause_extends_the_hold() {
        let t0 = Instant::now();
        let mut show = Slideshow::new(pacing(0, 1000, true), 1, t0);
        show.drew(1, t0);
        show.toggle_pause(t0 + Duration::from_millis(900));
        show.toggle_pause(t0 + Duration::from_millis(5900));
        assert_eq!(show.due(t0 + Duration::from_millis(5950)), Due::Wait);
        assert_eq!(show.due(t0 + Duration::from_millis(6000)), Due::Advance);
    }

    #[test]
    fn restart_and_finish_now_reset_the_phases() {
        let t0 = Instant::now();
        let mut show = Slideshow::new(pacing(1000, 1000, true), 10, t0);
        show.finish_now(t0);
        assert!(show.is_holding());
        assert_eq!(show.strips_done(), 10);
        show.restart(20, t0 + Duration::from_secs(1));
        assert!(!show.is_holding());
        assert_eq!(show.due(t0 + Duration::from_secs(1)), Due::Draw(1));
    }

    /// On battery with "hold": the slide being drawn is finished, then
    /// held with no wake-up until the power returns; "slow" stretches holds.
    #[test]
    fn economy_holds_after_the_slide_or_stretches_the_pause() {
        let t0 = Instant::now();
        let mut show = Slideshow::new(pacing(1000, 500, true), 10, t0);
        show.set_economy(Economy::Hold);
        assert_eq!(show.due(t0 + Duration::from_secs(2)), Due::Draw(10));
        show.drew(10, t0 + Duration::from_secs(2));
        assert_eq!(show.due(t0 + Duration::from_secs(3600)), Due::Wait);
        assert_eq!(show.wake_at(t0 + Duration::from_secs(3)), None);
        show.set_economy(Economy::Slow);
        let held = t0 + Duration::from_secs(2);
        assert_eq!(show.wake_at(held), Some(held + Duration::from_millis(2500)));
        assert_eq!(show.due(held + Duration::from_millis(2499)), Due::Wait);
        show.set_economy(Economy::None);
        assert_eq!(show.due(held + Duration::from_millis(500)), Due::Advance);
    }

    #[test]
    fn bad_seconds_become_zero() {
        let p = Pacing::from_seconds(f32::NAN, -3.0, true);
        assert_eq!(p.draw, Duration::ZERO);
        assert_eq!(p.pause, Duration::ZERO);
        assert_eq!(
            Pacing::from_seconds(1.5, 2.0, false).draw,
            Duration::from_millis(1500)
        );
    }
}
