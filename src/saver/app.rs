//! The winit modes: full screen on every monitor, the small preview, the
//! normal window, and (Windows) the child of the Control Panel preview.

use std::fmt::Debug;
use std::rc::Rc;
use std::time::Instant;

use winit::application::ApplicationHandler;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event::{DeviceEvent, DeviceId, ElementState, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, DeviceEvents, EventLoop};
use winit::keyboard::Key;
use winit::monitor::MonitorHandle;
use winit::window::{Window, WindowAttributes, WindowId};

use super::error::SaverError;
use super::heads::{self, Change, Head};
use super::input::{Action, WakeDetector, action_for_key};
use super::placement::{covering, find_heads};
use super::present::Presenter;
use super::screen::Screen;
use super::show::Show;
use super::slideshow::Pacing;
use super::span::Span;
use super::trace::Trace;
use crate::mountain::Mountain;
use crate::platform::events::{Motion, Notice, Notify};
use crate::platform::{self, Host};
use crate::render::{Damage, Size};
use crate::settings::{Monitors, Settings};

/// Which kind of winit window to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AppMode {
    /// One borderless window per monitor; input ends it.
    Fullscreen,
    /// A small stand-alone window (`/p` without a parent).
    Preview,
    /// A normal resizable window with the keyboard commands.
    Window,
    /// A child of a Windows window (`/p HWND`), following its size.
    Child(u64),
}

/// Size of the stand-alone preview: the Control Panel's little monitor, doubled.
const PREVIEW_SIZE: PhysicalSize<u32> = PhysicalSize::new(320, 240);
/// First size of the normal window.
const WINDOW_SIZE: PhysicalSize<u32> = PhysicalSize::new(960, 600);

/// Wakes the event loop from other threads.
#[derive(Debug, Clone)]
enum UserEvent {
    /// SIGTERM or SIGINT arrived.
    Terminate,
    /// News from a platform room's thread.
    Platform(Notice),
    /// The power or the display's state changed (`watch.rs`).
    Seen(super::watch::Seen),
}

impl Notify for winit::event_loop::EventLoopProxy<UserEvent> {
    fn notify(&self, notice: Notice) {
        let _ = self.send_event(UserEvent::Platform(notice));
    }
}

/// Runs `mode` with winit until it ends.
pub fn run(mode: AppMode, settings: Settings, opened: Option<Mountain>) -> Result<(), SaverError> {
    let backend = platform::choose_backend(super::options::x_display_named())?;
    let _claim = match mode {
        AppMode::Fullscreen => match platform::claim_display(backend) {
            Ok(Some(claim)) => Some(claim),
            Ok(None) => {
                crate::console::err(
                    "mountains: a full-screen saver already runs on this display; not starting another",
                );
                return Ok(());
            }
            Err(e) => {
                crate::log::warn(&format!("a second /s could start over this one: {e}"));
                None
            }
        },
        _ => None,
    };
    let parent = match mode {
        AppMode::Child(parent) => Some(parent),
        _ => None,
    };
    let mut builder = EventLoop::<UserEvent>::with_user_event();
    platform::use_backend(&mut builder, backend, parent);
    let event_loop = builder
        .build()
        .map_err(|e| platform::event_loop_failed(&e.to_string(), backend))?;
    // Without a window manager our windows never get keyboard focus, so the
    // full-screen saver listens to raw device input instead.
    event_loop.listen_device_events(match mode {
        AppMode::Fullscreen => DeviceEvents::Always,
        _ => DeviceEvents::Never,
    });
    let proxy = event_loop.create_proxy();
    crate::platform::signals::on_terminate(move || {
        let _ = proxy.send_event(UserEvent::Terminate);
    })
    .map_err(|e| SaverError::Other(format!("cannot watch for SIGTERM: {e}")))?;
    let fullscreen = mode == AppMode::Fullscreen;
    let host = Host::new(backend, fullscreen, parent, event_loop.create_proxy())?;
    let proxy = event_loop.create_proxy();
    let watcher = platform::watch_power_and_display(backend, move |seen| {
        let _ = proxy.send_event(UserEvent::Seen(seen));
    });
    let mut app = App {
        mode,
        host,
        seen: watcher.seen(),
        settings,
        opened,
        screens: Vec::new(),
        span: None,
        wake: WakeDetector::new(),
        error: None,
        trace: Trace::from_env(),
        started: false,
    };
    event_loop
        .run_app(&mut app)
        .map_err(|e| SaverError::Other(e.to_string()))?;
    app.error.map_or(Ok(()), Err)
}

struct App {
    mode: AppMode,
    /// What the window system asks of this run and knows for it.
    host: Host<winit::event_loop::EventLoopProxy<UserEvent>>,
    settings: Settings,
    opened: Option<Mountain>,
    /// The power and the display's state, as last seen (`watch.rs`).
    seen: super::watch::Seen,
    screens: Vec<Screen>,
    /// `monitors = "span"`: the one show the windows show their parts of.
    span: Option<Span>,
    wake: WakeDetector,
    error: Option<SaverError>,
    trace: Trace,
    started: bool,
}

impl ApplicationHandler<UserEvent> for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if std::mem::replace(&mut self.started, true) {
            return;
        }
        if let Err(e) = self.open_windows(event_loop) {
            self.fail(event_loop, e);
        }
        // The pointer's place at start is the origin a move is measured
        // from: taken before any event, so that no move becomes it.
        if let Some((x, y)) = self.host.start_origin() {
            self.wake.moved_to(x, y);
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, id: WindowId, event: WindowEvent) {
        let Some(i) = self.screens.iter().position(|s| s.window.id() == id) else {
            return;
        };
        match event {
            WindowEvent::CloseRequested | WindowEvent::Destroyed => {
                self.trace.ended_by(&event);
                event_loop.exit()
            }
            WindowEvent::Resized(size) => self.resize(event_loop, i, size),
            // winit scales a window it thinks moved to a monitor of another
            // scale (after RandR or Xft.dpi changes); a full-screen window
            // keeps covering its monitor exactly.
            WindowEvent::ScaleFactorChanged {
                mut inner_size_writer,
                ..
            } if self.host.keeps_size_on_rescale() => {
                if let Some(h) = self.screens[i].head {
                    let size = PhysicalSize::new(h.width, h.height);
                    let _ = inner_size_writer.request_inner_size(size);
                }
            }
            WindowEvent::RedrawRequested => self.present_all(event_loop, i),
            // Not the presses winit makes up for keys held as the window
            // takes the focus (the Tab of an Alt+Tab, the key of a
            // command that opened it): no one pressed them here.
            WindowEvent::KeyboardInput {
                event,
                is_synthetic: false,
                ..
            } if event.state == ElementState::Pressed && !event.repeat => {
                self.key(event_loop, i, &event.logical_key)
            }
            // The pointer's place on our window: a second witness beside
            // raw motion, which misses some moves (see `Host::cursor_moved`).
            WindowEvent::CursorMoved { position, .. } if self.mode == AppMode::Fullscreen => {
                let window = &*self.screens[i].window;
                let motion = self.host.cursor_moved(window, position, &mut self.wake);
                self.end_on_motion(event_loop, motion, &event);
            }
            WindowEvent::MouseInput {
                state: ElementState::Pressed,
                ..
            }
            | WindowEvent::MouseWheel { .. }
                if self.mode == AppMode::Fullscreen =>
            {
                self.trace.ended_by(&event);
                event_loop.exit()
            }
            _ => {}
        }
    }

    fn device_event(&mut self, event_loop: &ActiveEventLoop, _: DeviceId, event: DeviceEvent) {
        if let (AppMode::Fullscreen, DeviceEvent::MouseMotion { .. }) = (self.mode, &event) {
            match self.host.motion(&mut self.wake) {
                Motion::Raw => {}
                motion => return self.end_on_motion(event_loop, motion, &event),
            }
        }
        if self.mode == AppMode::Fullscreen && self.wake.device_event(&event) {
            self.trace.ended_by(&event);
            event_loop.exit();
        }
    }

    fn user_event(&mut self, event_loop: &ActiveEventLoop, event: UserEvent) {
        match event {
            UserEvent::Terminate => self.end_on_signal(event_loop),
            UserEvent::Platform(notice) => self.notice(event_loop, notice),
            UserEvent::Seen(seen) => self.follow_seen(event_loop, seen),
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if crate::platform::signals::ending() {
            return self.end_on_signal(event_loop);
        }
        let now = Instant::now();
        self.tick_span(event_loop, now);
        for i in 0..self.screens.len() {
            let damage = self.screens[i].show.tick(now);
            // The slide show moves on by itself: the title follows.
            self.update_title(i);
            self.present(event_loop, i, damage);
        }
        // A signal while strips were drawn: they stopped for it.
        if crate::platform::signals::ending() {
            return self.end_on_signal(event_loop);
        }
        let first = self.screens.first().map(|s| &*s.window);
        let tick = self.host.tick(first, now);
        if tick.parent_gone {
            self.trace.ended_by(&"the parent window is gone");
            event_loop.exit();
        }
        // Wake for the earliest of: a show's next strip or slide, what the
        // platform asks (the Windows preview's look at its parent, a retry
        // of the X11 input grab).
        let shows = self
            .screens
            .iter()
            .filter_map(|s| s.show.wake_at(now))
            .chain(self.span.as_ref().and_then(|s| s.wake_at(now)))
            .min();
        let wake = [shows, tick.wake_at].into_iter().flatten().min();
        event_loop.set_control_flow(wake.map_or(ControlFlow::Wait, ControlFlow::WaitUntil));
    }
}

impl App {
    /// News from a platform room: the monitors changed, or the pointer
    /// moved (full screen on X11, from the input grab: warps send no raw
    /// motion, and winit counts absolute devices' places).
    fn notice(&mut self, event_loop: &ActiveEventLoop, notice: Notice) {
        let fullscreen = self.mode == AppMode::Fullscreen;
        let away = match notice {
            Notice::Heads(ref heads) => return self.follow_heads(event_loop, heads),
            Notice::PointerAt(x, y) => fullscreen && self.wake.moved_to(x.into(), y.into()),
            Notice::PointerMoved(dx, dy) => fullscreen && self.wake.moved(dx, dy),
            Notice::PointerPlaced(x, y) => {
                self.trace
                    .note(&format!("the screen changed; the pointer is at ({x}, {y})"));
                return self.wake.origin_at(x.into(), y.into());
            }
        };
        if away {
            self.trace.ended_by(&notice);
            event_loop.exit()
        }
    }

    /// SIGTERM, SIGINT or SIGHUP: the handler's flag or the watcher's
    /// notice, whichever the loop sees first.
    fn end_on_signal(&mut self, event_loop: &ActiveEventLoop) {
        if !event_loop.exiting() {
            self.trace.ended_by(&UserEvent::Terminate);
            event_loop.exit();
        }
    }

    /// Ends the saver if `motion` says the pointer went away (`event`
    /// showed it, or the cursor's place).
    fn end_on_motion(&mut self, event_loop: &ActiveEventLoop, motion: Motion, event: &dyn Debug) {
        match motion {
            Motion::Raw | Motion::Handled => return,
            Motion::MovedTo(x, y) => self.trace.ended_by(&(x, y)),
            Motion::Away => self.trace.ended_by(event),
        }
        event_loop.exit();
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, error: SaverError) {
        self.error.get_or_insert(error);
        event_loop.exit();
    }

    fn open_windows(&mut self, event_loop: &ActiveEventLoop) -> Result<(), SaverError> {
        let base = self.base_attributes();
        match self.mode {
            AppMode::Fullscreen => self.open_fullscreen(event_loop, base),
            AppMode::Preview => {
                let attrs = base.with_inner_size(PREVIEW_SIZE).with_resizable(false);
                self.add_screen(event_loop, attrs, true, None)
            }
            AppMode::Window => {
                let attrs = base.with_inner_size(WINDOW_SIZE);
                self.add_screen(event_loop, attrs, true, None)
            }
            AppMode::Child(_) => {
                let attrs = self.host.child_attributes(base, &self.trace)?;
                self.add_screen(event_loop, attrs, true, None)
            }
        }
    }

    /// One borderless window per monitor; with `Monitors::Primary` the
    /// others stay black.
    fn open_fullscreen(
        &mut self,
        event_loop: &ActiveEventLoop,
        base: WindowAttributes,
    ) -> Result<(), SaverError> {
        let found = find_heads(event_loop, self.host.server_heads(), self.host.wayland());
        if found.is_empty() {
            let attrs = base
                .with_decorations(false)
                .with_fullscreen(Some(winit::window::Fullscreen::Borderless(None)));
            return self.add_screen(event_loop, attrs, true, None);
        }
        for (head, monitor) in &found {
            self.open_head(event_loop, base.clone(), *head, monitor.as_ref())?;
        }
        self.lay_span(event_loop);
        Ok(())
    }

    fn open_head(
        &mut self,
        event_loop: &ActiveEventLoop,
        base: WindowAttributes,
        head: Head,
        monitor: Option<&MonitorHandle>,
    ) -> Result<(), SaverError> {
        let mountain = match self.settings.monitors {
            Monitors::All => true,
            Monitors::Primary => head.primary,
            Monitors::Span => false,
        };
        let attrs = covering(base, &head, monitor, self.host.wayland());
        self.add_screen(event_loop, attrs, mountain, Some(head))
    }

    /// The monitors changed while running: windows move and resize to
    /// their new places (a resize redraws for the new size), windows of
    /// monitors that went close, new monitors get a window.
    fn follow_heads(&mut self, event_loop: &ActiveEventLoop, new: &[Head]) {
        let old: Vec<Head> = self.screens.iter().filter_map(|s| s.head).collect();
        if self.mode != AppMode::Fullscreen || old.len() != self.screens.len() {
            return;
        }
        // The server may have moved the pointer onto a monitor that stays.
        // The grab's connection says where (`UserEvent::PointerPlaced`);
        // without it, the next place is the new origin. (With it, that
        // next place would be the person's first move, not counted.)
        if !self.host.pointer_placed() {
            self.wake.reset_origin();
        }
        for change in heads::plan(&old, new) {
            match change {
                Change::Fit(i, head) => self.fit(event_loop, i, head),
                Change::Close(i) => drop(self.screens.remove(i)),
                Change::Open(head) => {
                    let base = self.base_attributes();
                    if let Err(e) = self.open_head(event_loop, base, head, None) {
                        crate::log::warn(&format!("cannot cover a new monitor: {e}"));
                    }
                }
            }
        }
        if self.span.is_none() {
            self.lay_span(event_loop);
            return;
        }
        // The slide on screen stays where it is, each window showing what
        // it can of it; the span is laid again when the next slide begins
        // (`tick_span`), not in the middle of one.
        for i in 0..self.screens.len() {
            self.paint_span(event_loop, i, None);
        }
    }

    /// The monitors the windows cover now.
    fn span_heads(&self) -> Vec<Head> {
        self.screens.iter().filter_map(|s| s.head).collect()
    }

    /// `monitors = "span"`: one show over the bounding rectangle of the
    /// windows' monitors (again, as a new slide, when they changed), each
    /// window showing its part.
    fn lay_span(&mut self, event_loop: &ActiveEventLoop) {
        if self.settings.monitors != Monitors::Span || self.mode != AppMode::Fullscreen {
            return;
        }
        let heads = self.span_heads();
        if self.span.as_ref().is_some_and(|s| s.laid_for(&heads)) {
            return;
        }
        let (settings, opened, pacing) = (&self.settings, &self.opened, self.pacing());
        let seen = self.seen;
        self.span = Span::new(&heads, |size| {
            let now = Instant::now();
            let mut show =
                super::options::new_show(settings.clone(), opened.clone(), pacing, size, now);
            super::watch::apply(seen, &mut show, now);
            show
        });
        for i in 0..self.screens.len() {
            self.paint_span(event_loop, i, None);
        }
    }

    /// Copies the span's new pixels (`damage`, or all of them) into window
    /// `i` and presents them.
    fn paint_span(&mut self, event_loop: &ActiveEventLoop, i: usize, damage: Option<&Damage>) {
        let Some(span) = &self.span else { return };
        let screen = &mut self.screens[i];
        let changed = match damage {
            Some(d) => span.paint(screen, d),
            None => span.paint_all(screen),
        };
        self.present(event_loop, i, changed);
    }

    fn tick_span(&mut self, event_loop: &ActiveEventLoop, now: Instant) {
        let heads = self.span_heads();
        let Some(span) = self.span.as_mut() else {
            return;
        };
        let slide = span.slide();
        let damage = span.tick(now);
        if span.slide() != slide && !span.laid_for(&heads) {
            // A new slide begins and the monitors changed during the last:
            // it begins over the monitors there are now.
            self.lay_span(event_loop);
            return;
        }
        for i in 0..self.screens.len() {
            self.paint_span(event_loop, i, Some(&damage));
        }
    }

    /// How the slide shows move on in this mode.
    fn pacing(&self) -> Pacing {
        Pacing::from_seconds(
            self.settings.draw_seconds,
            self.settings.pause_seconds,
            self.mode != AppMode::Window || self.settings.auto_redraw,
        )
    }

    /// Every show follows the power and the display's state.
    fn follow_seen(&mut self, event_loop: &ActiveEventLoop, seen: super::watch::Seen) {
        self.seen = seen;
        let now = Instant::now();
        for i in 0..self.screens.len() {
            let damage = super::watch::apply(seen, &mut self.screens[i].show, now);
            self.present(event_loop, i, damage.into());
        }
        let span_changed = self.span.as_mut().map(|span| span.follow(seen, now));
        if span_changed.is_some_and(|changed| !changed.is_empty()) {
            for i in 0..self.screens.len() {
                self.paint_span(event_loop, i, None);
            }
        }
    }

    fn fit(&mut self, event_loop: &ActiveEventLoop, i: usize, head: Head) {
        let screen = &mut self.screens[i];
        screen.head = Some(head);
        screen
            .window
            .set_outer_position(PhysicalPosition::new(head.x, head.y));
        let asked = PhysicalSize::new(head.width, head.height);
        // X11 answers with a Resized event; a platform that resizes at once
        // says so here.
        if let Some(size) = screen.window.request_inner_size(asked) {
            self.resize(event_loop, i, size);
        }
    }

    fn add_screen(
        &mut self,
        event_loop: &ActiveEventLoop,
        attrs: WindowAttributes,
        mountain: bool,
        head: Option<Head>,
    ) -> Result<(), SaverError> {
        // Before creating: the injected Alt may be read before create_window returns.
        if platform::FULLSCREEN_TAPS_ALT && attrs.fullscreen.is_some() {
            self.wake.expect_injected_alt();
        }
        let window = event_loop.create_window(attrs).map_err(|e| {
            let e = super::without_source_place(&e.to_string());
            SaverError::Other(format!("cannot create a window: {e}"))
        })?;
        let window = Rc::new(window);
        if self.mode == AppMode::Fullscreen {
            window.set_cursor_visible(false);
            platform::keep_covering(&window);
        }
        let size = window.inner_size();
        let size = Size::new(size.width, size.height);
        let presenter = Presenter::new(window.clone())
            .map_err(|e| SaverError::Other(format!("cannot draw in the window: {e}")))?;
        let now = Instant::now();
        let mut show = if mountain {
            let pacing = self.pacing();
            super::options::new_show(
                self.settings.clone(),
                self.opened.clone(),
                pacing,
                size,
                now,
            )
        } else {
            Show::blank(size, now)
        };
        super::watch::apply(self.seen, &mut show, now);
        self.screens
            .push(Screen::new(window, presenter, show, head));
        let i = self.screens.len() - 1;
        self.update_title(i);
        self.present_all(event_loop, i);
        Ok(())
    }

    fn resize(&mut self, event_loop: &ActiveEventLoop, i: usize, size: PhysicalSize<u32>) {
        let screen = &mut self.screens[i];
        let size = Size::new(size.width, size.height);
        if screen.show.size() == size {
            return;
        }
        let damage = screen.show.resize(size, Instant::now());
        self.present(event_loop, i, damage.into());
        self.paint_span(event_loop, i, None);
    }

    fn present_all(&mut self, event_loop: &ActiveEventLoop, i: usize) {
        let bounds = self.screens[i].bounds();
        self.present(event_loop, i, bounds.into());
    }

    fn present(&mut self, event_loop: &ActiveEventLoop, i: usize, damage: Damage) {
        match self.screens[i].present(&damage) {
            Ok(true) => self.trace.presented(),
            Ok(false) => {}
            Err(e) => self.fail(event_loop, SaverError::Other(e)),
        }
    }

    fn key(&mut self, event_loop: &ActiveEventLoop, i: usize, key: &Key) {
        if self.mode == AppMode::Fullscreen {
            // Windows: raw input (`device_event`) sees every key and knows
            // winit's injected Alt; here an Alt could be that tap, so only
            // the other keys end it (in case raw input is not working).
            let maybe_injected =
                platform::FULLSCREEN_TAPS_ALT && *key == Key::Named(winit::keyboard::NamedKey::Alt);
            if !maybe_injected {
                self.trace.ended_by(key);
                event_loop.exit();
            }
            return;
        }
        if let Some(action) = action_for_key(key) {
            self.act(event_loop, i, action);
        }
    }

    fn act(&mut self, event_loop: &ActiveEventLoop, i: usize, action: Action) {
        // Tests tell a key the saver got from one lost on its way.
        self.trace.note(&format!("key: {action:?}"));
        let Some(damage) = self.screens[i].act(action, Instant::now()) else {
            event_loop.exit();
            return;
        };
        self.update_title(i);
        self.present(event_loop, i, damage.into());
    }

    /// The window title tells the seed (to reproduce a mountain) and the
    /// state of the mountain on screen; sent only when it changes.
    fn update_title(&mut self, i: usize) {
        if self.mode == AppMode::Window {
            self.screens[i].update_title();
        }
    }

    /// Every window's title, and what the platform adds to it.
    fn base_attributes(&self) -> WindowAttributes {
        let attrs = Window::default_attributes().with_title("mountains");
        self.host.window_attributes(attrs)
    }
}
