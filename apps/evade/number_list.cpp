// Number lists of the command line (see number_list.hpp).
#include "number_list.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace evade::cli {

std::vector<double> parse_number_list(const std::string& text, char sep) {
  std::vector<double> out;
  std::size_t begin = 0;
  for (;;) {  // one field per pass; ends at the last field (begin only grows)
    const std::size_t end = std::min(text.find(sep, begin), text.size());
    const std::string field = text.substr(begin, end - begin);
    char* stop = nullptr;
    errno = 0;
    const double x = std::strtod(field.c_str(), &stop);
    const bool overflow = errno == ERANGE && std::isinf(x);
    if (field.empty() || stop != field.c_str() + field.size() || overflow) return {};
    out.push_back(x);
    if (end == text.size()) return out;
    begin = end + 1;
  }
}

}  // namespace evade::cli
