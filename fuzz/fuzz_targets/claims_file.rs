//! Claims files (`exactcheck::claimfile`): TOML or JSON text parsed, resolved and, when it
//! loads, every claim checked (with the lowered limits). The first byte chooses the format: `t`
//! the file is `fuzz.toml`, `j` `fuzz.json`, anything else `fuzz` (the format sniffed from the
//! text, as for a file without extension). Errors are one line; nothing panics.
#![no_main]
use exactcheck::claimfile::{check_with, parse};
use exactcheck_fuzz::{small_limits, text};
use libfuzzer_sys::fuzz_target;

fn one_line(r: Result<impl Sized, exactcheck::Error>, source: &str) {
    if let Err(e) = r {
        let line = e.to_string();
        assert!(
            !line.contains('\n'),
            "a multi-line error for {source:?}: {line:?}"
        );
    }
}

fuzz_target!(|data: &[u8]| {
    small_limits();
    let Some((&flag, rest)) = data.split_first() else {
        return;
    };
    let file = match flag {
        b't' => "fuzz.toml",
        b'j' => "fuzz.json",
        _ => "fuzz",
    };
    let source = text(rest);
    match parse(source, file, "fuzz") {
        Ok(claims) => one_line(check_with(&claims, None, true), source),
        Err(e) => one_line(Err::<(), _>(e), source),
    }
});
