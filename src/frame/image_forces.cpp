#include "emit/frame/image_forces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "emit/core/errors.hpp"

namespace emit {

ImageForces::ImageForces(const Mesh& mesh) {
  const auto count = static_cast<std::size_t>(mesh.triangle_count());
  areas_mm2_.resize(count);
  centroids_mm_.resize(count);
  for (std::size_t t = 0; t < count; ++t) {
    areas_mm2_[t] = mesh.triangle_area_mm2(static_cast<Index>(t));
    centroids_mm_[t] = mesh.triangle_centroid_mm(static_cast<Index>(t));
  }
  integrals_.reserve(count);
  contacts_.reserve(count);
}

const std::vector<double>& ImageForces::integrals(const Vector& image, const std::vector<Contact>& contacts) {
  if (image.size() != static_cast<Index>(areas_mm2_.size()))
    throw InvalidInput("image forces: the image has " + std::to_string(image.size()) +
                       " values, expected one per mesh element (" + std::to_string(areas_mm2_.size()) + ")");
  integrals_.assign(contacts.size(), 0.0);  // within the reserved capacity
  if (contacts.empty()) return integrals_;
  for (std::size_t k = 0; k < areas_mm2_.size(); ++k) {
    std::size_t nearest = 0;
    double nearest_mm2 = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < contacts.size(); ++j) {
      const Contact& c = contacts[j];
      const double d2 = (centroids_mm_[k] - Vector3(c.x_mm, c.y_mm, c.z_mm)).squaredNorm();
      if (d2 < nearest_mm2) nearest = j, nearest_mm2 = d2;
    }
    integrals_[nearest] += areas_mm2_[k] * image[static_cast<Index>(k)];
  }
  return integrals_;
}

const std::vector<Contact>& ImageForces::apply(const ImageForceLaw& law, const Vector& image,
                                               const std::vector<Contact>& contacts) {
  integrals(image, contacts);
  contacts_.assign(contacts.begin(), contacts.end());  // within the reserved capacity
  const double area_mm2 = law.indenter_area_mm2();
  const double force_std = law.force_relative_std(), pressure_std = law.pressure_relative_std();
  for (std::size_t j = 0; j < contacts_.size(); ++j) {
    Contact& c = contacts_[j];
    c.force_N = law.force_N(integrals_[j]);
    c.area_mm2 = area_mm2;
    c.pressure_N_per_mm2 = c.peak_pressure_N_per_mm2 = c.force_N / area_mm2;
    c.force_std_N = force_std * c.force_N;
    c.pressure_std_N_per_mm2 = pressure_std * c.pressure_N_per_mm2;
  }
  // std::sort works in place; NaN forces (from a NaN image) go last, keeping a strict weak order.
  const auto key = [](const Contact& c) {
    return std::isnan(c.force_N) ? -std::numeric_limits<double>::infinity() : c.force_N;
  };
  std::sort(contacts_.begin(), contacts_.end(), [&](const Contact& a, const Contact& b) { return key(a) > key(b); });
  return contacts_;
}

}  // namespace emit
