//! Memory for one-shot commands (`render`, `heightmap`): under a memory
//! limit (`ulimit -v`, a container's cap) a shortage is a message and exit
//! 1, never an abort half way through. Rust cannot recover from a failed
//! allocation, so the room is asked for once, before the work starts.

/// Memory the terrain and the drawing take beside the frame, per grid
/// point: the heights, their copies in subdivision and erosion, the
/// projected points, the shadow and sky-light maps (VmPeak of `render
/// --size 4000x4000` grows by 60 MiB from 2049 to 4097 points a side,
/// about 5 bytes a point; three times that, for safety).
const WORK_BYTES_PER_POINT: u64 = 16;

/// Beside that, the threads, their stacks and what the allocator keeps.
const WORK_BYTES_FIXED: u64 = 64 << 20;

/// Whether the memory to generate and draw a `2^exponent + 1` grid can be
/// had. The probe is given back at once; `Err` holds the MiB asked for.
pub fn room_to_work(exponent: u32) -> Result<(), u64> {
    let side = (1u64 << exponent) + 1;
    let bytes = side * side * WORK_BYTES_PER_POINT + WORK_BYTES_FIXED;
    let mut probe: Vec<u8> = Vec::new();
    usize::try_from(bytes)
        .ok()
        .and_then(|b| probe.try_reserve_exact(b).ok())
        .ok_or(bytes >> 20)
}

/// Makes every thread allocate from one pool. glibc otherwise reserves 64
/// MiB of address space for each thread's own pool on its first
/// allocation; under a limit that reservation can take the room
/// [`room_to_work`] found, and a later allocation aborts (seen at 160 MiB
/// for a 1080p `render`, while 104 MiB worked). A one-shot command makes
/// a few large allocations, so sharing one pool costs nothing measurable.
pub fn one_pool() {
    crate::platform::os::allocate_from_one_pool();
}

/// Big blocks (a field, a frame, a shadow map) each get pages of their own
/// from the system, given back when they are freed. glibc starts that way,
/// but once it frees such a block it raises its threshold to the block's
/// size, and a later field or map of that size comes from a pool instead,
/// whose freed pages it keeps: a slide show making a 4K mountain every
/// slide kept growing over its first slides, holding the heights of
/// slides gone. Fixing the threshold (at glibc's own starting value)
/// keeps what the process holds to what is alive. For the long-running
/// modes; call before other threads start.
pub fn give_back_big_blocks() {
    crate::platform::os::map_blocks_from(BIG_BLOCK_BYTES);
}

/// Gives the system back the free pages inside the allocator's pools.
/// Blocks under [`BIG_BLOCK_BYTES`] come from pools that keep the pages of
/// what was freed amid what is alive: after a slide's drawing, a redraw
/// and the next mountain's making, a held slide kept 4-12 MB of such
/// pages, more or less from slide to slide as the threads' work fell.
/// Called once a slide is held and once the next mountain is made; the
/// walk over the pools took 0.1-0.9 ms a call in a 4K slide show.
pub fn give_back_free_pages() {
    crate::platform::os::trim_pools();
}

/// glibc's starting mmap threshold: blocks this size and over are mapped.
const BIG_BLOCK_BYTES: i32 = 128 * 1024;
