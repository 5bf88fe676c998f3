//! The command's budget in memory and time: the backstops behind the named size limits of
//! [`crate::limits`].
//!
//! The size limits stop a computation *before* it grows (a constant of too many bits, too many
//! terms, too deep a nesting) with an error naming the limit. What they cannot foresee is
//! guarded here, for the command-line tool only:
//!
//! - **Memory.** [`Accounting`] is the binary's global allocator: the system allocator plus a
//!   count of the bytes in use. An allocation that would take the count past the `memory` limit
//!   (1,536 MB by default) ends the process at once with one line naming the limit and exit
//!   status 2, instead of the runtime's "memory allocation of N bytes failed" abort (or the
//!   kernel's OOM killer). Where the address space is smaller (`ulimit -v`, `RLIMIT_AS`), the
//!   cap is three quarters of it (the rest is code, stacks and the allocator's own slack), and
//!   an allocation the system refuses all the same ends the process with one line too, never
//!   with the runtime's abort. Each thread keeps its own balance and adds it to the shared count
//!   once it exceeds 256 kB either way (so the cores do not contend for one counter; the cap
//!   holds to within 256 kB per thread); the message is written without allocating (the
//!   allocator cannot call back into itself).
//! - **Time.** `--timeout SECONDS` starts a watchdog thread ([`start_timeout`]) that ends the
//!   process with one line and exit status 2 when the command has not finished in time.
//!
//! Either way the process groups of running `--program` float sides are killed first
//! ([`exactcheck_float::external::stop_all`]).
//! - **Progress.** A long `prove` or `solve` shows the seconds spent on standard error when that
//!   is a terminal ([`start_progress`], kept in the leaf module [`crate::progress`] so that
//!   [`crate::output`] can clear the line before writing without depending on this module).
//!
//! Hand-written because no crate does this: allocator-limiting crates (`cap`, `stats_alloc`)
//! return a null pointer past the cap, which the runtime turns into an abort with exit status 134
//! and a two-line message; exactcheck's contract is one line and exit status 2.

use exactcheck_core::limits;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicBool, AtomicIsize, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

pub use crate::progress::{clear_progress, start_progress};

/// Bytes handed out by the allocator and not yet freed, up to each thread's unflushed balance
/// (at most [`SLACK`] bytes per thread either way).
/// Signed: a thread may flush the free of memory whose allocation another thread has not
/// flushed yet.
static IN_USE: AtomicIsize = AtomicIsize::new(0);
/// The most bytes [`Accounting`] lets be in use; `usize::MAX` (no cap) until
/// [`enforce_memory_limit`] sets it.
static CAP: AtomicUsize = AtomicUsize::new(usize::MAX);
/// Whether [`CAP`] is the address space's bound rather than the `memory` limit's.
static CAP_IS_ADDRESS_SPACE: AtomicBool = AtomicBool::new(false);

/// How far a thread's own balance may drift before it is added to [`IN_USE`] (and checked
/// against the cap). Counting every allocation in the one shared atomic made all cores write the
/// same cache line; with a per-thread balance the shared counter is touched about once per
/// 256 kB allocated or freed, and the cap is enforced to within `SLACK` bytes per thread.
const SLACK: isize = 256 << 10;

thread_local! {
    /// This thread's allocations minus frees not yet added to [`IN_USE`]. A `const`-initialised
    /// `Cell` of a plain integer: no destructor is registered and nothing is allocated, so the
    /// allocator may use it. A thread that ends leaves its balance (below `SLACK`) uncounted.
    static BALANCE: Cell<isize> = const { Cell::new(0) };
}

/// The global allocator of the `exactcheck` binary: [`System`] plus the byte count checked
/// against the `memory` limit.
pub struct Accounting;

impl Accounting {
    /// Counts `size` more bytes in use; past the cap, ends the process (exit status 2).
    #[inline]
    fn grow(size: usize) {
        let size = isize::try_from(size).unwrap_or(isize::MAX);
        let flush = BALANCE
            .try_with(|b| {
                let v = b.get().saturating_add(size);
                if v > SLACK {
                    b.set(0);
                    Some(v)
                } else {
                    b.set(v);
                    None
                }
            })
            // During thread teardown the balance is gone: count directly.
            .unwrap_or(Some(size));
        if let Some(v) = flush {
            let now = IN_USE.fetch_add(v, Ordering::Relaxed).saturating_add(v);
            if usize::try_from(now).is_ok_and(|now| now > CAP.load(Ordering::Relaxed)) {
                out_of_memory();
            }
        }
    }

    #[inline]
    fn shrink(size: usize) {
        let size = isize::try_from(size).unwrap_or(isize::MAX);
        let flush = BALANCE
            .try_with(|b| {
                let v = b.get().saturating_sub(size);
                if v < -SLACK {
                    b.set(0);
                    Some(v)
                } else {
                    b.set(v);
                    None
                }
            })
            .unwrap_or(Some(-size));
        if let Some(v) = flush {
            IN_USE.fetch_add(v, Ordering::Relaxed);
        }
    }
}

// SAFETY: every method forwards to `System` with the same arguments; the accounting only
// observes sizes and never changes what is allocated.
unsafe impl GlobalAlloc for Accounting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        Accounting::grow(layout.size());
        // SAFETY: the caller's contract for `alloc` is `System`'s.
        let p = unsafe { System.alloc(layout) };
        if p.is_null() {
            refused(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        Accounting::grow(layout.size());
        // SAFETY: as for `alloc`.
        let p = unsafe { System.alloc_zeroed(layout) };
        if p.is_null() {
            refused(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` was allocated by `System` with `layout` (every allocation goes there).
        unsafe { System.dealloc(ptr, layout) };
        Accounting::shrink(layout.size());
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let old = layout.size();
        if new_size > old {
            Accounting::grow(new_size - old);
        }
        // SAFETY: as for `dealloc`; `new_size` satisfies `realloc`'s contract by the caller's.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if p.is_null() {
            refused(new_size);
        } else if new_size < old {
            Accounting::shrink(old - new_size);
        }
        p
    }
}

/// Caps the bytes in use at the `memory` limit (in MB). Called once by the CLI after the
/// `--limit` flags are read.
/// Where the address space is bounded (`RLIMIT_AS`) below the limit, the cap is three quarters
/// of that bound instead, so that the count reaches the cap before the system refuses memory.
pub fn enforce_memory_limit() {
    let mb = limits::MEMORY.get();
    let bytes = usize::try_from(mb.saturating_mul(1 << 20)).unwrap_or(usize::MAX);
    let room = address_space().map(|b| b / 4 * 3);
    match room {
        Some(room) if room < bytes => {
            CAP.store(room, Ordering::Relaxed);
            CAP_IS_ADDRESS_SPACE.store(true, Ordering::Relaxed);
        }
        _ => {
            CAP.store(bytes, Ordering::Relaxed);
            CAP_IS_ADDRESS_SPACE.store(false, Ordering::Relaxed);
        }
    }
}

/// The process's bound on its address space in bytes (`RLIMIT_AS`), if it has one.
#[cfg(unix)]
fn address_space() -> Option<usize> {
    let mut r = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: `getrlimit` writes one `rlimit` into the live, writable `r`.
    let ok = unsafe { libc::getrlimit(libc::RLIMIT_AS, &mut r) } == 0;
    (ok && r.rlim_cur != libc::RLIM_INFINITY)
        .then(|| usize::try_from(r.rlim_cur).unwrap_or(usize::MAX))
}

#[cfg(not(unix))]
fn address_space() -> Option<usize> {
    None
}

/// Bytes in use now (counted only when [`Accounting`] is the global allocator).
pub fn bytes_in_use() -> usize {
    usize::try_from(IN_USE.load(Ordering::Relaxed)).unwrap_or(0)
}

/// The largest block the C allocator takes from its heap rather than from a mapping of its own
/// (glibc's upper bound for this setting on 64-bit systems).
#[cfg(all(target_os = "linux", target_env = "gnu"))]
const HEAP_BLOCKS_UP_TO: libc::c_int = 32 << 20;

/// Free memory at the top of the C allocator's heap beyond this is returned to the system.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
const KEEP_FREE_UP_TO: libc::c_int = 64 << 20;

/// Makes the C allocator keep freed memory for reuse: blocks up to 32 MB come from its heap
/// and free memory up to 64 MB stays there, instead of glibc's default of mapping every block
/// above 128 kB separately and unmapping it on free. Exact polynomial arithmetic frees and
/// allocates vectors of hundreds of kilobytes all the time; with the default each one is
/// mapped afresh and every page of it faults on first touch (about 1.3 us a page on a virtual
/// machine, a fifth of the time of a mid-sized expansion). Returns whether the settings were
/// taken (always `false` off glibc, where the allocator's defaults stay).
///
/// Called first thing by the binaries; a library does not change the process's allocator.
pub fn keep_freed_memory() -> bool {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    {
        // SAFETY: `mallopt` only changes two parameters of glibc's allocator; it is called
        // before any other thread exists, and any values are valid (out-of-range ones are
        // refused with a zero return).
        unsafe {
            libc::mallopt(libc::M_MMAP_THRESHOLD, HEAP_BLOCKS_UP_TO) == 1
                && libc::mallopt(libc::M_TRIM_THRESHOLD, KEEP_FREE_UP_TO) == 1
        }
    }
    #[cfg(not(all(target_os = "linux", target_env = "gnu")))]
    {
        false
    }
}

/// A fixed buffer for formatting a message without allocating.
struct StackText {
    buf: [u8; 256],
    len: usize,
}

impl std::fmt::Write for StackText {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let room = self.buf.len() - self.len;
        let n = s.len().min(room);
        self.buf[self.len..self.len + n].copy_from_slice(&s.as_bytes()[..n]);
        self.len += n;
        Ok(())
    }
}

/// Set by the first thread that ends the process.
static ENDING: AtomicBool = AtomicBool::new(false);

/// Writes one line to standard error and ends the process with exit status 2, running no
/// destructors and allocating nothing (the temporary file of an output file being written is
/// removed first, [`crate::output::remove_temp_file`]). Only the first caller writes: with
/// claims checked on several threads, two of them can pass the memory cap at once (or the
/// watchdog fire while a thread passes it), and the contract is one line. The others wait for
/// the exit.
fn die(args: std::fmt::Arguments<'_>) -> ! {
    if ENDING.swap(true, Ordering::SeqCst) {
        wait_for_exit()
    }
    let mut text = StackText {
        buf: [0; 256],
        len: 0,
    };
    let _ = std::fmt::write(&mut text, args);
    crate::output::remove_temp_file();
    // A `--program` float side (and anything it started) does not outlive exactcheck.
    exactcheck_float::external::stop_all();
    exit_with(&text.buf[..text.len])
}

/// Blocks the calling thread when another thread is already ending the process (a `--timeout`
/// or the memory cap), so that the command's own result, often a failure caused by that ending
/// (a `--program` killed by it), is not reported in place of the ending's one line.
pub fn defer_to_ending() {
    if ENDING.load(Ordering::SeqCst) {
        wait_for_exit()
    }
}

/// Blocks this thread, allocating nothing, while another thread ends the process.
#[cfg(unix)]
fn wait_for_exit() -> ! {
    loop {
        // SAFETY: `pause` only suspends the calling thread until a signal arrives.
        unsafe {
            libc::pause();
        }
    }
}

#[cfg(not(unix))]
fn wait_for_exit() -> ! {
    loop {
        std::thread::sleep(Duration::from_secs(1));
    }
}

#[cfg(unix)]
fn exit_with(line: &[u8]) -> ! {
    // SAFETY: `write` reads `line.len()` bytes of a live buffer; `_exit` never returns.
    unsafe {
        let _ = libc::write(2, line.as_ptr().cast(), line.len());
        libc::_exit(2)
    }
}

#[cfg(not(unix))]
fn exit_with(line: &[u8]) -> ! {
    use std::io::Write as _;
    let _ = std::io::stderr().write_all(line);
    std::process::exit(2)
}

#[cold]
fn out_of_memory() -> ! {
    let l = &limits::MEMORY;
    if CAP_IS_ADDRESS_SPACE.load(Ordering::Relaxed) {
        die(format_args!(
            "exactcheck: error: {} exceeds {} MB, three quarters of the address space this process may use (ulimit -v), below the limit {} = {} {}\n",
            l.what(),
            CAP.load(Ordering::Relaxed) >> 20,
            l.name(),
            l.get(),
            l.unit()
        ))
    }
    die(format_args!(
        "exactcheck: error: {} exceeds the limit {} = {} {} (raise it with --limit {}=N)\n",
        l.what(),
        l.name(),
        l.get(),
        l.unit(),
        l.name()
    ))
}

/// Ends the process with one line when the system refuses an allocation of `size` bytes that
/// the cap allowed (an address space smaller than the limit, or memory exhausted): the runtime
/// would abort instead.
#[cold]
fn refused(size: usize) -> ! {
    let l = &limits::MEMORY;
    die(format_args!(
        "exactcheck: error: the system refused {} MB more memory with {} MB in use, below the limit {} = {} {} (lower it with --limit {}=N)\n",
        size.div_ceil(1 << 20),
        bytes_in_use() >> 20,
        l.name(),
        l.get(),
        l.unit(),
        l.name()
    ))
}

/// The shortest `--timeout`, in seconds: a shorter one would end every run before it starts.
pub const MIN_TIMEOUT: f64 = 0.001;

/// Ends the process with one line and exit status 2 when `seconds` have passed.
///
/// # Errors
/// A `seconds` that is not a finite number between [`MIN_TIMEOUT`] (a millisecond) and 1e9.
pub fn start_timeout(seconds: f64) -> Result<(), crate::Error> {
    if !(seconds.is_finite() && (MIN_TIMEOUT..=1e9).contains(&seconds)) {
        // The value as written when it is short (`-1`, `0`, `inf`), else in scientific notation
        // (`1e-300`), so the line stays short.
        let plain = format!("{seconds}");
        let got = if plain.len() > 24 {
            format!("{seconds:e}")
        } else {
            plain
        };
        return Err(crate::Error::Usage(format!(
            "--timeout must be a number of seconds between {MIN_TIMEOUT} and 1e9 (got {got})"
        )));
    }
    let budget = Duration::from_secs_f64(seconds);
    std::thread::Builder::new()
        .name("timeout".into())
        .spawn(move || {
            std::thread::sleep(budget);
            clear_progress();
            die(format_args!(
                "exactcheck: error: the command did not finish within --timeout {seconds} s\n"
            ))
        })
        .map_err(|e| crate::Error::Usage(format!("--timeout: cannot start its timer: {e}")))?;
    Ok(())
}

/// Starts rayon's global pool of worker threads for the command, on the thread that runs it:
/// `RAYON_NUM_THREADS` threads (at most the `threads` limit; unset, 0 or not a number: one per
/// core) with `stack` bytes of stack each (rayon's default when `None`).
///
/// Rayon builds its global pool once per process; if that build fails (the system refuses a
/// thread: `ulimit -u`, `ulimit -v`), every later parallel loop panics. So the threads are first
/// started in a trial pool; when that fails the command runs on one thread, its own (one line on
/// standard error says so), which needs no new thread. A pool built before (a process running
/// several commands) is kept.
///
/// # Errors
/// [`crate::Error::Limit`] when `RAYON_NUM_THREADS` is past the `threads` limit;
/// [`crate::Error::Usage`] when the trial pool started but the global one then could not.
pub fn start_thread_pool(stack: Option<usize>) -> Result<(), crate::Error> {
    let threads = worker_threads(std::env::var("RAYON_NUM_THREADS").ok().as_deref())?;
    start_pool_of(threads, stack)
}

/// The number of worker threads `RAYON_NUM_THREADS` asks for, as rayon reads it (unset, 0 or not
/// a number: one per core), within the `threads` limit.
///
/// # Errors
/// [`crate::Error::Limit`] past the limit.
pub fn worker_threads(env: Option<&str>) -> Result<usize, crate::Error> {
    let asked = env
        .and_then(|v| v.trim().parse::<u64>().ok())
        .filter(|&n| n > 0);
    let Some(n) = asked else {
        return Ok(std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get));
    };
    crate::limits::THREADS
        .check(n)
        .map_err(crate::Error::Limit)?;
    Ok(usize::try_from(n).unwrap_or(usize::MAX))
}

/// [`start_thread_pool`] with the number of threads given.
///
/// # Errors
/// As [`start_thread_pool`].
pub fn start_pool_of(threads: usize, stack: Option<usize>) -> Result<(), crate::Error> {
    use std::error::Error as _;
    static STARTED: std::sync::OnceLock<()> = std::sync::OnceLock::new();
    if STARTED.get().is_some() {
        return Ok(());
    }
    let builder = |n: usize| {
        let b = rayon::ThreadPoolBuilder::new().num_threads(n);
        match stack {
            Some(bytes) => b.stack_size(bytes),
            None => b,
        }
    };
    match trial_pool(threads, builder(threads)) {
        Ok(()) => {
            // An error without a source: the global pool exists already, which is as good.
            if let Err(e) = builder(threads).build_global() {
                if e.source().is_some() {
                    return Err(crate::Error::Usage(format!(
                        "cannot start {threads} worker threads: {e} (set RAYON_NUM_THREADS lower)"
                    )));
                }
            }
        }
        Err(e) => {
            eprintln!(
                "exactcheck: warning: cannot start {threads} worker threads ({e}); running on one thread"
            );
            // The calling thread is the pool's one worker: no thread to start, so no failure
            // beyond a pool that exists already.
            let _ = rayon::ThreadPoolBuilder::new()
                .num_threads(1)
                .use_current_thread()
                .build_global();
        }
    }
    let _ = STARTED.set(());
    Ok(())
}

/// Starts `threads` threads in a pool of their own and stops them again, waiting (a bounded
/// while) for them to end, so that the global pool built next finds their resources free.
fn trial_pool(
    threads: usize,
    builder: rayon::ThreadPoolBuilder,
) -> Result<(), rayon::ThreadPoolBuildError> {
    let ended = std::sync::Arc::new(AtomicUsize::new(0));
    let counter = std::sync::Arc::clone(&ended);
    let pool = builder
        .exit_handler(move |_| {
            counter.fetch_add(1, Ordering::SeqCst);
        })
        .build()?;
    drop(pool);
    let start = Instant::now();
    while ended.load(Ordering::SeqCst) < threads && start.elapsed() < Duration::from_secs(2) {
        std::thread::sleep(Duration::from_millis(1));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stack_text_truncates_instead_of_allocating() {
        let mut t = StackText {
            buf: [0; 256],
            len: 0,
        };
        let long = "x".repeat(300);
        let _ = std::fmt::write(&mut t, format_args!("{long}"));
        assert_eq!(t.len, 256);
    }

    #[test]
    fn the_allocator_takes_the_settings_on_glibc() {
        assert_eq!(
            keep_freed_memory(),
            cfg!(all(target_os = "linux", target_env = "gnu"))
        );
    }

    #[test]
    fn rayon_num_threads_is_read_as_rayon_reads_it_within_the_limit() {
        let cores = std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get);
        for default in [None, Some(""), Some("0"), Some("many")] {
            assert_eq!(worker_threads(default).unwrap(), cores, "{default:?}");
        }
        assert_eq!(worker_threads(Some(" 3 ")).unwrap(), 3);
        assert_eq!(worker_threads(Some("1024")).unwrap(), 1024);
        let e = worker_threads(Some("1025")).unwrap_err().to_string();
        assert!(
            e.contains("exceeds the limit threads = 1024 (found 1025"),
            "{e}"
        );
    }

    #[test]
    fn timeouts_must_be_positive_and_finite() {
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, 2e9, 1e-300, 0.0009] {
            assert!(start_timeout(bad).is_err(), "{bad}");
        }
    }
}
