// The one error type for bad input: a file (or key path) and what is wrong with it.
#pragma once
#include <stdexcept>
#include <string>

namespace fastshade {

// Thrown for anything the user gave us that we cannot use: a malformed mesh, a bad scene key,
// an unwritable output path, an absurd option. The message is one line, "WHERE: PROBLEM",
// and the program turns it into exit code 2.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& where, const std::string& problem)
      : std::runtime_error(where + ": " + problem) {}
};

}  // namespace fastshade
