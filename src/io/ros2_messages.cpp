#include "emit/io/ros2_messages.hpp"

#include <bit>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <span>
#include <type_traits>

#include "emit/core/errors.hpp"

namespace emit {

namespace {

// The definitions ROS 2 bags carry: the message's own fields, then each type it uses once.
constexpr std::string_view separator =
    "================================================================================\n";

constexpr std::string_view header_types =
    "MSG: std_msgs/Header\n"
    "# Standard metadata for higher-level stamped data types.\n"
    "builtin_interfaces/Time stamp\n"
    "string frame_id\n"
    "================================================================================\n"
    "MSG: builtin_interfaces/Time\n"
    "int32 sec\n"
    "uint32 nanosec\n";

constexpr std::string_view tactile_state_fields =
    "# One frame of a tactile skin's raw readings (modelled on tactile_msgs/TactileState).\n"
    "std_msgs/Header header\n"
    "emit_msgs/TactileSensor[] sensors\n"
    "================================================================================\n"
    "MSG: emit_msgs/TactileSensor\n"
    "# A sensor's readings: for an EMIT sheet of N electrodes, N*N volts, row l (electrode l\n"
    "# grounded) after row, column m the electrode read.\n"
    "string name\n"
    "float64[] values\n";

constexpr std::string_view tactile_contacts_fields =
    "# A frame's contacts, strongest first; an empty list when nothing touches. The header's\n"
    "# stamp: when the frame reached the host (its system clock, the Unix epoch).\n"
    "std_msgs/Header header\n"
    "uint64 frame       # the source's frame number\n"
    "float64 board_time # s, when the board took the frame, on the board's clock\n"
    "emit_msgs/TactileContact[] contacts\n"
    "emit_msgs/TactileContact[] ended  # tracked touches that ended with this frame: their last state\n"
    "================================================================================\n"
    "MSG: emit_msgs/TactileContact\n"
    "# A contact (modelled on tactile_msgs/TactileContact), in SI units.\n"
    "string name  # touch_<id> when tracked (the same while the touch lasts), else contact_<rank>\n"
    "geometry_msgs/Vector3 position  # m, a point of the sheet\n"
    "geometry_msgs/Vector3 normal    # the sheet's unit outward normal there\n"
    "geometry_msgs/Wrench wrench     # N: the press on the sheet, force = -force_N * normal\n"
    "float64 area                    # m^2\n"
    "float64 pressure                # Pa, mean over the area\n"
    "float64 peak_pressure           # Pa\n"
    "float64 position_std_x          # m, 1 sigma along the chart's first axis (0: not estimated)\n"
    "float64 position_std_y          # m, along its second\n"
    "float64 pressure_std            # Pa, 1 sigma\n"
    "float64 force_std               # N, 1 sigma\n"
    "# The outline as the ellipse of its second moments (all 0: none, a disc of the area):\n"
    "float64 semi_major_m            # m, the semi-axes\n"
    "float64 semi_minor_m            # m\n"
    "float64 orientation_rad         # rad, the major axis from the chart's first axis, in (-pi/2, pi/2]\n"
    "float64 area_std_m2             # m^2, 1 sigma of the area (0: not estimated)\n"
    "float64 orientation_std_rad     # rad, 1 sigma of the orientation (0: not estimated)\n"
    "# The outline as a polygon (first and last points joined), counter-clockwise, in m in the\n"
    "# sheet's chart: x, y on a flat sheet (z = 0). Empty: none.\n"
    "geometry_msgs/Polygon outline\n"
    "geometry_msgs/Vector3 velocity  # m/s along the chart's axes (z = 0); 0 when not tracked\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Polygon\n"
    "# A specification of a polygon where the first and last points are assumed to be connected\n"
    "Point32[] points\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Point32\n"
    "float32 x\n"
    "float32 y\n"
    "float32 z\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Wrench\n"
    "Vector3 force\n"
    "Vector3 torque\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Vector3\n"
    "float64 x\n"
    "float64 y\n"
    "float64 z\n";

constexpr std::string_view pressure_image_fields =
    "# The pressure per triangle of the mesh published once on the mesh topic (shape_msgs/Mesh).\n"
    "std_msgs/Header header\n"
    "uint64 frame        # the source's frame number\n"
    "float32[] pressure  # Pa, 0 where nothing presses\n";

constexpr std::string_view mesh_fields =
    "# Definition of a mesh.\n"
    "MeshTriangle[] triangles\n"
    "geometry_msgs/Point[] vertices\n"
    "================================================================================\n"
    "MSG: shape_msgs/MeshTriangle\n"
    "uint32[3] vertex_indices\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Point\n"
    "float64 x\n"
    "float64 y\n"
    "float64 z\n";

constexpr std::string_view point_cloud_fields =
    "# This message holds a collection of N-dimensional points, which may\n"
    "# contain additional information such as normals, intensity, etc. The\n"
    "# point data is stored as a binary blob, its layout described by the\n"
    "# contents of the \"fields\" array.\n"
    "std_msgs/Header header\n"
    "uint32 height\n"
    "uint32 width\n"
    "PointField[] fields\n"
    "bool    is_bigendian # Is this data bigendian?\n"
    "uint32  point_step   # Length of a point in bytes\n"
    "uint32  row_step     # Length of a row in bytes\n"
    "uint8[] data         # Actual point data, size is (row_step*height)\n"
    "bool is_dense        # True if there are no invalid points\n"
    "================================================================================\n"
    "MSG: sensor_msgs/PointField\n"
    "uint8 INT8    = 1\n"
    "uint8 UINT8   = 2\n"
    "uint8 INT16   = 3\n"
    "uint8 UINT16  = 4\n"
    "uint8 INT32   = 5\n"
    "uint8 UINT32  = 6\n"
    "uint8 FLOAT32 = 7\n"
    "uint8 FLOAT64 = 8\n"
    "string name      # Name of field\n"
    "uint32 offset    # Offset from start of point struct\n"
    "uint8  datatype  # Datatype enumeration, see above\n"
    "uint32 count     # How many elements in the field\n";

/// A stamped message's definition: its fields, then the header's types.
std::string with_header(std::string_view fields) {
  return std::string(fields) + std::string(separator) + std::string(header_types);
}

/// CDR (XCDR1, little-endian): each primitive aligned to its size, counted from after the
/// 4-byte encapsulation header; strings with their length (NUL included) and a NUL; sequences
/// with their count.
class CdrWriter {
 public:
  explicit CdrWriter(std::vector<std::uint8_t>& out) : out_(out) {
    out_.clear();
    out_.assign({0x00, 0x01, 0x00, 0x00});  // the encapsulation: CDR_LE, no options
  }
  template <typename T>
  void put(T value) {
    static_assert(std::is_arithmetic_v<T>);
    align(sizeof(T));
    const std::size_t at = out_.size();
    out_.resize(at + sizeof(T));
    std::memcpy(out_.data() + at, &value, sizeof(T));  // little-endian hosts (x86-64, ARM): as is
  }
  void string(std::string_view text) {
    put(static_cast<std::uint32_t>(text.size() + 1));
    out_.insert(out_.end(), text.begin(), text.end());
    out_.push_back(0);
  }
  void count(std::size_t n) { put(static_cast<std::uint32_t>(n)); }
  void header(Ros2Stamp stamp, std::string_view frame_id) {
    put(stamp.sec);
    put(stamp.nanosec);
    string(frame_id);
  }
  void vector3(const Vector3& v) {
    put(v.x());
    put(v.y());
    put(v.z());
  }

 private:
  void align(std::size_t size) {
    while ((out_.size() - 4) % size != 0) out_.push_back(0);
  }
  std::vector<std::uint8_t>& out_;
};

constexpr double degrees_to_radians = std::numbers::pi / 180;

static_assert(std::endian::native == std::endian::little, "CDR_LE is written as the host's bytes");

}  // namespace

const Ros2MessageType& tactile_state_message() {
  static const Ros2MessageType type{"emit_msgs/msg/TactileState", with_header(tactile_state_fields)};
  return type;
}
const Ros2MessageType& tactile_contacts_message() {
  static const Ros2MessageType type{"emit_msgs/msg/TactileContacts", with_header(tactile_contacts_fields)};
  return type;
}
const Ros2MessageType& pressure_image_message() {
  static const Ros2MessageType type{"emit_msgs/msg/PressureImage", with_header(pressure_image_fields)};
  return type;
}
const Ros2MessageType& pressure_cloud_message() {
  static const Ros2MessageType type{"sensor_msgs/msg/PointCloud2", with_header(point_cloud_fields)};
  return type;
}
const Ros2MessageType& mesh_message() {
  static const Ros2MessageType type{"shape_msgs/msg/Mesh", std::string(mesh_fields)};
  return type;
}

void check_ros2_frame_id(const std::string& frame_id, const std::string& option) {
  bool ok = !frame_id.empty() && frame_id.front() != '/';
  for (const char c : frame_id) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '/');
  if (!ok)
    throw InvalidInput(option + " \"" + frame_id +
                       "\": a frame id is letters, digits, _ and /, not starting with / (as tf2 takes it)");
}

std::uint64_t unix_time_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

Ros2Contact ros2_contact(const Contact& c, std::size_t rank) {
  const Vector3 normal(c.nx, c.ny, c.nz);
  std::array<char, 32> name{};  // "contact_" or "touch_" and up to 20 digits
  if (c.id >= 0) std::snprintf(name.data(), name.size(), "touch_%lld", static_cast<long long>(c.id));
  else std::snprintf(name.data(), name.size(), "contact_%zu", rank);
  Ros2Contact r{name,
                1e-3 * Vector3(c.x_mm, c.y_mm, c.z_mm),
                normal,
                -c.force_N * normal,
                1e-6 * c.area_mm2,
                1e6 * c.pressure_N_per_mm2,
                1e6 * c.peak_pressure_N_per_mm2,
                1e-3 * c.x_std_mm,
                1e-3 * c.y_std_mm,
                1e6 * c.pressure_std_N_per_mm2,
                c.force_std_N,
                1e-3 * c.semi_major_mm,
                1e-3 * c.semi_minor_mm,
                degrees_to_radians * c.orientation_deg,
                1e-6 * c.area_std_mm2,
                degrees_to_radians * c.orientation_std_deg,
                {},
                static_cast<std::uint32_t>(c.outline.size),
                1e-3 * Vector3(c.vx_mm_per_s, c.vy_mm_per_s, 0)};
  for (int k = 0; k < c.outline.size; ++k)
    for (int axis = 0; axis < 2; ++axis)
      r.outline_m[static_cast<std::size_t>(k)][static_cast<std::size_t>(axis)] =
          1e-3f * c.outline.vertices_mm[static_cast<std::size_t>(k)][static_cast<std::size_t>(axis)];
  return r;
}

void encode_tactile_state(std::vector<std::uint8_t>& out, Ros2Stamp stamp, std::string_view frame_id,
                          std::string_view sensor_name, const FrameView& volts) {
  CdrWriter cdr(out);
  cdr.header(stamp, frame_id);
  cdr.count(1);
  cdr.string(sensor_name);
  cdr.count(static_cast<std::size_t>(volts.size()));
  for (Index i = 0; i < volts.size(); ++i) cdr.put(volts.data()[i]);
}

namespace {

void put_contacts(CdrWriter& cdr, const std::vector<Contact>& contacts) {
  cdr.count(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Ros2Contact c = ros2_contact(contacts[i], i);
    cdr.string(c.name.data());
    cdr.vector3(c.position_m);
    cdr.vector3(c.normal);
    cdr.vector3(c.force_N);        // the wrench's force
    cdr.vector3(Vector3::Zero());  // and torque
    for (const double v :
         {c.area_m2, c.pressure_Pa, c.peak_pressure_Pa, c.position_std_x_m, c.position_std_y_m, c.pressure_std_Pa,
          c.force_std_N, c.semi_major_m, c.semi_minor_m, c.orientation_rad, c.area_std_m2, c.orientation_std_rad})
      cdr.put(v);
    cdr.count(c.outline_size);  // geometry_msgs/Polygon: its Point32s
    for (std::uint32_t k = 0; k < c.outline_size; ++k) {
      cdr.put(c.outline_m[k][0]);
      cdr.put(c.outline_m[k][1]);
      cdr.put(0.0f);
    }
    cdr.vector3(c.velocity_m_per_s);
  }
}

}  // namespace

void encode_tactile_contacts(std::vector<std::uint8_t>& out, Ros2Stamp stamp, std::string_view frame_id,
                             std::uint64_t frame, const std::vector<Contact>& contacts, double board_time_s,
                             const std::vector<Contact>* ended) {
  CdrWriter cdr(out);
  cdr.header(stamp, frame_id);
  cdr.put(frame);
  cdr.put(board_time_s);
  put_contacts(cdr, contacts);
  if (ended) put_contacts(cdr, *ended);
  else cdr.count(0);
}

void encode_pressure_image(std::vector<std::uint8_t>& out, Ros2Stamp stamp, std::string_view frame_id,
                           std::uint64_t frame, const Vector& pressure_N_per_mm2) {
  CdrWriter cdr(out);
  cdr.header(stamp, frame_id);
  cdr.put(frame);
  cdr.count(static_cast<std::size_t>(pressure_N_per_mm2.size()));
  for (Index k = 0; k < pressure_N_per_mm2.size(); ++k) cdr.put(static_cast<float>(1e6 * pressure_N_per_mm2[k]));
}

std::vector<float> pressure_cloud_points_m(const Mesh& mesh) {
  std::vector<float> points(3 * static_cast<std::size_t>(mesh.triangle_count()));
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    Vector3 centroid = Vector3::Zero();
    for (int corner = 0; corner < 3; ++corner) centroid += mesh.nodes_mm.row(mesh.triangles(t, corner)).transpose();
    for (int axis = 0; axis < 3; ++axis)
      points[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(axis)] =
          static_cast<float>(1e-3 / 3 * centroid[axis]);
  }
  return points;
}

void fill_pressure_cloud_data(std::span<std::uint8_t> data, std::span<const float> points_m,
                              const Vector& pressure_N_per_mm2) {
  for (std::size_t k = 0; k < points_m.size() / 3; ++k) {
    const std::array<float, 4> point{points_m[3 * k], points_m[3 * k + 1], points_m[3 * k + 2],
                                     static_cast<float>(1e6 * pressure_N_per_mm2[static_cast<Index>(k)])};
    std::memcpy(data.data() + pressure_cloud_point_bytes * k, point.data(), pressure_cloud_point_bytes);
  }
}

void encode_pressure_cloud(std::vector<std::uint8_t>& out, Ros2Stamp stamp, std::string_view frame_id,
                           std::span<const float> points_m, const Vector& pressure_N_per_mm2) {
  const std::size_t width = points_m.size() / 3;
  CdrWriter cdr(out);
  cdr.header(stamp, frame_id);
  cdr.put(std::uint32_t{1});  // height: an unordered cloud
  cdr.count(width);
  cdr.count(pressure_cloud_fields.size());
  for (const PointFieldLayout& field : pressure_cloud_fields) {
    cdr.string(field.name);
    cdr.put(field.offset);
    cdr.put(field.datatype);
    cdr.put(field.count);
  }
  cdr.put(std::uint8_t{0});  // is_bigendian
  cdr.put(static_cast<std::uint32_t>(pressure_cloud_point_bytes));
  cdr.count(pressure_cloud_point_bytes * width);  // row_step
  cdr.count(pressure_cloud_point_bytes * width);  // data's length, then its bytes
  const std::size_t at = out.size();
  out.resize(at + pressure_cloud_point_bytes * width);
  fill_pressure_cloud_data({out.data() + at, pressure_cloud_point_bytes * width}, points_m, pressure_N_per_mm2);
  cdr.put(std::uint8_t{1});  // is_dense
}

void encode_mesh(std::vector<std::uint8_t>& out, const Mesh& mesh) {
  CdrWriter cdr(out);
  cdr.count(static_cast<std::size_t>(mesh.triangle_count()));
  for (Index t = 0; t < mesh.triangle_count(); ++t)
    for (int corner = 0; corner < 3; ++corner) cdr.put(static_cast<std::uint32_t>(mesh.triangles(t, corner)));
  cdr.count(static_cast<std::size_t>(mesh.node_count()));
  for (Index v = 0; v < mesh.node_count(); ++v) cdr.vector3(1e-3 * mesh.nodes_mm.row(v).transpose());
}

}  // namespace emit
