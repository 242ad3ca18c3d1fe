//! A program a test started, with its stderr in a file: what it said, its
//! status, and its end (killed when dropped). The Xvfb saver and the sway
//! client each hold one.

use std::path::PathBuf;
use std::process::{Child, ExitStatus};
use std::time::{Duration, Instant};

/// A started program; killed on drop.
pub struct Running {
    child: Option<Child>,
    stderr: PathBuf,
}

impl Running {
    /// `child`, which writes its stderr to the file `stderr`.
    pub fn new(child: Child, stderr: PathBuf) -> Self {
        Running {
            child: Some(child),
            stderr,
        }
    }

    /// What it wrote on stderr so far.
    pub fn stderr(&self) -> String {
        std::fs::read_to_string(&self.stderr).unwrap_or_default()
    }

    /// The file its stderr goes to.
    pub fn stderr_path(&self) -> &PathBuf {
        &self.stderr
    }

    /// Its process id (setpriv execs it: the same process).
    pub fn pid(&self) -> u32 {
        self.child.as_ref().unwrap().id()
    }

    /// Its exit status if it has ended.
    pub fn exited(&mut self) -> Option<ExitStatus> {
        self.child.as_mut().unwrap().try_wait().unwrap()
    }

    /// Waits up to `limit` for it to end.
    pub fn wait(&mut self, limit: Duration) -> Option<ExitStatus> {
        let end = Instant::now() + limit;
        while Instant::now() < end {
            if let Some(status) = self.exited() {
                return Some(status);
            }
            std::thread::sleep(Duration::from_millis(2));
        }
        None
    }

    /// Fails the test with its stderr if it has ended already.
    pub fn assert_running(&mut self) {
        if let Some(status) = self.exited() {
            panic!("mountains ended early ({status}):\n{}", self.stderr());
        }
    }

    /// Kills it with SIGKILL, as a crash would end it.
    pub fn kill(&mut self) {
        if let Some(mut child) = self.child.take() {
            let _ = child.kill();
            let _ = child.wait();
        }
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        self.kill();
    }
}
