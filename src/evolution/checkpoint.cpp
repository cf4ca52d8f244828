#include "evolution/checkpoint.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sstream>
#include <unistd.h>

namespace gbssn1d {

namespace {

constexpr char magic[] = "gbssn1d checkpoint 1\n";

class Writer {
public:
  explicit Writer(std::FILE* f) : f_(f) {}
  template <class T>
  void put(const T& v) {
    ok_ = ok_ && std::fwrite(&v, sizeof(T), 1, f_) == 1;
  }
  void put_bytes(const void* p, std::size_t n) {
    ok_ = ok_ && (n == 0 || std::fwrite(p, 1, n, f_) == n);
  }
  bool ok() const { return ok_; }

private:
  std::FILE* f_;
  bool ok_ = true;
};

class Reader {
public:
  Reader(std::FILE* f, const std::filesystem::path& path) : f_(f), path_(path) {}
  template <class T>
  T get() {
    T v{};
    get_bytes(&v, sizeof(T));
    return v;
  }
  void get_bytes(void* p, std::size_t n) {
    if (n != 0 && std::fread(p, 1, n, f_) != n)
      throw CheckpointError(fmt::format("{} is truncated", path_.string()));
  }

private:
  std::FILE* f_;
  const std::filesystem::path& path_;
};

} // namespace

bool same_run(const std::string& config_a, const std::string& config_b) {
  auto kept = [](const std::string& config) {
    std::istringstream in(config);
    std::string text;
    for (std::string line; std::getline(in, line);)
      if (line.rfind("tmax = ", 0) != 0 && line.rfind("out = ", 0) != 0
          && line.rfind("force = ", 0) != 0)
        text += line + "\n";
    return text;
  };
  return kept(config_a) == kept(config_b);
}

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f)
    throw OutputError(
        fmt::format("cannot open {} for writing: {}", tmp.string(), std::strerror(errno)));
  Writer w(f);
  w.put_bytes(magic, sizeof(magic) - 1);
  w.put<std::uint64_t>(c.config.size());
  w.put_bytes(c.config.data(), c.config.size());
  w.put(c.step);
  w.put(c.t);
  w.put(c.dt);
  w.put(c.k_series);
  w.put(c.k_profiles);
  w.put<std::uint8_t>(c.h_AH.has_value());
  w.put(c.h_AH.value_or(0.0));
  w.put<std::uint8_t>(c.had_horizon);
  w.put<std::uint8_t>(c.reported);
  w.put(c.evaluations);
  for (std::uint64_t v : {c.marks.series, c.marks.profiles, c.marks.horizons, c.marks.series_header,
                          c.marks.profiles_header, c.marks.horizons_header})
    w.put(v);
  w.put<std::uint64_t>(c.u.size());
  w.put_bytes(c.u.data(), c.u.size() * sizeof(double));
  const bool ok = w.ok() && std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
  std::fclose(f);
  if (!ok) {
    std::filesystem::remove(tmp);
    throw OutputError(fmt::format("cannot write the checkpoint {}", tmp.string()));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec); // atomic: the old checkpoint or the new one
  if (ec)
    throw OutputError(fmt::format("cannot replace {}: {}", file.string(), ec.message()));
}

Checkpoint read_checkpoint(const std::filesystem::path& file) {
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if (!f)
    throw CheckpointError(fmt::format("cannot read {}: {}", file.string(), std::strerror(errno)));
  struct Closer {
    std::FILE* f;
    ~Closer() { std::fclose(f); }
  } closer{f};
  Reader r(f, file);
  char head[sizeof(magic) - 1];
  r.get_bytes(head, sizeof(head));
  if (std::memcmp(head, magic, sizeof(head)) != 0)
    throw CheckpointError(fmt::format("{} is not a gbssn1d checkpoint", file.string()));
  Checkpoint c;
  const auto n_config = r.get<std::uint64_t>();
  if (n_config > (1u << 20))
    throw CheckpointError(fmt::format("{} is corrupt", file.string()));
  c.config.resize(n_config);
  r.get_bytes(c.config.data(), n_config);
  c.step = r.get<std::int64_t>();
  c.t = r.get<double>();
  c.dt = r.get<double>();
  c.k_series = r.get<std::int64_t>();
  c.k_profiles = r.get<std::int64_t>();
  const bool has_h = r.get<std::uint8_t>() != 0;
  const double h = r.get<double>();
  if (has_h)
    c.h_AH = h;
  c.had_horizon = r.get<std::uint8_t>() != 0;
  c.reported = r.get<std::uint8_t>() != 0;
  c.evaluations = r.get<std::uint64_t>();
  for (std::uint64_t* v :
       {&c.marks.series, &c.marks.profiles, &c.marks.horizons, &c.marks.series_header,
        &c.marks.profiles_header, &c.marks.horizons_header})
    *v = r.get<std::uint64_t>();
  const auto n = r.get<std::uint64_t>();
  if (n > (std::uint64_t{1} << 34))
    throw CheckpointError(fmt::format("{} is corrupt", file.string()));
  c.u.resize(n);
  r.get_bytes(c.u.data(), n * sizeof(double));
  if (std::fgetc(f) != EOF)
    throw CheckpointError(fmt::format("{} has trailing bytes", file.string()));
  return c;
}

} // namespace gbssn1d
