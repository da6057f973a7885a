// MCAP files (io/mcap_writer.hpp, io/tactile_mcap.hpp): the records as the format lays them out,
// PATH.partial until close() and PATH only after, nothing created for a missing folder, and a
// frame's three messages written without allocating once warm. tests/mcap/read_back_test.mjs
// reads whole recordings back with the format's own reader.
#include "emit/io/mcap_writer.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "emit/core/errors.hpp"
#include "emit/io/tactile_mcap.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

namespace fs = std::filesystem;

TEST(McapWriter, RecordsAreLaidOutAndTheFileAppearsOnClose) {
  const std::string folder = test::temp_folder("mcap_writer");
  const std::string path = folder + "/a.mcap";
  {
    McapWriter mcap(path, "ros2");
    EXPECT_EQ(mcap.add_schema("s", "ros2msg", "int32 x\n"), 1);  // schema ids start at 1 (0: none)
    EXPECT_EQ(mcap.add_channel(1, "/t", "cdr"), 0);
    const std::vector<std::uint8_t> data = {1, 2, 3};
    mcap.write_message(0, 5, 10, 11, data);
    EXPECT_TRUE(fs::exists(path + ".partial"));
    EXPECT_FALSE(fs::exists(path));
    mcap.close();
  }
  EXPECT_FALSE(fs::exists(path + ".partial"));
  const std::string bytes = test::read_text(path);
  // magic 8 + header (9 + 4+4 "ros2" + 4+len "emit x.y.z") + schema (9 + 2 + 4+1 + 4+7 + 4+8)
  // + channel (9 + 2 + 2 + 4+2 + 4+3 + 4) + message (9 + 22 + 3) + data end (9 + 4) + footer
  // (9 + 20) + magic 8.
  ASSERT_GT(bytes.size(), 29u);
  std::uint32_t library = 0;
  std::memcpy(&library, bytes.data() + 8 + 9 + 8, 4);
  EXPECT_EQ(bytes.substr(8 + 9 + 8 + 4, library).rfind("emit ", 0), 0u);
  EXPECT_EQ(bytes.size(), 8 + (9 + 8 + 4 + library) + 39 + 30 + 34 + 13 + 29 + 8);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89MCAP0\r\n"));
  EXPECT_EQ(bytes.substr(bytes.size() - 8), std::string("\x89MCAP0\r\n"));
  EXPECT_EQ(bytes[8], '\x01');                           // the header record
  EXPECT_EQ(bytes[bytes.size() - 8 - 29], '\x02');       // the footer record
  EXPECT_EQ(bytes[bytes.size() - 8 - 29 - 13], '\x0f');  // data end
}

TEST(McapWriter, AMissingFolderIsRefusedBeforeAnythingIsWritten) {
  const std::string folder = test::temp_folder("mcap_missing");
  const std::string message = test::error_of([&] { McapWriter(folder + "/no/such/a.mcap", "ros2"); });
  EXPECT_NE(message.find("folder " + folder + "/no/such does not exist"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(folder + "/no"));
}

TEST(McapWriter, WithoutCloseThePartialFileStaysAndTheTargetIsUntouched) {
  const std::string folder = test::temp_folder("mcap_unclosed");
  const std::string path = folder + "/a.mcap";
  { std::ofstream(path) << "a good file"; }
  {
    McapWriter mcap(path, "ros2");
    mcap.add_schema("s", "ros2msg", "");
  }  // an error or a crash: no close()
  EXPECT_EQ(test::read_text(path), "a good file");
  EXPECT_TRUE(fs::exists(path + ".partial"));
}

TEST(TactileMcap, AFrameIsWrittenWithoutAllocatingOnceWarm) {
  const std::string folder = test::temp_folder("tactile_mcap");
  const Mesh mesh = test::strip_mesh(60, 60, 20, 20);
  TactileMcap mcap(folder + "/run.mcap", "default 60 mm", mesh, 0);
  const Frame volts = Frame::Constant(16, 16, 0.5);
  const std::vector<Contact> contacts(2);
  const Vector pressure = Vector::Zero(mesh.triangle_count());
  mcap.write(0, 0, frame_view(volts), contacts, pressure);  // warm-up
  {
    const test::AllocationCounter counter;
    mcap.write(1, 20'000'000, frame_view(volts), contacts, pressure);
    EXPECT_EQ(counter.count(), 0);
  }
  mcap.close();
  EXPECT_EQ(mcap.frames(), 2u);
  EXPECT_TRUE(fs::exists(folder + "/run.mcap"));
}

// The messages' header frame is the one named (`emit live --frame-id`), in every frame's three
// messages (MCAP stores them uncompressed: the CDR string is in the file's bytes as written); a
// name tf2 refuses is refused before the file is made.
TEST(TactileMcap, TheHeadersCarryTheFrameNamed) {
  const std::string folder = test::temp_folder("tactile_mcap_frame");
  const Mesh mesh = test::strip_mesh(60, 60, 20, 20);
  TactileMcap mcap(folder + "/run.mcap", "default 60 mm", mesh, 0, "left_palm");
  const Frame volts = Frame::Constant(16, 16, 0.5);
  const Vector pressure = Vector::Zero(mesh.triangle_count());
  for (std::uint64_t f = 0; f < 2; ++f) mcap.write(f, f * 20'000'000, frame_view(volts), {}, pressure);
  mcap.close();
  const std::string bytes = test::read_text(folder + "/run.mcap");
  std::size_t named = 0;
  for (std::size_t at = bytes.find("left_palm"); at != std::string::npos; at = bytes.find("left_palm", at + 1)) ++named;
  EXPECT_EQ(named, 8u) << "two frames of four stamped messages (frames, contacts, pressure, its cloud)";
  EXPECT_EQ(bytes.find("emit_sheet"), std::string::npos);
  for (const char* refused : {"/left_palm", "", "left palm"})
    EXPECT_THROW(TactileMcap(folder + "/bad.mcap", "default 60 mm", mesh, 0, refused), InvalidInput) << refused;
  EXPECT_FALSE(fs::exists(folder + "/bad.mcap.partial"));
}

}  // namespace
}  // namespace emit
