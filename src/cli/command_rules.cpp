#include "cli/command_rules.hpp"

#include "config/params.hpp"

#include <fmt/format.h>

#include <set>
#include <string>

namespace gbssn1d {

void check_jobs(int jobs) {
  constexpr int jobs_max = 1024;
  if (jobs < 1 || jobs > jobs_max)
    throw ParamError("-j", std::to_string(jobs), fmt::format("must lie in [1, {}]", jobs_max));
}

void refuse_repeated_flags(const std::vector<std::string>& args) {
  std::set<std::string> seen;
  for (const auto& a : args) {
    const bool short_jobs = a.rfind("-j", 0) == 0;
    if ((a.rfind("--", 0) != 0 || a == "--") && !short_jobs)
      continue;
    std::string name = a.substr(0, a.find('='));
    if (short_jobs || name == "--jobs")
      name = "-j/--jobs";
    if (name == "--sweep")
      continue;
    if (!seen.insert(name).second)
      throw ParamError(name, "is given more than once (a flag may be given once; flags given "
                             "with --config may be overridden once)");
  }
}

void refuse_empty_values(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() > 2 && a.rfind("--", 0) == 0 && a.back() == '=')
      throw ParamError(a.substr(0, a.size() - 1),
                       "is given an empty value: put the value after '=', or leave the flag out");
    if (a.empty()) {
      const bool after_flag = i > 0 && args[i - 1].rfind("-", 0) == 0;
      throw ParamError(after_flag ? args[i - 1] : std::string("argument"),
                       after_flag ? "is given an empty value: give a value, or leave the flag out"
                                  : "an empty argument is not a value of any flag");
    }
  }
}

std::vector<std::string> pass_through(const std::vector<std::string>& extras,
                                      const std::vector<std::string>& own) {
  for (const auto& a : extras)
    for (const auto& flag : own)
      if (a == "--" + flag || a.rfind("--" + flag + "=", 0) == 0)
        throw ParamError("--" + flag, a, "is set by the study itself for each member");
  return extras;
}

} // namespace gbssn1d
