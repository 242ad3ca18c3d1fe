//! Packages and other platforms: the Windows exe under Wine and its resources, the .deb and the zip, the contrib files (xscreensaver XML, man page).

#[path = "../common/mod.rs"]
mod common;

mod contrib_files;
mod packages;
mod windows_resources;
mod wine;
mod wine_power;
mod wine_span;
