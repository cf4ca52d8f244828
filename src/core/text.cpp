#include "core/text.hpp"

#include <fmt/format.h>

namespace gbssn1d {

std::string printable(const std::string& s) {
  std::string out;
  for (unsigned char c : s)
    out += (c >= 0x20 && c < 0x7f) ? std::string(1, static_cast<char>(c))
                                   : fmt::format("\\x{:02x}", c);
  return out;
}

} // namespace gbssn1d
