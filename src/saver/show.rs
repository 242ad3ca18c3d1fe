//! One window's slide show: its frame, the mountain being drawn, the next one
//! being generated in the background. Knows nothing about windows.

use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use super::on_screen::OnScreen;
use super::overlay::Overlay;
use super::redraw::{Drawn, Redraw};
use super::slideshow::{Due, Economy, Pacing, Slideshow};
use super::source;
use crate::mountain::Mountain;
use crate::render::{Damage, Frame, Painter, Rect, Size, detail};
use crate::settings::Settings;
use crate::settings::keys::{self, Change};

/// Where the next mountain comes from.
enum Next {
    /// Nothing prepared yet.
    None,
    /// Being generated on another thread with these settings (the detail
    /// fitted), the settings of the moment.
    Pending(JoinHandle<Mountain>, Settings),
}

/// What to do once the redraw under way is done, because something asked
/// for another while it ran.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Again {
    /// Draw the mountain again (a new size, new colours).
    Redraw,
    /// Make it again, then draw it (Low Detail).
    Remake,
}

/// How often the event loop looks whether a redraw is finished: a frame
/// takes tens of milliseconds, and a look costs next to nothing.
const REDRAW_POLL: Duration = Duration::from_millis(4);

/// The slide show of one window: what is on screen and what comes next.
pub struct Show {
    settings: Settings,
    /// The settings the mountain on screen was made with.
    made_with: Settings,
    /// A data set opened by the user: shown every time instead of generating.
    opened: Option<Mountain>,
    current: Option<OnScreen>,
    next: Next,
    frame: Option<Frame>,
    /// The window's size: the frame's, or the one a redraw is drawing for.
    size: Size,
    painter: Option<Painter>,
    /// A complete redraw under way; the old frame stays up until it is done.
    redraw: Option<Redraw>,
    /// Asked for while `redraw` ran: one redraw at a time, so a storm of
    /// resizes costs one thread, not one each.
    again: Option<Again>,
    slideshow: Slideshow,
    /// Number of the slide on screen, counted from 0: picks its source.
    slide: u64,
    /// Text over the picture: `-fps`, the list of keys.
    overlay: Overlay,
    /// The display is powered off: nothing is drawn or made until it is on.
    asleep: bool,
}

impl Show {
    /// A show of `size` pixels that starts drawing its first
    /// mountain (`opened`, or a generated one) at `now`.
    pub fn new(
        settings: Settings,
        opened: Option<Mountain>,
        pacing: Pacing,
        size: Size,
        now: Instant,
    ) -> Self {
        let first = match &opened {
            Some(m) => OnScreen::new(m.clone(), None),
            None => {
                let made = detail::for_frame(&settings, size);
                OnScreen::new(Mountain::generate(&made), Some(made))
            }
        };
        let mut show = Show::empty(settings, pacing, size, now);
        show.opened = opened;
        show.current = Some(first);
        show.start_drawing(size, now);
        show
    }

    /// A black show that never draws a mountain (a monitor left blank).
    pub fn blank(size: Size, now: Instant) -> Self {
        let pacing = Pacing::from_seconds(0.0, 0.0, false);
        let mut show = Show::empty(Settings::default(), pacing, size, now);
        show.frame = Frame::new(size.width, size.height);
        show
    }

    /// A show with no mountain and no frame yet.
    fn empty(settings: Settings, pacing: Pacing, size: Size, now: Instant) -> Self {
        Show {
            made_with: settings.clone(),
            settings,
            opened: None,
            current: None,
            next: Next::None,
            frame: None,
            size,
            painter: None,
            redraw: None,
            again: None,
            slideshow: Slideshow::new(pacing, 0, now),
            slide: 0,
            overlay: Overlay::default(),
            asleep: false,
        }
    }

    /// Draws the frame rate and load over the picture from now on (`-fps`).
    pub fn show_fps(&mut self) {
        self.overlay = Overlay::new(true);
    }

    /// Shows `line` (what a key just did) over the picture for a while.
    pub fn note(&mut self, line: String, now: Instant) -> Rect {
        self.overlay.note(line, now);
        self.redraw_overlay(now)
    }

    /// H, F1: shows the list of keys for a while, or hides it.
    pub fn toggle_help(&mut self, now: Instant) -> Rect {
        self.overlay.toggle_help(now);
        self.redraw_overlay(now)
    }

    /// Puts the picture back under the text and draws the text due now.
    fn redraw_overlay(&mut self, now: Instant) -> Rect {
        let Some(frame) = self.frame.as_mut() else {
            return Rect::default();
        };
        let lifted = self.overlay.lift(frame);
        lifted.union(&self.overlay.draw(frame, now))
    }

    /// The pixels to present; `None` while the window has no area.
    pub fn frame(&self) -> Option<&Frame> {
        self.frame.as_ref()
    }

    /// The pixels, to draw into from outside: a window showing its part
    /// of a span (see `span.rs`) keeps a black show for them.
    pub(super) fn frame_mut(&mut self) -> Option<&mut Frame> {
        self.frame.as_mut()
    }

    /// The mountain on screen, if any. While a slide is held its heights
    /// may have been let go (see `on_screen.rs`): they are made again here,
    /// which takes as long as generating them did.
    pub fn current(&self) -> Option<Mountain> {
        self.current.as_ref().map(OnScreen::mountain)
    }

    /// The seed of the mountain on screen, if a seed made it.
    pub fn seed(&self) -> Option<u64> {
        self.current.as_ref().and_then(OnScreen::seed)
    }

    /// The settings this show draws with.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The settings the mountain on screen is saved with (the S key): drawn
    /// as it is now, and made as it was (a key that shapes only the next
    /// mountain, changed since, is not this one's).
    pub fn saved_settings(&self) -> Settings {
        let mut saved = self.settings.clone();
        for key in keys::KEYS.iter().filter(|k| k.change == Change::Next) {
            keys::copy(key, &self.made_with, &mut saved);
        }
        saved
    }

    /// The window title for what is on screen now (see `actions::window_title`).
    pub fn title(&self) -> String {
        super::actions::window_title(
            &self.settings,
            &self.made_with,
            self.seed(),
            self.is_paused(),
        )
    }

    /// When this show next needs `tick`; `None`: not until an event arrives.
    pub fn wake_at(&self, now: Instant) -> Option<Instant> {
        if self.asleep {
            return None;
        }
        if self.redraw.is_some() {
            return Some(now + REDRAW_POLL);
        }
        self.painter.as_ref()?;
        let show = self.slideshow.wake_at(now);
        match self.overlay.help_ends() {
            Some(t) => Some(show.map_or(t, |s| s.min(t))),
            None => show,
        }
    }

    /// Does what is due at `now` and returns the pixels that changed;
    /// nothing once a signal asked the program to end (the next mountain
    /// would be waited for, a redraw shown, strips drawn, for no one).
    pub fn tick(&mut self, now: Instant) -> Damage {
        if crate::platform::signals::ending() || self.asleep {
            return Damage::default();
        }
        if self.redraw.as_ref().is_some_and(|r| !r.is_done()) {
            return Damage::default();
        }
        if self.redraw.is_some() {
            return self.settle(now).into();
        }
        let (Some(painter), Some(frame)) = (self.painter.as_mut(), self.frame.as_mut()) else {
            return Damage::default();
        };
        match self.slideshow.due(now) {
            Due::Wait if self.overlay.help_ends().is_some_and(|t| t <= now) => {
                self.redraw_overlay(now).into()
            }
            Due::Wait => Damage::default(),
            Due::Draw(strips) => {
                let lifted = self.overlay.lift(frame);
                let (mut damage, drawn) = step_unless_ending(painter, frame, strips);
                damage.add(lifted);
                self.overlay.count_frame(now);
                damage.add(self.overlay.draw(frame, now));
                self.slideshow.drew(drawn, now);
                if painter.is_done() && !self.slideshow.is_holding() {
                    self.slideshow.finish_now(now);
                }
                if self.slideshow.is_holding() {
                    self.prepare_next();
                }
                damage
            }
            Due::Advance => self.advance(now).into(),
        }
    }

    /// Waits for the mountain being made on another thread, if one is,
    /// and lets the show go: no work of it runs afterwards. For a caller
    /// that must know that (a test counting the process's heap, whose next
    /// test would count a detached maker's field). The saver's exit does
    /// not wait: the process ends with the thread.
    pub fn finish(mut self) {
        if let Next::Pending(handle, _) = std::mem::replace(&mut self.next, Next::None) {
            crate::log::joined(handle, "making the next mountain");
        }
    }

    /// Starts the next mountain now (the N key, or the end of a hold).
    pub fn advance(&mut self, now: Instant) -> Rect {
        if self.current.is_none() {
            return Rect::default();
        }
        let next = match std::mem::replace(&mut self.next, Next::None) {
            // A signal came while the next mountain was still being made
            // (a loaded machine): the program ends, nothing more is shown.
            Next::Pending(handle, made) if !finished_unless_ending(&handle) => {
                self.next = Next::Pending(handle, made);
                return Rect::default();
            }
            // Made again below, on this thread, if its thread failed.
            Next::Pending(handle, made) => {
                crate::log::joined(handle, "making the next mountain").map(|m| (m, Some(made)))
            }
            Next::None => None,
        };
        // A redraw of the old mountain still under way is not wanted now,
        // nor the old painter: the new scene is built without them.
        self.redraw = None;
        self.again = None;
        self.painter = None;
        self.current = None;
        let (mountain, made) = next.unwrap_or_else(|| self.make_next_now());
        self.current = Some(OnScreen::new(mountain, made));
        // Any change of settings dropped the mountain prepared before it, so
        // the one now on screen was made with the settings of the moment.
        self.made_with = self.settings.clone();
        self.slide += 1;
        let size = self.size();
        // The first strips go out with the cleared frame: no blank flash.
        let cleared = self.start_drawing(size, now);
        cleared.union(&self.tick(now).bounds())
    }

    /// The N key: a freshly generated mountain, also after `--open`
    /// (the opened data set is let go, as New does in Mountain Terrain).
    pub fn new_mountain(&mut self, now: Instant) -> Rect {
        if self.opened.take().is_some() {
            self.next = Next::None;
        }
        self.advance(now)
    }

    /// The O key: show `mountain` (a data set the user opened) from now on,
    /// as `--open` does, until N asks for a new one.
    pub fn open(&mut self, mountain: Mountain, now: Instant) -> Rect {
        if self.current.is_none() {
            return Rect::default();
        }
        self.opened = Some(mountain);
        self.next = Next::None;
        self.advance(now)
    }

    /// Fits the show to a new window size: the mountain is redrawn whole on
    /// other threads, and shown by the `tick` after it is done.
    pub fn resize(&mut self, size: Size, now: Instant) -> Rect {
        self.size = size;
        // The slide the display shows when it comes back is drawn at this size.
        if self.asleep {
            return Rect::default();
        }
        if self.current.is_none() {
            self.frame = Frame::new(size.width, size.height);
            return self.frame.as_ref().map(Frame::bounds).unwrap_or_default();
        }
        self.begin_redraw(now)
    }

    /// Waits for a redraw under way, if any, and shows it: the rectangle
    /// that changed (empty when there was none). One asked for meanwhile
    /// starts then.
    pub fn settle(&mut self, now: Instant) -> Rect {
        let Some(redraw) = self.redraw.take() else {
            return Rect::default();
        };
        let shown = match redraw.wait() {
            Some(drawn) => self.show_redrawn(drawn, now),
            // The drawing thread failed: draw here, strip by strip.
            None => {
                self.start_drawing(self.size, now);
                self.tick(now).bounds()
            }
        };
        let next = match self.again.take() {
            Some(Again::Redraw) => self.begin_redraw(now),
            Some(Again::Remake) => self.begin_remake(now),
            None => Rect::default(),
        };
        shown.union(&next)
    }

    /// True (and remembered) when a redraw is under way: `again` follows it.
    fn after_redraw(&mut self, again: Again) -> bool {
        if self.redraw.is_none() {
            return false;
        }
        if self.again != Some(Again::Remake) {
            self.again = Some(again);
        }
        true
    }

    /// Follows the power: under `Economy::Hold` the slide being drawn is
    /// finished and held, and the next mountain is not made until the
    /// power returns.
    pub fn set_economy(&mut self, economy: Economy) {
        self.slideshow.set_economy(economy);
        if self.slideshow.is_holding() {
            self.prepare_next();
        }
    }

    /// Follows the display's power: while it is off nothing is drawn or
    /// made (a redraw under way is called off); when it comes back a fresh
    /// slide starts. Returns the pixels that changed.
    pub fn set_display(&mut self, on: bool, now: Instant) -> Rect {
        if self.asleep != on {
            return Rect::default();
        }
        self.asleep = !on;
        if !on {
            self.redraw = None;
            self.again = None;
            return Rect::default();
        }
        self.advance(now)
    }

    /// Number of the slide on screen, counted from 0.
    pub(super) fn slide(&self) -> u64 {
        self.slide
    }

    /// True while the display is off for this show.
    pub fn is_asleep(&self) -> bool {
        self.asleep
    }

    /// Pauses or resumes the drawing and the hold.
    pub fn toggle_pause(&mut self, now: Instant) {
        self.slideshow.toggle_pause(now);
    }

    /// True while paused.
    pub fn is_paused(&self) -> bool {
        self.slideshow.is_paused()
    }

    /// Applies new settings; `change` (the key table's word for the key that
    /// changed) says whether the mountain on screen is drawn again, made
    /// again, or left for the next mountain to use them.
    pub fn change_settings(&mut self, settings: Settings, change: Change, now: Instant) -> Rect {
        self.settings = settings;
        // A mountain generated with the old settings would ignore the change.
        self.next = Next::None;
        if self.slideshow.is_holding() {
            self.prepare_next();
        }
        match change {
            Change::Repaint => self.begin_redraw(now),
            Change::Remake => self.begin_remake(now),
            Change::Next | Change::Nothing => Rect::default(),
        }
    }

    /// Makes the mountain on screen again from its seed, with the settings
    /// it was made with but the new values of the keys whose change remakes
    /// (Low Detail: the same mountain, coarser or finer), then draws it. A
    /// mountain read from a file is only drawn again.
    fn begin_remake(&mut self, now: Instant) -> Rect {
        let Some(seed) = self
            .current
            .as_ref()
            .filter(|m| m.generated())
            .and_then(OnScreen::seed)
        else {
            return self.begin_redraw(now);
        };
        if self.after_redraw(Again::Remake) {
            return Rect::default();
        }
        for key in keys::KEYS.iter().filter(|k| k.change == Change::Remake) {
            keys::copy(key, &self.settings, &mut self.made_with);
        }
        let made = self.generator_settings_for(&self.made_with);
        self.painter = None;
        match Redraw::remake(seed, made, &self.settings, self.size) {
            Ok(redraw) => {
                self.redraw = Some(redraw);
                Rect::default()
            }
            Err(drawn) => self.show_redrawn(*drawn, now),
        }
    }

    /// The size this show draws for (the window's); the frame on screen
    /// keeps the old size until a redraw for a new one is done.
    pub fn size(&self) -> Size {
        self.size
    }

    /// Starts redrawing the current mountain whole at the show's size; the
    /// drawing under way stops where it is and the old frame stays up. A
    /// redraw already under way is finished first, then this one starts.
    fn begin_redraw(&mut self, now: Instant) -> Rect {
        if self.after_redraw(Again::Redraw) {
            return Rect::default();
        }
        let Some(mountain) = self.current.as_ref() else {
            return Rect::default();
        };
        self.painter = None;
        // Heights let go during the hold are made again on the redraw's thread.
        let drawn = mountain.drawn_with(&self.settings);
        let redraw = match mountain.parked() {
            Some((seed, made)) => Redraw::remake(seed, made.clone(), &drawn, self.size),
            None => Redraw::start(mountain.field(), &drawn, self.size),
        };
        match redraw {
            Ok(redraw) => {
                self.redraw = Some(redraw);
                Rect::default()
            }
            Err(drawn) => self.show_redrawn(*drawn, now),
        }
    }

    /// Puts a finished redraw on screen and starts the hold.
    fn show_redrawn(&mut self, drawn: Drawn, now: Instant) -> Rect {
        if let Some(mountain) = self.current.as_mut() {
            mountain.redrawn(drawn.field, drawn.made);
        }
        self.frame = drawn.frame;
        self.overlay.forget();
        self.slideshow.restart(drawn.painter.strips_total(), now);
        self.painter = Some(drawn.painter);
        self.slideshow.finish_now(now);
        self.prepare_next();
        self.frame.as_ref().map(Frame::bounds).unwrap_or_default()
    }

    /// Clears the frame (made at `size`) and plans drawing the current mountain into it.
    fn start_drawing(&mut self, size: Size, now: Instant) -> Rect {
        let Some(mountain) = self.current.as_ref() else {
            return Rect::default();
        };
        let reused = self.frame.as_ref().map(Frame::size) == Some(size);
        if !reused {
            // Free the old pixels before allocating the new ones: peak memory.
            self.frame = None;
            self.frame = Frame::new(size.width, size.height);
        }
        self.overlay.forget();
        let Some(frame) = self.frame.as_mut() else {
            self.painter = None;
            return Rect::default();
        };
        // Black until the painter's first step paints its background. A new
        // frame is black already (and untouched pages cost nothing yet).
        if reused {
            frame.clear(0);
        }
        let drawn = mountain.drawn_with(&self.settings);
        // The clock's sun where it stands as this slide begins.
        let hour = crate::solar::now_for(&drawn);
        let painter = Painter::at_hour(mountain.field(), &drawn, size, hour);
        self.slideshow.restart(painter.strips_total(), now);
        self.painter = Some(painter);
        frame.bounds()
    }

    /// Starts generating the next mountain in the background, once per
    /// hold. The heights on screen, drawn, are let go first: the two
    /// fields are not in memory at once (the peak memory at 4K).
    fn prepare_next(&mut self) {
        if self.opened.is_some() {
            return;
        }
        if self.painter.as_ref().is_some_and(Painter::is_done)
            && let Some(current) = self.current.as_mut()
        {
            current.park();
            // The drawing's working memory is gone too; the hold keeps the frame.
            crate::memory::give_back_free_pages();
        }
        if !matches!(self.next, Next::None) || self.slideshow.is_held_for_power() {
            return;
        }
        let settings = self.generator_settings();
        let made = settings.clone();
        let slide = self.slide + 1;
        let spawned = std::thread::Builder::new()
            .name("generate".into())
            .spawn(move || source::next_mountain(&settings, slide));
        // Without a thread the mountain is generated when it is needed.
        if let Ok(handle) = spawned {
            self.next = Next::Pending(handle, made);
        }
    }

    /// The next mountain, made here, and the generator's settings if it
    /// was generated.
    fn make_next_now(&self) -> (Mountain, Option<Settings>) {
        match &self.opened {
            Some(m) => (m.clone(), None),
            None => {
                let made = self.generator_settings();
                (source::next_mountain(&made, self.slide + 1), Some(made))
            }
        }
    }

    /// The settings with `detail = "auto"` fitted to this window's size.
    fn generator_settings(&self) -> Settings {
        self.generator_settings_for(&self.settings)
    }

    /// `settings` with `detail = "auto"` fitted to this window's size.
    fn generator_settings_for(&self, settings: &Settings) -> Settings {
        detail::for_frame(settings, self.size)
    }
}

/// Waits for `thread` to finish; false if a signal asked the program to
/// end first (joining would keep the loop from reading the notice).
fn finished_unless_ending<T>(thread: &JoinHandle<T>) -> bool {
    while !thread.is_finished() {
        if crate::platform::signals::ending() {
            return false;
        }
        std::thread::sleep(Duration::from_millis(2));
    }
    true
}

/// Strips drawn between two looks at `signals::ending`: a look costs
/// nothing, a strip a fraction of a millisecond.
const STRIPS_BETWEEN_LOOKS: usize = 4;

/// Draws `strips` more strips, fewer if a signal asks the program to end
/// meanwhile: a show that fell behind (a loaded machine, nice 10 under
/// xscreensaver) catches up with hundreds of strips in one tick, and the
/// loop would read the notice only after them. Returns the pixels changed
/// and the strips drawn.
fn step_unless_ending(painter: &mut Painter, frame: &mut Frame, strips: usize) -> (Damage, usize) {
    let mut damage = Damage::default();
    let mut drawn = 0;
    while drawn < strips && !crate::platform::signals::ending() {
        let n = (strips - drawn).min(STRIPS_BETWEEN_LOOKS);
        for r in painter.step(frame, n).rects() {
            damage.add(r);
        }
        drawn += n;
    }
    (damage, drawn)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::Detail;
    use crate::terrain::Heightfield;
    use crate::terrain::heightmap::GeneratorParams;
    use std::sync::Arc;
    use std::time::Duration;

    fn small_settings() -> Settings {
        Settings {
            detail: Detail::Level(5),
            seed: Some(7),
            ..Settings::default()
        }
    }

    fn pacing() -> Pacing {
        Pacing::from_seconds(1.0, 2.0, true)
    }

    #[test]
    fn draws_over_time_then_holds_then_advances() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(64, 48), t0);
        assert!(!show.tick(t0).is_empty());
        let half = show.tick(t0 + Duration::from_millis(500));
        assert!(!half.is_empty());
        show.tick(t0 + Duration::from_millis(1000));
        assert_eq!(
            show.wake_at(t0 + Duration::from_millis(1000)),
            Some(t0 + Duration::from_millis(3000))
        );
        assert!(show.tick(t0 + Duration::from_millis(2000)).is_empty());
        let next = show.tick(t0 + Duration::from_millis(3000)).bounds();
        assert_eq!(
            next,
            Rect {
                x0: 0,
                y0: 0,
                x1: 64,
                y1: 48
            }
        );
        assert_eq!(show.current().and_then(|m| m.seed), Some(7));
    }

    /// The title describes the mountain on screen: it follows the slide
    /// show when it moves on by itself, and a key for the next mountain
    /// (cragginess, low detail) shows only with that mountain.
    #[test]
    fn the_title_follows_the_mountain_on_screen() {
        let t0 = Instant::now();
        let first = Settings {
            seed: None,
            ..small_settings()
        };
        let mut show = Show::new(first.clone(), None, pacing(), Size::new(64, 48), t0);
        let seed = |show: &Show| show.current().and_then(|m| m.seed).unwrap();
        let one = seed(&show);
        assert!(
            show.title().contains(&format!("seed {one},")),
            "{}",
            show.title()
        );
        let craggier = Settings {
            cragginess: 128,
            ..first
        };
        show.change_settings(craggier, Change::Next, t0);
        assert!(show.title().contains("cragginess 96"), "{}", show.title());
        // Saved now, the mountain on screen says how it was made.
        assert_eq!(show.saved_settings().cragginess, 96);
        show.tick(t0 + Duration::from_millis(1000));
        show.tick(t0 + Duration::from_millis(3000));
        let two = seed(&show);
        assert_ne!(one, two, "the slide show did not move on");
        let title = show.title();
        assert!(
            title.contains(&format!("seed {two},")) && title.contains("cragginess 128"),
            "{title}"
        );
    }

    #[test]
    fn resize_redraws_fully_at_the_new_size() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(64, 48), t0);
        assert!(
            show.resize(Size::new(100, 30), t0).is_empty(),
            "drawn before done"
        );
        assert_eq!(show.size(), Size::new(100, 30));
        let damage = show.settle(t0);
        assert_eq!(
            damage,
            Rect {
                x0: 0,
                y0: 0,
                x1: 100,
                y1: 30
            }
        );
        let frame = show.frame().expect("frame");
        assert_eq!((frame.width(), frame.height()), (100, 30));
        let mut full = Frame::new(100, 30).unwrap();
        let m = show.current().unwrap();
        crate::render::render_full(&m.field, show.settings(), &mut full);
        assert_eq!(frame.pixels(), full.pixels());
    }

    /// A storm of resizes (monitors changing) costs one redraw at a time:
    /// those asked while one runs become one more, at the latest size,
    /// started when the first is shown (not a thread each, piling up).
    #[test]
    fn resizes_during_a_redraw_make_one_more_at_the_last_size() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(64, 48), t0);
        for size in [Size::new(100, 30), Size::new(80, 60), Size::new(70, 50)] {
            show.resize(size, t0);
        }
        assert!(
            show.again == Some(Again::Redraw),
            "the later resizes were lost"
        );
        show.settle(t0);
        let frame = show.frame().expect("frame");
        assert_eq!((frame.width(), frame.height()), (100, 30));
        assert!(show.redraw.is_some(), "no redraw for the last size");
        show.settle(t0);
        assert!(show.redraw.is_none() && show.again.is_none());
        let frame = show.frame().expect("frame");
        assert_eq!((frame.width(), frame.height()), (70, 50));
        let mut full = Frame::new(70, 50).unwrap();
        let m = show.current().unwrap();
        crate::render::render_full(&m.field, show.settings(), &mut full);
        assert_eq!(frame.pixels(), full.pixels());
    }

    #[test]
    fn after_a_resize_the_redrawn_mountain_is_held() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(64, 48), t0);
        show.tick(t0 + Duration::from_millis(1000));
        let t1 = t0 + Duration::from_millis(1200);
        show.resize(Size::new(80, 60), t1);
        show.settle(t1);
        assert!(
            show.tick(t1).is_empty(),
            "drew again right after the resize"
        );
        assert_eq!(show.wake_at(t1), Some(t1 + Duration::from_secs(2)));
    }

    /// The event loop is not held up by a redraw: the old picture stays
    /// up, the show asks to be looked at again soon, and a later tick puts
    /// the new frame up.
    #[test]
    fn a_redraw_runs_beside_the_event_loop_and_a_tick_shows_it() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(64, 48), t0);
        show.tick(t0 + Duration::from_millis(1000));
        let t1 = t0 + Duration::from_millis(1200);
        assert!(show.resize(Size::new(90, 40), t1).is_empty());
        let old = show.frame().map(|f| (f.width(), f.height()));
        assert_eq!(
            old,
            Some((64, 48)),
            "the old frame left before the new one was done"
        );
        assert_eq!(show.wake_at(t1), Some(t1 + REDRAW_POLL));
        let mut damage = Rect::default();
        // No clock: a tick shows the redraw once its thread is done.
        while damage.is_empty() {
            std::thread::yield_now();
            damage = show.tick(t1).bounds();
        }
        assert_eq!((damage.x1, damage.y1), (90, 40));
        let mut full = Frame::new(90, 40).unwrap();
        crate::render::render_full(&show.current().unwrap().field, show.settings(), &mut full);
        assert!(
            show.frame() == Some(&full),
            "the redraw differs from a full frame"
        );
        assert_eq!(
            show.wake_at(t1),
            Some(t1 + Duration::from_secs(2)),
            "not held"
        );
    }

    /// While a slide is held and the next mountain is made, the heights
    /// on screen are not in memory (two 4K fields at once were most of the
    /// saver's peak); a redraw or a save gets them back bit for bit.
    #[test]
    fn a_held_slide_lets_its_heights_go_until_they_are_wanted() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(64, 48), t0);
        let made = Heightfield::clone(&show.current().unwrap().field);
        let shown = Arc::downgrade(&show.current().unwrap().field);
        show.tick(t0 + Duration::from_millis(500));
        assert!(shown.upgrade().is_some(), "let go while drawing");
        show.tick(t0 + Duration::from_millis(1000));
        assert!(show.slideshow.is_holding());
        assert!(
            shown.upgrade().is_none(),
            "the held slide keeps its heights while the next are made"
        );
        assert_eq!(
            *show.current().unwrap().field,
            made,
            "made again differently"
        );
        let t1 = t0 + Duration::from_millis(1500);
        show.resize(Size::new(70, 50), t1);
        show.settle(t1);
        let mut full = Frame::new(70, 50).unwrap();
        crate::render::render_full(&made, show.settings(), &mut full);
        assert!(show.frame() == Some(&full), "the redraw differs");
        assert_eq!(show.seed(), Some(7));
    }

    #[test]
    fn zero_size_has_no_frame_and_does_not_panic() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(0, 0), t0);
        assert!(show.frame().is_none());
        assert!(show.tick(t0 + Duration::from_secs(5)).is_empty());
        show.resize(Size::new(10, 10), t0);
        assert!(!show.settle(t0).is_empty());
    }

    #[test]
    fn an_opened_data_set_is_shown_again_instead_of_generating() {
        let t0 = Instant::now();
        let mut field = Heightfield::flat(4, 100.0);
        field.set(3, 3, 42.0);
        let opened = Mountain {
            field: Arc::new(field),
            seed: None,
            generated: false,
            recorded: None,
        };
        let mut show = Show::new(
            small_settings(),
            Some(opened),
            pacing(),
            Size::new(32, 32),
            t0,
        );
        show.advance(t0);
        let shown = show.current().unwrap();
        assert_eq!(shown.seed, None);
        assert_eq!(shown.field.get(3, 3), 42.0);
    }

    /// A data set is drawn under the keys its file recorded (here the
    /// essay's look), strip by strip and in a redraw alike.
    #[test]
    fn an_opened_data_set_is_drawn_under_its_recorded_look() {
        let t0 = Instant::now();
        let mut made = small_settings();
        crate::settings::load::apply_set(&mut made, crate::settings::keys::LOOK.name, "essay")
            .unwrap();
        let field = Arc::new(crate::terrain::generate(&made, 5));
        let opened = Mountain {
            field: field.clone(),
            seed: Some(5),
            generated: false,
            recorded: Some(GeneratorParams::from_settings(&made)),
        };
        let drawn = opened.drawn_with(&small_settings());
        assert_eq!(drawn, made);
        let full = |s: &Settings, size: Size| {
            let mut frame = Frame::new(size.width, size.height).unwrap();
            crate::render::render_full(&field, s, &mut frame);
            frame
        };
        let mut show = Show::new(
            small_settings(),
            Some(opened),
            pacing(),
            Size::new(64, 48),
            t0,
        );
        show.tick(t0 + Duration::from_millis(1000));
        assert!(show.frame() == Some(&full(&made, Size::new(64, 48))));
        assert!(show.frame() != Some(&full(show.settings(), Size::new(64, 48))));
        show.resize(Size::new(50, 40), t0);
        show.settle(t0);
        assert!(show.frame() == Some(&full(&made, Size::new(50, 40))));
    }

    #[test]
    fn new_mountain_lets_go_of_an_opened_data_set() {
        let t0 = Instant::now();
        let opened = Mountain {
            field: Arc::new(Heightfield::flat(4, 100.0)),
            seed: None,
            generated: false,
            recorded: None,
        };
        let mut show = Show::new(
            small_settings(),
            Some(opened),
            pacing(),
            Size::new(32, 32),
            t0,
        );
        show.new_mountain(t0);
        let shown = show.current().unwrap();
        assert_eq!((shown.seed, shown.field.exponent()), (Some(7), 5));
    }

    #[test]
    fn an_opened_data_set_stays_on_screen_until_n() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(32, 32), t0);
        let mut field = Heightfield::flat(4, 100.0);
        field.set(3, 3, 9.0);
        let opened = Mountain {
            field: Arc::new(field),
            seed: Some(99),
            generated: false,
            recorded: None,
        };
        assert!(!show.open(opened, t0).is_empty());
        assert_eq!(show.current().unwrap().seed, Some(99));
        show.advance(t0);
        assert_eq!(
            show.current().unwrap().seed,
            Some(99),
            "the next slide shows it again"
        );
        show.new_mountain(t0);
        assert_eq!(show.current().unwrap().seed, Some(7));
    }

    #[test]
    fn terrain_changes_apply_to_the_next_mountain() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(32, 32), t0);
        let mut s = small_settings();
        s.detail = Detail::Level(6);
        assert!(show.change_settings(s, Change::Next, t0).is_empty());
        assert_eq!(show.current().unwrap().field.exponent(), 5);
        show.advance(t0);
        assert_eq!(show.current().unwrap().field.exponent(), 6);
    }

    /// Low Detail remakes the mountain on screen (Mountain Terrain: OK
    /// "redraws the mountains with the options that apply to the current
    /// set (Color, Relative Depth, Low Detail)"): the same seed, a grid of
    /// half the side, made and drawn beside the event loop; a terrain key
    /// changed before it still waits for the next mountain.
    #[test]
    fn low_detail_remakes_the_mountain_on_screen() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(32, 32), t0);
        let before = show.current().unwrap().field.clone();
        let mut s = small_settings();
        s.cragginess = 128;
        show.change_settings(s.clone(), Change::Next, t0);
        s.low_detail = true;
        show.change_settings(s.clone(), Change::Remake, t0);
        show.settle(t0);
        let now = show.current().unwrap();
        assert_eq!((now.seed, now.field.exponent()), (Some(7), 4));
        assert_ne!(now.field.exponent(), before.exponent());
        let title = show.title();
        assert!(title.contains("low detail"), "{title}");
        assert!(!title.contains("cragginess 128"), "{title}");
        let mut expected = Frame::new(32, 32).unwrap();
        let mut made = small_settings();
        made.low_detail = true;
        crate::render::render_full(&now.field, &s, &mut expected);
        assert_eq!(now.field.as_ref(), &crate::terrain::generate(&made, 7));
        assert_eq!(show.frame(), Some(&expected));
    }

    /// While the display is off nothing is drawn or made and nothing
    /// wakes the loop; when it comes back a fresh slide starts at once.
    #[test]
    fn display_off_stops_all_work_and_a_fresh_slide_follows() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(64, 48), t0);
        show.tick(t0 + Duration::from_millis(300));
        let drawn = show.slideshow.strips_done();
        assert!(show.set_display(false, t0).is_empty());
        assert!(show.is_asleep());
        assert_eq!(show.wake_at(t0), None);
        assert!(show.tick(t0 + Duration::from_secs(60)).is_empty());
        assert_eq!(show.slideshow.strips_done(), drawn, "drew while off");
        assert!(
            show.resize(Size::new(80, 60), t0).is_empty(),
            "redrew while off"
        );
        assert!(show.redraw.is_none());
        let t1 = t0 + Duration::from_secs(61);
        let fresh = show.set_display(true, t1);
        assert_eq!(show.slide, 1, "no fresh slide when the display came back");
        assert_eq!((fresh.x1, fresh.y1), (80, 60));
        assert!(show.wake_at(t1).is_some());
    }

    /// On battery with "hold" the next mountain is not made during the
    /// hold, and nothing wakes the loop; when the power returns it is made
    /// and the slide show goes on.
    #[test]
    fn a_power_hold_makes_nothing_until_the_power_returns() {
        let t0 = Instant::now();
        let mut show = Show::new(small_settings(), None, pacing(), Size::new(64, 48), t0);
        show.set_economy(Economy::Hold);
        show.tick(t0 + Duration::from_millis(1000));
        assert!(show.slideshow.is_holding());
        assert!(
            matches!(show.next, Next::None),
            "the next mountain was made"
        );
        assert_eq!(show.wake_at(t0 + Duration::from_secs(1)), None);
        assert!(show.tick(t0 + Duration::from_secs(3600)).is_empty());
        show.set_economy(Economy::None);
        assert!(matches!(show.next, Next::Pending(..)));
        assert!(!show.tick(t0 + Duration::from_secs(3601)).is_empty());
        assert_eq!(show.slide, 1);
    }

    #[test]
    fn a_blank_show_stays_black_and_asleep() {
        let t0 = Instant::now();
        let mut show = Show::blank(Size::new(8, 8), t0);
        assert_eq!(show.wake_at(t0), None);
        assert!(show.tick(t0 + Duration::from_secs(60)).is_empty());
        assert!(show.frame().unwrap().pixels().iter().all(|&p| p == 0));
    }
}
