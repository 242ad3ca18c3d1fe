//! The winit modes: full screen on every monitor, the small preview, the
//! normal window, and (Windows) the child of the Control Panel preview.

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
use super::trace::Trace;
#[cfg(unix)]
use super::x11::grab::Pointer;
use crate::mountain::Mountain;
use crate::render::Damage;
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
    #[cfg(windows)]
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
    /// The monitors are now these (full screen on X11).
    #[cfg_attr(not(unix), allow(dead_code))]
    Heads(Vec<Head>),
    /// The pointer is at this place on the screen (full screen on X11,
    /// from the input grab: warps send no raw motion).
    #[cfg_attr(not(unix), allow(dead_code))]
    PointerAt(i16, i16),
    /// A relative pointing device moved by this much (full screen on X11,
    /// from XInput 2 raw motion: winit's counts absolute devices' places).
    #[cfg_attr(not(unix), allow(dead_code))]
    PointerMoved(f64, f64),
    /// The screen changed and the server may have moved the pointer: it is
    /// here now (full screen on X11, from the input grab's connection).
    #[cfg_attr(not(unix), allow(dead_code))]
    PointerPlaced(i16, i16),
    /// The power or the display's state changed (`watch.rs`).
    Seen(super::watch::Seen),
}

/// Runs `mode` with winit until it ends.
pub fn run(mode: AppMode, settings: Settings, opened: Option<Mountain>) -> Result<(), SaverError> {
    #[cfg(unix)]
    let backend = super::libcheck::check_display(super::options::x_display_named())?;
    #[cfg(target_os = "linux")]
    let _claim = match mode {
        AppMode::Fullscreen => match super::single::claim(backend) {
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
    let mut builder = EventLoop::<UserEvent>::with_user_event();
    #[cfg(windows)]
    if let AppMode::Child(_) = mode {
        super::win32::embed::leave_dpi_to_the_parent(&mut builder);
    }
    #[cfg(unix)]
    let wayland = force_backend(&mut builder, backend);
    #[cfg(not(unix))]
    let wayland = false;
    let event_loop = builder
        .build()
        .map_err(|e| SaverError::from_event_loop(&e.to_string(), wayland))?;
    // Without a window manager our windows never get keyboard focus, so the
    // full-screen saver listens to raw device input instead.
    event_loop.listen_device_events(match mode {
        AppMode::Fullscreen => DeviceEvents::Always,
        _ => DeviceEvents::Never,
    });
    let proxy = event_loop.create_proxy();
    crate::signals::on_terminate(move || {
        let _ = proxy.send_event(UserEvent::Terminate);
    })
    .map_err(|e| SaverError::Other(format!("cannot watch for SIGTERM: {e}")))?;
    #[cfg(unix)]
    let server_heads = match mode {
        AppMode::Fullscreen if !wayland => watch_heads(&event_loop),
        _ => Vec::new(),
    };
    #[cfg(not(unix))]
    let server_heads = Vec::new();
    // X11: the visual and, for full screen, the pointer's place before the
    // windows map: the origin its moves (warps too, which no device
    // reports as raw motion) are measured from.
    #[cfg(unix)]
    let first_look = match wayland {
        true => super::x11::pointer::FirstLook::default(),
        false => super::x11::pointer::first_look(mode == AppMode::Fullscreen),
    };
    #[cfg(unix)]
    if let Some(why) = first_look.refusal {
        return Err(SaverError::Unsupported(why));
    }
    #[cfg(unix)]
    let (x11_visual, pointer_origin) = (first_look.visual, first_look.pointer);
    #[cfg(not(unix))]
    let x11_visual = None;
    let proxy = event_loop.create_proxy();
    let watcher = super::watch::start(wayland, move |seen| {
        let _ = proxy.send_event(UserEvent::Seen(seen));
    });
    let mut app = App {
        mode,
        wayland,
        seen: watcher.seen(),
        settings,
        opened,
        screens: Vec::new(),
        server_heads,
        x11_visual,
        #[cfg(unix)]
        pointer_origin,
        wake: WakeDetector::new(),
        error: None,
        trace: Trace::from_env(),
        started: false,
        #[cfg(unix)]
        grab: None,
        #[cfg(unix)]
        watching_pointer: false,
        #[cfg(unix)]
        raw_motion_watched: false,
        proxy: event_loop.create_proxy(),
    };
    event_loop
        .run_app(&mut app)
        .map_err(|e| SaverError::Other(e.to_string()))?;
    app.error.map_or(Ok(()), Err)
}

/// Makes winit use `backend`, the one whose libraries were checked (winit
/// would choose by itself, without heeding `-display`); true for Wayland.
#[cfg(unix)]
fn force_backend(
    builder: &mut winit::event_loop::EventLoopBuilder<UserEvent>,
    backend: super::backend::Backend,
) -> bool {
    use super::backend::Backend;
    use winit::platform::wayland::EventLoopBuilderExtWayland;
    use winit::platform::x11::EventLoopBuilderExtX11;
    match backend {
        Backend::X11 => builder.with_x11(),
        Backend::Wayland => builder.with_wayland(),
    };
    backend == Backend::Wayland
}

/// X11 full screen: the server's monitors at start and, from then on,
/// `UserEvent::Heads` whenever they change. Without RandR: Xinerama's list,
/// not followed.
#[cfg(unix)]
fn watch_heads(event_loop: &EventLoop<UserEvent>) -> Vec<Head> {
    let proxy = event_loop.create_proxy();
    let watched = super::x11::heads::watch(move |heads| {
        let _ = proxy.send_event(UserEvent::Heads(heads));
    });
    watched.unwrap_or_else(|e| {
        crate::log::warn(&format!("monitor changes will not be followed: {e}"));
        super::x11::heads::query().unwrap_or_default()
    })
}

struct App {
    mode: AppMode,
    /// Running on a Wayland compositor: no window positions, no grabs,
    /// full screen is the compositor's to give.
    wayland: bool,
    settings: Settings,
    opened: Option<Mountain>,
    /// The power and the display's state, as last seen (`watch.rs`).
    seen: super::watch::Seen,
    screens: Vec<Screen>,
    /// The monitors the X server listed at start (empty: ask winit).
    server_heads: Vec<Head>,
    /// The X visual windows are made with, when not the screen's own.
    x11_visual: Option<u32>,
    /// X11 full screen: the pointer's place before the windows opened.
    #[cfg(unix)]
    pointer_origin: Option<(f64, f64)>,
    wake: WakeDetector,
    error: Option<SaverError>,
    trace: Trace,
    started: bool,
    /// Full screen on X11: the keyboard and pointer grab, until it holds.
    #[cfg(unix)]
    grab: Option<super::x11::grab::InputGrab>,
    /// Whether the grab's pointer motion is passed on yet.
    #[cfg(unix)]
    watching_pointer: bool,
    /// Whether relative devices' raw motion comes from the grab's thread
    /// (`UserEvent::PointerMoved`), so winit's own is not counted.
    #[cfg(unix)]
    raw_motion_watched: bool,
    /// For events from threads of our own (the grab's pointer motion).
    #[cfg_attr(not(unix), allow(dead_code))]
    proxy: winit::event_loop::EventLoopProxy<UserEvent>,
}

impl ApplicationHandler<UserEvent> for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if std::mem::replace(&mut self.started, true) {
            return;
        }
        #[cfg(unix)]
        if let Some((x, y)) = self.pointer_origin.take() {
            self.wake.moved_to(x, y);
        }
        if let Err(e) = self.open_windows(event_loop) {
            self.fail(event_loop, e);
        }
        // The cursor's place at start is the origin a move is measured
        // from. Taken lazily, a move that arrives before the first motion
        // event (Wine may deliver none until then) would become the origin.
        #[cfg(windows)]
        if self.mode == AppMode::Fullscreen
            && let Some((x, y)) = super::win32::fullscreen::cursor_position()
        {
            self.wake.moved_to(x.into(), y.into());
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
            #[cfg(unix)]
            WindowEvent::ScaleFactorChanged {
                mut inner_size_writer,
                ..
            } if !self.wayland => {
                if let Some(h) = self.screens[i].head {
                    let size = PhysicalSize::new(h.width, h.height);
                    let _ = inner_size_writer.request_inner_size(size);
                }
            }
            WindowEvent::RedrawRequested => self.present_all(event_loop, i),
            WindowEvent::KeyboardInput { event, .. }
                if event.state == ElementState::Pressed && !event.repeat =>
            {
                self.key(event_loop, i, &event.logical_key)
            }
            // Raw motion may not arrive (Wine before its first one); the
            // window's own pointer event is the second witness.
            #[cfg(windows)]
            WindowEvent::CursorMoved { .. } if self.mode == AppMode::Fullscreen => {
                self.cursor_moved_win32(event_loop);
            }
            // Wayland sends no raw motion without the relative-pointer
            // protocol; the pointer's place on our window tells as well.
            WindowEvent::CursorMoved { position, .. }
                if self.mode == AppMode::Fullscreen
                    && self.wayland
                    && self.wake.moved_to(position.x, position.y) =>
            {
                self.trace.ended_by(&event);
                event_loop.exit()
            }
            // X11: raw motion misses a warped pointer (`xdotool mousemove`,
            // remote desktops); the pointer's place on the screen does not.
            // Once the grab reports the pointer in root coordinates
            // (`UserEvent::PointerAt`) this witness stands down: its place
            // is relative to a window, and a window a monitor change moved
            // would turn a pointer that stayed into a move.
            #[cfg(unix)]
            WindowEvent::CursorMoved { position, .. }
                if self.mode == AppMode::Fullscreen && !self.wayland && !self.watching_pointer =>
            {
                let window = self.screens[i].window.inner_position();
                if let Ok(at) = window
                    && self
                        .wake
                        .moved_to(f64::from(at.x) + position.x, f64::from(at.y) + position.y)
                {
                    self.trace.ended_by(&event);
                    event_loop.exit()
                }
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
        #[cfg(windows)]
        if let (AppMode::Fullscreen, DeviceEvent::MouseMotion { .. }) = (self.mode, &event) {
            // winit passes absolute devices' coordinates on as deltas, and
            // Wine sends one such motion when the window appears: the
            // cursor's position is what counts.
            if self.cursor_moved_win32(event_loop) {
                return;
            }
        }
        #[cfg(unix)]
        if self.raw_motion_watched && matches!(event, DeviceEvent::MouseMotion { .. }) {
            return;
        }
        if self.mode == AppMode::Fullscreen && self.wake.device_event(&event) {
            self.trace.ended_by(&event);
            event_loop.exit();
        }
    }

    fn user_event(&mut self, event_loop: &ActiveEventLoop, event: UserEvent) {
        match event {
            UserEvent::Terminate => self.end_on_signal(event_loop),
            UserEvent::Heads(heads) => self.follow_heads(event_loop, &heads),
            UserEvent::PointerAt(x, y) => {
                if self.mode == AppMode::Fullscreen && self.wake.moved_to(x.into(), y.into()) {
                    self.trace.ended_by(&event);
                    event_loop.exit()
                }
            }
            UserEvent::PointerMoved(dx, dy) => {
                if self.mode == AppMode::Fullscreen && self.wake.moved(dx, dy) {
                    self.trace.ended_by(&event);
                    event_loop.exit()
                }
            }
            UserEvent::PointerPlaced(x, y) => {
                self.trace
                    .note(&format!("the screen changed; the pointer is at ({x}, {y})"));
                self.wake.origin_at(x.into(), y.into())
            }
            UserEvent::Seen(seen) => self.follow_seen(event_loop, seen),
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if crate::signals::ending() {
            return self.end_on_signal(event_loop);
        }
        let now = Instant::now();
        for i in 0..self.screens.len() {
            let damage = self.screens[i].show.tick(now);
            // The slide show moves on by itself: the title follows.
            self.update_title(i);
            self.present(event_loop, i, damage);
        }
        // A signal while strips were drawn: they stopped for it.
        if crate::signals::ending() {
            return self.end_on_signal(event_loop);
        }
        #[cfg(windows)]
        if let AppMode::Child(parent) = self.mode {
            self.follow_parent(event_loop, parent);
        }
        #[cfg(unix)]
        let grabbing = self.grab_input();
        #[cfg(not(unix))]
        let grabbing = false;
        // Wake for the earliest of: a show's next strip or slide, the
        // Windows preview's look at its parent, a retry of the input grab.
        let shows = self
            .screens
            .iter()
            .filter_map(|s| s.show.wake_at(now))
            .min();
        #[cfg(windows)]
        let parent =
            matches!(self.mode, AppMode::Child(_)).then(|| now + super::win32::embed::PARENT_POLL);
        #[cfg(not(windows))]
        let parent = None;
        let grab = grabbing.then(|| now + super::slideshow::FRAME_INTERVAL);
        let wake = [shows, parent, grab].into_iter().flatten().min();
        event_loop.set_control_flow(wake.map_or(ControlFlow::Wait, ControlFlow::WaitUntil));
    }
}

/// Every window's title and name: the Wayland app_id and the X11 class are
/// "mountains", as the desktop entry is named.
/// `x11_visual`: the visual to draw with on an X screen whose own one
/// softbuffer cannot take (see x11_visual.rs).
fn base_attributes(x11_visual: Option<u32>) -> WindowAttributes {
    let attrs = Window::default_attributes().with_title("mountains");
    #[cfg(unix)]
    let attrs = winit::platform::wayland::WindowAttributesExtWayland::with_name(
        attrs,
        "mountains",
        "mountains",
    );
    #[cfg(unix)]
    let attrs = match x11_visual {
        Some(id) => winit::platform::x11::WindowAttributesExtX11::with_x11_visual(attrs, id),
        None => attrs,
    };
    #[cfg(not(unix))]
    let _ = x11_visual;
    attrs
}

impl App {
    /// Full screen: grabs keyboard and pointer for the first window; true
    /// while the grab is still being attempted.
    #[cfg(unix)]
    fn grab_input(&mut self) -> bool {
        if self.mode != AppMode::Fullscreen {
            return false;
        }
        if self.grab.is_none() {
            let xid = self
                .screens
                .first()
                .and_then(|s| super::present::x11_window_id(&*s.window));
            match xid {
                Some(xid) => self.grab = Some(super::x11::grab::InputGrab::new(xid)),
                None => return false,
            }
        }
        let Some(grab) = self.grab.as_mut() else {
            return false;
        };
        let held = grab.try_grab();
        if held && !self.watching_pointer {
            self.watching_pointer = true;
            let proxy = self.proxy.clone();
            self.raw_motion_watched = grab.watch_motion(move |pointer| {
                let event = match pointer {
                    Pointer::At(x, y) => UserEvent::PointerAt(x, y),
                    Pointer::Moved(dx, dy) => UserEvent::PointerMoved(dx, dy),
                    Pointer::Placed(x, y) => UserEvent::PointerPlaced(x, y),
                };
                let _ = proxy.send_event(event);
            });
        }
        !held
    }

    /// SIGTERM, SIGINT or SIGHUP: the handler's flag or the watcher's
    /// notice, whichever the loop sees first.
    fn end_on_signal(&mut self, event_loop: &ActiveEventLoop) {
        if !event_loop.exiting() {
            self.trace.ended_by(&UserEvent::Terminate);
            event_loop.exit();
        }
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, error: SaverError) {
        self.error.get_or_insert(error);
        event_loop.exit();
    }

    /// Full screen on Windows: ends the saver if the cursor is further than
    /// the threshold from where it started. False when its place is unknown.
    #[cfg(windows)]
    fn cursor_moved_win32(&mut self, event_loop: &ActiveEventLoop) -> bool {
        if super::win32::fullscreen::take_display_change() {
            self.wake.reset_origin();
        }
        let Some((x, y)) = super::win32::fullscreen::cursor_position() else {
            return false;
        };
        if self.wake.moved_to(x.into(), y.into()) {
            self.trace.ended_by(&(x, y));
            event_loop.exit();
        }
        true
    }

    fn open_windows(&mut self, event_loop: &ActiveEventLoop) -> Result<(), SaverError> {
        let base = base_attributes(self.x11_visual);
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
            #[cfg(windows)]
            AppMode::Child(parent) => {
                let matched = super::win32::embed::match_parent_dpi(parent);
                self.trace
                    .note(&format!("preview DPI awareness as the parent's: {matched}"));
                let attrs = super::win32::embed::child_attributes(base, parent)?;
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
        let found = find_heads(event_loop, &self.server_heads, self.wayland);
        if found.is_empty() {
            let attrs = base
                .with_decorations(false)
                .with_fullscreen(Some(winit::window::Fullscreen::Borderless(None)));
            return self.add_screen(event_loop, attrs, true, None);
        }
        for (head, monitor) in found {
            self.open_head(event_loop, base.clone(), head, monitor.as_ref())?;
        }
        Ok(())
    }

    fn open_head(
        &mut self,
        event_loop: &ActiveEventLoop,
        base: WindowAttributes,
        head: Head,
        monitor: Option<&MonitorHandle>,
    ) -> Result<(), SaverError> {
        let mountain = self.settings.monitors == Monitors::All || head.primary;
        let attrs = covering(base, &head, monitor, self.wayland);
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
        #[cfg(unix)]
        let placed_by_grab = self.watching_pointer;
        #[cfg(not(unix))]
        let placed_by_grab = false;
        if !placed_by_grab {
            self.wake.reset_origin();
        }
        for change in heads::plan(&old, new) {
            match change {
                Change::Fit(i, head) => self.fit(event_loop, i, head),
                Change::Close(i) => drop(self.screens.remove(i)),
                Change::Open(head) => {
                    let base = base_attributes(self.x11_visual);
                    if let Err(e) = self.open_head(event_loop, base, head, None) {
                        crate::log::warn(&format!("cannot cover a new monitor: {e}"));
                    }
                }
            }
        }
    }

    /// Every show follows the power and the display's state.
    fn follow_seen(&mut self, event_loop: &ActiveEventLoop, seen: super::watch::Seen) {
        self.seen = seen;
        let now = Instant::now();
        for i in 0..self.screens.len() {
            let damage = super::watch::apply(seen, &mut self.screens[i].show, now);
            self.present(event_loop, i, damage.into());
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
        // winit taps Alt for every window created full screen (Windows).
        #[cfg(windows)]
        if attrs.fullscreen.is_some() {
            self.wake.expect_injected_alt();
        }
        let window = event_loop.create_window(attrs).map_err(|e| {
            let e = super::without_source_place(&e.to_string());
            SaverError::Other(format!("cannot create a window: {e}"))
        })?;
        let window = Rc::new(window);
        if self.mode == AppMode::Fullscreen {
            window.set_cursor_visible(false);
            #[cfg(windows)]
            super::win32::fullscreen::keep_covering(&window);
        }
        let size = window.inner_size();
        let size = (size.width, size.height);
        let presenter = Presenter::new(window.clone())
            .map_err(|e| SaverError::Other(format!("cannot draw in the window: {e}")))?;
        let now = Instant::now();
        let mut show = if mountain {
            let pacing = Pacing::from_seconds(
                self.settings.draw_seconds,
                self.settings.pause_seconds,
                self.mode != AppMode::Window || self.settings.auto_redraw,
            );
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
        if screen.show.size() == (size.width, size.height) {
            return;
        }
        let damage = screen
            .show
            .resize((size.width, size.height), Instant::now());
        self.present(event_loop, i, damage.into());
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
                cfg!(windows) && *key == Key::Named(winit::keyboard::NamedKey::Alt);
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

    /// The preview child follows its parent's size and dies with it.
    #[cfg(windows)]
    fn follow_parent(&mut self, event_loop: &ActiveEventLoop, parent: u64) {
        use super::win32::embed::{follow_parent, parent_alive};
        let alive = match self.screens.first() {
            Some(s) => follow_parent(parent, &s.window),
            None => parent_alive(parent),
        };
        if !alive {
            self.trace.ended_by(&"the parent window is gone");
            event_loop.exit();
        }
    }
}
