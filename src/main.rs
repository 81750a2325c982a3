//! The `barylab` command line: the app (no arguments) and the headless commands.

mod cli;
mod output;
mod progress_line;

/// mimalloc keeps freed pages for reuse: a frame of a dense mesh allocates its set-up
/// triangles anew, and with the system allocator every frame paid the page faults of fresh
/// memory again.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> std::process::ExitCode {
    cli::main()
}
