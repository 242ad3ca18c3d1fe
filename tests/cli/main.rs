//! The command line and the project: flags, commands, the README, the code's architecture.

#[path = "../common/mod.rs"]
mod common;

mod architecture;
mod arguments;
mod commands;
mod readme;
