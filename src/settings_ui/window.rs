//! The settings window: winit events in, `Screen` frames out via softbuffer.

use std::num::NonZeroU32;
use std::rc::Rc;
use std::time::{Duration, Instant};

use winit::application::ApplicationHandler;
use winit::dpi::{LogicalSize, PhysicalPosition, PhysicalSize};
use winit::event::{ElementState, KeyEvent, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key, ModifiersState, NamedKey};
use winit::window::{Window, WindowId};

use crate::platform::{self, Backend};
use crate::render::Size;

use super::layout::{MIN_H, MIN_W, WINDOW_H, WINDOW_W, whole_scale, window_size};
use super::model::Input;
use super::screen::{Next, Screen};

/// How often the preferences file is checked for outside edits.
const FILE_POLL: Duration = Duration::from_millis(700);

/// Builds the `Screen` once the window's size and scale are known.
pub type MakeScreen = Box<dyn FnOnce(Size, u32) -> Screen>;

struct App {
    make: Option<MakeScreen>,
    parent: Option<u64>,
    backend: Backend,
    window: Option<Rc<Window>>,
    surface: Option<softbuffer::Surface<Rc<Window>, Rc<Window>>>,
    screen: Option<Screen>,
    modifiers: ModifiersState,
    cursor: PhysicalPosition<f64>,
    wheel_pixels: f64,
    scale: u32,
    error: Option<String>,
}

/// Opens the window on `backend` (the saver's choice,
/// `platform::choose_backend`) and runs it until OK or Cancel. `parent`
/// is the window that owns the dialog on Windows (`/c:<HWND>`).
pub fn run(make: MakeScreen, parent: Option<u64>, backend: Backend) -> Result<(), String> {
    let mut builder = EventLoop::<Terminate>::with_user_event();
    platform::use_backend(&mut builder, backend, None);
    // Why it could not start in the saver's words: which display was
    // named and why it cannot be opened, not a place in winit's source.
    let event_loop = builder
        .build()
        .map_err(|e| platform::event_loop_failed(&e.to_string(), backend).to_string())?;
    // Asked once winit holds its connection: on an X server with no other
    // client, the check's own connection closing first reset the server
    // and winit's was refused (docs/platform-notes.md).
    if let Some(why) = platform::refusal(backend) {
        return Err(why);
    }
    // SIGTERM, SIGINT, SIGHUP: close as Cancel does (nothing written), exit 0.
    let proxy = event_loop.create_proxy();
    crate::platform::signals::on_terminate(move || {
        let _ = proxy.send_event(Terminate);
    })
    .map_err(|e| format!("cannot watch for SIGTERM: {e}"))?;
    let mut app = App {
        make: Some(make),
        parent,
        backend,
        window: None,
        surface: None,
        screen: None,
        modifiers: ModifiersState::empty(),
        cursor: PhysicalPosition::new(-1.0, -1.0),
        wheel_pixels: 0.0,
        scale: 1,
        error: None,
    };
    event_loop
        .run_app(&mut app)
        .map_err(|e| format!("window event loop failed: {e}"))?;
    app.error.map_or(Ok(()), Err)
}

fn attributes(parent: Option<u64>, backend: Backend) -> winit::window::WindowAttributes {
    let attrs = Window::default_attributes()
        .with_title("Mountains settings")
        .with_inner_size(LogicalSize::new(WINDOW_W, WINDOW_H))
        .with_min_inner_size(LogicalSize::new(MIN_W, MIN_H));
    platform::settings_attributes(attrs, backend, parent)
}

impl App {
    fn fail(&mut self, event_loop: &ActiveEventLoop, message: String) {
        self.error = Some(message);
        event_loop.exit();
    }

    fn open(&mut self, event_loop: &ActiveEventLoop) -> Result<(), String> {
        let window = event_loop
            .create_window(attributes(self.parent, self.backend))
            .map_err(|e| {
                let e = crate::saver::without_source_place(&e.to_string());
                format!("cannot open the settings window: {e}")
            })?;
        let window = Rc::new(window);
        let context = softbuffer::Context::new(window.clone()).map_err(|e| e.to_string())?;
        let surface =
            softbuffer::Surface::new(&context, window.clone()).map_err(|e| e.to_string())?;
        self.scale = pick_scale(&window);
        keep_min_size(&window, self.scale);
        let want = window_size(self.scale, monitor_size(&window));
        let want = PhysicalSize::new(want.width, want.height);
        let size = window
            .request_inner_size(want)
            .unwrap_or(window.inner_size());
        let scale = self.scale;
        if let Some(make) = self.make.take() {
            self.screen = Some(make(
                Size::new(size.width.max(1), size.height.max(1)),
                scale,
            ));
        }
        self.surface = Some(surface);
        window.request_redraw();
        self.window = Some(window);
        Ok(())
    }

    fn present(&mut self) -> Result<(), String> {
        let (Some(screen), Some(surface)) = (self.screen.as_mut(), self.surface.as_mut()) else {
            return Ok(());
        };
        let frame = screen.draw();
        let (Some(w), Some(h)) = (
            NonZeroU32::new(frame.width()),
            NonZeroU32::new(frame.height()),
        ) else {
            return Ok(());
        };
        surface.resize(w, h).map_err(|e| e.to_string())?;
        let mut buffer = surface.buffer_mut().map_err(|e| e.to_string())?;
        if buffer.len() == frame.pixels().len() {
            buffer.copy_from_slice(frame.pixels());
        }
        buffer.present().map_err(|e| e.to_string())
    }

    fn send(&mut self, event_loop: &ActiveEventLoop, input: Input) {
        let Some(screen) = self.screen.as_mut() else {
            return;
        };
        if screen.input(input) == Next::Close {
            event_loop.exit();
        } else if let Some(w) = &self.window {
            w.request_redraw();
        }
    }

    fn key(&mut self, event_loop: &ActiveEventLoop, event: KeyEvent) {
        if event.state != ElementState::Pressed {
            return;
        }
        let shift = self.modifiers.shift_key();
        let input = match &event.logical_key {
            Key::Named(named) => named_input(*named, shift),
            Key::Character(s) if !self.modifiers.control_key() && !self.modifiers.alt_key() => {
                for c in s.chars() {
                    self.send(event_loop, Input::Char(c));
                }
                None
            }
            _ => None,
        };
        if let Some(input) = input {
            self.send(event_loop, input);
        }
    }

    fn wheel(&mut self, event_loop: &ActiveEventLoop, delta: MouseScrollDelta) {
        let lines = match delta {
            MouseScrollDelta::LineDelta(_, y) => y.round() as i32,
            MouseScrollDelta::PixelDelta(p) => {
                self.wheel_pixels += p.y;
                let whole = (self.wheel_pixels / 30.0).trunc();
                self.wheel_pixels -= whole * 30.0;
                whole as i32
            }
        };
        if lines != 0 {
            let (x, y) = (self.cursor.x, self.cursor.y);
            self.send(event_loop, Input::Wheel(x, y, lines));
        }
    }

    fn resized(&mut self) {
        let (Some(w), Some(screen)) = (&self.window, self.screen.as_mut()) else {
            return;
        };
        let size = w.inner_size();
        screen.resize(Size::new(size.width, size.height), self.scale);
        w.request_redraw();
    }
}

/// The smallest window in pixels at our whole scale, which may differ from
/// the scale factor winit turns logical sizes into (1.5 is drawn at 2).
fn keep_min_size(window: &Window, scale: u32) {
    window.set_min_inner_size(Some(PhysicalSize::new(MIN_W * scale, MIN_H * scale)));
}

/// The whole scale for the window's scale factor and its monitor.
fn pick_scale(window: &Window) -> u32 {
    whole_scale(window.scale_factor(), monitor_size(window))
}

/// The size of the monitor the window is on, if known.
fn monitor_size(window: &Window) -> Option<Size> {
    window
        .current_monitor()
        .map(|m| Size::new(m.size().width, m.size().height))
}

fn named_input(key: NamedKey, shift: bool) -> Option<Input> {
    Some(match key {
        NamedKey::Tab => Input::Tab { back: shift },
        NamedKey::ArrowUp => Input::Up,
        NamedKey::ArrowDown => Input::Down,
        NamedKey::ArrowLeft => Input::Left,
        NamedKey::ArrowRight => Input::Right,
        NamedKey::PageUp => Input::PageUp,
        NamedKey::PageDown => Input::PageDown,
        NamedKey::Home => Input::Home,
        NamedKey::End => Input::End,
        NamedKey::Enter => Input::Enter,
        NamedKey::Space => Input::Space,
        NamedKey::Escape => Input::Escape,
        NamedKey::Backspace => Input::Backspace,
        _ => return None,
    })
}

/// A signal asked the settings screen to close.
#[derive(Debug, Clone, Copy)]
struct Terminate;

impl ApplicationHandler<Terminate> for App {
    fn user_event(&mut self, event_loop: &ActiveEventLoop, _: Terminate) {
        event_loop.exit();
    }

    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.window.is_none()
            && let Err(e) = self.open(event_loop)
        {
            self.fail(event_loop, e);
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        match event {
            // Destroyed: another client destroyed the window (as the
            // saver's windows, it then ends rather than run on unseen).
            // Either way nothing is written, as Cancel.
            WindowEvent::CloseRequested | WindowEvent::Destroyed => event_loop.exit(),
            WindowEvent::Resized(_) => self.resized(),
            WindowEvent::ScaleFactorChanged { .. } => {
                if let Some(w) = &self.window {
                    self.scale = pick_scale(w);
                    keep_min_size(w, self.scale);
                }
                self.resized();
            }
            WindowEvent::ModifiersChanged(m) => self.modifiers = m.state(),
            // Synthetic presses are keys already held when the window got
            // the focus, such as the Enter that started us from a terminal:
            // acting on them would press OK at once.
            WindowEvent::KeyboardInput {
                event,
                is_synthetic: false,
                ..
            } => self.key(event_loop, event),
            WindowEvent::CursorMoved { position, .. } => {
                self.cursor = position;
                self.send(event_loop, Input::Move(position.x, position.y));
            }
            WindowEvent::MouseInput {
                state,
                button: MouseButton::Left,
                ..
            } => {
                let (x, y) = (self.cursor.x, self.cursor.y);
                let input = match state {
                    ElementState::Pressed => Input::Press(x, y),
                    ElementState::Released => Input::Release(x, y),
                };
                self.send(event_loop, input);
            }
            WindowEvent::MouseWheel { delta, .. } => self.wheel(event_loop, delta),
            WindowEvent::RedrawRequested => {
                let more = self.screen.as_mut().is_some_and(Screen::step_preview);
                if let Err(e) = self.present() {
                    self.fail(event_loop, format!("cannot draw the settings window: {e}"));
                    return;
                }
                if more && let Some(w) = &self.window {
                    w.request_redraw();
                }
            }
            _ => {}
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        // The signal handler's flag, seen before the watcher's notice.
        if crate::platform::signals::ending() {
            return event_loop.exit();
        }
        if self.screen.as_mut().is_some_and(Screen::poll_file)
            && let Some(w) = &self.window
        {
            w.request_redraw();
        }
        event_loop.set_control_flow(ControlFlow::WaitUntil(Instant::now() + FILE_POLL));
    }
}
