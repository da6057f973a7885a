// The ROS 2 package ros2/emit_msgs (what a ROS 2 user builds with colcon to echo emit's topics)
// holds the messages emit writes: its .msg files, the DDS types of idl/emit_ros2.idl (`emit live
// --dds`) and the definitions in emit's MCAP files (io/ros2_messages.hpp), field by field: the
// same names, in the same order, of the same types. A field added to one and not the others is
// a ROS node that cannot read emit's topics, or a bag its own messages do not describe.
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "emit/io/ros2_messages.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

/// A field as "TYPE NAME", TYPE in one spelling for all three: IDL's primitives (double, float,
/// uint64, …), a message as pkg::Name, a sequence as sequence<T>, a fixed array as T[N].
using Fields = std::vector<std::string>;

/// A .msg type in the one spelling; `package` resolves a type named without one.
std::string from_msg(std::string type, const std::string& package) {
  static const std::map<std::string, std::string> primitives{{"float64", "double"}, {"float32", "float"},
                                                             {"uint64", "uint64"},  {"int64", "int64"},
                                                             {"uint32", "uint32"},  {"int32", "int32"},
                                                             {"uint8", "uint8"},    {"string", "string"},
                                                             {"bool", "boolean"},   {"uint16", "uint16"},
                                                             {"int16", "int16"},    {"int8", "int8"}};
  std::string suffix;
  bool sequence = false;
  if (const std::size_t bracket = type.find('['); bracket != std::string::npos) {
    suffix = type.substr(bracket);
    type.resize(bracket);
    sequence = suffix == "[]";
  }
  if (const auto p = primitives.find(type); p != primitives.end()) type = p->second;
  else if (const std::size_t slash = type.find('/'); slash != std::string::npos)
    type = type.substr(0, slash) + "::" + type.substr(slash + 1);
  else type = package + "::" + type;
  return sequence ? "sequence<" + type + ">" : type + suffix;
}

/// A .msg text's fields (comments and blank lines left out).
Fields msg_fields(const std::string& text, const std::string& package) {
  Fields fields;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string type, name;
    if (!(words >> type >> name)) continue;
    fields.push_back(from_msg(type, package) + " " + name);
  }
  return fields;
}

/// The definition as MCAP carries it: the message's own fields, then "MSG: pkg/Type" sections.
std::map<std::string, Fields> definition_sections(const Ros2MessageType& message) {
  std::map<std::string, Fields> sections;
  std::string name = message.name, text;
  name.erase(name.find("/msg/"), 4);  // emit_msgs/msg/TactileState → emit_msgs/TactileState
  const auto flush = [&] {
    sections[name] = msg_fields(text, name.substr(0, name.find('/')));
    text.clear();
  };
  std::istringstream lines(message.definition);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("=====", 0) == 0) continue;
    if (line.rfind("MSG: ", 0) == 0) {
      flush();
      name = line.substr(5);
      continue;
    }
    text += line + "\n";
  }
  flush();
  return sections;
}

/// pkg::msg::dds_::Name_ → pkg::Name (the IDL's spelling of a ROS type); others as they are.
std::string from_idl(std::string type) {
  if (type.rfind("sequence<", 0) == 0) return "sequence<" + from_idl(type.substr(9, type.size() - 10)) + ">";
  if (const std::size_t dds = type.find("::msg::dds_::"); dds != std::string::npos)
    type = type.substr(0, dds) + "::" + type.substr(dds + 13, type.size() - dds - 14);
  return type;
}

/// The IDL's structs of module `package` (pkg::msg::dds_::Name_), by their ROS name (pkg/Name).
std::map<std::string, Fields> idl_structs(const std::string& idl, const std::string& package) {
  std::map<std::string, Fields> structs;
  const std::size_t module = idl.find("module " + package + " {");
  EXPECT_NE(module, std::string::npos) << package;
  const std::string body = idl.substr(module, idl.find("}; }; };", module) - module);
  for (std::size_t at = body.find("struct "); at != std::string::npos; at = body.find("struct ", at)) {
    const std::size_t open = body.find('{', at), close = body.find('}', open);
    std::string name = body.substr(at + 7, open - at - 7);
    name = name.substr(0, name.find('_'));
    Fields& fields = structs[package + "/" + name];
    std::istringstream members(body.substr(open + 1, close - open - 1));
    for (std::string member; std::getline(members, member, ';');) {
      const std::size_t first = member.find_first_not_of(" \n"), space = member.find_last_of(' ');
      if (first == std::string::npos || space == std::string::npos || space < first) continue;
      std::string field = member.substr(space + 1), array;
      if (const std::size_t bracket = field.find('['); bracket != std::string::npos)
        array = field.substr(bracket), field.resize(bracket);
      fields.push_back(from_idl(member.substr(first, space - first)) + array + " " + field);
    }
    at = close;
  }
  return structs;
}

const char* const messages[] = {"TactileSensor", "TactileState", "TactileContact", "TactileContacts", "PressureImage"};

TEST(Ros2Package, TheMsgFilesTheIdlAndTheMcapDefinitionsHoldTheSameFields) {
  const std::string idl = test::read_text(test::source_path("idl/emit_ros2.idl"));
  const std::map<std::string, Fields> dds = idl_structs(idl, "emit_msgs");
  std::map<std::string, Fields> mcap;
  for (const Ros2MessageType* m : {&tactile_state_message(), &tactile_contacts_message(), &pressure_image_message()})
    for (auto& [name, fields] : definition_sections(*m)) mcap[name] = fields;
  EXPECT_EQ(dds.size(), std::size(messages)) << "a type in the IDL without its .msg, or the other way";
  for (const std::string name : messages) {
    SCOPED_TRACE(name);
    const Fields msg =
        msg_fields(test::read_text(test::source_path("ros2/emit_msgs/msg/" + name + ".msg")), "emit_msgs");
    ASSERT_FALSE(msg.empty());
    ASSERT_TRUE(dds.count("emit_msgs/" + name)) << "not in idl/emit_ros2.idl";
    EXPECT_EQ(msg, dds.at("emit_msgs/" + name)) << "ros2/emit_msgs/msg/" << name << ".msg against the IDL";
    ASSERT_TRUE(mcap.count("emit_msgs/" + name)) << "not in the MCAP definitions";
    EXPECT_EQ(msg, mcap.at("emit_msgs/" + name)) << "ros2/emit_msgs/msg/" << name << ".msg against MCAP's";
  }
  // The standard types they use, as the IDL spells them (ROS 2's own definitions).
  const std::map<std::string, Fields> geometry = idl_structs(idl, "geometry_msgs");
  for (const std::string name :
       {"geometry_msgs/Vector3", "geometry_msgs/Wrench", "geometry_msgs/Polygon", "geometry_msgs/Point32"}) {
    ASSERT_TRUE(mcap.count(name)) << name;
    EXPECT_EQ(mcap.at(name), geometry.at(name)) << name;
  }
  // The package lists every .msg for rosidl, and depends on the packages they use.
  const std::string cmake = test::read_text(test::source_path("ros2/emit_msgs/CMakeLists.txt"));
  const std::string package = test::read_text(test::source_path("ros2/emit_msgs/package.xml"));
  for (const std::string name : messages)
    EXPECT_NE(cmake.find("\"msg/" + name + ".msg\""), std::string::npos) << name << " not generated";
  for (const char* dependency :
       {"<depend>std_msgs</depend>", "<depend>geometry_msgs</depend>",
        "<member_of_group>rosidl_interface_packages</member_of_group>", "<name>emit_msgs</name>"})
    EXPECT_NE(package.find(dependency), std::string::npos) << dependency;
}

// The comparison is not blind: a field renamed, retyped or dropped in a .msg is caught.
TEST(Ros2Package, ADifferenceInAFieldIsSeen) {
  const Fields base = msg_fields("uint64 frame\nfloat32[] pressure  # Pa\n", "emit_msgs");
  EXPECT_EQ(base, (Fields{"uint64 frame", "sequence<float> pressure"}));
  EXPECT_NE(base, msg_fields("uint64 frame\nfloat64[] pressure\n", "emit_msgs"));
  EXPECT_NE(base, msg_fields("uint64 frame\nfloat32[] pressures\n", "emit_msgs"));
  EXPECT_NE(base, msg_fields("float32[] pressure\n", "emit_msgs"));
  EXPECT_EQ(msg_fields("TactileContact[] ended\n", "emit_msgs"),
            msg_fields("emit_msgs/TactileContact[] ended\n", "emit_msgs"));
  const auto idl = idl_structs(
      "module emit_msgs { module msg { module dds_ {\n  @final struct P_ {\n    uint64 "
      "frame;\n    sequence<float> pressure;\n  };\n}; }; };",
      "emit_msgs");
  EXPECT_EQ(idl.at("emit_msgs/P"), base);
}

}  // namespace
}  // namespace emit
