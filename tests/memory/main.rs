//! Memory, measured by a counting global allocator (the one binary that has one): each test holds `common::counting::alone()` while it measures, as the byte counts are the whole process's.

#[path = "../common/mod.rs"]
mod common;

#[global_allocator]
static ALLOCATOR: common::counting::Counting = common::counting::Counting;

mod heightmap_alloc;
mod hostile_corpus;
mod night_memory;
mod png_memory;
mod saver_memory;
mod settings_allocations;
mod terrain_memory;
