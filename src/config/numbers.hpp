// The one reader of numbers given as text for parameters: the grammar of core/decimal.hpp, and
// a refusal as a ParamError naming the flag, the text and why.
#pragma once

#include "config/params.hpp"
#include "core/decimal.hpp"
#include "core/text.hpp"

#include <charconv>
#include <cmath>
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
  if (const auto value = parse_decimal<T>(text))
    return *value;
  if constexpr (std::is_floating_point_v<T>) {
    // a well-formed number beyond a double's range (1e-400, 1e999) is not "not finite": say so
    if (const std::string why = real_out_of_range(text); !why.empty())
      throw ParamError(flag, printable(text), why);
  }
  throw ParamError(flag, text.empty() ? std::string("''") : printable(text),
                   std::string("must be ") + number_kind<T>());
}

} // namespace gbssn1d
