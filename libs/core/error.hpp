#pragma once
// Errors and exit codes shared by every rockfrac application.
//
// A UserError is something the user can fix (bad dictionary, missing file,
// impossible parameter): the application prints its one-line message and
// exits with code 1. Anything else that escapes main is an internal error
// (exit code 2): a bug, to be reported.
#include <stdexcept>
#include <string>

namespace rockfrac {

enum ExitCode : int { exitSuccess = 0, exitUserError = 1, exitInternalError = 2 };

class UserError : public std::runtime_error {
public:
    explicit UserError(const std::string& message) : std::runtime_error(message) {}
};

// The user stopped the program (SIGINT/SIGTERM) while it ran simulations: what was done is
// kept, and no result may be drawn from the runs the stop cut short. Not a UserError, so
// that code which tolerates a failed run (catching UserError and going on without it) never
// catches a stop; runApplication reports it like a UserError (exit code 1).
class Interrupted : public std::runtime_error {
public:
    explicit Interrupted(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace rockfrac
