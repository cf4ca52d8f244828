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

std::optional<MemberRecord> read_samples(const fs::path& file, const std::string& key,
                                         std::int64_t step) {
  std::string bytes;
  {
    std::ifstream f(file, std::ios::binary);
    std::ostringstream text;
    text << f.rdbuf();
    if (!f)
      return std::nullopt;
    bytes = text.str();
  }
  // the checksum over every byte before it: a flipped or cut byte is not reused
  std::uint64_t stored = 0;
  if (bytes.size() < sizeof(stored))
    return std::nullopt;
  std::memcpy(&stored, bytes.data() + bytes.size() - sizeof(stored), sizeof(stored));
  bytes.resize(bytes.size() - sizeof(stored));
  if (fnv1a(bytes) != stored)
    return std::nullopt;
  std::istringstream in(bytes);
  auto get = [&](void* p, std::size_t n) {
    return static_cast<bool>(in.read(static_cast<char*>(p), static_cast<std::streamsize>(n)));
  };
  std::uint64_t key_size = 0;
  if (!get(&key_size, sizeof(key_size)) || key_size != key.size())
    return std::nullopt;
  std::string saved_key(key_size, '\0');
  if (!get(saved_key.data(), key_size) || saved_key != key)
    return std::nullopt;
  std::int64_t saved_step = -1;
  std::uint64_t rows = 0;
  if (!get(&saved_step, sizeof(saved_step)) || saved_step != step || !get(&rows, sizeof(rows))
      || rows > (1u << 26))
    return std::nullopt;
  MemberRecord rec;
  rec.rows.resize(rows);
  if (!get(rec.rows.data(), rows * sizeof(SeriesRow)))
    return std::nullopt;
  for (auto* list : {&rec.field_samples, &rec.H_samples}) {
    list->resize(rows);
    for (auto& v : *list) {
      std::uint64_t n = 0;
      if (!get(&n, sizeof(n)) || n > (1u << 26))
        return std::nullopt;
      v.resize(n);
      if (!get(v.data(), n * sizeof(double)))
        return std::nullopt;
    }
  }
  if (in.peek() != std::char_traits<char>::eof())
    return std::nullopt; // bytes left over: not what write_samples wrote
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
