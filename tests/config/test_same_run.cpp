// The one notion of "the same run" (config/config_file.hpp: effective, run_key, idle_flags):
// each flag's table entry says where it acts, and these tests hold the table to what the runs
// do. A flag that the table calls idle in a configuration must change no number the run writes
// (else two different runs would be called the same), and where the table says it acts, the
// key and the numbers change with it (else the comparison could not fail).
#include "../cli/cli_support.hpp"
#include "config/config_file.hpp"
#include "config/params.hpp"
#include "config/same_run.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace gbssn1d;
using gbssn1d::testing::command_words;
using gbssn1d::testing::resolved_evolve;
using gbssn1d::testing::run;
using gbssn1d::testing::scratch;
using gbssn1d::testing::slurp;

namespace {

/// The names of the flags idle_flags() calls idle in `p`.
std::set<std::string> idle_names(const ResolvedParams& p) {
  std::set<std::string> names;
  for (const auto& group : idle_flags(p))
    names.insert(group.flags.begin(), group.flags.end());
  return names;
}

/// The numbers a run wrote: every .dat file's lines that are not '#' comments (headers echo
/// the flags, which differ by design).
std::map<std::string, std::string> numbers(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".dat")
      continue;
    std::istringstream in(slurp(e.path()));
    std::string kept;
    for (std::string line; std::getline(in, line);)
      if (line.rfind('#', 0) != 0)
        kept += line + "\n";
    out[e.path().filename().string()] = kept;
  }
  return out;
}

/// The numbers of an evolve run with `args` (which must succeed).
std::map<std::string, std::string> numbers_of(const std::string& args, const std::string& name) {
  const fs::path out = scratch("same_run_" + name);
  const auto r = run("evolve " + args + " --out " + out.string());
  INFO(args << "\n" << r.err);
  REQUIRE(r.status == 0);
  auto n = numbers(out);
  REQUIRE(n.count("timeseries.dat") == 1);
  REQUIRE(n.count("profiles.dat") == 1);
  fs::remove_all(out);
  return n;
}

const std::string trumpet =
    "--id 1log-trumpet --grid uniform --N 64 --rmax 16 --tmax 1 --dt-series 0.25 "
    "--dt-profiles 0.5";

} // namespace

TEST_CASE("the same run: a flag the table calls idle changes no number the run writes, and "
          "where it acts it changes them and the run key") {
  const fs::path file = scratch("same_run_hAH.dat");
  {
    std::ofstream f(file);
    f << "# t r_ah\n";
    for (int k = 0; k <= 8; ++k)
      f << 0.25 * k << " " << 0.8304 + 0.01 * k << "\n";
  }
  struct Case {
    std::string base, flag, acting; // the flag is idle with `base`, acts with `acting`
  };
  const std::string shifted = trumpet + " --rahA 0.5 --rah0 1";
  const std::string hAH = shifted + " --rah-hAH-file " + file.string();
  const std::string boxes = "--id 1log-trumpet --grid boxes --levels 3 --N 32 --rmax 16 --tmax 1 "
                            "--dt-series 0.25 --dt-profiles 0.5";
  const std::string boxes64 = "--id 1log-trumpet --grid boxes --levels 3 --N 32 --rmax 64 "
                              "--tmax 1 --dt-series 0.25 --dt-profiles 0.5";
  const std::vector<Case> cases{
      {trumpet, "--rah0 0.6", trumpet + " --rahA 0.5"},
      // an explicit profile: auto sets the width itself (--rah-width is then not used)
      {trumpet, "--rah-width 2", shifted + " --rah-profile rational"},
      {trumpet, "--rah-rcut 6", shifted},
      {trumpet, "--rah-taper step", shifted},
      {trumpet, "--rah-ramp 3", shifted},
      {trumpet, "--rah-profile gauss", shifted},
      {trumpet, "--rah-normal unit", shifted},
      {trumpet, "--rah-chi-smooth 0.1", shifted + " --rah-normal smooth"},
      {shifted, "--rah-chi-smooth 0.1", shifted + " --rah-normal smooth"},
      {trumpet, "--rah-hAH-file " + file.string(), shifted},
      {trumpet, "--rah-variant no-shift-derivatives", shifted},
      {trumpet, "--rah-variant no-shift-second-derivatives", shifted},
      {trumpet, "--rah-variant delta-rhs-from-gd", shifted},
      {trumpet, "--rah-variant driver-full-shift", shifted},
      // searches inside the step need searches every n steps
      {trumpet + " --ah-every step", "--rah-variant midstep-update", shifted + " --ah-every step"},
      {trumpet, "--dr-inner 0.03", "--id 1log-trumpet --N 64 --rmax 16 --tmax 1"},
      {trumpet, "--lapse0 one", "--id wormhole --grid uniform --N 64 --rmax 16 --tmax 1"},
      // Z4c's damping does nothing in BSSN
      {trumpet, "--kappa1 0.3", trumpet + " --formulation z4c"},
      {trumpet, "--kappa2 0.5", trumpet + " --formulation z4c"},
      // kappa2 only ever multiplies kappa1 in Z4c's equations
      {trumpet + " --formulation z4c --kappa1 0 --kappa1-hole 0", "--kappa2 0.5",
       trumpet + " --formulation z4c"},
      {trumpet, "--kappa1-hole 0", trumpet + " --formulation z4c"},
      // the searches steer the shift alone: idle without it, and with an h_AH file
      {trumpet, "--ah-every 4", shifted},
      {trumpet, "--ah-every extrapolated", shifted},
      {trumpet, "--ah-tmin 0.5", shifted},
      {trumpet, "--ah-tmax 0.5", shifted},
      {trumpet, "--ah-interval 0.5", shifted},
      {hAH, "--ah-every 4", shifted},
      {hAH, "--ah-every extrapolated", shifted},
      {hAH, "--ah-tmin 0.5", shifted},
      {hAH, "--ah-tmax 0.5", shifted},
      // a taper radius without a taper
      {boxes64 + " --box-taper 0", "--box-taper-from 2", boxes64},
      // a taper where no fine box reaches beyond --box-taper-from (16 M): rmax 16, the largest
      // fine box 8 M; with rmax 64 the level-1 box reaches 32 M
      {boxes, "--box-taper 0.25", boxes64},
      // without the horizon shift beta_GD is the whole shift: upwind-gd is upwind-full, and B's
      // matched driver term is Delta^r's own (with the shift, upwind-gd differs only where
      // beta_H turns the full shift against beta_GD: a strong stretch, not --rahA 0.5 --rah0 1)
      {trumpet, "--delta-advection upwind-gd", trumpet + " --rahA 2 --rah0 1.5"},
      {trumpet, "--driver-advection upwind-gd", shifted},
      {trumpet, "--driver-advection upwind-full", shifted},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Case& c = cases[k];
    INFO("flag " << c.flag << " with " << c.base);
    // the table: idle with the base, and the same run key
    const ResolvedParams base = resolved_evolve(c.base),
                         with = resolved_evolve(c.base + " " + c.flag);
    const std::string name = c.flag.substr(2, c.flag.find(' ') - 2);
    CHECK(idle_names(with).count(name) == 1);
    CHECK(idle_names(base).count(name) == 0);
    CHECK(idle_names(base).size() + 1 == idle_names(with).size());
    CHECK(run_key(with) == run_key(base));
    // the runs: the same numbers
    CHECK(numbers_of(c.base + " " + c.flag, "idle_a") == numbers_of(c.base, "idle_b"));
    // where it acts: another key, other numbers
    const ResolvedParams acting = resolved_evolve(c.acting),
                         acting_with = resolved_evolve(c.acting + " " + c.flag);
    CHECK(idle_names(acting_with).count(name) == 0);
    CHECK(run_key(acting_with) != run_key(acting));
    if (c.flag.rfind("--rah-variant midstep", 0) == 0 || c.flag.rfind("--rah-hAH", 0) == 0
        || c.flag == "--rah-rcut 6" || c.flag == "--rah0 0.6" || c.flag == "--dr-inner 0.03"
        || c.flag == "--lapse0 one" || c.flag == "--rah-chi-smooth 0.1"
        || c.flag == "--rah-profile gauss" || c.flag == "--kappa1 0.3" || c.flag == "--ah-tmin 0.5"
        || c.flag == "--ah-interval 0.5" || c.flag == "--box-taper-from 2"
        || c.flag == "--box-taper 0.25" || c.flag.rfind("--delta-advection", 0) == 0
        || c.flag.rfind("--driver-advection", 0) == 0)
      CHECK(numbers_of(c.acting + " " + c.flag, "acts_a") != numbers_of(c.acting, "acts_b"));
  }
  fs::remove(file);
}

TEST_CASE("idle flags: named with their values, grouped by why, in the run's warnings, and a "
          "resolved default is not one") {
  const ResolvedParams quiet = resolved_evolve(trumpet);
  CHECK(idle_flags(quiet).empty());
  CHECK(warnings(quiet).empty()); // box-taper resolved to 0 on a single grid: not given
  const ResolvedParams p =
      resolved_evolve(trumpet + " --rah0 0.6 --rah-profile gauss --dr-inner 0.03");
  const auto idle = idle_flags(p);
  REQUIRE(idle.size() == 2);
  CHECK(idle[0].because == "with --grid uniform");
  CHECK(idle[0].given == std::vector<std::string>{"--dr-inner 0.03"});
  CHECK(idle[1].because == "with --rahA 0");
  CHECK(idle[1].given == std::vector<std::string>{"--rah0 0.6", "--rah-profile gauss"});
  CHECK(idle[1].warning().rfind("--rah0 0.6, --rah-profile gauss do nothing with --rahA 0: ", 0)
        == 0);
  const auto w = warnings(p);
  CHECK(std::count(w.begin(), w.end(), idle[0].warning()) == 1);
  CHECK(std::count(w.begin(), w.end(), idle[1].warning()) == 1);
  // smooth normal's chi_s with the shift on but another normal
  const auto chi = idle_flags(resolved_evolve(trumpet + " --rahA 0.5 --rah-chi-smooth 0.1"));
  REQUIRE(chi.size() == 1);
  CHECK(chi[0].because == "with --rah-normal conformal");
}

TEST_CASE("the effective configuration: without --out and --force, idle flags at their "
          "resolved defaults, the rest as given") {
  Params given = resolved_evolve(trumpet + " --rah0 0.6 --ko-sigma 0.2").flags();
  given.out = "somewhere";
  given.force = true;
  const ResolvedParams p = resolve(given);
  const Params e = effective(p);
  CHECK(e.out.empty());
  CHECK_FALSE(e.force);
  CHECK(e.rah0 == Params{}.rah0);
  CHECK(e.ko_sigma == 0.2);
  CHECK(e.box_taper == p.flags().box_taper); // resolved on a single grid: 0, kept
  CHECK(run_key(p) == config_text(e));
}

TEST_CASE("the horizon searches' flags do nothing without the shift or with an h_AH file, "
          "and the search schedules of --rah-variant nothing with the file: warned about") {
  auto warned = [](const ResolvedParams& p, const std::string& start) {
    const auto w = warnings(p);
    return std::count_if(w.begin(), w.end(),
                         [&](const std::string& s) { return s.rfind(start, 0) == 0; });
  };
  // the searches with the shift off
  const auto off = idle_flags(resolved_evolve(trumpet + " --ah-every 4 --ah-tmin 1 --ah-tmax 2"));
  REQUIRE(off.size() == 1);
  CHECK(off[0].warning().rfind("--ah-every 4, --ah-tmin 1, --ah-tmax 2 do nothing with --rahA 0", 0)
        == 0);
  // midstep-update changes when h_AH is searched for: nothing is with an h_AH file
  const std::string file = trumpet + " --rahA 0.5 --rah-hAH-file h.dat";
  const ResolvedParams midstep =
      resolved_evolve(file + " --ah-every step --rah-variant midstep-update");
  CHECK(warned(midstep, "--rah-variant midstep-update does nothing with --rah-hAH-file") == 1);
  const auto idle = idle_flags(midstep);
  REQUIRE(idle.size() == 1);
  CHECK(idle[0].warning().rfind("--ah-every step does nothing with --rah-hAH-file: ", 0) == 0);
  CHECK(warned(resolved_evolve(file), "--rah-variant") == 0);
  CHECK(
      warned(resolved_evolve(file + " --ah-tmin 1"), "--ah-tmin 1 does nothing with --rah-hAH-file")
      == 1);
}

TEST_CASE("a taper radius is warned about where it tapers nothing: without a taper, or beyond "
          "every fine box") {
  const std::string boxes = "--id 1log-trumpet --grid boxes --levels 3 --N 32 --rmax 16 --tmax 1";
  auto warned = [](const ResolvedParams& p, const std::string& start) {
    const auto w = warnings(p);
    return std::count_if(w.begin(), w.end(),
                         [&](const std::string& s) { return s.rfind(start, 0) == 0; });
  };
  const std::string beyond = "--box-taper-from 1000000 (M) lies beyond every fine box (the "
                             "largest ends at r = rmax/2 = 8 M): --box-taper 0.5 tapers no box";
  CHECK(warned(resolved_evolve(boxes + " --box-taper-from 1e6"), beyond) == 1);
  CHECK(warned(resolved_evolve(boxes + " --box-taper-from 8"), "--box-taper-from 8 (M)") == 1);
  CHECK(warned(resolved_evolve(boxes + " --box-taper-from 7.5"), "--box-taper-from") == 0);
  CHECK(warned(resolved_evolve(boxes), "--box-taper-from") == 0); // the default 16 M: by design
  // the taper's radius without a taper: an idle flag (from 4 M the 8 M box would be tapered)
  const auto untapered = idle_flags(resolved_evolve(boxes + " --box-taper 0 --box-taper-from 4"));
  REQUIRE(untapered.size() == 1);
  CHECK(untapered[0].warning().rfind("--box-taper-from 4 does nothing with --box-taper 0: ", 0)
        == 0);
  // and a taper where no fine box reaches beyond its radius: idle too, saying why
  const auto unreached = idle_flags(resolved_evolve(boxes + " --box-taper 0.25"));
  REQUIRE(unreached.size() == 1);
  CHECK(unreached[0].warning().rfind(
            "--box-taper 0.25 does nothing with no fine box beyond --box-taper-from 16 (the "
            "largest reaches 8 M): ",
            0)
        == 0);
}

TEST_CASE("--kappa2 does nothing without damping (it only ever multiplies kappa1): warned about") {
  const auto z4c = idle_flags(
      resolved_evolve(trumpet + " --formulation z4c --kappa1 0 --kappa1-hole 0 --kappa2 0.5"));
  REQUIRE(z4c.size() == 1);
  CHECK(z4c[0].warning().rfind("--kappa2 0.5 does nothing with --kappa1 0 --kappa1-hole 0: ", 0)
        == 0);
  CHECK(idle_flags(resolved_evolve(trumpet + " --formulation z4c --kappa2 0.5")).empty());
  // the damping near the hole is damping too
  CHECK(
      idle_flags(resolved_evolve(trumpet + " --formulation z4c --kappa1 0 --kappa2 0.5")).empty());
}

TEST_CASE("rule values are recorded as such in config.toml and read back as unset: a Z4c run's "
          "kappa1 reused with BSSN is no flag given, and a rule follows the inputs it reads") {
  const fs::path z = scratch("rule_values_z4c"), b = scratch("rule_values_bssn"),
                 m = scratch("rule_values_m2");
  REQUIRE(run("evolve --formulation z4c --id 1log-trumpet --grid uniform --N 80 --rmax 20 "
              "--tmax 0.5 --out "
              + z.string())
              .status
          == 0);
  const std::string text = slurp(z / "config.toml");
  // the values are recorded (the run is repeatable from the file), and which came from rules
  CHECK(text.find("\nkappa1 = 0.02\n") != std::string::npos);
  CHECK(text.find("\n# rule values, not given: eta, kappa1, kappa1-hole, norm-rmax, box-taper\n")
        != std::string::npos);
  // reused with BSSN: no warning of a --kappa1 never given, and none recorded again
  const auto bssn = run("evolve --config " + (z / "config.toml").string()
                        + " --formulation bssn --force --out " + b.string());
  INFO(bssn.err);
  REQUIRE(bssn.status == 0);
  CHECK(bssn.err.find("kappa1") == std::string::npos);
  CHECK(slurp(b / "config.toml").find("kappa1") == std::string::npos);
  // with another M the rules give that M's values (kappa1 0.02/M, eta 2/M), as the flags would
  const auto m2 = run("evolve --config " + (z / "config.toml").string() + " --M 2 --out "
                      + m.string() + " --force");
  INFO(m2.err);
  REQUIRE(m2.status == 0);
  CHECK(slurp(m / "config.toml").find("\nkappa1 = 0.01\n") != std::string::npos);
  CHECK(slurp(m / "config.toml").find("\neta = 1\n") != std::string::npos);
  // given on the command line, a value equal to its rule's is still a rule's value
  CHECK(rule_valued_keys(resolved_evolve(trumpet + " --formulation z4c --kappa1 0.02"))
        == std::vector<std::string>{"eta", "kappa1", "kappa1-hole", "norm-rmax", "box-taper"});
  CHECK(rule_valued_keys(resolved_evolve(trumpet + " --formulation z4c --kappa1 0.05"))
        == std::vector<std::string>{"eta", "kappa1-hole", "norm-rmax", "box-taper"});
  // a line naming a key no rule gives is refused (it would leave a given value unset)
  std::ofstream(b / "edited.toml") << "N = 64\n# rule values, not given: N\n";
  const auto edited =
      run("evolve --config " + (b / "edited.toml").string() + " --out " + (b / "x").string());
  CHECK(edited.status == 2);
  CHECK(edited.err.find("names 'N', which no rule gives") != std::string::npos);
  CHECK_FALSE(fs::exists(b / "x"));
  for (const auto& d : {z, b, m})
    fs::remove_all(d);
}

// Guards --z4c-lapse-adm's row of the table (Acts::with_z4c, config/flag_table.cpp): Theta is
// driven by H ((I3), Sec. 17) whether or not it is damped, so the lapse driven by K-hat + 2 Theta
// is another lapse than the one driven by K-hat in every Z4c run, undamped ones too. Called idle
// without damping (as --kappa2 rightly is), two different undamped runs would share a run key,
// the flag would be warned about as doing nothing, and left out of the effective configuration.
TEST_CASE("--z4c-lapse-adm acts in Z4c without damping: its own run key, config line and "
          "numbers, idle in BSSN alone") {
  const std::string undamped = trumpet + " --formulation z4c --kappa1 0 --kappa1-hole 0";
  const ResolvedParams base = resolved_evolve(undamped),
                       with = resolved_evolve(undamped + " --z4c-lapse-adm");
  CHECK(idle_names(with).count("z4c-lapse-adm") == 0);
  CHECK(idle_names(with) == idle_names(base));
  const auto w = warnings(with);
  CHECK(std::none_of(w.begin(), w.end(), [](const std::string& s) {
    return s.find("--z4c-lapse-adm") != std::string::npos;
  }));
  CHECK(run_key(with) != run_key(base));
  CHECK(config_text(effective(with)).find("z4c-lapse-adm = true") != std::string::npos);
  CHECK(config_text(effective(base)).find("z4c-lapse-adm = false") != std::string::npos);
  CHECK(numbers_of(undamped + " --z4c-lapse-adm", "adm_a") != numbers_of(undamped, "adm_b"));
  // with damping it acts too, and in BSSN it is idle: there is no Theta
  CHECK(idle_names(resolved_evolve(trumpet + " --formulation z4c --z4c-lapse-adm"))
            .count("z4c-lapse-adm")
        == 0);
  const ResolvedParams bssn = resolved_evolve(trumpet),
                       bssn_with = resolved_evolve(trumpet + " --z4c-lapse-adm");
  CHECK(idle_names(bssn_with).count("z4c-lapse-adm") == 1);
  CHECK(run_key(bssn_with) == run_key(bssn));
}
