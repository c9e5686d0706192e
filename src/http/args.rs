//! Value parsers for `fieldbal serve`'s numeric settings.
//!
//! A limit, timeout or count of 0 would start a service that refuses or
//! drops everything (`--solve-slots 0`: every solve waits for a slot that
//! never comes, then 503; `--request-timeout-secs 0`: every request 408;
//! `--max-planes 0`: every session `too_large`), so these settings refuse 0
//! at start, naming the flag, instead of accepting it silently. Settings
//! where 0 means something (`--shutdown-grace-secs`, `--solve-queue-ms`)
//! keep the plain parser.

/// A whole number of at least 1.
pub fn positive_u64(s: &str) -> Result<u64, String> {
    let n: u64 = s
        .trim()
        .parse()
        .map_err(|e| format!("not a whole number ({e})"))?;
    if n == 0 {
        return Err(
            "must be at least 1 (0 would refuse every request this setting governs)".into(),
        );
    }
    Ok(n)
}

/// [`positive_u64`] for counts and sizes.
pub fn positive_usize(s: &str) -> Result<usize, String> {
    usize::try_from(positive_u64(s)?).map_err(|_| "too large for this machine".into())
}

#[cfg(test)]
mod tests {
    use clap::Parser;

    use crate::cli::Cli;

    fn serve(args: &[&str]) -> Result<Cli, String> {
        let mut all = vec!["fieldbal", "serve"];
        all.extend_from_slice(args);
        Cli::try_parse_from(all).map_err(|e| e.to_string())
    }

    #[test]
    fn zero_limits_timeouts_and_slots_are_refused_at_start_naming_the_flag() {
        for flag in [
            "--solve-slots",
            "--request-timeout-secs",
            "--body-limit-bytes",
            "--max-planes",
            "--max-sensors",
            "--max-speed-points",
            "--max-runs",
            "--max-readings",
            "--header-read-timeout-secs",
            "--write-timeout-secs",
            "--max-connections",
        ] {
            let err = serve(&[flag, "0"])
                .err()
                .unwrap_or_else(|| panic!("{flag} 0 accepted"));
            assert!(
                err.contains(flag) && err.contains("at least 1"),
                "{flag}: {err}"
            );
            assert!(serve(&[flag, "3"]).is_ok(), "{flag} 3 refused");
        }
    }

    #[test]
    fn zero_stays_meaningful_where_it_means_no_wait() {
        assert!(serve(&["--shutdown-grace-secs", "0", "--solve-queue-ms", "0"]).is_ok());
    }

    #[test]
    fn the_defaults_still_parse() {
        assert!(serve(&[]).is_ok());
    }
}
