// The one reader of numbers given as text for parameters: the grammar of core/decimal.hpp, and
// a refusal as a ParamError naming the flag, the text and why.
#pragma once

#include "config/params.hpp"
#include "core/decimal.hpp"
#include "core/text.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace gbssn1d {

template <class T>
constexpr const char* number_kind() {
  if constexpr (std::is_floating_point_v<T>)
    return "a finite decimal number";
  else
    return "a whole decimal number";
}

template <class T>
T parse_number(const std::string& flag, const std::string& text) {
  if (const auto value = parse_decimal<T>(text)) {
    // a subnormal double (1e-320) holds few digits and its arithmetic is slow: refused as 1e-400
    // is, so that every real-valued flag has the same limits
    if constexpr (std::is_floating_point_v<T>)
      if (*value != 0 && std::abs(*value) < std::numeric_limits<T>::min())
        throw ParamError(flag, printable(text),
                         "is too small in magnitude for a double (below about 2.2e-308, a "
                         "subnormal number): give 0 or a larger value");
    return *value;
  }
  if constexpr (std::is_floating_point_v<T>) {
    // a well-formed number beyond a double's range (1e-400, 1e999) is not "not finite": say so
    if (const std::string why = real_out_of_range(text); !why.empty())
      throw ParamError(flag, printable(text), why);
  } else {
    // a whole number too large for the flag's type (99999999999999999999) is one: say so
    const std::string_view digits = !text.empty() && (text[0] == '-' || text[0] == '+')
                                        ? std::string_view(text).substr(1)
                                        : std::string_view(text);
    if (!digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos)
      throw ParamError(flag, printable(text),
                       fmt::format("is a whole number beyond this flag's range ({} ... {})",
                                   std::numeric_limits<T>::min(), std::numeric_limits<T>::max()));
  }
  throw ParamError(flag, text.empty() ? std::string("''") : printable(text),
                   std::string("must be ") + number_kind<T>());
}

} // namespace gbssn1d
