//! Hostile conditions: signals, bad environments and inputs, memory limits.

#[path = "../common/mod.rs"]
mod common;

mod inputs;
mod memory_limits;
