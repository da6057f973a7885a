// The floors only point down (src/floors.txt): every #include of the library, the CLI and the
// benchmarks is read, and one that reaches a floor above its own, or another folder of its own
// floor, fails the test naming the file and the line.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

/// Folder → floor (0 = the bottom), from a floors file: one floor a line, bottom first, its
/// folders separated by spaces; '#' starts a comment.
std::map<std::string, int> read_floors(const fs::path& path) {
  std::ifstream in(path);
  std::map<std::string, int> floor_of;
  std::string line;
  for (int floor = 0; std::getline(in, line);) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string folder;
    bool any = false;
    while (words >> folder) floor_of[folder] = floor, any = true;
    floor += any;
  }
  return floor_of;
}

/// The folder a file of the tree belongs to: include/emit/<f>/…, src/<f>/…, firmware/…, or the
/// top folder (cli, bench, python).
std::string folder_of(const fs::path& relative) {
  auto part = relative.begin();
  std::string top = part->string();
  if (top == "include" || top == "src") {
    if (top == "include") ++part;  // emit/
    ++part;
    return part != relative.end() ? part->string() : "";
  }
  return top;
}

/// The folder an include names: "emit/<f>/…" → f; the firmware's "core/…" → firmware; a bare
/// name is a private header of the including file's own folder.
std::string included_folder(const std::string& include, const std::string& own_folder) {
  if (include.rfind("emit/", 0) == 0) {
    const std::size_t slash = include.find('/', 5);
    return slash == std::string::npos ? "" : include.substr(5, slash - 5);
  }
  if (include.rfind("core/", 0) == 0) return "firmware";
  return own_folder;
}

struct Violation {
  std::string where;  ///< path:line
  std::string what;
};

/// Every include under `root`'s include/emit, src, cli, bench, python and firmware that breaks the floors.
std::vector<Violation> check_includes(const fs::path& root, const std::map<std::string, int>& floor_of) {
  std::vector<Violation> violations;
  std::vector<fs::path> files;
  for (const char* top : {"include/emit", "src", "cli", "bench", "python", "firmware"})
    if (fs::is_directory(root / top))
      for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
        const std::string extension = entry.path().extension().string();
        if (entry.is_regular_file() &&
            (extension == ".hpp" || extension == ".cpp" || extension == ".h" || extension == ".ino"))
          files.push_back(entry.path());
      }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    const fs::path relative = fs::relative(file, root);
    const std::string own = folder_of(relative);
    const auto own_floor = floor_of.find(own);
    if (own_floor == floor_of.end()) {
      violations.push_back({relative.string(), "its folder \"" + own + "\" is on no floor of the floors file"});
      continue;
    }
    std::ifstream in(file);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const std::size_t hash = line.find_first_not_of(" \t");
      if (hash == std::string::npos || line.compare(hash, 8, "#include") != 0) continue;
      const std::size_t open = line.find('"');
      if (open == std::string::npos) continue;  // <system> headers
      const std::string include = line.substr(open + 1, line.find('"', open + 1) - open - 1);
      const std::string target = included_folder(include, own);
      const std::string where = relative.string() + ":" + std::to_string(number);
      const auto target_floor = floor_of.find(target);
      if (target_floor == floor_of.end())
        violations.push_back({where, "includes " + include + " from \"" + target + "\", a folder on no floor"});
      else if (target != own && target_floor->second >= own_floor->second)
        violations.push_back({where, "includes " + include + ": \"" + target + "\" (floor " +
                                         std::to_string(target_floor->second) + ") is not below \"" + own +
                                         "\" (floor " + std::to_string(own_floor->second) + ")"});
    }
  }
  return violations;
}

std::string describe(const std::vector<Violation>& violations) {
  std::string text;
  for (const Violation& v : violations) text += v.where + ": " + v.what + "\n";
  return text;
}

}  // namespace

TEST(IncludeDirection, EveryIncludePointsDown) {
  const fs::path root = fs::path(emit::test::source_path("")).parent_path();  // without the trailing /
  const auto floor_of = read_floors(root / "src/floors.txt");
  ASSERT_GE(floor_of.size(), 10u) << "src/floors.txt lists too few folders";
  const std::vector<Violation> violations = check_includes(root, floor_of);
  EXPECT_TRUE(violations.empty()) << violations.size() << " include(s) break the floors of src/floors.txt:\n"
                                  << describe(violations);
}

TEST(IncludeDirection, EveryFolderOfTheLibraryIsOnAFloor) {
  const fs::path root = fs::path(emit::test::source_path("")).parent_path();  // without the trailing /
  const auto floor_of = read_floors(root / "src/floors.txt");
  for (const char* top : {"include/emit", "src"}) {
    for (const auto& entry : fs::directory_iterator(root / top)) {
      if (entry.is_directory()) {  // braces: EXPECT_TRUE expands to an if-else (gcc's -Wdangling-else)
        EXPECT_TRUE(floor_of.count(entry.path().filename().string()))
            << top << "/" << entry.path().filename().string() << " is on no floor of src/floors.txt";
      }
    }
  }
}

// The check itself: a tree with one upward include and one sideways include on a shared floor
// gives exactly those two, by file and line; a downward include and a private header give none.
TEST(IncludeDirection, NamesTheFileAndLineOfAnIncludeThatPointsUp) {
  const fs::path root = emit::test::temp_folder("include_direction");
  fs::create_directories(root / "src/low");
  fs::create_directories(root / "src/high");
  fs::create_directories(root / "src/side");
  std::ofstream(root / "floors.txt") << "# test\nlow\nhigh side\n";
  std::ofstream(root / "src/high/fine.cpp")
      << "#include \"emit/low/a.hpp\"\n#include \"private.hpp\"\n#include <vector>\n";
  std::ofstream(root / "src/low/bad.cpp")
      << "// comment\n#include \"emit/low/b.hpp\"\n  #include \"emit/high/c.hpp\"\n";
  std::ofstream(root / "src/side/bad.cpp") << "#include \"emit/high/d.hpp\"\n";
  const auto floor_of = read_floors(root / "floors.txt");
  EXPECT_EQ(floor_of.at("low"), 0);
  EXPECT_EQ(floor_of.at("side"), 1);
  const std::vector<Violation> violations = check_includes(root, floor_of);
  ASSERT_EQ(violations.size(), 2u) << describe(violations);
  EXPECT_EQ(violations[0].where, "src/low/bad.cpp:3");
  EXPECT_NE(violations[0].what.find("\"high\" (floor 1) is not below \"low\" (floor 0)"), std::string::npos);
  EXPECT_EQ(violations[1].where, "src/side/bad.cpp:1");
}
