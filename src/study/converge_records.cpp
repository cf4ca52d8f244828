#include "study/converge_records.hpp"

#include "evolution/checkpoint.hpp"
#include "io/output.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace gbssn1d {

namespace fs = std::filesystem;

void write_samples(const fs::path& file, const std::string& key, std::int64_t step,
                   const MemberRecord& rec) {
  std::string blob;
  auto put = [&](const void* p, std::size_t n) { blob.append(static_cast<const char*>(p), n); };
  const std::uint64_t rows = rec.rows.size(), key_size = key.size();
  put(&key_size, sizeof(key_size));
  put(key.data(), key.size());
  put(&step, sizeof(step));
  put(&rows, sizeof(rows));
  put(rec.rows.data(), rows * sizeof(SeriesRow));
  for (const auto* list : {&rec.field_samples, &rec.H_samples})
    for (const auto& v : *list) {
      const std::uint64_t n = v.size();
      put(&n, sizeof(n));
      put(v.data(), n * sizeof(double));
    }
  const std::uint64_t hash = fnv1a(blob);
  put(&hash, sizeof(hash));
  write_file_atomically(file, blob);
}

namespace {

/// A file's bytes, or nothing if it cannot be read.
std::optional<std::string> file_bytes(const fs::path& file) {
  std::ifstream f(file, std::ios::binary);
  if (!f)
    return std::nullopt;
  std::ostringstream text;
  text << f.rdbuf();
  if (!f && !f.eof())
    return std::nullopt;
  return text.str();
}

} // namespace

std::string completed_key(const std::string& samples_key, const std::string& member_config) {
  return samples_key + "\ncompleted with:\n" + member_config;
}

std::int64_t output_files_hash(const fs::path& dir) {
  std::string all;
  for (const char* name : {"timeseries.dat", "profiles.dat", "horizon.dat"}) {
    const std::optional<std::string> bytes = file_bytes(dir / name);
    const std::uint64_t n = bytes ? bytes->size() : ~std::uint64_t{0};
    all.append(reinterpret_cast<const char*>(&n), sizeof(n));
    if (bytes)
      all += *bytes;
  }
  const std::uint64_t hash = fnv1a(all);
  std::int64_t step = 0;
  std::memcpy(&step, &hash, sizeof(step));
  return step;
}

std::optional<MemberRecord> read_samples(const fs::path& file, const std::string& key,
                                         std::int64_t step, std::string* why) {
  const auto fail = [&](const char* reason) {
    if (why)
      *why = reason;
    return std::nullopt;
  };
  std::optional<std::string> read = file_bytes(file);
  if (!read || read->empty())
    return fail(read ? "it is empty" : "it cannot be read");
  std::string& bytes = *read;
  // the checksum over every byte before it: a flipped or cut byte is not reused
  std::uint64_t stored = 0;
  if (bytes.size() < sizeof(stored))
    return fail("it is cut short");
  std::memcpy(&stored, bytes.data() + bytes.size() - sizeof(stored), sizeof(stored));
  bytes.resize(bytes.size() - sizeof(stored));
  if (fnv1a(bytes) != stored)
    return fail("its checksum does not match (a flipped or cut byte)");
  std::istringstream in(bytes);
  auto get = [&](void* p, std::size_t n) {
    return static_cast<bool>(in.read(static_cast<char*>(p), static_cast<std::streamsize>(n)));
  };
  std::uint64_t key_size = 0;
  if (!get(&key_size, sizeof(key_size)) || key_size > bytes.size())
    return fail("it is broken");
  std::string saved_key(key_size, '\0');
  if (!get(saved_key.data(), key_size))
    return fail("it is broken");
  if (saved_key != key)
    return fail("it was saved for other inputs, fields or radii");
  std::int64_t saved_step = -1;
  if (!get(&saved_step, sizeof(saved_step)))
    return fail("it is broken");
  if (saved_step != step)
    return fail(samples_other_step);
  std::uint64_t rows = 0;
  if (!get(&rows, sizeof(rows)) || rows > (1u << 26))
    return fail("it is broken");
  MemberRecord rec;
  rec.rows.resize(rows);
  if (!get(rec.rows.data(), rows * sizeof(SeriesRow)))
    return fail("it is broken");
  for (auto* list : {&rec.field_samples, &rec.H_samples}) {
    list->resize(rows);
    for (auto& v : *list) {
      std::uint64_t n = 0;
      if (!get(&n, sizeof(n)) || n > (1u << 26))
        return fail("it is broken");
      v.resize(n);
      if (!get(v.data(), n * sizeof(double)))
        return fail("it is broken");
    }
  }
  if (in.peek() != std::char_traits<char>::eof())
    return fail("it is broken"); // bytes left over: not what write_samples wrote
  return rec;
}

double rms_difference(const std::vector<double>& a, const std::vector<double>& b,
                      std::size_t offset, std::size_t count) {
  double sum = 0.0;
  for (std::size_t j = offset; j < offset + count; ++j)
    sum += (a[j] - b[j]) * (a[j] - b[j]);
  return std::sqrt(sum / static_cast<double>(count));
}

} // namespace gbssn1d
