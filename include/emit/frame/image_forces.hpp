#pragma once
/// \file image_forces.hpp
/// A linear method's contacts given their force by emit's force law (model/force_law.hpp): each
/// contact's integral of the image, I_j = Σ A_k δφ_k over the elements nearer its point than any
/// other contact's (the whole sheet for one contact: the integral is a linear functional of the
/// frame, the same whatever the image's blur), and from it F = (b1/I + b2)^b3. The frame does not
/// pin a contact's area, so each is reported with the calibration's indenter area, its pressure
/// F/A (peak and mean alike, a flat indenter's) and 1σs that say how little the area is known.
///
/// Offline/online split: the constructor keeps the mesh's element areas and centroids and sizes
/// every buffer for the worst case (every element its own contact); integrals() and apply() run
/// per frame and allocate nothing.
#include <vector>

#include "emit/core/types.hpp"
#include "emit/frame/contacts.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/model/force_law.hpp"

namespace emit {

class ImageForces {
 public:
  explicit ImageForces(const Mesh& mesh);

  /// Each contact's integral of `image` (#F values, e.g. δφ [V]) over the elements nearest it
  /// (by the 3D distance from the element's centroid to the contact's point) [V·mm²], in the
  /// contacts' order; empty without contacts. Valid until the next call.
  /// \throw InvalidInput if `image` is not one value per element.
  const std::vector<double>& integrals(const Vector& image, const std::vector<Contact>& contacts);

  /// The contacts with force, area, pressures and σs from `law` on their integrals, strongest
  /// first; position and element count as found. Valid until the next call.
  const std::vector<Contact>& apply(const ImageForceLaw& law, const Vector& image,
                                    const std::vector<Contact>& contacts);

 private:
  std::vector<double> areas_mm2_;
  std::vector<Vector3> centroids_mm_;
  std::vector<double> integrals_;  ///< capacity #F
  std::vector<Contact> contacts_;  ///< capacity #F
};

}  // namespace emit
