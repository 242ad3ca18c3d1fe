//! An X server with DPMS for the tests: a socket in front of Xvfb (which
//! has no DPMS extension, nor has Xorg's dummy driver) that passes every
//! request, reply, event and file descriptor on, and answers the DPMS
//! extension itself: its QueryExtension, GetVersion, Capable, GetTimeouts
//! and Info, with the power level the test sets (`set_power`).
//!
//! A DPMS request is sent on to the server as a GetInputFocus (a void one
//! as a NoOperation), so the server numbers it as the client does, and the
//! answer to it is rewritten as the DPMS reply: no sequence numbers to
//! shift. It reads the wire format (little-endian clients only) just far
//! enough for that.
#![allow(dead_code)]

use std::collections::HashMap;
use std::os::fd::AsRawFd;
use std::os::unix::net::{UnixListener, UnixStream};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

use super::wl_proxy::{close_all, receive_with_fds, send_with_fds};

/// The major opcode the proxy gives DPMS (above any Xvfb hands out).
const DPMS_MAJOR: u8 = 240;
/// QueryExtension's, GetInputFocus's and NoOperation's opcodes.
const QUERY_EXTENSION: u8 = 98;
const GET_INPUT_FOCUS: u8 = 43;
const NO_OPERATION: u8 = 127;

/// A reply the proxy makes in place of the server's.
#[derive(Debug, Clone, Copy)]
enum Fake {
    /// QueryExtension("DPMS"): present.
    DpmsPresent,
    /// A DPMS request with a reply: its minor opcode.
    Dpms(u8),
}

/// The proxy: its display and the power it reports.
pub struct XDpms {
    display: String,
    off: Arc<AtomicBool>,
    socket: std::path::PathBuf,
}

impl XDpms {
    /// Listens on a free display in front of the X server `display` (`:N`).
    pub fn start(display: &str) -> XDpms {
        let number: u32 = display
            .trim_start_matches(':')
            .parse()
            .expect("a display :N");
        let server_path = format!("/tmp/.X11-unix/X{number}");
        let (listener, mine, socket) = (300..400)
            .find_map(|n| {
                let path = std::path::PathBuf::from(format!("/tmp/.X11-unix/X{n}"));
                UnixListener::bind(&path).ok().map(|l| (l, n, path))
            })
            .expect("a free display number for the proxy");
        let off = Arc::new(AtomicBool::new(false));
        let power = off.clone();
        std::thread::spawn(move || {
            for client in listener.incoming() {
                let Ok(client) = client else { return };
                let Ok(server) = UnixStream::connect(&server_path) else {
                    return;
                };
                let fakes = Arc::new(Mutex::new(HashMap::new()));
                let (c2, s2, f2, p2) = (
                    client.try_clone().unwrap(),
                    server.try_clone().unwrap(),
                    fakes.clone(),
                    power.clone(),
                );
                std::thread::spawn(move || requests(&client, &server, &fakes));
                std::thread::spawn(move || replies(&s2, &c2, &f2, &p2));
            }
        });
        XDpms {
            display: format!(":{mine}"),
            off,
            socket,
        }
    }

    /// The `DISPLAY` value that reaches the server through the proxy.
    pub fn display(&self) -> &str {
        &self.display
    }

    /// Powers the monitor off (DPMS level Off) or on.
    pub fn set_power(&self, on: bool) {
        self.off.store(!on, Ordering::SeqCst);
    }
}

impl Drop for XDpms {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.socket);
    }
}

fn u16_at(b: &[u8], at: usize) -> usize {
    u16::from_le_bytes([b[at], b[at + 1]]) as usize
}

fn u32_at(b: &[u8], at: usize) -> usize {
    u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]]) as usize
}

/// Client to server: the setup, then request by request, DPMS ones
/// replaced and noted by sequence number.
fn requests(client: &UnixStream, server: &UnixStream, fakes: &Mutex<HashMap<u16, Fake>>) {
    let mut pending: Vec<u8> = Vec::new();
    let mut setup_done = false;
    let mut seq: u16 = 0;
    while let Some((bytes, fds)) = receive_with_fds(client.as_raw_fd()) {
        pending.extend(bytes);
        let mut out = Vec::new();
        loop {
            if !setup_done {
                if pending.len() < 12 {
                    break;
                }
                let size =
                    12 + u16_at(&pending, 6).div_ceil(4) * 4 + u16_at(&pending, 8).div_ceil(4) * 4;
                if pending.len() < size {
                    break;
                }
                out.extend(pending.drain(..size));
                setup_done = true;
                continue;
            }
            if pending.len() < 4 {
                break;
            }
            let mut size = u16_at(&pending, 2) * 4;
            if size == 0 {
                // BIG-REQUESTS: the length follows, in words.
                if pending.len() < 8 {
                    break;
                }
                size = u32_at(&pending, 4) * 4;
            }
            if pending.len() < size {
                break;
            }
            let request: Vec<u8> = pending.drain(..size).collect();
            seq = seq.wrapping_add(1);
            out.extend(rewrite(&request, seq, fakes));
        }
        send_with_fds(server.as_raw_fd(), &out, &fds);
        close_all(&fds);
    }
    let _ = server.shutdown(std::net::Shutdown::Both);
}

/// The request as sent on: DPMS ones turned into GetInputFocus (noted for
/// a made-up reply) or NoOperation.
fn rewrite(request: &[u8], seq: u16, fakes: &Mutex<HashMap<u16, Fake>>) -> Vec<u8> {
    let fake = match request[0] {
        QUERY_EXTENSION => {
            let len = u16_at(request, 4);
            (request.get(8..8 + len) == Some(b"DPMS")).then_some(Fake::DpmsPresent)
        }
        DPMS_MAJOR => match request[1] {
            minor @ (0 | 1 | 2 | 7) => Some(Fake::Dpms(minor)),
            _ => return vec![NO_OPERATION, 0, 1, 0],
        },
        _ => None,
    };
    match fake {
        Some(fake) => {
            fakes.lock().unwrap().insert(seq, fake);
            vec![GET_INPUT_FOCUS, 0, 1, 0]
        }
        None => request.to_vec(),
    }
}

/// Server to client: the setup reply, then 32-byte events and errors and
/// replies of any length, the noted ones rewritten.
fn replies(
    server: &UnixStream,
    client: &UnixStream,
    fakes: &Mutex<HashMap<u16, Fake>>,
    off: &AtomicBool,
) {
    let mut pending: Vec<u8> = Vec::new();
    let mut setup_done = false;
    while let Some((bytes, fds)) = receive_with_fds(server.as_raw_fd()) {
        pending.extend(bytes);
        let mut out = Vec::new();
        loop {
            if !setup_done {
                if pending.len() < 8 {
                    break;
                }
                let size = 8 + u16_at(&pending, 6) * 4;
                if pending.len() < size {
                    break;
                }
                out.extend(pending.drain(..size));
                setup_done = true;
                continue;
            }
            if pending.len() < 32 {
                break;
            }
            let kind = pending[0] & 0x7f;
            let size = match kind {
                1 | 35 => 32 + u32_at(&pending, 4) * 4,
                _ => 32,
            };
            if pending.len() < size {
                break;
            }
            let mut message: Vec<u8> = pending.drain(..size).collect();
            if kind == 1 {
                let seq = u16_at(&message, 2) as u16;
                if let Some(fake) = fakes.lock().unwrap().remove(&seq) {
                    message = made_up(fake, seq, off.load(Ordering::SeqCst));
                }
            }
            out.extend(message);
        }
        send_with_fds(client.as_raw_fd(), &out, &fds);
        close_all(&fds);
    }
    let _ = client.shutdown(std::net::Shutdown::Both);
}

/// The proxy's reply for `fake`: 32 bytes, no extra length.
fn made_up(fake: Fake, seq: u16, off: bool) -> Vec<u8> {
    let mut r = vec![0u8; 32];
    r[0] = 1;
    r[2..4].copy_from_slice(&seq.to_le_bytes());
    match fake {
        Fake::DpmsPresent => {
            r[8] = 1;
            r[9] = DPMS_MAJOR;
        }
        // GetVersion: 1.1.
        Fake::Dpms(0) => {
            r[8] = 1;
            r[10] = 1;
        }
        // Capable: yes.
        Fake::Dpms(1) => r[8] = 1,
        // Info: power level (0 On, 3 Off) and DPMS enabled.
        Fake::Dpms(7) => {
            r[8] = if off { 3 } else { 0 };
            r[10] = 1;
        }
        // GetTimeouts: all zero.
        Fake::Dpms(_) => {}
    }
    r
}
