//! The facts of the report's header: the command line, the date (UTC), the versions and the
//! machine.
//!
//! The date is computed from the system clock with the proleptic Gregorian calendar by hand
//! ([`civil_date`], the days-to-civil algorithm: shift the epoch to 0000-03-01 so the leap day
//! ends a year, split into 400-year eras of 146,097 days, then year-of-era and day-of-year) so
//! the tool needs no date crate for one line of its report. The command line is quoted for a
//! POSIX shell by hand too ([`shell_quote`]): single quotes around any word with a character
//! outside a safe set.

use std::ffi::OsString;
use std::time::{SystemTime, UNIX_EPOCH};

/// What the header states besides the subject.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Meta {
    /// The command line that produced the report, quoted for a shell.
    pub command: String,
    /// The date and time of the run, `YYYY-MM-DD HH:MM:SS UTC`.
    pub date: String,
    /// exactcheck's version.
    pub version: String,
    /// The git commit it was built from (`None`: not built from a git checkout).
    pub commit: Option<String>,
    /// `rustc --version` of the build.
    pub rustc: String,
    /// The versions of num-bigint and num-rational the build locked.
    pub num_bigint: String,
    /// See `num_bigint`.
    pub num_rational: String,
    /// The machine: logical cores, OS and architecture.
    pub machine: String,
}

impl Meta {
    /// The facts of this run: `args` is the command line (program name first).
    pub fn now(args: &[OsString]) -> Meta {
        let seconds = SystemTime::now()
            .duration_since(UNIX_EPOCH)
            .map_or(0, |d| d.as_secs());
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        let commit = env!("EXACTCHECK_GIT_COMMIT");
        let or_unknown = |s: &str| {
            if s.is_empty() {
                "unknown".to_string()
            } else {
                s.to_string()
            }
        };
        Meta {
            command: command_line(args),
            date: utc_timestamp(seconds),
            version: env!("CARGO_PKG_VERSION").to_string(),
            commit: (!commit.is_empty()).then(|| commit.to_string()),
            rustc: or_unknown(env!("EXACTCHECK_RUSTC")),
            num_bigint: or_unknown(env!("EXACTCHECK_NUM_BIGINT")),
            num_rational: or_unknown(env!("EXACTCHECK_NUM_RATIONAL")),
            machine: format!(
                "{cores} logical core{}, {} {}",
                if cores == 1 { "" } else { "s" },
                std::env::consts::OS,
                std::env::consts::ARCH
            ),
        }
    }
}

/// The command line as one shell-quoted string; the program is named by its file name
/// (`exactcheck`), not the path it was started from.
pub fn command_line(args: &[OsString]) -> String {
    args.iter()
        .enumerate()
        .map(|(i, a)| {
            let a = a.to_string_lossy();
            if i == 0 {
                let name = std::path::Path::new(a.as_ref())
                    .file_name()
                    .map_or_else(|| a.to_string(), |n| n.to_string_lossy().to_string());
                shell_quote(&name)
            } else {
                shell_quote(&a)
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// `word` as a POSIX shell reads it back: unchanged when every character is safe, else in
/// single quotes (a single quote inside written `'\''`).
pub fn shell_quote(word: &str) -> String {
    let safe = |c: char| c.is_ascii_alphanumeric() || "-_./=:,+@%^".contains(c);
    if !word.is_empty() && word.chars().all(safe) {
        word.to_string()
    } else {
        format!("'{}'", word.replace('\'', r"'\''"))
    }
}

/// `seconds` since the Unix epoch as `YYYY-MM-DD HH:MM:SS UTC`.
pub fn utc_timestamp(seconds: u64) -> String {
    let days = seconds / 86_400;
    let rem = seconds % 86_400;
    let (y, m, d) = civil_date(days);
    format!(
        "{y:04}-{m:02}-{d:02} {:02}:{:02}:{:02} UTC",
        rem / 3600,
        rem / 60 % 60,
        rem % 60
    )
}

/// The Gregorian date `(year, month, day)` of the day `days` after 1970-01-01.
pub fn civil_date(days: u64) -> (u64, u64, u64) {
    // Days since 0000-03-01 (719,468 days before the epoch): March-based years put the leap
    // day last.
    let z = days + 719_468;
    let era = z / 146_097;
    let doe = z % 146_097; // day of the 400-year era, 0..=146096
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365; // 0..=399
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100); // day of the March-based year
    let mp = (5 * doy + 2) / 153; // March = 0
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + u64::from(month <= 2);
    (year, month, day)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates_of_known_days() {
        assert_eq!(civil_date(0), (1970, 1, 1));
        assert_eq!(civil_date(59), (1970, 3, 1));
        // 2000-02-29 (a leap day of a year divisible by 400) and the day after.
        assert_eq!(civil_date(11_016), (2000, 2, 29));
        assert_eq!(civil_date(11_017), (2000, 3, 1));
        // 2100 is not a leap year: 2100-02-28 is followed by 2100-03-01.
        assert_eq!(civil_date(47_540), (2100, 2, 28));
        assert_eq!(civil_date(47_541), (2100, 3, 1));
        assert_eq!(utc_timestamp(1_700_000_000), "2023-11-14 22:13:20 UTC");
        assert_eq!(utc_timestamp(951_868_799), "2000-02-29 23:59:59 UTC");
    }

    #[test]
    fn every_day_follows_the_previous_one() {
        let days_in = |y: u64, m: u64| match m {
            2 if (y % 4 == 0 && y % 100 != 0) || y % 400 == 0 => 29,
            2 => 28,
            4 | 6 | 9 | 11 => 30,
            _ => 31,
        };
        let mut prev = civil_date(0);
        for day in 1..200_000 {
            let (y, m, d) = civil_date(day);
            let expected = if prev.2 < days_in(prev.0, prev.1) {
                (prev.0, prev.1, prev.2 + 1)
            } else if prev.1 < 12 {
                (prev.0, prev.1 + 1, 1)
            } else {
                (prev.0 + 1, 1, 1)
            };
            assert_eq!((y, m, d), expected, "day {day}");
            prev = (y, m, d);
        }
    }

    #[test]
    fn command_lines_read_back_in_a_shell() {
        assert_eq!(shell_quote("report"), "report");
        assert_eq!(shell_quote("out dir"), "'out dir'");
        assert_eq!(shell_quote("it's"), r"'it'\''s'");
        assert_eq!(shell_quote(""), "''");
        let args: Vec<OsString> = ["/x/target/release/exactcheck", "report", "-o", "my out"]
            .iter()
            .map(OsString::from)
            .collect();
        assert_eq!(command_line(&args), "exactcheck report -o 'my out'");
    }
}
