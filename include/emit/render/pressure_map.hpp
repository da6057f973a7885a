#pragma once
/// \file pressure_map.hpp
/// A pressure image as a picture: the per-element pressure drawn smooth over the mesh (N/mm², from
/// 0), with circles or ellipses outlined (contacts found: contact_outline; or the true presses). A
/// flat sheet is drawn from +z (render_field); a curved one, a mesh not flat (mesh/flatness.hpp),
/// as the shaded picture (render_shaded_surface: an oblique view and the top view, and the bottom
/// view for a sheet those leave partly unseen), shaded_pressure_map_width_px wide.
#include <string>
#include <vector>

#include "emit/frame/contacts.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/render/field_image.hpp"

namespace emit {

inline constexpr int shaded_pressure_map_width_px = 1024;  ///< two panels of 341 px beside the colour bar

/// A contact's mark: its outline's polygon when it has one (frame/contact_outline.hpp; its chart
/// points placed on `surface`, the sheet's shape), else the ellipse of its second moments when it
/// has one (semi_major_mm > 0: frame/contacts.hpp), else the circle of its area.
Circle contact_outline(const Contact& contact, const Shape& surface = {});

/// A field on the sheet as a picture: render_field for a flat sheet, render_shaded_surface (at
/// least shaded_pressure_map_width_px wide) for a curved one. \param nodal_values  #V values.
Image render_sheet_field(const Mesh& mesh, const Vector& nodal_values, const std::vector<Circle>& outlines,
                         FieldImageOptions options);

/// How a run's pressure maps are drawn (`--images`, `--pressure-range`, `--image-width`).
struct PressureMapOptions {
  /// The colour bar's top [N/mm²], the same for every frame of a run so that frames compare;
  /// 0: each frame's own largest pressure.
  double max_pressure_N_per_mm2 = 0;
  int width_px = 640;     ///< a curved sheet's picture is at least shaded_pressure_map_width_px
  void validate() const;  ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// Writes the PNG (atomically). \param element_pressure  #F values [N/mm²]. \throw IoError.
void write_pressure_map(const Mesh& mesh, const Vector& element_pressure, const std::vector<Circle>& outlines,
                        const std::string& title, const std::string& path, const PressureMapOptions& options = {});

/// A contact's label on a map: its id when tracked and its force to 0.1 N, "#3  4.2 N", or the
/// force alone.
std::string contact_label(const Contact& contact);

/// A frame's picture's name, its number zero-padded to six digits so that names sort in frame
/// order ("frame_000042.png"; a run holds at most 131,072 frames: core/limits.hpp).
std::string frame_image_name(std::size_t frame);

}  // namespace emit
