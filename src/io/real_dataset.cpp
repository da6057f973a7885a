#include "emit/io/real_dataset.hpp"

#include <cmath>
#include <filesystem>

#include "emit/core/errors.hpp"
#include "emit/core/quote_input.hpp"
#include "emit/io/csv_numbers.hpp"
#include "emit/io/line_reader.hpp"

namespace emit {

namespace {

/// Every line of a file of frames (blank lines skipped), each `width` values (the first line's
/// when width is 0).
Matrix read_rows(const std::string& path, const std::string& what, Index width, std::size_t max_values) {
  if (!std::filesystem::exists(path)) throw IoError(path + ": missing (" + what + ")");
  LineReader lines(path, what);
  std::vector<double> values, row;
  Index rows = 0;
  for (std::string line; lines.next(line);) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    parse_csv_numbers(line, lines, row, true);  // a reading not finite is masked (model/reading_screen.hpp)
    if (width == 0) width = static_cast<Index>(row.size());
    if (static_cast<Index>(row.size()) != width)
      throw InvalidInput(lines.where() + ": " + std::to_string(row.size()) + " values, the frames have " +
                         std::to_string(width));
    if (values.size() + row.size() > max_values)
      throw InvalidInput(lines.where() + ": more than " + std::to_string(max_values) + " values in all; too large");
    values.insert(values.end(), row.begin(), row.end());
    ++rows;
  }
  if (rows == 0) throw InvalidInput(path + ": no frames");
  Matrix m(rows, width);
  for (Index i = 0; i < rows; ++i)
    for (Index j = 0; j < width; ++j) m(i, j) = values[static_cast<std::size_t>(i * width + j)];
  return m;
}

std::vector<std::vector<Vector2>> read_truth(const std::string& path, Index presses) {
  if (!std::filesystem::exists(path)) throw IoError(path + ": missing (the presses' true places)");
  LineReader lines(path, "truth file");
  std::string line;
  if (!lines.next(line) || line.rfind("frame,contact,x_mm,y_mm", 0) != 0)
    throw InvalidInput(path + ":1: expected the header \"frame,contact,x_mm,y_mm[,...]\", got " + quote_input(line));
  std::vector<std::vector<Vector2>> contacts(static_cast<std::size_t>(presses));
  std::vector<double> v;
  while (lines.next(line)) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    parse_csv_numbers(line, lines, v);
    if (v.size() < 4)
      throw InvalidInput(lines.where() + ": expected frame,contact,x_mm,y_mm, got " + quote_input(line));
    if (v[0] < 0 || v[0] >= static_cast<double>(presses) || v[0] != std::floor(v[0]))
      throw InvalidInput(lines.where() + ": frame " + quote_input(line.substr(0, line.find(','))) +
                         " is not a frame of frames.csv (0 to " + std::to_string(presses - 1) + ")");
    contacts[static_cast<std::size_t>(v[0])].emplace_back(v[2], v[3]);
  }
  return contacts;
}

}  // namespace

RealDataset read_real_dataset(const std::string& folder, std::size_t max_values) {
  if (!std::filesystem::is_directory(folder)) throw IoError(folder + ": not a folder of real presses");
  const auto file = [&](const char* name) { return (std::filesystem::path(folder) / name).string(); };
  RealDataset d;
  d.folder = folder;
  d.frames = read_rows(file("frames.csv"), "frames file", 0, max_values);
  const std::string per_frame = file("references_per_frame.csv");
  d.per_frame_references = std::filesystem::exists(per_frame);
  if (d.per_frame_references) {
    d.references = read_rows(per_frame, "references file", d.readings(), max_values);
    if (d.references.rows() != d.presses())
      throw InvalidInput(per_frame + ": " + std::to_string(d.references.rows()) + " references for " +
                         std::to_string(d.presses()) + " frames in frames.csv");
  } else {
    if (!std::filesystem::exists(file("reference.csv")))
      throw IoError(folder + ": neither references_per_frame.csv nor reference.csv (the unpressed frames)");
    const Matrix one = read_rows(file("reference.csv"), "reference file", d.readings(), max_values);
    if (one.rows() != 1)
      throw InvalidInput(file("reference.csv") + ": " + std::to_string(one.rows()) + " frames; expected one");
    d.references = one.replicate(d.presses(), 1);
  }
  d.contacts = read_truth(file("truth.csv"), d.presses());
  return d;
}

}  // namespace emit
