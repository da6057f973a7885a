#pragma once
/// \file field_image.hpp
/// A picture of a scalar field on the sheet: the mesh coloured by nodal values (linear inside
/// each triangle), the border, the electrodes drawn thick and numbered, outlined circles (the
/// presses), a colour bar with its range and unit, and a title.
#include <limits>
#include <string>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/render/image.hpp"

namespace emit {

/// An outlined circle (a contact, a press): its centre (x, y) and, on a curved sheet, the centre's
/// height z (render_field ignores it; render_shaded_surface draws the circle in the sheet's
/// tangent plane there). Or an outlined ellipse or polygon (a contact's outline, frame/contacts.hpp).
struct Circle {
  Vector2 center_mm{0, 0};
  double radius_mm = 0;  ///< a circle's radius; an ellipse's semi-major axis
  double z_mm = 0;
  /// Drawn as an ellipse when `ellipse`: semi-axes radius_mm and semi_minor_mm (≤ radius_mm), the
  /// major axis at orientation_deg from the sheet's x axis seen from +z (on a curved sheet, in the
  /// tangent plane along that direction's projection).
  bool ellipse = false;
  double semi_minor_mm = 0, orientation_deg = 0;
  /// Drawn as this closed polygon instead when it has 3 points or more (a contact's outline,
  /// frame/contact_outline.hpp, placed on the sheet): render_field draws its (x, y),
  /// render_shaded_surface its points as they are.
  std::vector<Vector3> polygon_mm{};
  /// Written beside the mark, up and right of it, white on a dark edge (a contact's id and force;
  /// render_field only). Empty: none.
  std::string label{};
};

struct FieldImageOptions {
  int width_px = 640;      ///< the image's width; the height follows the sheet's aspect
  std::string title;       ///< drawn at the top
  std::string unit = "V";  ///< shown on the colour bar
  double min_value = std::numeric_limits<double>::quiet_NaN();  ///< NaN: the field's minimum
  double max_value = std::numeric_limits<double>::quiet_NaN();  ///< NaN: the field's maximum
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// Sequential colour map (perceptually ordered, dark → bright) for t in [0, 1].
Rgb colormap(double t);

/// Where a sheet point (x, y) in mm lands in the picture, for tests that check colours.
struct FieldLayout {
  double scale_px_per_mm = 1, origin_x_px = 0, origin_y_px = 0, min_x_mm = 0, max_y_mm = 0;
  int pixel_x(double x_mm) const;
  int pixel_y(double y_mm) const;
};

/// Renders `nodal_values` (#V) over a flat mesh (z ignored). `layout`, if given, receives the
/// mapping from mm to pixels.
Image render_field(const Mesh& mesh, const Vector& nodal_values, const std::vector<Circle>& outlines,
                   const FieldImageOptions& options, FieldLayout* layout = nullptr);

}  // namespace emit
