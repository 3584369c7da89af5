// printf-style formatting into a std::string, for the text outputs of the commands (one line
// at a time: at most 511 characters, longer text is cut).
#pragma once

#include <string>

namespace evade {

/// The text of fmt with its arguments, as std::snprintf writes it.
__attribute__((format(printf, 1, 2))) std::string format_text(const char* fmt, ...);

}  // namespace evade
