#include "config/input_files.hpp"

#include "core/text.hpp"
#include "evolution/checkpoint.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

namespace gbssn1d {

std::optional<std::string> prescribed_horizon_content(const Params& p) {
  if (!uses_hAH_file(p))
    return std::nullopt;
  std::ifstream in(p.rah_hAH_file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof())
    throw ParamError("--rah-hAH-file", printable(p.rah_hAH_file), "cannot be read");
  return text.str();
}

std::string copy_hash(const std::string& bytes) {
  return fmt::format("{:016x}", fnv1a(bytes));
}

std::string copy_hash_line(const std::optional<std::string>& content) {
  return content ? fmt::format("{}{}\n", copy_hash_key, copy_hash(*content)) : std::string();
}

std::string input_files_text(const Params& p) {
  try {
    return copy_hash_line(prescribed_horizon_content(p));
  } catch (const ParamError&) {
    return fmt::format("{}(unreadable)\n", copy_hash_key);
  }
}

std::optional<std::string> recorded_copy_hash(const std::string& text) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(copy_hash_key, 0) == 0)
      return line.substr(copy_hash_key.size());
  return std::nullopt;
}

std::vector<std::string> input_file_differences(const std::string& old_text,
                                                const std::string& new_text) {
  const auto a = recorded_copy_hash(old_text), b = recorded_copy_hash(new_text);
  if (a == b)
    return {};
  const auto shown = [](const std::optional<std::string>& h) {
    return h ? "fnv1a " + *h : std::string("(none)");
  };
  return {fmt::format("rah-hAH-file content: {} -> {}", shown(a), shown(b))};
}

} // namespace gbssn1d
