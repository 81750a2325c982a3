//! The `barylab` command line: the app (no arguments) and the headless commands.

mod cli;
mod output;

fn main() -> std::process::ExitCode {
    cli::main()
}
