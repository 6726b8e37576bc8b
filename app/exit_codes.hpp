#pragma once
// Exit codes of `spiral` (documented in docs/output-format.md and `--help`).
namespace spiral::app {
inline constexpr int kExitOk = 0;
inline constexpr int kExitInternalError = 1;  ///< a bug: please report it
inline constexpr int kExitBadInput = 2;       ///< project file or command-line arguments
inline constexpr int kExitSolverFailure = 3;  ///< a solver did not converge / impossible geometry
inline constexpr int kExitOutputError = 4;    ///< results could not be written

/// The footer of `spiral --help` and of every command's `--help`.
inline constexpr const char* kExitCodeHelp =
    "Exit codes: 0 ok, 1 internal error, 2 bad input (project file or arguments), "
    "3 solver failure, 4 output could not be written.";
}  // namespace spiral::app
