// The text of config files: strings written as TOML basic strings and read back exactly, and
// the `key = value` lines of a file (declared in config/config_file.hpp).
#include "config/config_file.hpp"

#include "core/text.hpp"

#include <fmt/format.h>

#include <charconv>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace gbssn1d {

std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
    case '"':
      out += "\\\"";
      break;
    case '\\':
      out += "\\\\";
      break;
    case '\n':
      out += "\\n";
      break;
    case '\t':
      out += "\\t";
      break;
    case '\r':
      out += "\\r";
      break;
    default:
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
        out += fmt::format("\\u{:04X}", static_cast<unsigned char>(c));
      else
        out += c;
    }
  }
  return out + "\"";
}

namespace {

/// A basic string (TOML's, with escapes) whose opening '"' is at line[k], for `key`: its value,
/// with k past the closing '"'. `fail(why)` throws.
template <class Fail>
std::string read_basic_string(const std::string& line, std::size_t& k, const std::string& key,
                              const Fail& fail) {
  std::string value;
  bool closed = false;
  for (++k; k < line.size() && !closed; ++k) {
    const char c = line[k];
    if (c == '"') {
      closed = true;
    } else if (c != '\\') {
      value += c;
    } else if (++k >= line.size()) {
      break;
    } else if (const char e = line[k]; e == 'u' && k + 4 < line.size()) {
      unsigned code = 0;
      const auto [ptr, ec] = std::from_chars(line.data() + k + 1, line.data() + k + 5, code, 16);
      if (ec != std::errc() || ptr != line.data() + k + 5 || code > 0x7f)
        fail(fmt::format("key '{}': \\u escapes above 007F are not read", key));
      value += static_cast<char>(code);
      k += 4;
    } else {
      const std::map<char, char> escapes{
          {'"', '"'}, {'\\', '\\'}, {'n', '\n'}, {'t', '\t'}, {'r', '\r'}};
      const auto it = escapes.find(e);
      if (it == escapes.end())
        fail(fmt::format("key '{}': unknown escape '\\{}' in its string", key,
                         printable(std::string(1, e))));
      value += it->second;
    }
  }
  if (!closed)
    fail(fmt::format("key '{}': its string has no closing '\"'", key));
  return value;
}

} // namespace

std::vector<std::pair<std::string, std::string>> read_config_text(const std::string& text,
                                                                  const std::string& path) {
  std::vector<std::pair<std::string, std::string>> items;
  std::map<std::string, std::size_t> first_line;
  std::istringstream in(text);
  std::size_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    auto fail = [&](const std::string& why) {
      throw ParamError("--config", path, fmt::format("line {}: {}", number, why));
    };
    std::size_t k = line.find_first_not_of(" \t\r");
    if (k == std::string::npos || line[k] == '#')
      continue;
    if (line[k] == '[')
      fail(fmt::format("'{}': sections are not read; write every key at the top level",
                       printable(line.substr(k))));
    const std::size_t key_end = line.find_first_not_of(
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-", k);
    const std::string key = line.substr(k, key_end == std::string::npos ? key_end : key_end - k);
    k = key_end == std::string::npos ? line.size() : line.find_first_not_of(" \t", key_end);
    if (key.empty() || k == std::string::npos || line[k] != '=')
      fail(fmt::format("'{}' is not a `key = value` line", printable(line)));
    k = line.find_first_not_of(" \t", k + 1);
    if (k == std::string::npos)
      fail(fmt::format("key '{}' has no value", key));
    std::string value;
    if (line[k] == '"') { // a basic string, with escapes
      value = read_basic_string(line, k, key, fail);
    } else if (line[k] == '\'') { // a literal string: no escapes
      const std::size_t end = line.find('\'', k + 1);
      if (end == std::string::npos)
        fail(fmt::format("key '{}': its string has no closing \"'\"", key));
      value = line.substr(k + 1, end - k - 1);
      k = end + 1;
    } else { // a bare value: one word (a number, true or false), up to white space or '#'
      const std::size_t end = line.find_first_of(" \t\r#", k);
      value = line.substr(k, end == std::string::npos ? std::string::npos : end - k);
      if (value.find_first_of("[{\"',") != std::string::npos)
        fail(fmt::format("key '{}' needs exactly one value, not '{}'", key,
                         printable(line.substr(k))));
      k = end == std::string::npos ? line.size() : end;
    }
    if (const std::size_t rest = line.find_first_not_of(" \t\r", k);
        rest != std::string::npos && line[rest] != '#')
      fail(fmt::format("key '{}': '{}' after its value", key, printable(line.substr(rest))));
    if (const auto [it, fresh] = first_line.emplace(key, number); !fresh)
      fail(fmt::format("key '{}' is given again (first on line {})", key, it->second));
    items.emplace_back(key, value);
  }
  return items;
}

} // namespace gbssn1d
