//! A Wayland socket in front of the test's sway that passes every message
//! (and file descriptor) on, and can play a compositor sway 1.7 cannot be:
//! one without wlr-layer-shell (its global is kept from the clients), one
//! whose output goes away (a `wl_registry.global_remove` for it), one that
//! closes layer surfaces (`zwlr_layer_surface_v1.closed`), one that powers
//! its outputs off and on (`zwlr_output_power_v1.mode`; sway 1.7's headless
//! outputs fail to commit `dpms off`).
//!
//! It reads the wire format (a 32-bit object id, a 32-bit size << 16 |
//! opcode, the arguments) just far enough to know the registries, the
//! outputs' globals, the layer shell and its surfaces.
#![allow(dead_code)]

use std::os::fd::{AsRawFd, RawFd};
use std::os::unix::net::{UnixListener, UnixStream};
use std::path::Path;
use std::sync::{Arc, Mutex};

/// What the proxy does to the compositor's messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edit {
    /// Everything passes.
    Nothing,
    /// The `zwlr_layer_shell_v1` global is not announced.
    HideLayerShell,
}

/// The proxy: its socket, and what it learnt of each client.
pub struct WlProxy {
    clients: Arc<Mutex<Vec<Arc<Link>>>>,
}

/// One client's connection: the writing end towards it and what it bound.
struct Link {
    to_client: Mutex<UnixStream>,
    seen: Mutex<Seen>,
}

/// What a client's messages and the compositor's answers showed.
#[derive(Default)]
struct Seen {
    /// Registry object ids (the client's `wl_display.get_registry`).
    registries: Vec<u32>,
    /// Each registry's `wl_output` globals: (registry id, global name).
    outputs: Vec<(u32, u32)>,
    /// The client's `zwlr_layer_shell_v1` object ids.
    shells: Vec<u32>,
    /// The client's `zwlr_layer_surface_v1` object ids.
    surfaces: Vec<u32>,
    /// The client's `zwlr_output_power_manager_v1` object ids.
    power_managers: Vec<u32>,
    /// The client's `zwlr_output_power_v1` object ids.
    output_powers: Vec<u32>,
    /// Those whose first `mode` the compositor has said (passed on): ours
    /// go after it, or its first word ("on") would undo ours.
    answered_powers: Vec<u32>,
}

impl WlProxy {
    /// Listens on `socket` (a path the clients can reach) in front of the
    /// compositor at `compositor`.
    pub fn start(socket: &Path, compositor: &Path, edit: Edit) -> WlProxy {
        let _ = std::fs::remove_file(socket);
        let listener = UnixListener::bind(socket).expect("bind the proxy's socket");
        // The clients may run as another user (nobody, under root).
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(socket, std::fs::Permissions::from_mode(0o777)).unwrap();
        let clients = Arc::new(Mutex::new(Vec::new()));
        let list = clients.clone();
        let compositor = compositor.to_path_buf();
        std::thread::spawn(move || {
            for client in listener.incoming() {
                let Ok(client) = client else { return };
                let Ok(server) = UnixStream::connect(&compositor) else {
                    return;
                };
                let link = Arc::new(Link {
                    to_client: Mutex::new(client.try_clone().unwrap()),
                    seen: Mutex::new(Seen::default()),
                });
                list.lock().unwrap().push(link.clone());
                let up = link.clone();
                let server_in = server.try_clone().unwrap();
                std::thread::spawn(move || client_to_server(&client, &server, &up));
                std::thread::spawn(move || server_to_client(&server_in, &link, edit));
            }
        });
        WlProxy { clients }
    }

    /// Tells every client that the `wl_output` global announced last is
    /// gone (a monitor unplugged); how many registries were told.
    pub fn remove_last_output(&self) -> usize {
        let mut told = 0;
        for link in self.clients.lock().unwrap().iter() {
            let seen = link.seen.lock().unwrap();
            let Some(last) = seen.outputs.iter().map(|&(_, name)| name).max() else {
                continue;
            };
            for &(registry, name) in &seen.outputs {
                if name == last {
                    link.send(registry, 1, &name.to_ne_bytes());
                    told += 1;
                }
            }
        }
        told
    }

    /// Closes up to `count` layer surfaces not closed yet (in the order
    /// they were made), as a compositor does when it wants them gone; how
    /// many were closed.
    pub fn close_layer_surfaces(&self, count: usize) -> usize {
        let mut closed = 0;
        for link in self.clients.lock().unwrap().iter() {
            let mut seen = link.seen.lock().unwrap();
            while closed < count && !seen.surfaces.is_empty() {
                let id = seen.surfaces.remove(0);
                link.send(id, 1, &[]);
                closed += 1;
            }
        }
        closed
    }
}

impl WlProxy {
    /// Tells every client watching its outputs' power that they are now
    /// off (`on` false) or on; how many output power objects were told.
    /// Only those the compositor has answered: its first `mode` event
    /// comes after the client asks, and would follow ours.
    pub fn set_output_power(&self, on: bool) -> usize {
        let mut told = 0;
        for link in self.clients.lock().unwrap().iter() {
            let seen = link.seen.lock().unwrap();
            for &id in &seen.answered_powers {
                // zwlr_output_power_v1.mode(mode): 0 off, 1 on.
                link.send(id, 0, &u32::from(on).to_ne_bytes());
                told += 1;
            }
        }
        told
    }
}

impl Link {
    /// Sends the client an event of ours, between two of the compositor's.
    fn send(&self, object: u32, opcode: u16, args: &[u8]) {
        let mut message = object.to_ne_bytes().to_vec();
        let size = (8 + args.len()) as u32;
        message.extend((size << 16 | u32::from(opcode)).to_ne_bytes());
        message.extend(args);
        let to = self.to_client.lock().unwrap();
        send_with_fds(to.as_raw_fd(), &message, &[]);
    }
}

/// Passes the client's requests on unchanged, noting the objects it makes.
fn client_to_server(client: &UnixStream, server: &UnixStream, link: &Link) {
    let mut pending = Vec::new();
    while let Some((bytes, fds)) = receive_with_fds(client.as_raw_fd()) {
        // Noted before the compositor sees them: its answer (a registry's
        // globals) is read on another thread, which must know the registry
        // by then, or the outputs it announces go unnoted (a flaky test
        // under load, once in CI).
        pending.extend(&bytes);
        for (object, opcode, args) in take_messages(&mut pending) {
            note_request(&mut link.seen.lock().unwrap(), object, opcode, &args);
        }
        send_with_fds(server.as_raw_fd(), &bytes, &fds);
        close_all(&fds);
    }
}

/// Passes the compositor's events on, message by message (so that ours go
/// between them), leaving out what `edit` hides.
fn server_to_client(server: &UnixStream, link: &Link, edit: Edit) {
    let mut pending = Vec::new();
    let mut fds_waiting: Vec<RawFd> = Vec::new();
    while let Some((bytes, fds)) = receive_with_fds(server.as_raw_fd()) {
        fds_waiting.extend(fds);
        pending.extend(bytes);
        for (object, opcode, args) in take_messages(&mut pending) {
            let global = global_interface(&link.seen.lock().unwrap(), object, opcode, &args);
            if let Some((name, interface)) = &global {
                if edit == Edit::HideLayerShell && interface == "zwlr_layer_shell_v1" {
                    continue;
                }
                if interface == "wl_output" {
                    link.seen.lock().unwrap().outputs.push((object, *name));
                }
            }
            let mut message = object.to_ne_bytes().to_vec();
            let size = (8 + args.len()) as u32;
            message.extend((size << 16 | u32::from(opcode)).to_ne_bytes());
            message.extend(&args);
            {
                let to = link.to_client.lock().unwrap();
                send_with_fds(to.as_raw_fd(), &message, &fds_waiting);
            }
            close_all(&fds_waiting);
            fds_waiting.clear();
            // zwlr_output_power_v1.mode, passed on: ours may follow it now
            // (`to_client` let go first: `set_output_power` holds `seen`
            // while it sends).
            let mut seen = link.seen.lock().unwrap();
            if opcode == 0
                && seen.output_powers.contains(&object)
                && !seen.answered_powers.contains(&object)
            {
                seen.answered_powers.push(object);
            }
        }
    }
    // The compositor hung up: so does the client's side.
    let _ = link
        .to_client
        .lock()
        .unwrap()
        .shutdown(std::net::Shutdown::Both);
}

/// A `wl_registry.global` event's global name and interface.
fn global_interface(seen: &Seen, object: u32, opcode: u16, args: &[u8]) -> Option<(u32, String)> {
    if opcode != 0 || !seen.registries.contains(&object) {
        return None;
    }
    let name = word(args, 0)?;
    Some((name, string_at(args, 4)?.0))
}

/// Notes the objects a request makes: registries, layer shells, layer
/// surfaces, output power managers and their output powers.
fn note_request(seen: &mut Seen, object: u32, opcode: u16, args: &[u8]) {
    match (object, opcode) {
        // wl_display.get_registry(new_id)
        (1, 1) => seen.registries.extend(word(args, 0)),
        // wl_registry.bind(name, interface, version, new_id)
        (o, 0) if seen.registries.contains(&o) => match string_at(args, 4) {
            Some((interface, next)) if interface == "zwlr_layer_shell_v1" => {
                seen.shells.extend(word(args, next + 4))
            }
            Some((interface, next)) if interface == "zwlr_output_power_manager_v1" => {
                seen.power_managers.extend(word(args, next + 4))
            }
            _ => {}
        },
        // zwlr_output_power_manager_v1.get_output_power(new_id, output)
        (o, 0) if seen.power_managers.contains(&o) => seen.output_powers.extend(word(args, 0)),
        // zwlr_layer_shell_v1.get_layer_surface(new_id, ...)
        (o, 0) if seen.shells.contains(&o) => seen.surfaces.extend(word(args, 0)),
        _ => {}
    }
}

/// The whole messages at the front of `pending` (taken out of it).
fn take_messages(pending: &mut Vec<u8>) -> Vec<(u32, u16, Vec<u8>)> {
    let mut messages = Vec::new();
    while let (Some(object), Some(second)) = (word(pending, 0), word(pending, 4)) {
        let size = (second >> 16) as usize;
        if size < 8 || pending.len() < size {
            break;
        }
        let args = pending[8..size].to_vec();
        messages.push((object, (second & 0xffff) as u16, args));
        pending.drain(..size);
    }
    messages
}

/// The 32-bit word at byte `at`.
fn word(bytes: &[u8], at: usize) -> Option<u32> {
    let b = bytes.get(at..at + 4)?;
    Some(u32::from_ne_bytes(b.try_into().ok()?))
}

/// The string at byte `at` (length with its NUL, bytes, padding) and the
/// byte after it.
fn string_at(bytes: &[u8], at: usize) -> Option<(String, usize)> {
    let len = word(bytes, at)? as usize;
    let text = bytes.get(at + 4..at + 4 + len.saturating_sub(1))?;
    let next = at + 4 + len.div_ceil(4) * 4;
    Some((String::from_utf8_lossy(text).into_owned(), next))
}

/// Most descriptors one message carries (libwayland's own limit).
const MAX_FDS: usize = 28;

/// Reads what arrives on `fd` with the descriptors passed along; `None`
/// at its end.
pub fn receive_with_fds(fd: RawFd) -> Option<(Vec<u8>, Vec<RawFd>)> {
    let mut data = vec![0u8; 4096];
    let mut control = vec![0u8; 1024];
    let mut iov = libc::iovec {
        iov_base: data.as_mut_ptr().cast(),
        iov_len: data.len(),
    };
    // SAFETY: msghdr is plain data; the buffers outlive the call.
    let mut msg: libc::msghdr = unsafe { std::mem::zeroed() };
    msg.msg_iov = &mut iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control.as_mut_ptr().cast();
    msg.msg_controllen = control.len();
    let n = loop {
        // SAFETY: msg points at live buffers of the sizes given.
        let n = unsafe { libc::recvmsg(fd, &mut msg, libc::MSG_CMSG_CLOEXEC) };
        if n < 0 && std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted {
            continue;
        }
        break n;
    };
    if n <= 0 {
        return None;
    }
    let mut fds = Vec::new();
    // SAFETY: the CMSG macros walk the control buffer recvmsg filled.
    unsafe {
        let mut cmsg = libc::CMSG_FIRSTHDR(&msg);
        while !cmsg.is_null() {
            if (*cmsg).cmsg_level == libc::SOL_SOCKET && (*cmsg).cmsg_type == libc::SCM_RIGHTS {
                let header = libc::CMSG_LEN(0) as usize;
                let count = ((*cmsg).cmsg_len as usize - header) / 4;
                let first = libc::CMSG_DATA(cmsg).cast::<RawFd>();
                fds.extend((0..count).map(|i| first.add(i).read_unaligned()));
            }
            cmsg = libc::CMSG_NXTHDR(&msg, cmsg);
        }
    }
    data.truncate(n as usize);
    Some((data, fds))
}

/// Writes all of `bytes` to `fd`, the descriptors `fds` with the first part.
pub fn send_with_fds(fd: RawFd, bytes: &[u8], fds: &[RawFd]) {
    assert!(fds.len() <= MAX_FDS, "{} descriptors at once", fds.len());
    let mut sent = 0;
    let mut fds = fds;
    while sent < bytes.len() {
        let mut iov = libc::iovec {
            iov_base: bytes[sent..].as_ptr() as *mut _,
            iov_len: bytes.len() - sent,
        };
        let space = unsafe { libc::CMSG_SPACE((fds.len() * 4) as u32) } as usize;
        let mut control = vec![0u8; space.max(1)];
        // SAFETY: msghdr is plain data; the buffers outlive the call.
        let mut msg: libc::msghdr = unsafe { std::mem::zeroed() };
        msg.msg_iov = &mut iov;
        msg.msg_iovlen = 1;
        if !fds.is_empty() {
            msg.msg_control = control.as_mut_ptr().cast();
            msg.msg_controllen = space;
            // SAFETY: the control buffer has room for one header and the fds.
            unsafe {
                let cmsg = libc::CMSG_FIRSTHDR(&msg);
                (*cmsg).cmsg_level = libc::SOL_SOCKET;
                (*cmsg).cmsg_type = libc::SCM_RIGHTS;
                (*cmsg).cmsg_len = libc::CMSG_LEN((fds.len() * 4) as u32) as usize;
                let first = libc::CMSG_DATA(cmsg).cast::<RawFd>();
                for (i, &f) in fds.iter().enumerate() {
                    first.add(i).write_unaligned(f);
                }
            }
        }
        // SAFETY: msg points at live buffers of the sizes given.
        let n = unsafe { libc::sendmsg(fd, &msg, libc::MSG_NOSIGNAL) };
        if n < 0 {
            if std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted {
                continue;
            }
            return;
        }
        sent += n as usize;
        fds = &[];
    }
}

pub fn close_all(fds: &[RawFd]) {
    for &fd in fds {
        // SAFETY: each descriptor came from recvmsg and was passed on.
        unsafe { libc::close(fd) };
    }
}
