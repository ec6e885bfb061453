#pragma once
// How a subcommand ends on an error: a message on stderr and the exit code that docs/cli.md
// gives for that kind of error, the same in every subcommand.
#include <functional>
#include <string>

#include "commands.hpp"
#include "kestrel/error.hpp"

namespace kestrel::cli {

/// An error that ends a subcommand with a given exit code.
class CommandError : public Error {
 public:
  CommandError(ExitCode code, const std::string& message) : Error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

/// Runs a subcommand's body and returns its exit code. An error is printed as
/// "kestrel NAME: message"; a CommandError exits with its code, any other kestrel::Error with 2
/// (the command line or an input file it names is wrong), anything else with 1.
int run_command_body(const char* name, const std::function<int()>& body);

}  // namespace kestrel::cli
