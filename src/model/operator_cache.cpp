#include "emit/model/operator_cache.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "emit/core/errors.hpp"
#include "emit/core/output_file.hpp"
#include "emit/sensor/sensor_json.hpp"

namespace emit {

namespace {

// 2: compact factors in float; 3: and λ²; 4: and the measurements' precision
constexpr char magic[8] = {'E', 'M', 'I', 'T', 'O', 'P', 'R', '4'};

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = 1469598103934665603ull) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

std::uint64_t mesh_hash(const Mesh& mesh) {
  std::uint64_t h = fnv1a(mesh.nodes_mm.data(), sizeof(double) * static_cast<std::size_t>(mesh.nodes_mm.size()));
  h = fnv1a(mesh.triangles.data(), sizeof(int) * static_cast<std::size_t>(mesh.triangles.size()), h);
  for (const auto& nodes : mesh.electrode_nodes) h = fnv1a(nodes.data(), sizeof(int) * nodes.size(), h);
  return h;
}

std::string path_for(const std::string& cache_dir, const std::string& key) {
  return cache_dir + "/operator-" + hex(fnv1a(key.data(), key.size())) + ".bin";
}

}  // namespace

std::string default_cache_dir() {
  if (const char* dir = std::getenv("EMIT_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/emit";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/emit";
  return ".emit-cache";
}

std::string operator_cache_key(const Sensor& sensor, const Mesh& mesh, const MeasurementSet& measurements,
                               const OperatorOptions& options) {
  std::ostringstream key;
  key.precision(17);
  key << "emit-operator-v4|sensor:" << sensor_to_json(sensor).dump() << "|mesh:" << hex(mesh_hash(mesh))
      << "|triangles:" << mesh.triangle_count() << "|measurements:";
  for (int i : measurements.frame_index) key << i << ',';
  key << "|prior:" << prior_name(options.prior) << "|lambda2:";
  // An automatic λ² is a function of the rest of the key (the Jacobian's spectrum): the key names
  // the rule, and the file holds the λ² it chose (CompactOperator::lambda2), checked on loading.
  if (options.lambda2 == 0) key << "auto(" << options.relative_lambda2 << "x spectrum_scale)";
  else key << options.lambda2;
  key << "|noser_exponent:" << options.noser_exponent << "|rank_cutoff:" << options.rank_cutoff;
  return key.str();
}

namespace {

template <class T>
bool read_value(std::istream& in, T& value) {
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof value));
}

template <class T>
void write_value(std::ostream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

bool read_floats(std::istream& in, Eigen::MatrixXf& m) {
  return static_cast<bool>(
      in.read(reinterpret_cast<char*>(m.data()), static_cast<std::streamsize>(sizeof(float) * m.size())));
}

void write_floats(std::ostream& out, const Eigen::MatrixXf& m) {
  out.write(reinterpret_cast<const char*>(m.data()), static_cast<std::streamsize>(sizeof(float) * m.size()));
}

}  // namespace

std::optional<CompactOperator> load_cached_operator(const std::string& cache_dir, const std::string& key) {
  std::ifstream in(path_for(cache_dir, key), std::ios::binary);
  if (!in) return std::nullopt;
  char file_magic[8];
  std::uint64_t key_size = 0;
  if (!in.read(file_magic, 8) || std::string(file_magic, 8) != std::string(magic, 8)) return std::nullopt;
  if (!read_value(in, key_size) || key_size != key.size()) return std::nullopt;
  std::string file_key(key_size, '\0');
  if (!in.read(file_key.data(), static_cast<std::streamsize>(key_size)) || file_key != key) return std::nullopt;
  std::int64_t rows = 0, cols = 0, rank = 0;
  double bound = 0, largest = 0, lambda2 = 0;
  if (!read_value(in, rows) || !read_value(in, cols) || !read_value(in, rank) || !read_value(in, bound) ||
      !read_value(in, largest) || !read_value(in, lambda2) || !(lambda2 > 0) || rows <= 0 || cols <= 0 || rank < 0 ||
      rank > cols || rows > (1 << 26) || cols > (1 << 14))
    return std::nullopt;
  Eigen::MatrixXf left(rows, rank), right(rank, cols), precision(cols, cols);
  if (!read_floats(in, left) || !read_floats(in, right) || !read_floats(in, precision)) return std::nullopt;
  return CompactOperator(std::move(left), std::move(right), bound, largest, lambda2, std::move(precision));
}

void store_cached_operator(const std::string& cache_dir, const std::string& key, const CompactOperator& op) {
  std::error_code error;
  std::filesystem::create_directories(cache_dir, error);
  if (error) throw IoError(cache_dir + ": cannot create cache folder (" + error.message() + ")");
  OutputFile file({"", path_for(cache_dir, key)});
  auto& out = file.stream();
  out.write(magic, 8);
  write_value(out, static_cast<std::uint64_t>(key.size()));
  out.write(key.data(), static_cast<std::streamsize>(key.size()));
  write_value(out, static_cast<std::int64_t>(op.rows()));
  write_value(out, static_cast<std::int64_t>(op.cols()));
  write_value(out, static_cast<std::int64_t>(op.rank()));
  write_value(out, op.truncation_bound());
  write_value(out, op.largest_singular_value());
  write_value(out, op.lambda2());
  write_floats(out, op.left());
  write_floats(out, op.right());
  if (op.precision().rows() != op.cols()) throw InvalidInput("operator cache: the operator has no precision to store");
  write_floats(out, op.precision());
  file.commit();
}

}  // namespace emit
