#pragma once
// What the pictures of a field on a mesh share (render_field's flat one, render_shaded_surface's
// two panels): the checks of their inputs, the colour range and its labels, the title, the colour
// bar, and the drawing primitives (a triangle's pixels, a thick segment, a ring) in picture
// coordinates: x right and y down, pixel (i, j) covering [i, i+1) × [j, j+1), centres at
// half-integers.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "emit/core/types.hpp"
#include "emit/mesh/mesh.hpp"
#include "emit/render/field_image.hpp"
#include "emit/render/image.hpp"

namespace emit::detail {

inline constexpr Rgb white{255, 255, 255};
inline constexpr Rgb text_colour{20, 20, 20};
inline constexpr Rgb border_colour{40, 40, 40};
inline constexpr Rgb electrode_colour{215, 95, 0};  // dark orange: stands out against every colour of the map
inline constexpr Rgb outline_shadow{25, 25, 25};

inline constexpr int font_scale = 2;
inline constexpr int padding_px = 8;
inline constexpr int label_margin_px = 40;  ///< room around the sheet for the electrode numbers
inline constexpr int bar_width_px = 18;
inline constexpr int bar_label_gap_px = 6;               ///< between the colour bar and its labels
inline constexpr double electrode_half_width_px = 1.75;  ///< 3–4 px lines
inline constexpr double border_half_width_px = 0.75;
/// The sides of an outlined ellipse's polygon (a circle's: within 0.06 % of its radius).
inline constexpr int ellipse_segments = 96;

/// A rectangle of pixels, x right and y down.
struct Box {
  int x = 0, y = 0, width = 0, height = 0;
};

/// The values that map to the two ends of the colour map.
struct ValueRange {
  double min = 0, max = 0;
  /// Position of `value` in the map; a single-valued range maps to its middle (no division by 0).
  double fraction(double value) const { return max > min ? (value - min) / (max - min) : 0.5; }
};

/// \throw InvalidInput, its message starting with `who`, if the mesh is empty, a node's x or y is
/// not finite (z too when `check_z`), a triangle or electrode names a node the mesh does not have,
/// or `nodal_values` is not one value per node.
void check_field_inputs(const Mesh& mesh, const Vector& nodal_values, bool check_z, const std::string& who);

/// The options' range, each NaN end replaced by the field's extreme (non-finite values ignored).
/// \throw InvalidInput (naming `who`) if the result is not a finite interval.
ValueRange value_range(const Vector& values, const FieldImageOptions& options, const std::string& who);

/// `value` as printf's %.4g, then the unit after a space (if any).
std::string value_label(double value, const std::string& unit);

/// Splits `text` at spaces into lines no wider than `max_width_px` at font_scale (a single long
/// word overflows).
std::vector<std::string> wrap_text(const std::string& text, int max_width_px);

/// The height in pixels of the title's lines (0 for none), the padding above them included.
int title_height_px(const std::vector<std::string>& title_lines);

/// Draws the title's lines at the top left.
void draw_title(Image& image, const std::vector<std::string>& title_lines);

/// The colour map in `bar` (its maximum at the top), framed, labelled to its right: its ends with
/// the unit, and between them ticks at round values (1, 2, 2.5 or 5 × 10^k apart, three to
/// five of them) where their labels clear the ends'.
void draw_colour_bar(Image& image, const Box& bar, double min_value, double max_value, const std::string& unit);

/// A mark's label (a contact's id and force) up and right of the mark at `centre_px`, `reach_px`
/// out along the diagonal: white with a dark edge, so that it reads on every colour of the map.
void draw_mark_label(Image& image, const Vector2& centre_px, double reach_px, const std::string& label);

/// A round step near `span` / 4: 1, 2, 2.5 or 5 × 10^k.
double round_step(double span);

/// Axes in mm along a flat sheet's picture: where they go and how mm map to pixels.
struct MmAxes {
  double min_x_mm = 0, max_x_mm = 0, min_y_mm = 0, max_y_mm = 0;
  double origin_x_px = 0, origin_y_px = 0, scale_px_per_mm = 1;  ///< pixel of (min_x, max_y)
  int x_axis_y_px = 0;                                           ///< the x axis's line (under the sheet)
  int y_axis_x_px = 0;                                           ///< the y axis's line (left of the sheet)
  double x_px(double x_mm) const { return origin_x_px + (x_mm - min_x_mm) * scale_px_per_mm; }
  double y_px(double y_mm) const { return origin_y_px + (max_y_mm - y_mm) * scale_px_per_mm; }
};
/// Width of the y axis's labels, its ticks and the gaps beside them [px]; height of the x axis's.
inline constexpr int y_axis_width_px = 40, x_axis_height_px = 22;

/// The x axis under the sheet and the y axis left of it, ticked at round values (round_step of
/// the larger extent) with their values, "mm" after the last x value.
void draw_mm_axes(Image& image, const MmAxes& axes);

/// A scale bar of a round length (1, 2 or 5 × 10^k mm, the longest within `max_width_px` with
/// its label) at (x, y), labelled "L mm" to its right: a flat picture's distances read off it.
void draw_scale_bar(Image& image, int x, int y, double px_per_mm, int max_width_px);

/// The pixels (inclusive bounds) whose centres may lie in [x_min, x_max] × [y_min, y_max],
/// clipped to the image. Clamping happens in double so far-off shapes cannot overflow an int.
struct PixelRange {
  int x0, x1, y0, y1;
};
PixelRange pixels_within(const Image& image, double x_min, double x_max, double y_min, double y_max);

/// Calls visit(x, y, weight) for every pixel of `image` whose centre lies inside the triangle
/// (edges included, so neighbouring triangles leave no cracks), `weight` its three barycentric
/// weights (each corner's share: the sub-triangle opposite it over the whole). Plain doubles
/// rather than Eigen vectors: this loop runs for every pixel of the sheet. A triangle of no area
/// has no pixels.
template <typename Visit>
void for_each_triangle_pixel(const Image& image, const std::array<Vector2, 3>& corners, Visit&& visit) {
  const double px[3] = {corners[0].x(), corners[1].x(), corners[2].x()};
  const double py[3] = {corners[0].y(), corners[1].y(), corners[2].y()};
  const double area = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]);  // doubled, signed
  if (area == 0) return;
  const PixelRange r = pixels_within(image, std::min({px[0], px[1], px[2]}), std::max({px[0], px[1], px[2]}),
                                     std::min({py[0], py[1], py[2]}), std::max({py[0], py[1], py[2]}));
  constexpr double edge_tolerance = 1e-9;  // barycentric weights are relative, so this is scale-free
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      const double qx = x + 0.5, qy = y + 0.5;
      std::array<double, 3> weight{};
      for (int k = 0; k < 3; ++k) {
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        weight[k] = ((px[a] - qx) * (py[b] - qy) - (py[a] - qy) * (px[b] - qx)) / area;
      }
      if (weight[0] < -edge_tolerance || weight[1] < -edge_tolerance || weight[2] < -edge_tolerance) continue;
      visit(x, y, weight);
    }
}

/// Calls visit(x, y, s) for every pixel whose centre lies within `half_width` of segment ab
/// (round caps), s in [0, 1] the parameter of the segment's point nearest the centre.
template <typename Visit>
void for_each_segment_pixel(const Image& image, const Vector2& a, const Vector2& b, double half_width, Visit&& visit) {
  const PixelRange r = pixels_within(image, std::min(a.x(), b.x()) - half_width, std::max(a.x(), b.x()) + half_width,
                                     std::min(a.y(), b.y()) - half_width, std::max(a.y(), b.y()) + half_width);
  const Vector2 ab = b - a;
  const double length2 = ab.squaredNorm();
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) {
      const Vector2 q(x + 0.5, y + 0.5);
      const double s = length2 > 0 ? std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
      if ((a + s * ab - q).norm() <= half_width) visit(x, y, s);
    }
}

/// Paints every pixel whose centre lies within `half_width` of segment ab (round caps).
void draw_segment(Image& image, const Vector2& a, const Vector2& b, double half_width, Rgb colour);

/// Paints every pixel whose centre lies within `half_width` of the circle.
void draw_ring(Image& image, const Vector2& centre, double radius, double half_width, Rgb colour);

/// Writes electrode e's number just outside the sheet: from `middle_px` (the electrode's middle)
/// along `away` (a unit vector, from the sheet's centre outwards), far enough that the label's box
/// clears the electrode line.
void draw_electrode_label(Image& image, int e, const Vector2& middle_px, const Vector2& away);

}  // namespace emit::detail
