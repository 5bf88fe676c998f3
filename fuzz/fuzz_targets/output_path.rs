//! The spelling checks of output paths and the temporary file next to an output
//! (`exactcheck::output::check_path_text`, `temp_path`): no file system access.
//!
//! From the input (UTF-8 text; other bytes are skipped): the text as an output path, as a file
//! and as a directory. Checked: a refusal is one sentence that stays one line as an error; an
//! accepted path is not empty, not `-`, has no NUL byte, and as a file names a file (its last
//! segment is not empty, `.` or `..`, and `Path::file_name` finds it); its temporary file lies
//! in the same directory, is hidden, differs from the output, ends in `.tmp` and stays short
//! whatever the output's name. Never a panic.
#![no_main]
use exactcheck::output::{check_path_text, temp_path, Target};
use exactcheck_fuzz::MAX_INPUT;
use libfuzzer_sys::fuzz_target;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let data = &data[..data.len().min(MAX_INPUT)];
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    for target in [Target::File, Target::Dir] {
        match check_path_text(text, target) {
            Err(why) => {
                assert!(!why.is_empty());
                let shown = exactcheck::Error::Usage(why).to_string();
                assert!(!shown.contains('\n'), "{shown:?}");
            }
            Ok(()) => {
                assert!(
                    !text.is_empty() && text != "-" && !text.contains('\0'),
                    "{text:?}"
                );
                if target == Target::Dir {
                    continue;
                }
                let path = Path::new(text);
                let name = path
                    .file_name()
                    .unwrap_or_else(|| panic!("{text:?} was accepted as a file"));
                for n in [0, u64::MAX] {
                    let temp = temp_path(path, n);
                    assert_ne!(temp.as_path(), path, "{text:?}");
                    let same_dir = match (temp.parent(), path.parent()) {
                        (Some(a), Some(b)) => a.components().eq(b.components()),
                        _ => false,
                    };
                    assert!(same_dir, "{text:?}: {temp:?}");
                    let temp_name = temp.file_name().expect("a file name").to_string_lossy();
                    assert!(temp_name.starts_with('.') && temp_name.ends_with(".tmp"));
                    assert_ne!(temp.file_name(), Some(name), "{text:?}");
                    assert!(temp_name.len() <= 100 + 48, "{temp_name:?}");
                }
            }
        }
    }
});
