// printf-style formatting into a std::string (text_format.hpp).
#include "evade/core/text_format.hpp"

#include <cstdarg>
#include <cstdio>

namespace evade {

// C-style variadic on purpose: the printf format attribute (text_format.hpp) lets the compiler
// check every call's arguments against its format string, which a parameter pack would not.
std::string format_text(const char* fmt, ...) {  // NOLINT(cert-dcl50-cpp)
  char buf[512];
  va_list args;
  va_start(args, fmt);
  (void)std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  return buf;
}

}  // namespace evade
