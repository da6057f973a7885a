#pragma once
/// \file conductivity_jacobian.hpp
/// For current-injection EIT (fem/complete_electrode_model.hpp): how each reading changes with
/// each triangle's sheet conductance, ∂V/∂σ_e, by the adjoint method (docs/physics.md,
/// "Current-injection skins"). A reading is a drive's currents I_d and a pair of electrodes read
/// as U_+ − U_−, which is I_mᵀ U(I_d) for the unit pattern I_m = e_+ − e_−. The system matrix
/// depends on σ_e only through σ_e G_e, G_e the triangle's stiffness at unit conductance
/// (fem/stiffness.hpp), so with u_d = u(I_d) and u_m = u(I_m) (reciprocity: the same solve)
///   ∂V_dm/∂σ_e = −u_m|_eᵀ G_e u_d|_e.
/// One solve per drive and per measured pair, then a 3 × 3 product per triangle and reading.
#include <array>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/fem/complete_electrode_model.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/sensor/excitation.hpp"
#include "emit/sensor/sensor.hpp"

namespace emit {

/// J [V/S], #readings × #F, row i for readings[i] (sensor/excitation.hpp: reading i's drive is
/// column `drive` of `drives_A`, N × D).
/// \throw InvalidInput for a reading naming a drive or electrode that does not exist.
Matrix conductivity_jacobian(const Mesh& mesh, const CompleteElectrodeModel& model, const Matrix& drives_A,
                             const std::vector<EitReading>& readings);

/// A current-injection skin's relative Jacobian ∂log V/∂σ on a uniform sheet (σ = 1/R□), the
/// one difference imaging of log(V/V_ref) uses: its complete electrode model (the excitation's
/// contact impedances; none: the shunt model), ∂V/∂σ as above, each row divided by its reading.
/// `model_s`, if given, receives the seconds the model's assembly and factorisation took.
/// \throw InvalidInput for a sensor without an excitation, SolverError for a reading of 0 V.
Matrix relative_conductivity_jacobian(const Mesh& mesh, const Sensor& sensor, double* model_s = nullptr);

}  // namespace emit
