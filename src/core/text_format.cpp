// printf-style formatting into a std::string (text_format.hpp).
#include "evade/core/text_format.hpp"

#include <cstdarg>
#include <cstdio>

namespace evade {

std::string format_text(const char* fmt, ...) {
  char buf[512];
  va_list args;
  va_start(args, fmt);
  (void)std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  return buf;
}

}  // namespace evade
