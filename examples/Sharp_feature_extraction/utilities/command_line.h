// What the command-line programs share when they parse their arguments: one clear line and
// exit status 1 on a bad argument.

#ifndef SFE_UTILITIES_COMMAND_LINE_H
#define SFE_UTILITIES_COMMAND_LINE_H

#include <cstdlib>
#include <iostream>
#include <string>

namespace sfe_utilities {

/// Prints "PROGRAM: MESSAGE" on stderr and exits with status 1.
[[noreturn]] inline void fail(const std::string& program, const std::string& message)
{
  std::cerr << program << ": " << message << std::endl;
  std::exit(1);
}

/// The value of `option`, a non-negative number; fails (as `program`) on anything else.
inline double non_negative_number(const std::string& program, const std::string& option, const char* text)
{
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if(end == text || *end != '\0' || !(v >= 0))
    fail(program, "option " + option + " expects a non-negative number, got '" + text + "'");
  return v;
}

} // namespace sfe_utilities

#endif
