// brash::InputError: the one exception type for bad user input (files, case keys, arguments).
// The message must name the file (and line or key where there is one) and the problem.
#pragma once
#include <stdexcept>
#include <string>

namespace brash {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace brash
