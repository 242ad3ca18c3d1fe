//! What the test binaries share: one module, declared by each area's
//! main.rs as `mod common;`. A binary uses what it needs; the rest is
//! compiled and unused, hence the crate-wide dead-code allowance below.
#![allow(dead_code)]

pub mod counting;
pub mod files;
pub mod golden;
pub mod headless;
pub mod heightmaps;
pub mod hostile;
pub mod lakes_reference;
pub mod pe;
#[cfg(target_os = "linux")]
pub mod power;
#[cfg(unix)]
pub mod randr;
#[cfg(unix)]
pub mod running;
#[cfg(unix)]
pub mod signals;
#[cfg(target_os = "linux")]
pub mod sway;
pub mod terrain_setup;
pub mod tools;
pub mod wine;
#[cfg(target_os = "linux")]
pub mod wl_pointer;
#[cfg(target_os = "linux")]
pub mod wl_proxy;
#[cfg(target_os = "linux")]
pub mod x_dpms;
#[cfg(unix)]
pub mod xvfb;
