//! The saver on a display: X11 under Xvfb (full screen, --root, --window-id, monitors, ARGB, errors, xscreensaver, power and display-off), Wayland under a headless sway, and the settings screen in a window.

#[path = "../common/mod.rs"]
mod common;

mod argb;
mod churn;
mod display;
mod errors;
mod monitors;
mod power;
mod settings_screen;
mod span;
mod wayland;
mod wayland_power;
mod xscreensaver;
