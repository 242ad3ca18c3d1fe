//! The window layer: the only module that knows about winit, softbuffer and X11.
