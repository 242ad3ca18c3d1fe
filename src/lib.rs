//! `mountains`: a fractal-mountain screensaver.
//!
//! `terrain` makes heights, `render` turns them into pixels, `settings` holds
//! preferences, `saver` puts frames on screens. Only `saver` knows about windows.

#![warn(missing_docs)]
// Printing goes through `console`: `println!` and `eprintln!` panic on a
// closed pipe.
#![warn(clippy::print_stdout, clippy::print_stderr)]

pub mod cli;
pub mod clock;
pub mod commands;
pub mod console;
pub mod contrib;
pub mod cores;
pub mod fsutil;
pub mod help;
pub mod log;
pub mod memory;
pub mod mountain;
pub mod power;
pub mod quality;
pub mod quote;
pub mod render;
pub mod saved;
pub mod saver;
pub mod settings;
pub mod settings_ui;
pub mod signals;
pub mod snapshot;
pub mod spelling;
pub mod terrain;
mod threads;
#[cfg(unix)]
pub mod x11_visual;
