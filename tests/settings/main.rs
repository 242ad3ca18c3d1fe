//! Preferences: the key table, loading, saving, looks, and the settings screen drawn headless.

#[path = "../common/mod.rs"]
mod common;

mod keys_and_load;
mod looks;
mod save;
mod screen;
