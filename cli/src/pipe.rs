//! Output into a closed pipe: `lpe-check diff --cases 3000 | head -1` stops quietly, as
//! Unix tools do, instead of panicking.
//!
//! Rust ignores SIGPIPE, so a write to a pipe whose reader has gone fails with
//! `BrokenPipe`, and `println!` turns that failure into a panic ("failed printing to
//! stdout: Broken pipe"). Rather than thread an `io::Result` through every subcommand's
//! printing, the binary installs [`quiet_on_closed_pipe`] as its panic hook: a panic that
//! is exactly that failure ends the process at once, printing nothing, with
//! [`CLOSED_PIPE_EXIT`]; any other panic goes on to the hook that was there before.

/// The exit status after output into a closed pipe: 128 + SIGPIPE, what a shell reports
/// for a tool that SIGPIPE ended (`yes | head -1` under `set -o pipefail`).
pub const CLOSED_PIPE_EXIT: i32 = 128 + 13;

/// The exit code of a subcommand whose own write to standard output failed with `e`:
/// [`CLOSED_PIPE_EXIT`], quietly, when the reader has gone; otherwise 2 with the error
/// (a full disk is not a success).
pub fn write_failed(e: &std::io::Error) -> std::process::ExitCode {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        std::process::ExitCode::from(CLOSED_PIPE_EXIT as u8)
    } else {
        eprintln!("error: writing the output: {e}");
        std::process::ExitCode::from(2)
    }
}

/// Whether a panic message is `print!`/`eprint!`'s failure on a closed pipe.
pub fn is_closed_pipe(message: &str) -> bool {
    let printing = message.starts_with("failed printing to stdout")
        || message.starts_with("failed printing to stderr");
    // The message carries the OS error's text, which Rust takes from the C locale it
    // never changes: "Broken pipe (os error 32)".
    printing && message.contains("Broken pipe")
}

/// Installs the panic hook described in the module docs.
pub fn quiet_on_closed_pipe() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let payload = info.payload();
        let message = payload
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| payload.downcast_ref::<&str>().copied())
            .unwrap_or("");
        if is_closed_pipe(message) {
            std::process::exit(CLOSED_PIPE_EXIT);
        }
        previous(info);
    }));
}

#[cfg(test)]
mod tests {
    use super::is_closed_pipe;

    #[test]
    fn only_a_print_into_a_closed_pipe_is_quiet() {
        assert!(is_closed_pipe(
            "failed printing to stdout: Broken pipe (os error 32)"
        ));
        assert!(is_closed_pipe(
            "failed printing to stderr: Broken pipe (os error 32)"
        ));
        // Other failures of the same print, and other panics naming a pipe, still
        // report as internal failures.
        assert!(!is_closed_pipe(
            "failed printing to stdout: No space left on device (os error 28)"
        ));
        assert!(!is_closed_pipe("Broken pipe while talking to the adapter"));
        assert!(!is_closed_pipe(""));
    }
}
