//! The saver on a display: X11 under Xvfb (full screen, --root, --window-id, monitors, ARGB, errors, xscreensaver), Wayland under a headless sway, and the settings screen in a window.

#[path = "../common/mod.rs"]
mod common;

mod argb;
mod churn;
mod display;
mod errors;
mod monitors;
mod settings_screen;
mod span;
mod wayland;
mod xscreensaver;
