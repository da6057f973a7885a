// Electrodes slid along the border without remeshing: the electrode's nodes move by the shift
// along the border, the sheet keeps its shape, and the frames are those of the remeshed sheet
// with the electrodes moved, to discretisation error.
#include "emit/mesh/slide_electrodes.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "emit/core/errors.hpp"
#include "emit/fem/forward_model.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/sensor/sensor_json.hpp"
#include "emit/twin/press_contact.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

double total_area(const Mesh& mesh) {
  double area = 0;
  for (Index t = 0; t < mesh.triangle_count(); ++t) area += mesh.triangle_area_mm2(t);
  return area;
}

TEST(SlideElectrodes, MovesTheElectrodesNodesAlongTheBorderAndKeepsTheSheet) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  std::vector<double> shift(16, 0.0);
  shift[1] = 0.4, shift[6] = -0.5, shift[13] = 0.25;
  const Mesh slid = slide_electrodes(mesh, sensor, shift);
  const Border& border = *sensor.border;
  for (int e = 0; e < 16; ++e)
    for (int v : mesh.electrode_nodes[e]) {
      const double before = border.project(mesh.nodes_mm.row(v).head<2>().transpose()).s_mm;
      const Border::Projection after = border.project(slid.nodes_mm.row(v).head<2>().transpose());
      // On the border, moved by exactly its electrode's shift (a straight side: round-off).
      EXPECT_LT(after.distance_mm, 1e-9);
      EXPECT_NEAR(after.s_mm - before, shift[static_cast<std::size_t>(e)], 1e-9) << "electrode " << e;
    }
  // Nodes slide within the sheet: its area is the same to round-off (3600 mm²).
  EXPECT_NEAR(total_area(slid), 3600, 1e-9);
  // The sensor moved the same way.
  const Sensor moved = with_electrodes_slid(sensor, shift);
  EXPECT_NEAR(moved.electrodes[6].center_s_mm - sensor.electrodes[6].center_s_mm, -0.5, 1e-12);
}

TEST(SlideElectrodes, GivesTheRemeshedSheetsFrames) {
  const Sensor sensor = load_sensor(test::source_path("examples/sensors/square30.json"));
  MeshOptions options = reconstruction_mesh_options(sensor);
  options.electrode_edge_size_factor = 0.25;
  const Mesh mesh = generate_mesh(sensor, options);
  std::vector<double> shift(16, 0.0);
  for (std::size_t e = 0; e < shift.size(); ++e)
    shift[e] = (e % 2 ? 0.3 : -0.3) * (1 + 0.1 * static_cast<double>(e % 3));
  const Mesh slid = slide_electrodes(mesh, sensor, shift);
  const Mesh remeshed = generate_mesh(with_electrodes_slid(sensor, shift), options);
  const std::vector<Press> press{{11, 17, 2.5, 3}};
  const auto frame = [&](const Mesh& m) {
    ForwardModel model(m, sensor.sheet_resistance_ohm_per_sq);
    return model.solve_frame(press_contact_load(m, press, sensor.contact), sensor.drive_voltage_V);
  };
  const Frame nominal = frame(mesh), by_sliding = frame(slid), by_remeshing = frame(remeshed);
  // Two discretisations of the same moved sheet differ by discretisation error only, a small part
  // of what the move itself changes (measured: 2.1 %); a slide that did not move the physics
  // would leave the full difference.
  const double moved = (by_remeshing - nominal).norm();
  EXPECT_LT((by_sliding - by_remeshing).norm(), 0.2 * moved);
}

TEST(SlideElectrodes, RefusesWhatItCannotDo) {
  const Sensor sensor = default_sensor();
  const Mesh mesh = generate_mesh(sensor, reconstruction_mesh_options(sensor));
  EXPECT_THROW(slide_electrodes(mesh, sensor, std::vector<double>(15, 0.0)), InvalidInput);
  std::vector<double> far(16, 0.0);
  far[3] = 2.5;  // more than half the 3 mm of room beyond its ends
  EXPECT_THROW(slide_electrodes(mesh, sensor, far), InvalidInput);
  far[3] = NAN;
  EXPECT_THROW(slide_electrodes(mesh, sensor, far), InvalidInput);
}

}  // namespace
}  // namespace emit
