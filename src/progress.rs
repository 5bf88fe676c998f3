//! The progress line: "working: WHAT (N s)" on standard error while a long command runs, cleared
//! before the command's output is written. A leaf module: the process budget
//! ([`crate::budget`], which starts it) and the output writers ([`crate::output`], which clear
//! it) both use it.

use std::io::IsTerminal as _;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Whether the progress line is on screen (guarded so that it is cleared exactly once).
static PROGRESS: Mutex<bool> = Mutex::new(false);
/// Set when the command's output begins: no progress line after that.
static PROGRESS_DONE: AtomicBool = AtomicBool::new(false);

/// Shows "working: WHAT (N s)" on standard error, updated every second, once the command has run
/// for two seconds; only when standard error is a terminal. Cleared by [`clear_progress`].
pub fn start_progress(what: &'static str) {
    if !std::io::stderr().is_terminal() {
        return;
    }
    let start = Instant::now();
    let _ = std::thread::Builder::new()
        .name("progress".into())
        .spawn(move || {
            std::thread::sleep(Duration::from_secs(2));
            loop {
                {
                    let Ok(mut shown) = PROGRESS.lock() else {
                        return;
                    };
                    if PROGRESS_DONE.load(Ordering::Relaxed) {
                        return;
                    }
                    use std::io::Write as _;
                    let _ = write!(
                        std::io::stderr(),
                        "\r\x1b[Kexactcheck: working: {what} ({} s; --timeout bounds it)",
                        start.elapsed().as_secs()
                    );
                    *shown = true;
                }
                std::thread::sleep(Duration::from_secs(1));
            }
        });
}

/// Removes the progress line, if shown, and stops it for good (before output is written).
pub fn clear_progress() {
    PROGRESS_DONE.store(true, Ordering::Relaxed);
    if let Ok(mut shown) = PROGRESS.lock() {
        if *shown {
            use std::io::Write as _;
            let _ = write!(std::io::stderr(), "\r\x1b[K");
            *shown = false;
        }
    }
}
