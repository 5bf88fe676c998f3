//! The process groups of the running programs (Unix), for [`super::stop_all`] and the signal
//! handler: each program runs in a group of its own, and the whole group is stopped.
use std::sync::atomic::{AtomicI32, Ordering};
use std::sync::Once;

/// Room for this many programs running at once; a group that finds no slot is still
/// stopped with its runner, only not by [`kill_all`].
const SLOTS: usize = 64;

/// Process group ids (the programs' pids) in use; 0 marks a free slot.
static LIVE: [AtomicI32; SLOTS] = [const { AtomicI32::new(0) }; SLOTS];

fn pgid(pid: u32) -> i32 {
    i32::try_from(pid).unwrap_or(0)
}

pub(super) fn register(pid: u32) {
    let g = pgid(pid);
    for slot in &LIVE {
        if slot
            .compare_exchange(0, g, Ordering::SeqCst, Ordering::SeqCst)
            .is_ok()
        {
            return;
        }
    }
}

pub(super) fn unregister(pid: u32) {
    let g = pgid(pid);
    for slot in &LIVE {
        let _ = slot.compare_exchange(g, 0, Ordering::SeqCst, Ordering::SeqCst);
    }
}

/// Kills the group led by `pid`.
pub(super) fn kill(pid: u32) {
    let g = pgid(pid);
    if g > 0 {
        // SAFETY: `kill` takes plain integers; a group that is gone gives ESRCH, harmless.
        unsafe {
            libc::kill(-g, libc::SIGKILL);
        }
    }
}

pub(super) fn kill_all() {
    for slot in &LIVE {
        let g = slot.load(Ordering::SeqCst);
        if g > 0 {
            // SAFETY: as in `kill`; `kill` is async-signal-safe.
            unsafe {
                libc::kill(-g, libc::SIGKILL);
            }
        }
    }
}

extern "C" fn on_signal(sig: libc::c_int) {
    kill_all();
    // SAFETY: `signal` and `raise` are async-signal-safe; with the default action restored,
    // the signal ends the process as it would have without the handler.
    unsafe {
        libc::signal(sig, libc::SIG_DFL);
        libc::raise(sig);
    }
}

/// Installs [`on_signal`] for SIGINT, SIGTERM and SIGHUP where their action is the default
/// (an ignored signal stays ignored), once per process.
pub(super) fn install_signal_handlers() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
            // SAFETY: `sigaction` reads and writes the structs given; a zeroed `sigaction`
            // is a valid value (no flags, empty mask), then filled in.
            unsafe {
                let mut old: libc::sigaction = std::mem::zeroed();
                if libc::sigaction(sig, std::ptr::null(), &mut old) != 0
                    || old.sa_sigaction != libc::SIG_DFL
                {
                    continue;
                }
                let mut new: libc::sigaction = std::mem::zeroed();
                new.sa_sigaction = on_signal as extern "C" fn(libc::c_int) as usize;
                libc::sigemptyset(&mut new.sa_mask);
                new.sa_flags = libc::SA_RESTART;
                libc::sigaction(sig, &new, std::ptr::null_mut());
            }
        }
    });
}
