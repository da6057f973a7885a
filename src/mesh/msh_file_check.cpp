#include "emit/mesh/msh_file_check.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "file_bytes.hpp"
#include "sheet_file_access.hpp"
#include "triangle_limit.hpp"

namespace emit {

namespace {

using detail::FileBytes;

/// A value in an ASCII .msh is a number: longer than this it is not one Gmsh writes.
constexpr std::size_t max_token_bytes = 64;
/// A section's marker line ("$Nodes", "$EndNodes"); other lines of a section passed over may be
/// longer (a physical name), their rest unread.
constexpr std::size_t max_line_bytes = 256;
/// A surface of T triangles uses at most 3T nodes (the limit's T, and one more triangle's).
constexpr double nodes_per_triangle_bound = 3;

/// The nodes of an element of each type of the MSH format (Gmsh's reference manual, "MSH file
/// format": 1 a 2-node line, 2 a 3-node triangle, 15 a point, …); 0 for a type it does not list.
int nodes_of_type(std::int64_t type) {
  switch (type) {
    case 15: return 1;
    case 1: return 2;
    case 2:
    case 8: return 3;
    case 3:
    case 4:
    case 26: return 4;
    case 7:
    case 27: return 5;
    case 6:
    case 9:
    case 28: return 6;
    case 5:
    case 16: return 8;
    case 10:
    case 20: return 9;
    case 11:
    case 21: return 10;
    case 22: return 12;
    case 19: return 13;
    case 14: return 14;
    case 18:
    case 23:
    case 24: return 15;
    case 13: return 18;
    case 17:
    case 29: return 20;
    case 25: return 21;
    case 12: return 27;
    case 30: return 35;
    case 31: return 56;
    case 92: return 64;
    case 93: return 125;
    default: return 0;
  }
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\n'; }

std::string trimmed(const std::string& text) {
  std::size_t begin = 0, end = text.size();
  while (begin < end && is_space(text[begin])) ++begin;
  while (end > begin && is_space(text[end - 1])) --end;
  return text.substr(begin, end - begin);
}

/// Reads a .msh forwards: lines, and values as ASCII words or binary (native little-endian: int 4
/// bytes, size_t and double 8), keeping the line (ASCII) or byte (binary) for messages.
class MshReader {
 public:
  MshReader(FileBytes& in, std::string file) : in_(in), file_(std::move(file)) {}

  void set_binary(bool binary) { binary_ = binary; }
  bool binary() const { return binary_; }
  void set_section(const std::string& section) { section_ = section; }

  [[noreturn]] void fail(const std::string& what) const {
    const std::string where = binary_ ? "byte " + std::to_string(in_.offset()) : "line " + std::to_string(last_line_);
    throw InvalidInput(file_ + ": " + where + (section_.empty() ? "" : ", " + section_) + ": " + what);
  }

  /// The next line (its rest, after values read from it): false at the end of the file.
  bool line(std::string& out) {
    bool too_long = false;
    if (!in_.line(out, max_line_bytes, too_long)) return false;
    last_line_ = line_++;
    if (too_long) out += "...";
    return true;
  }

  /// An ASCII word (whitespace-separated), in either mode (binary MSH 2 gives its counts so).
  std::string word(const char* what) {
    std::string text;
    char c = 0;
    while (true) {
      if (!in_.read(&c, 1)) fail("the file ends before " + std::string(what));
      if (!is_space(c)) break;
      if (c == '\n') ++line_;
    }
    last_line_ = line_;
    while (true) {
      text += c;
      if (text.size() > max_token_bytes) fail(std::string(what) + ": " + quote_input(text, 40) + " is not a number");
      if (!in_.read(&c, 1)) break;
      if (is_space(c)) {
        if (c == '\n') ++line_;
        break;
      }
    }
    return text;
  }

  /// A count or a tag: size_t in binary 4.1, an ASCII whole number ≥ 0 otherwise.
  std::uint64_t count(const char* what) {
    if (binary_) {
      std::uint64_t value = 0;
      if (!in_.read(&value, sizeof value)) fail("the file ends before " + std::string(what));
      return value;
    }
    return ascii_count(what);
  }
  std::uint64_t ascii_count(const char* what) {
    const std::string text = word(what);
    char* end = nullptr;
    errno = 0;
    const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
    if (text[0] == '-' || text[0] == '+' || *end != '\0' || errno == ERANGE)
      fail(std::string(what) + " must be a whole number, got " + quote_input(text, 40));
    return value;
  }
  /// An int in binary (4 bytes), an ASCII whole number otherwise.
  std::int64_t integer(const char* what) {
    if (binary_) {
      std::int32_t value = 0;
      if (!in_.read(&value, sizeof value)) fail("the file ends before " + std::string(what));
      return value;
    }
    const std::string text = word(what);
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE)
      fail(std::string(what) + " must be a whole number, got " + quote_input(text, 40));
    return value;
  }
  double real(const char* what) {
    if (binary_) {
      double value = 0;
      if (!in_.read(&value, sizeof value)) fail("the file ends before " + std::string(what));
      return value;
    }
    const std::string text = word(what);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0')
      fail(std::string(what) + " must be a number, got " + quote_input(text, 40));
    return value;
  }
  /// Passes over `count` × `per` values, of `bytes` each in binary, or ASCII whole numbers.
  void skip_values(std::uint64_t count, std::uint64_t per, std::uint64_t bytes, const char* what) {
    if (!binary_) {
      for (std::uint64_t i = 0; i < count; ++i)
        for (std::uint64_t k = 0; k < per; ++k) ascii_count(what);
      return;
    }
    if (count > in_.size() / (per * bytes) || !in_.skip(count * per * bytes))
      fail("the file ends inside " + std::string(what));
  }
  /// The section's closing line, "$End<name>".
  void end_of_section(const std::string& marker) {
    std::string text;
    if (binary_) {
      // The binary data ends its line; the marker is on the next.
      if (!line(text)) fail("the file ends before " + marker);
      if (trimmed(text).empty() && !line(text)) fail("the file ends before " + marker);
      if (trimmed(text) != marker) fail("expected " + marker + ", got " + quote_input(text, 40));
      return;
    }
    text = word(marker.c_str());
    if (text != marker)
      fail("expected " + marker + " (the counts above do not match what follows), got " + quote_input(text, 40));
  }

 private:
  FileBytes& in_;
  std::string file_;
  std::string section_;
  bool binary_ = false;
  std::int64_t line_ = 1;       ///< the line the reading is on
  std::int64_t last_line_ = 0;  ///< the line of the last value or line read
};

std::string point_text(double x, double y, double z) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", x, y, z);
  return text;
}

void check_node(MshReader& r, std::uint64_t tag, double x, double y, double z) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    r.fail("node " + std::to_string(tag) + " is at " + point_text(x, y, z) + ", not finite numbers");
}

std::int64_t read_nodes(MshReader& r, double version, double max_triangles) {
  const auto bound = [&](std::uint64_t nodes) {
    if (static_cast<double>(nodes) > nodes_per_triangle_bound * (max_triangles + 1))
      r.fail(std::to_string(nodes) + " nodes (its header), more than " +
             std::to_string(static_cast<long long>(nodes_per_triangle_bound)) + " per triangle allowed, " +
             detail::beyond_triangle_limit(max_triangles, "use a coarser mesh"));
  };
  if (version < 4) {
    const std::uint64_t nodes = r.ascii_count("the number of nodes");
    bound(nodes);
    for (std::uint64_t i = 0; i < nodes; ++i) {
      const std::uint64_t tag =
          r.binary() ? static_cast<std::uint64_t>(r.integer("a node's tag")) : r.count("a node's tag");
      const double x = r.real("x"), y = r.real("y"), z = r.real("z");
      check_node(r, tag, x, y, z);
    }
    r.end_of_section("$EndNodes");
    return static_cast<std::int64_t>(nodes);
  }
  const std::uint64_t blocks = r.count("the number of node blocks");
  const std::uint64_t nodes = r.count("the number of nodes");
  r.count("the smallest node tag");
  r.count("the largest node tag");
  bound(nodes);
  std::uint64_t seen = 0;
  std::vector<std::uint64_t> tags;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::int64_t dimension = r.integer("a node block's dimension");
    r.integer("a node block's entity");
    const std::int64_t parametric = r.integer("whether a node block is parametric");
    const std::uint64_t count = r.count("a node block's number of nodes");
    if (dimension < 0 || dimension > 3) r.fail("a node block of dimension " + std::to_string(dimension) + " (0 to 3)");
    if (parametric != 0 && parametric != 1) r.fail("a node block's parametric flag is " + std::to_string(parametric));
    if (count > nodes - seen) r.fail("node blocks of more nodes than the header's " + std::to_string(nodes));
    seen += count;
    tags.clear();
    for (std::uint64_t i = 0; i < count; ++i) tags.push_back(r.count("a node's tag"));
    for (std::uint64_t i = 0; i < count; ++i) {
      const double x = r.real("x"), y = r.real("y"), z = r.real("z");
      for (std::int64_t u = 0; u < parametric * dimension; ++u) r.real("a parametric coordinate");
      check_node(r, tags[i], x, y, z);
    }
  }
  if (seen != nodes)
    r.fail("node blocks of " + std::to_string(seen) + " nodes; the header says " + std::to_string(nodes));
  r.end_of_section("$EndNodes");
  return static_cast<std::int64_t>(nodes);
}

std::int64_t read_elements(MshReader& r, double version, double max_triangles) {
  std::uint64_t triangles = 0;
  const auto add_triangles = [&](std::uint64_t count, const char* where) {
    triangles += count;
    if (static_cast<double>(triangles) > max_triangles)
      r.fail(std::to_string(triangles) + " triangles or more (" + where + "), " +
             detail::beyond_triangle_limit(max_triangles, "use a coarser mesh"));
  };
  const auto nodes_of = [&](std::int64_t type) {
    const int nodes = nodes_of_type(type);
    if (nodes == 0) r.fail("an element of type " + std::to_string(type) + ", which the MSH format does not list");
    return nodes;
  };
  if (version < 4) {
    const std::uint64_t elements = r.ascii_count("the number of elements");
    std::uint64_t seen = 0;
    while (seen < elements) {
      if (r.binary()) {
        // Blocks of elements of one type: type, count, tags each, then each element's ints.
        const std::int64_t type = r.integer("an element block's type");
        const std::int64_t count = r.integer("an element block's number of elements");
        const std::int64_t tags = r.integer("an element block's number of tags");
        const int nodes = nodes_of(type);
        if (count <= 0 || static_cast<std::uint64_t>(count) > elements - seen)
          r.fail("an element block of " + std::to_string(count) + " elements, beyond the " + std::to_string(elements) +
                 " the header says");
        if (tags < 0 || tags > 1000) r.fail("elements of " + std::to_string(tags) + " tags each");
        if (type == 2) add_triangles(static_cast<std::uint64_t>(count), "an element block's header");
        r.skip_values(static_cast<std::uint64_t>(count),
                      1 + static_cast<std::uint64_t>(tags) + static_cast<std::uint64_t>(nodes), 4, "an element block");
        seen += static_cast<std::uint64_t>(count);
        continue;
      }
      r.ascii_count("an element's tag");
      const std::int64_t type = r.integer("an element's type");
      const std::uint64_t tags = r.ascii_count("an element's number of tags");
      if (tags > 1000) r.fail("an element of " + std::to_string(tags) + " tags");
      const int nodes = nodes_of(type);
      if (type == 2) add_triangles(1, "counted element by element");
      r.skip_values(tags, 1, 4, "an element's tags");
      r.skip_values(static_cast<std::uint64_t>(nodes), 1, 4, "an element's nodes");
      ++seen;
    }
    r.end_of_section("$EndElements");
    return static_cast<std::int64_t>(triangles);
  }
  const std::uint64_t blocks = r.count("the number of element blocks");
  const std::uint64_t elements = r.count("the number of elements");
  r.count("the smallest element tag");
  r.count("the largest element tag");
  std::uint64_t seen = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    r.integer("an element block's dimension");
    r.integer("an element block's entity");
    const std::int64_t type = r.integer("an element block's type");
    const std::uint64_t count = r.count("an element block's number of elements");
    const int nodes = nodes_of(type);
    if (count > elements - seen)
      r.fail("element blocks of more elements than the header's " + std::to_string(elements));
    if (type == 2) add_triangles(count, "an element block's header");
    r.skip_values(count, 1 + static_cast<std::uint64_t>(nodes), 8, "an element block");
    seen += count;
  }
  if (seen != elements)
    r.fail("element blocks of " + std::to_string(seen) + " elements; the header says " + std::to_string(elements));
  r.end_of_section("$EndElements");
  return static_cast<std::int64_t>(triangles);
}

}  // namespace

MshFileSummary check_msh_file(const std::string& path, double max_triangles) {
  detail::check_sheet_file_access(path, "mesh file");
  const std::string file = quote_input(path, 120);
  FileBytes in(path, file);
  MshReader r(in, file);
  MshFileSummary summary;
  std::string text;
  if (!r.line(text) || trimmed(text) != "$MeshFormat")
    r.fail("not a Gmsh .msh file: it does not begin with \"$MeshFormat\"");
  r.set_section("$MeshFormat");
  if (!r.line(text)) r.fail("the file ends inside $MeshFormat");
  // "version file-type data-size": three words, the last two whole numbers.
  std::vector<std::string> words;
  for (std::size_t i = 0; i < text.size();) {
    while (i < text.size() && is_space(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !is_space(text[i])) ++i;
    if (i > start) words.push_back(text.substr(start, i - start));
  }
  const auto whole = [](const std::string& word) {
    char* end = nullptr;
    const long value = std::strtol(word.c_str(), &end, 10);
    return *end == '\0' && end != word.c_str() ? value : -1;
  };
  if (words.size() != 3) r.fail("expected \"version file-type data-size\", got " + quote_input(text, 40));
  const std::string& version = words[0];
  const long file_type = whole(words[1]), data_size = whole(words[2]);
  if (version == "4.1") summary.version = 4.1;
  else if (version == "2" || version == "2.0" || version == "2.1" || version == "2.2") summary.version = 2.2;
  else
    r.fail("version " + quote_input(version, 16) +
           ": emit reads .msh 4.1 and 2.2 (save it again from Gmsh as version 4.1, its default)");
  if (file_type != 0 && file_type != 1) r.fail("file-type " + std::to_string(file_type) + " (0 ASCII, 1 binary)");
  if (data_size != 8) r.fail("data-size " + std::to_string(data_size) + " (emit reads 8-byte values)");
  summary.binary = file_type == 1;
  if (summary.binary) {
    r.set_binary(true);
    const std::int64_t one = r.integer("the byte order's 1");
    if (one != 1) r.fail("written in the other byte order (big-endian): save it as ASCII");
    r.set_binary(false);
  }
  if (summary.binary) r.line(text);  // the rest of the binary 1's line
  if (!r.line(text) || trimmed(text) != "$EndMeshFormat") r.fail("expected $EndMeshFormat");
  bool nodes_seen = false, elements_seen = false;
  while (r.line(text)) {
    const std::string name = trimmed(text);
    r.set_section("");
    if (name.empty()) continue;
    if (name[0] != '$' || name.rfind("$End", 0) == 0)
      r.fail("expected a section ($Nodes, $Elements, ...), got " + quote_input(text, 40));
    r.set_section(name);
    r.set_binary(summary.binary);
    if (name == "$Nodes" || name == "$Elements") {
      if (name == "$Nodes" ? nodes_seen : elements_seen) r.fail("a second " + name + " section");
      if (name == "$Nodes") {
        nodes_seen = true;
        summary.node_count = read_nodes(r, summary.version, max_triangles);
      } else {
        elements_seen = true;
        summary.triangle_count = read_elements(r, summary.version, max_triangles);
      }
      r.set_binary(false);
      continue;
    }
    // Another section (physical names, entities, periodicity, data): passed over to its end.
    r.set_binary(false);
    const std::string end = "$End" + name.substr(1);
    bool ended = false;
    while (!ended && r.line(text)) ended = trimmed(text) == end;
    if (!ended) r.fail("the file ends before " + end);
  }
  r.set_section("");
  if (!nodes_seen) r.fail("no $Nodes section");
  if (!elements_seen) r.fail("no $Elements section");
  if (summary.triangle_count == 0) r.fail("no 3-node triangles (element type 2): the sheet is a surface of triangles");
  return summary;
}

}  // namespace emit
