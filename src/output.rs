//! Everything a command writes: standard output, output files, output directories.
//!
//! **Standard output.** `println!` panics when standard output is closed or full ("failed
//! printing to stdout"). The commands write through [`println()`] / [`print()`] instead, which
//! return the failure as [`Error::Output`]: [`crate::cli::main`] ends quietly with exit status 0
//! on a broken pipe (the reader, e.g. `head -1`, has what it wanted; Rust ignores `SIGPIPE`, so
//! the write returns `EPIPE`) and reports any other failure as one line, "cannot write standard
//! output: No space left on device", with exit status 2. Every write is flushed at once, so a
//! failure is seen by the command that caused it and not later by the runtime's exit-time flush
//! (which would ignore it). A report of several parts is collected in a [`Text`] and printed
//! whole once complete, so an error or `--timeout` in a later part leaves nothing rather than
//! the first parts looking like the whole report.
//!
//! **Output files.** Every file a command writes goes through [`write_file`]: the path is
//! checked first ([`check_output_file`]: not empty, not a directory, not one of the command's
//! inputs), the contents go to a new temporary file in the same directory, are flushed to disk
//! and renamed over the path. A full disk, the file-size limit (`ulimit -f`; [`ignore_sigxfsz`]
//! makes the write fail with `EFBIG` instead of killing the process), a kill or a second writer
//! never leave a truncated file under the name, and the file that was there stays as it was
//! until the new one is complete. A symbolic link at the path is replaced, not followed. An
//! existing device or pipe (`/dev/null`) and the names in `/dev` and `/proc` (`/dev/stdout`)
//! are written directly: there is nothing to replace. Output directories are checked before the work ([`check_output_dir`]) and
//! created only once there is something to write ([`create_dirs`]).

use crate::Error;
use std::fmt::Display;
use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

/// Writes `text` and a newline to standard output and flushes it.
///
/// # Errors
/// [`Error::Output`] when the write or the flush fails (test it with
/// [`Error::is_broken_pipe`]).
pub fn println(text: impl Display) -> Result<(), Error> {
    crate::progress::clear_progress();
    write_line(&mut io::stdout().lock(), text)
}

/// Writes `text` (no newline added) to standard output and flushes it.
///
/// # Errors
/// As [`println()`].
pub fn print(text: impl Display) -> Result<(), Error> {
    crate::progress::clear_progress();
    let mut out = io::stdout().lock();
    write!(out, "{text}")
        .and_then(|()| out.flush())
        .map_err(Error::Output)
}

/// Writes `text` and a newline to any writer and flushes it, mapping a failure to
/// [`Error::Output`] (the writer stands for standard output).
///
/// # Errors
/// As [`println()`].
pub fn write_line(out: &mut impl Write, text: impl Display) -> Result<(), Error> {
    writeln!(out, "{text}")
        .and_then(|()| out.flush())
        .map_err(Error::Output)
}

/// The progress of a command's steps (claims checked, figures drawn, sweeps run) on standard
/// error: a bar on a terminal, nothing when standard error is piped or `quiet` is set.
pub struct Steps {
    bar: Option<indicatif::ProgressBar>,
}

impl Steps {
    /// A bar of `count` steps; hidden when `quiet` or when standard error is not a terminal.
    pub fn new(count: u64, quiet: bool) -> Steps {
        let bar = (!quiet && io::IsTerminal::is_terminal(&io::stderr())).then(|| {
            let bar = indicatif::ProgressBar::new(count);
            if let Ok(style) = indicatif::ProgressStyle::with_template(
                "{spinner} [{bar:24}] {pos}/{len} {msg} ({elapsed})",
            ) {
                bar.set_style(style.progress_chars("=> "));
            }
            bar.enable_steady_tick(std::time::Duration::from_millis(120));
            bar
        });
        Steps { bar }
    }

    /// Starts the step described by `what`.
    pub fn start(&self, what: &str) {
        if let Some(bar) = &self.bar {
            bar.set_message(what.to_string());
        }
    }

    /// Ends the current step.
    pub fn done(&self) {
        if let Some(bar) = &self.bar {
            bar.inc(1);
        }
    }
}

impl Drop for Steps {
    fn drop(&mut self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

/// A text report collected whole, printed once complete by [`Text::print`].
#[derive(Debug, Default)]
pub struct Text(String);

impl Text {
    /// An empty report.
    pub fn new() -> Text {
        Text::default()
    }

    /// Appends `text` and a newline.
    pub fn line(&mut self, text: impl Display) {
        use std::fmt::Write as _;
        // Writing into a String cannot fail.
        let _ = writeln!(self.0, "{text}");
    }

    /// Prints the whole report to standard output.
    ///
    /// # Errors
    /// As [`print()`].
    pub fn print(self) -> Result<(), Error> {
        print(self.0)
    }
}

/// What an output path names: a file to write, or a directory to write files into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// A file ([`write_file`]).
    File,
    /// A directory ([`create_dirs`]).
    Dir,
}

impl Target {
    fn noun(self) -> &'static str {
        match self {
            Target::File => "file",
            Target::Dir => "directory",
        }
    }
}

/// Checks how an output path is spelled (no file system access): `Err` says why `path` cannot
/// name the output file or directory. Refused: the empty path (it would mean the working
/// directory, and `report -o ''` wrote `./index.html`), a NUL byte, `-` (standard output, which
/// a command that writes to it handles before calling this; `./-` names a file called `-`), and
/// for a file a path ending in `/`, `.` or `..` (it names a directory; `out.svg/.` would write
/// `out.svg`).
///
/// # Errors
/// One sentence saying what is wrong with `path`.
pub fn check_path_text(path: &str, target: Target) -> Result<(), String> {
    let noun = target.noun();
    if path.is_empty() {
        return Err(format!("the output path is empty; name a {noun}"));
    }
    if path.contains('\0') {
        return Err(format!("the output path {path} contains a NUL byte"));
    }
    if path == "-" {
        return Err(format!(
            "`-` means standard output, and this output is a {noun}; write ./- for a {noun} named -"
        ));
    }
    if target == Target::File {
        let last = path.rsplit(std::path::is_separator).next().unwrap_or(path);
        if last.is_empty() || last == "." || last == ".." {
            return Err(format!(
                "the output path {path} names a directory, not a file"
            ));
        }
    }
    Ok(())
}

/// The longest part of the output file's name kept in its temporary file's name (the whole
/// name plus the suffix could pass the file system's 255-byte limit).
const TEMP_NAME_BYTES: usize = 100;

/// The temporary file [`write_file`] writes before renaming it to `path`: in the same
/// directory (a rename within one file system is atomic), hidden, named after the output, this
/// process and `n`: `dir/.NAME.PID.N.tmp`.
pub fn temp_path(path: &Path, n: u64) -> PathBuf {
    let name = path
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    let mut cut = name.len().min(TEMP_NAME_BYTES);
    while !name.is_char_boundary(cut) {
        cut -= 1;
    }
    let temp = format!(".{}.{}.{n}.tmp", &name[..cut], std::process::id());
    match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir.join(temp),
        _ => PathBuf::from(temp),
    }
}

/// Whether writing `output` would replace the file `input`: the same file (device and inode;
/// any spelling of the path, or a hard link). A symbolic link at `output` is not followed (the
/// rename replaces the link, not its target); one at `input` is.
fn replaces(output: &Path, input: &Path) -> bool {
    let (Ok(out), Ok(inp)) = (fs::symlink_metadata(output), fs::metadata(input)) else {
        return false;
    };
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt as _;
        out.dev() == inp.dev() && out.ino() == inp.ino()
    }
    #[cfg(not(unix))]
    {
        let _ = (out, inp);
        matches!(
            (fs::canonicalize(output), fs::canonicalize(input)),
            (Ok(a), Ok(b)) if a == b
        )
    }
}

/// Checks the output file `path` before any work is done: spelled as a file
/// ([`check_path_text`]), not an existing directory, and not one of `inputs` (the files the
/// command reads; `plot p.json -o p.json` would replace the problem with its figure).
///
/// # Errors
/// [`Error::Usage`] naming the path and what is wrong.
pub fn check_output_file(path: &str, inputs: &[&Path]) -> Result<(), Error> {
    check_path_text(path, Target::File).map_err(Error::Usage)?;
    let target = Path::new(path);
    if fs::metadata(target).is_ok_and(|m| m.is_dir()) {
        return Err(Error::Usage(format!(
            "the output path {path} is a directory, not a file"
        )));
    }
    if let Some(input) = inputs.iter().find(|i| replaces(target, i)) {
        return Err(Error::Usage(format!(
            "the output file {path} is the input {}; writing it would replace the input (choose another output)",
            input.display()
        )));
    }
    Ok(())
}

/// Checks the output directory `dir` before any work is done: spelled as a directory
/// ([`check_path_text`]) and, when it exists, a directory.
///
/// # Errors
/// [`Error::Usage`] naming the path and what is wrong.
pub fn check_output_dir(dir: &str) -> Result<(), Error> {
    check_path_text(dir, Target::Dir).map_err(Error::Usage)?;
    let path = Path::new(dir);
    if path.exists() && !path.is_dir() {
        return Err(Error::Usage(format!(
            "the output directory {dir} is a file, not a directory"
        )));
    }
    Ok(())
}

/// Creates the output directory `dir` and its missing parents (after [`check_output_dir`]).
/// Returns the directories it created, deepest last, for [`remove_created_dirs`] when the
/// write that follows fails.
///
/// # Errors
/// [`Error::Usage`] as [`check_output_dir`]; [`Error::Write`] when a directory cannot be
/// created.
pub fn create_dirs(dir: &str) -> Result<Vec<PathBuf>, Error> {
    check_output_dir(dir)?;
    let mut missing = Vec::new();
    let mut at = Some(Path::new(dir));
    while let Some(p) = at.filter(|p| !p.as_os_str().is_empty() && !p.exists()) {
        missing.push(p.to_path_buf());
        at = p.parent();
    }
    missing.reverse();
    fs::create_dir_all(dir).map_err(|source| Error::Write {
        path: dir.to_string(),
        source,
    })?;
    Ok(missing)
}

/// Removes the directories [`create_dirs`] created, deepest first, where they are still empty.
pub fn remove_created_dirs(created: &[PathBuf]) {
    for d in created.iter().rev() {
        let _ = fs::remove_dir(d);
    }
}

/// Writes `contents` to the file `path` whole or not at all (see the module documentation):
/// checked by [`check_output_file`] against `inputs`, written to [`temp_path`], flushed to
/// disk, given the permissions of the file it replaces, and renamed over `path`.
///
/// # Errors
/// [`Error::Usage`] as [`check_output_file`]; [`Error::Write`] when the temporary file cannot
/// be created, written or renamed (it is removed; `path` is left as it was).
pub fn write_file(path: &str, contents: &[u8], inputs: &[&Path]) -> Result<(), Error> {
    check_output_file(path, inputs)?;
    let target = Path::new(path);
    let fail = |source| Error::Write {
        path: path.to_string(),
        source,
    };
    if in_place(target) {
        return fs::OpenOptions::new()
            .write(true)
            .create(true)
            .truncate(true)
            .open(target)
            .and_then(|mut f| f.write_all(contents).and_then(|()| f.flush()))
            .map_err(fail);
    }
    let (temp, mut file) = create_temp(target).map_err(fail)?;
    let guard = TempFile::register(temp);
    let replaced = fs::symlink_metadata(target)
        .ok()
        .filter(fs::Metadata::is_file);
    let written = file
        .write_all(contents)
        .and_then(|()| match &replaced {
            Some(m) => file.set_permissions(m.permissions()),
            None => Ok(()),
        })
        .and_then(|()| file.sync_all());
    drop(file);
    written.map_err(fail)?;
    fs::rename(&guard.path, target).map_err(fail)?;
    guard.keep();
    // The rename itself reaches the disk with the directory; a failure here loses nothing
    // that is not already in place.
    if let Some(dir) = target.parent().filter(|d| !d.as_os_str().is_empty()) {
        let _ = fs::File::open(dir).and_then(|d| d.sync_all());
    }
    Ok(())
}

/// Whether `target` is written in place rather than replaced: a device, pipe or socket (it
/// cannot be replaced by a rename), or a name in `/dev` or `/proc` (`/dev/stdout`,
/// `/dev/fd/1`: links to this process's open files, which a rename would destroy, not write).
fn in_place(target: &Path) -> bool {
    if fs::metadata(target).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
        return true;
    }
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    fs::canonicalize(dir).is_ok_and(|d| d.starts_with("/dev") || d.starts_with("/proc"))
}

/// Creates a new temporary file for `target` ([`temp_path`]), never opening an existing one.
fn create_temp(target: &Path) -> io::Result<(PathBuf, fs::File)> {
    static NEXT: AtomicU64 = AtomicU64::new(0);
    loop {
        let temp = temp_path(target, NEXT.fetch_add(1, Ordering::Relaxed));
        match fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&temp)
        {
            Ok(file) => return Ok((temp, file)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
}

/// The temporary file being written, as a C string, so that [`remove_temp_file`] can remove it
/// without allocating when `--timeout` or the `memory` limit ends the process.
#[cfg(unix)]
static PENDING: Mutex<Option<std::ffi::CString>> = Mutex::new(None);

/// A temporary file, removed when dropped unless [`TempFile::keep`] was called.
struct TempFile {
    path: PathBuf,
    kept: bool,
}

impl TempFile {
    fn register(path: PathBuf) -> TempFile {
        #[cfg(unix)]
        {
            use std::os::unix::ffi::OsStrExt as _;
            let c = std::ffi::CString::new(path.as_os_str().as_bytes()).ok();
            if let Ok(mut pending) = PENDING.lock() {
                *pending = c;
            }
        }
        TempFile { path, kept: false }
    }

    /// The file was renamed into place: nothing to remove.
    fn keep(mut self) {
        self.kept = true;
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        forget_pending();
        if !self.kept {
            let _ = fs::remove_file(&self.path);
        }
    }
}

fn forget_pending() {
    #[cfg(unix)]
    if let Ok(mut pending) = PENDING.lock() {
        *pending = None;
    }
}

/// Removes the temporary file being written, if any, allocating nothing: called by the
/// process's backstops ([`crate::budget`]) just before they end it.
pub fn remove_temp_file() {
    #[cfg(unix)]
    if let Ok(pending) = PENDING.try_lock() {
        if let Some(c) = pending.as_ref() {
            // SAFETY: `unlink` reads a NUL-terminated string that lives while the lock is held.
            unsafe {
                libc::unlink(c.as_ptr());
            }
        }
    }
}

/// Makes a write past the file-size limit (`ulimit -f`) fail with `EFBIG` ("File too large"),
/// reported as one line, instead of the default `SIGXFSZ` killing the process with a core dump
/// and no message. Called once at start-up.
pub fn ignore_sigxfsz() {
    #[cfg(unix)]
    // SAFETY: setting a signal's disposition to "ignore" installs no handler code.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A writer that fails every write with the given error kind.
    struct Failing(io::ErrorKind);

    impl Write for Failing {
        fn write(&mut self, _: &[u8]) -> io::Result<usize> {
            Err(io::Error::from(self.0))
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn failures_become_errors_not_panics() {
        let e = write_line(&mut Failing(io::ErrorKind::BrokenPipe), "x").unwrap_err();
        assert!(e.is_broken_pipe());
        let e = write_line(&mut Failing(io::ErrorKind::Other), "x").unwrap_err();
        assert!(!e.is_broken_pipe());
        assert!(
            e.to_string().starts_with("cannot write standard output: "),
            "{e}"
        );
        let full = Error::Output(io::Error::from_raw_os_error(28));
        #[cfg(target_os = "linux")]
        assert_eq!(
            full.to_string(),
            "cannot write standard output: No space left on device"
        );
        let mut buf = Vec::new();
        write_line(&mut buf, 42).unwrap();
        assert_eq!(buf, b"42\n");
    }

    /// A fresh scratch directory for one test.
    fn scratch(tag: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!(
            "exactcheck-output-unit-{tag}-{}",
            std::process::id()
        ));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn output_paths_that_name_no_file_are_refused_by_their_spelling() {
        for (path, target, why) in [
            ("", Target::File, "is empty"),
            ("", Target::Dir, "is empty"),
            ("-", Target::File, "standard output"),
            ("-", Target::Dir, "standard output"),
            ("a\0b", Target::File, "NUL"),
            ("out/", Target::File, "names a directory"),
            ("out.svg/.", Target::File, "names a directory"),
            ("..", Target::File, "names a directory"),
            ("a/..", Target::File, "names a directory"),
        ] {
            let e = check_path_text(path, target).unwrap_err();
            assert!(e.contains(why), "{path:?}: {e}");
        }
        for (path, target) in [
            ("out.svg", Target::File),
            ("./-", Target::File),
            ("a/b/.c", Target::File),
            ("out/", Target::Dir),
            (".", Target::Dir),
        ] {
            assert_eq!(check_path_text(path, target), Ok(()), "{path:?}");
        }
    }

    #[test]
    fn the_temporary_file_is_hidden_next_to_the_output() {
        let t = temp_path(Path::new("a/b/fig.svg"), 7);
        assert_eq!(t.parent(), Some(Path::new("a/b")));
        let name = t.file_name().unwrap().to_string_lossy().into_owned();
        assert_eq!(name, format!(".fig.svg.{}.7.tmp", std::process::id()));
        let t = temp_path(Path::new("fig.svg"), 0);
        assert_eq!(t.parent(), Some(Path::new("")));
        let long = "é".repeat(120);
        let t = temp_path(Path::new(&long), 0);
        assert!(t.file_name().unwrap().len() < 160, "{t:?}");
    }

    #[test]
    fn a_file_is_replaced_whole_and_a_failed_write_leaves_the_old_one() {
        let dir = scratch("replace");
        let out = dir.join("out.txt");
        let out_s = out.to_str().unwrap();
        fs::write(&out, "old").unwrap();
        write_file(out_s, b"new", &[]).unwrap();
        assert_eq!(fs::read_to_string(&out).unwrap(), "new");
        // The output is an input: refused, the file untouched.
        let e = write_file(out_s, b"x", &[out.as_path()]).unwrap_err();
        assert!(e.to_string().contains("is the input"), "{e}");
        assert_eq!(fs::read_to_string(&out).unwrap(), "new");
        // A directory in the way of the rename: the error names the path, no temporary file
        // is left.
        let e = write_file(dir.to_str().unwrap(), b"x", &[]).unwrap_err();
        assert!(e.to_string().contains("is a directory"), "{e}");
        let missing = dir.join("no/such/dir/f.txt");
        let e = write_file(missing.to_str().unwrap(), b"x", &[]).unwrap_err();
        assert!(
            matches!(e, Error::Write { .. }) && e.to_string().starts_with("cannot write "),
            "{e}"
        );
        let names: Vec<_> = fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(names, vec![std::ffi::OsString::from("out.txt")]);
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn output_directories_are_checked_created_and_removed_again() {
        let dir = scratch("dirs");
        let file = dir.join("plain");
        fs::write(&file, "x").unwrap();
        let e = check_output_dir(file.to_str().unwrap())
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("is a file, not a directory") && !e.contains('\n'),
            "{e}"
        );
        let sub = dir.join("a/b");
        let created = create_dirs(sub.to_str().unwrap()).unwrap();
        assert!(sub.is_dir());
        assert_eq!(created, vec![dir.join("a"), dir.join("a/b")]);
        remove_created_dirs(&created);
        assert!(!dir.join("a").exists());
        assert_eq!(
            create_dirs(dir.to_str().unwrap()).unwrap(),
            Vec::<PathBuf>::new()
        );
        fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn the_backstops_remove_the_temporary_file_being_written() {
        let dir = scratch("pending");
        let temp = dir.join(".x.tmp");
        fs::write(&temp, "partial").unwrap();
        let guard = TempFile::register(temp.clone());
        remove_temp_file();
        assert!(!temp.exists());
        guard.keep();
        // Once kept (renamed into place), nothing is pending.
        fs::write(&temp, "complete").unwrap();
        remove_temp_file();
        assert!(temp.exists());
        fs::remove_dir_all(&dir).unwrap();
    }
}
