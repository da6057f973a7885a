#include "emit/model/conductivity_jacobian.hpp"

#include <chrono>
#include <map>

#include "emit/core/errors.hpp"
#include "emit/fem/stiffness.hpp"

namespace emit {

Matrix conductivity_jacobian(const Mesh& mesh, const CompleteElectrodeModel& model, const Matrix& drives_A,
                             const std::vector<EitReading>& readings) {
  const int N = model.electrode_count();
  if (drives_A.rows() != N)
    throw InvalidInput("EIT Jacobian: drives of " + std::to_string(drives_A.rows()) + " currents for " +
                       std::to_string(N) + " electrodes");
  // The measured pairs, each solved once as a unit drive.
  std::map<std::array<int, 2>, Index> pair_column;
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const EitReading& r = readings[i];
    if (r.drive < 0 || r.drive >= drives_A.cols() || r.plus < 0 || r.plus >= N || r.minus < 0 || r.minus >= N ||
        r.plus == r.minus)
      throw InvalidInput("EIT Jacobian: reading " + std::to_string(i) + " names no drive or pair of electrodes");
    pair_column.emplace(std::array<int, 2>{r.plus, r.minus}, static_cast<Index>(pair_column.size()));
  }
  Matrix pairs_A = Matrix::Zero(N, static_cast<Index>(pair_column.size()));
  for (const auto& [pair, column] : pair_column) pairs_A(pair[0], column) = 1, pairs_A(pair[1], column) = -1;
  const Matrix u_drive = model.node_potentials_V(drives_A);
  const Matrix u_pair = model.node_potentials_V(pairs_A);

  Matrix J(static_cast<Index>(readings.size()), mesh.triangle_count());
  for (Index t = 0; t < mesh.triangle_count(); ++t) {
    const auto v = mesh.triangles.row(t);
    const Eigen::Matrix3d G =
        local_stiffness(mesh.nodes_mm.row(v[0]), mesh.nodes_mm.row(v[1]), mesh.nodes_mm.row(v[2]), 1.0);
    for (std::size_t i = 0; i < readings.size(); ++i) {
      const EitReading& r = readings[i];
      const Index p = pair_column.at({r.plus, r.minus});
      const Eigen::Vector3d ud(u_drive(v[0], r.drive), u_drive(v[1], r.drive), u_drive(v[2], r.drive));
      const Eigen::Vector3d um(u_pair(v[0], p), u_pair(v[1], p), u_pair(v[2], p));
      J(static_cast<Index>(i), t) = -um.dot(G * ud);
    }
  }
  return J;
}

Matrix relative_conductivity_jacobian(const Mesh& mesh, const Sensor& sensor, double* model_s) {
  if (!sensor.excitation) throw InvalidInput("relative conductivity Jacobian: the sensor has no excitation");
  const Excitation& e = *sensor.excitation;
  const Vector sigma = Vector::Constant(mesh.triangle_count(), 1.0 / sensor.sheet_resistance_ohm_per_sq);
  std::vector<double> z = e.contact_impedance_ohm_mm;
  if (z.empty()) z.assign(static_cast<std::size_t>(mesh.electrode_count()), 0.0);
  const auto start = std::chrono::steady_clock::now();
  const CompleteElectrodeModel model(mesh, sigma, z);
  if (model_s) *model_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const Matrix drives = e.drive_currents_A(mesh.electrode_count());
  const Matrix U = model.electrode_potentials_V(drives);
  Matrix J = conductivity_jacobian(mesh, model, drives, e.readings);
  for (std::size_t r = 0; r < e.readings.size(); ++r) {
    const EitReading& m = e.readings[r];
    const double v = U(m.plus, m.drive) - U(m.minus, m.drive);
    if (v == 0)
      throw SolverError("relative conductivity Jacobian: reading " + std::to_string(r) + " is 0 V on a uniform sheet");
    J.row(static_cast<Index>(r)) /= v;
  }
  return J;
}

}  // namespace emit
