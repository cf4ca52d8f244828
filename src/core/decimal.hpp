// The one grammar of numbers given as text: command-line flags, config files, sweep values,
// converge lists, tables and h_AH files. Whatever the path, the same text is the same number.
//
// The grammar is decimal only: an optional sign, digits, and for real numbers an optional
// fraction and exponent ("1", "-2.5", "1e-3", "+0.25"). Leading zeros are decimal ("032" is
// 32: a physicist writes them for alignment, never to mean octal, which is how strtol and
// CLI11 read them). Refused: hexadecimal, "inf" and "nan" words, surrounding white space,
// trailing characters, integers written with a fraction or exponent ("1e3" cells), values
// out of the type's range. config/numbers.hpp turns a refusal into a message naming its flag.
#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace gbssn1d {

/// The number `text` stands for, or nothing if it is not one by the grammar above.
template <class T>
std::optional<T> parse_decimal(std::string_view text) {
  static_assert(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>);
  if (!text.empty() && text.front() == '+')
    text.remove_prefix(1);
  if (text.empty())
    return std::nullopt;
  // digits, sign, and for real numbers '.', 'e', 'E' only: no "inf", "nan", "0x", spaces
  for (char c : text) {
    const bool digit = c >= '0' && c <= '9';
    const bool real_part = std::is_floating_point_v<T> && (c == '.' || c == 'e' || c == 'E');
    if (!digit && !real_part && c != '-' && c != '+')
      return std::nullopt;
  }
  if (text.front() == '+' || (text.size() > 1 && text[0] == '-' && text[1] == '+'))
    return std::nullopt; // "++1", "-+1"
  T value{};
  const char* end = text.data() + text.size();
  std::from_chars_result result;
  if constexpr (std::is_floating_point_v<T>)
    result = std::from_chars(text.data(), end, value, std::chars_format::general);
  else
    result = std::from_chars(text.data(), end, value, 10);
  if (result.ec != std::errc() || result.ptr != end)
    return std::nullopt;
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(value))
      return std::nullopt;
    if (value == T{0})
      value = T{0}; // -0 is 0: one value, one configuration (a sweep's 0,-0 are one member)
  }
  return value;
}

/// What the grammar calls the kind of number a flag takes, for messages.
/// Why a well-formed real number is not a double: its magnitude beyond about 1.8e308, or
/// below about 2e-308 but not 0 (an empty string: in range, or not well formed).
inline std::string real_out_of_range(std::string_view text) {
  double value{};
  const char* end = text.data() + text.size();
  if (!text.empty() && text.front() == '+')
    text.remove_prefix(1);
  const auto r = std::from_chars(text.data(), end, value, std::chars_format::general);
  if (text.empty() || r.ec != std::errc::result_out_of_range || r.ptr != end
      || text.find_first_not_of("0123456789.eE+-") != std::string_view::npos)
    return {};
  const auto e = text.find_first_of("eE");
  const bool negative_exponent =
      e != std::string_view::npos && e + 1 < text.size() && text[e + 1] == '-';
  return negative_exponent ? "is too small in magnitude for a double (below about 2e-308): give 0 "
                             "or a larger value"
                           : "is too large in magnitude for a double (beyond about 1.8e308)";
}

/// The number `text` stands for, or ParamError naming `flag`, the text and the grammar.
} // namespace gbssn1d
