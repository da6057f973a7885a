#pragma once
/// \file shaded_surface.hpp
/// A picture of a scalar field on a curved sheet (a triangle mesh in 3D): two or three panels side
/// by side, each an orthographic view of the mesh coloured by nodal values (linear inside each
/// triangle, colormap()) and shaded by a fixed light, hidden parts removed by a z-buffer:
/// - left, the oblique view, from azimuth −60° and elevation 30° (the viewer in the direction
///   (cos 30° cos −60°, cos 30° sin −60°, sin 30°) from the sheet: in front of it at −y, to the +x
///   side, 30° up);
/// - next, the top view, from +z (x right, y up, as render_field draws a flat sheet);
/// - right, only where those two leave part of the surface unseen (a sleeve's underside: see
///   unseen_from_above_fraction), the bottom view, from −z (x right, y down).
/// Over the surface: the border dark, the electrodes thick in render_field's orange with their
/// numbers (where their middle is in sight), outlined circles (contacts, presses) in the surface's
/// tangent plane at their centres; beside the panels a colour bar with its range and unit, above
/// them their captions and the title. A mark (a line, a circle, a number) shows only where the
/// surface under it is in sight in that panel: a circle's point stands for the surface's point
/// nearest it, and at a pixel the surface does not cover (a silhouette, a rim seen edge-on) a mark
/// is hidden when all of the surface within two pixels lies in front of it.
#include <optional>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/render/field_image.hpp"
#include "emit/render/image.hpp"

namespace emit {

inline constexpr double oblique_azimuth_deg = -60;   ///< the oblique panel's view: angle about +z from +x
inline constexpr double oblique_elevation_deg = 30;  ///< and above the plane z = 0

/// One panel's orthographic projection. A point P (mm) lands at picture coordinates
/// (offset_x_px + scale · P·right, offset_y_px − scale · P·up) (x right, y down, pixel (i, j)
/// covering [i, i+1) × [j, j+1)), at depth P·toward_viewer, larger nearer the viewer.
struct SurfaceView {
  Vector3 right{1, 0, 0}, up{0, 1, 0}, toward_viewer{0, 0, 1};  ///< orthonormal, right × up = toward_viewer
  double scale_px_per_mm = 1, offset_x_px = 0, offset_y_px = 0;
  int left_px = 0, top_px = 0, size_px = 0;  ///< the panel: a square of pixels

  /// The view from azimuth φ (about +z, from +x) and elevation θ: toward_viewer = (cos θ cos φ,
  /// cos θ sin φ, sin θ), right = (−sin φ, cos φ, 0), up = toward_viewer × right. The top view is
  /// φ = −90°, θ = 90°. Scale and offsets are left at 1 and 0.
  static SurfaceView looking_from(double azimuth_deg, double elevation_deg);

  Vector2 to_px(const Vector3& point_mm) const;  ///< continuous picture coordinates
  int pixel_x(const Vector3& point_mm) const;    ///< the column of the pixel it lands in
  int pixel_y(const Vector3& point_mm) const;    ///< the row
  double depth_mm(const Vector3& point_mm) const { return point_mm.dot(toward_viewer); }
};

/// Where everything goes: the picture's size and the panels' projections.
struct ShadedLayout {
  int width_px = 0, height_px = 0;
  SurfaceView oblique, top;
  std::optional<SurfaceView> bottom;  ///< the view from −z (x right, y down), if the picture has it
};

/// The share of the surface's area above which the picture gets its bottom panel.
inline constexpr double bottom_panel_min_unseen_fraction = 0.03;

/// The share of the mesh's area (0 to 1) that neither the oblique nor the top view shows: the
/// triangles whose centroid lies behind the surface drawn at its pixel (a z-buffer of about 256 px
/// across, the marks' depth tolerance) in both. 0 for a flat sheet or a dome; about a third for a
/// sleeve (its underside, less what the oblique view sees of it).
double unseen_from_above_fraction(const Mesh& mesh);

/// The unit vector towards the light (world frame, the same for both panels): from above, over the
/// oblique viewer's left shoulder, (−1, −5, 7)/√75.
Vector3 shading_light_direction();

/// The brightness a facet of unit normal n gets: ambient + diffuse · |n · l| = 0.35 + 0.65 |n · l|
/// (|…| so both sides of the sheet are lit); a pixel's colour is colormap(t) times this, rounded.
double lambert_shade(const Vector3& unit_normal);

/// Where render_shaded_surface puts everything for this mesh and these options (options.width_px
/// is the whole picture's; title, unit and width decide the layout, not the values). The bottom
/// panel is there when unseen_from_above_fraction(mesh) exceeds bottom_panel_min_unseen_fraction.
/// All panels share one scale, the largest at which each view of the mesh fits its square.
/// \throw InvalidInput as render_shaded_surface does for the mesh, or if width_px leaves panels
/// under 40 px.
ShadedLayout plan_shaded_layout(const Mesh& mesh, const FieldImageOptions& options);

/// Renders `nodal_values` (#V) over `mesh` (nodes in 3D, triangles of either orientation), with
/// `outlines` (circles of radius radius_mm about (center_mm, z_mm)). `layout`, if given, receives
/// plan_shaded_layout's answer.
/// \throw InvalidInput if the mesh is empty, a node is not finite, a triangle or electrode names a
/// node the mesh does not have, the values are not one per node, the colour range is not an
/// interval, or the mesh has no extent in a view.
Image render_shaded_surface(const Mesh& mesh, const Vector& nodal_values, const std::vector<Circle>& outlines,
                            const FieldImageOptions& options, ShadedLayout* layout = nullptr);

}  // namespace emit
